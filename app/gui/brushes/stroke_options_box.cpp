#include "stroke_options_box.h"

#include "brush_value_store.h"
#include "parameter_form.h"

#include "octaclay/gpu/stroke.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSettings>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace octaclay::app {
namespace {

constexpr std::array kAxes{gpu::kSymmetryX, gpu::kSymmetryY, gpu::kSymmetryZ};
constexpr std::array kPressureNames{"none", "radius", "strength"};

} // namespace

StrokeOptionsBox::StrokeOptionsBox(QWidget* parent) : QGroupBox(tr("Stroke"), parent) {
  load();
  auto* layout = new QFormLayout(this);

  pressureCombo_ = makeNarrowCombo();
  pressureCombo_->setObjectName(QStringLiteral("pressureTarget"));
  pressureCombo_->addItem(tr("None"), static_cast<int>(PressureTarget::None));
  pressureCombo_->addItem(tr("Radius"), static_cast<int>(PressureTarget::Radius));
  pressureCombo_->addItem(tr("Strength"), static_cast<int>(PressureTarget::Strength));
  pressureCombo_->setCurrentIndex(static_cast<int>(pressureTarget_));
  pressureCombo_->setToolTip(tr("What pen pressure scales"));
  connect(pressureCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) setPressureTarget(static_cast<PressureTarget>(index));
  });
  layout->addRow(tr("Pressure"), pressureCombo_);

  stabilizerSlider_ = new QSlider(Qt::Horizontal);
  stabilizerSlider_->setObjectName(QStringLiteral("stabilizer"));
  stabilizerSlider_->setRange(0, 100);
  stabilizerSlider_->setValue(stabilizerPercent_);
  stabilizerSlider_->setToolTip(tr("Lazy mouse: how far the brush trails the cursor, smoothing "
                                   "the stroke (0 follows the cursor exactly)"));
  stabilizerLabel_ = new QLabel;
  stabilizerLabel_->setMinimumWidth(
      stabilizerLabel_->fontMetrics().horizontalAdvance(QStringLiteral("100 %")));
  stabilizerLabel_->setText(QStringLiteral("%1 %").arg(stabilizerPercent_));
  connect(stabilizerSlider_, &QSlider::valueChanged, this,
          [this](int percent) { setStabilizer(static_cast<float>(percent) / 100.0f); });
  auto* stabilizerRow = new QHBoxLayout;
  stabilizerRow->addWidget(stabilizerSlider_, 1);
  stabilizerRow->addWidget(stabilizerLabel_);
  layout->addRow(tr("Stabilizer"), stabilizerRow);

  auto* symmetryRow = new QHBoxLayout;
  const std::array<QString, 3> axisNames{QStringLiteral("X"), QStringLiteral("Y"),
                                         QStringLiteral("Z")};
  for (std::size_t k = 0; k < 3; ++k) {
    auto* box = new QCheckBox(axisNames[k]);
    box->setObjectName(QStringLiteral("symmetry") + axisNames[k]);
    box->setToolTip(tr("Mirror strokes across the model's %1 = 0 plane").arg(axisNames[k]));
    box->setChecked((symmetry_ & kAxes[k]) != 0);
    const unsigned bit = kAxes[k];
    connect(box, &QCheckBox::toggled, this,
            [this, bit](bool on) { setSymmetry(on ? symmetry_ | bit : symmetry_ & ~bit); });
    symmetryBoxes_[k] = box;
    symmetryRow->addWidget(box);
  }
  symmetryRow->addStretch(1);
  layout->addRow(tr("Symmetry"), symmetryRow);

  keepDetailBox_ = new QCheckBox(tr("Keep detail"));
  keepDetailBox_->setObjectName(QStringLiteral("keepDetail"));
  keepDetailBox_->setToolTip(tr("When a stroke pulls the surface far, samples move in from around "
                                "it so the pulled part keeps its detail. Off: samples stay where "
                                "the brush put them."));
  keepDetailBox_->setChecked(keepDetail_);
  connect(keepDetailBox_, &QCheckBox::toggled, this, &StrokeOptionsBox::setKeepDetail);
  layout->addRow(keepDetailBox_);
}

void StrokeOptionsBox::setPressureTarget(PressureTarget target) {
  if (target == pressureTarget_) return;
  pressureTarget_ = target;
  {
    const QSignalBlocker block(pressureCombo_);
    pressureCombo_->setCurrentIndex(static_cast<int>(target));
  }
  save();
  emit changed();
}

void StrokeOptionsBox::setStabilizer(float amount) {
  const int percent = static_cast<int>(std::lround(clampFinite(amount, 0.0f, 1.0f, 0.0f) * 100.0f));
  if (percent == stabilizerPercent_) return;
  stabilizerPercent_ = percent;
  {
    const QSignalBlocker block(stabilizerSlider_);
    stabilizerSlider_->setValue(percent);
  }
  stabilizerLabel_->setText(QStringLiteral("%1 %").arg(percent));
  save();
  emit changed();
}

void StrokeOptionsBox::setSymmetry(unsigned axes) {
  axes &= gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ;
  if (axes == symmetry_) return;
  symmetry_ = axes;
  for (std::size_t k = 0; k < 3; ++k) {
    const QSignalBlocker block(symmetryBoxes_[k]);
    symmetryBoxes_[k]->setChecked((axes & kAxes[k]) != 0);
  }
  save();
  emit changed();
}

void StrokeOptionsBox::setKeepDetail(bool on) {
  if (on == keepDetail_) return;
  keepDetail_ = on;
  {
    const QSignalBlocker block(keepDetailBox_);
    keepDetailBox_->setChecked(on);
  }
  save();
  emit changed();
}

void StrokeOptionsBox::save() const {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  settings.setValue(QStringLiteral("pressureTarget"),
                    QString::fromLatin1(kPressureNames[static_cast<std::size_t>(pressureTarget_)]));
  settings.setValue(QStringLiteral("stabilizer"), stabilizerPercent_);
  settings.setValue(QStringLiteral("symmetry"), symmetry_);
  settings.setValue(QStringLiteral("keepDetail"), keepDetail_);
}

void StrokeOptionsBox::load() {
  QSettings settings;
  settings.beginGroup(QStringLiteral("brushPanel"));
  const QString pressure = settings.value(QStringLiteral("pressureTarget")).toString();
  for (std::size_t k = 0; k < kPressureNames.size(); ++k)
    if (pressure == QLatin1String(kPressureNames[k]))
      pressureTarget_ = static_cast<PressureTarget>(k);
  bool ok = false;
  if (const int percent = settings.value(QStringLiteral("stabilizer")).toInt(&ok); ok)
    stabilizerPercent_ = std::clamp(percent, 0, 100);
  if (const uint axes = settings.value(QStringLiteral("symmetry")).toUInt(&ok); ok)
    symmetry_ = axes & (gpu::kSymmetryX | gpu::kSymmetryY | gpu::kSymmetryZ);
  if (const QVariant keep = settings.value(QStringLiteral("keepDetail")); keep.isValid())
    keepDetail_ = keep.toBool();
}

} // namespace octaclay::app
