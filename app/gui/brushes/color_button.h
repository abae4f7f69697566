#pragma once

#include <QColor>
#include <QPushButton>

namespace octaclay::app {

/// A button showing a colour (swatch and #rrggbbaa) that opens QColorDialog when clicked. The
/// value is the `color` property, so tests and scripts can set it without the dialog.
class ColorButton : public QPushButton {
  Q_OBJECT
  Q_PROPERTY(QColor color READ color WRITE setColor NOTIFY colorChanged)

public:
  explicit ColorButton(QWidget* parent = nullptr);

  QColor color() const { return color_; }
  /// Shows `color` (alpha included); emits colorChanged when it differs from the current one.
  void setColor(const QColor& color);

signals:
  void colorChanged(const QColor& color);

private:
  void pickColor();

  QColor color_;
};

} // namespace octaclay::app
