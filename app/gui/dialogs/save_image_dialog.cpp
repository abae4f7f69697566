#include "save_image_dialog.h"

#include <QCheckBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>

namespace octaclay::app {

SaveImageDialog::SaveImageDialog(QSize viewSize, int maxSide, QWidget* parent)
    : QDialog(parent), viewSize_(viewSize) {
  setWindowTitle(tr("Save image"));
  auto* form = new QFormLayout(this);
  viewSizeButton_ =
      new QRadioButton(tr("As the view: %1 × %2").arg(viewSize.width()).arg(viewSize.height()));
  viewSizeButton_->setChecked(true);
  auto* custom = new QRadioButton(tr("Custom:"));
  width_ = new QSpinBox;
  height_ = new QSpinBox;
  for (QSpinBox* box : {width_, height_}) {
    box->setRange(16, std::max(16, maxSide));
    box->setSuffix(tr(" px"));
    box->setEnabled(false);
  }
  width_->setValue(viewSize.width() * 2);
  height_->setValue(viewSize.height() * 2);
  connect(custom, &QRadioButton::toggled, width_, &QWidget::setEnabled);
  connect(custom, &QRadioButton::toggled, height_, &QWidget::setEnabled);
  auto* customRow = new QHBoxLayout;
  customRow->addWidget(custom);
  customRow->addWidget(width_);
  customRow->addWidget(new QLabel(QStringLiteral("×")));
  customRow->addWidget(height_);
  form->addRow(tr("Size"), viewSizeButton_);
  form->addRow(QString(), customRow);
  transparent_ = new QCheckBox(tr("Transparent background"));
  transparent_->setToolTip(tr("Only the model is opaque, for laying the picture over another"));
  form->addRow(QString(), transparent_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
}

ImageRequest SaveImageDialog::request() const {
  ImageRequest r;
  r.size = viewSizeButton_->isChecked() ? viewSize_ : QSize(width_->value(), height_->value());
  r.background = !transparent_->isChecked();
  return r;
}

} // namespace octaclay::app
