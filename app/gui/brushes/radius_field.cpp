#include "radius_field.h"

#include "brush_value_store.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QSignalBlocker>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

QString radiusText(RadiusUnit unit, float value) {
  if (unit == RadiusUnit::View) return QStringLiteral("%1 px").arg(std::lround(value));
  return QStringLiteral("%1 %").arg(double(value) * 100.0, 0, 'f', 1);
}

RadiusField::RadiusField(QWidget* parent) : QWidget(parent) {
  spin_ = new QDoubleSpinBox;
  spin_->setObjectName(QStringLiteral("radius"));
  unitCombo_ = new QComboBox;
  unitCombo_->setObjectName(QStringLiteral("radiusUnit"));
  unitCombo_->addItem(tr("px"), static_cast<int>(RadiusUnit::View));
  unitCombo_->setItemData(0, tr("View: pixels on screen, the same size at every zoom"),
                          Qt::ToolTipRole);
  unitCombo_->addItem(tr("%"), static_cast<int>(RadiusUnit::Scene));
  unitCombo_->setItemData(
      1, tr("Scene: percent of the model's bounding-box diagonal, the same size on the model"),
      Qt::ToolTipRole);
  unitCombo_->setToolTip(tr("What the radius is measured in: pixels of the view (the brush looks "
                            "the same at every zoom) or percent of the model's size"));
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(spin_, 1);
  layout->addWidget(unitCombo_);
  connect(spin_, &QDoubleSpinBox::valueChanged, this, [this](double shown) {
    emit valueEdited(unit_ == RadiusUnit::View ? static_cast<float>(shown)
                                               : static_cast<float>(shown / 100.0));
  });
  connect(unitCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) emit unitChosen(static_cast<RadiusUnit>(unitCombo_->itemData(index).toInt()));
  });
  setValue(RadiusUnit::Scene, BrushValues{}.radius);
}

void RadiusField::setValue(RadiusUnit unit, float value) {
  const QSignalBlocker blockSpin(spin_), blockUnit(unitCombo_);
  unit_ = unit;
  unitCombo_->setCurrentIndex(unitCombo_->findData(static_cast<int>(unit)));
  if (unit == RadiusUnit::View) {
    spin_->setDecimals(0);
    spin_->setRange(kMinRadiusPixels, kMaxRadiusPixels);
    spin_->setSingleStep(5.0);
    spin_->setSuffix(QStringLiteral(" px"));
    spin_->setToolTip(tr("Brush radius, in pixels of the view where the stroke begins"));
    spin_->setValue(static_cast<double>(value));
  } else {
    spin_->setDecimals(1);
    spin_->setRange(static_cast<double>(kMinRadius) * 100.0,
                    static_cast<double>(kMaxRadius) * 100.0);
    spin_->setSingleStep(0.5);
    spin_->setSuffix(QStringLiteral(" %"));
    spin_->setToolTip(tr("Brush radius, in percent of the model's bounding-box diagonal"));
    spin_->setValue(static_cast<double>(value) * 100.0);
  }
}

} // namespace octaclay::app
