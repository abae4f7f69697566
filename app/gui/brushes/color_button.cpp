#include "color_button.h"

#include <QColorDialog>
#include <QIcon>
#include <QPixmap>

namespace octaclay::app {

ColorButton::ColorButton(QWidget* parent) : QPushButton(parent) {
  connect(this, &QPushButton::clicked, this, &ColorButton::pickColor);
  setColor(Qt::white);
}

void ColorButton::setColor(const QColor& color) {
  const bool changed = color != color_;
  color_ = color;
  QPixmap swatch(16, 16);
  swatch.fill(color);
  setIcon(QIcon(swatch));
  setText(color.name(color.alpha() < 255 ? QColor::HexArgb : QColor::HexRgb));
  if (changed) emit colorChanged(color_);
}

void ColorButton::pickColor() {
  const QColor picked =
      QColorDialog::getColor(color_, this, tr("Choose a colour"), QColorDialog::ShowAlphaChannel);
  if (picked.isValid()) setColor(picked);
}

} // namespace octaclay::app
