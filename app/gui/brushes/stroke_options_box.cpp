#include "stroke_options_box.h"

#include "brush_state.h"
#include "parameter_form.h"

#include "octaclay/gpu/stroke.h"

#include <QCheckBox>
#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace octaclay::app {
namespace {

constexpr std::array kAxes{gpu::kSymmetryX, gpu::kSymmetryY, gpu::kSymmetryZ};

} // namespace

StrokeOptionsBox::StrokeOptionsBox(BrushState& state, QWidget* parent)
    : QGroupBox(tr("Stroke"), parent), state_(state) {
  auto* layout = new QFormLayout(this);

  pressureCombo_ = makeNarrowCombo();
  pressureCombo_->setObjectName(QStringLiteral("pressureTarget"));
  pressureCombo_->addItem(tr("None"), static_cast<int>(PressureTarget::None));
  pressureCombo_->addItem(tr("Radius"), static_cast<int>(PressureTarget::Radius));
  pressureCombo_->addItem(tr("Strength"), static_cast<int>(PressureTarget::Strength));
  pressureCombo_->setToolTip(tr("What pen pressure scales"));
  connect(pressureCombo_, &QComboBox::currentIndexChanged, this, [this](int index) {
    if (index >= 0) state_.setPressureTarget(static_cast<PressureTarget>(index));
  });
  layout->addRow(tr("Pressure"), pressureCombo_);

  stabilizerSlider_ = new QSlider(Qt::Horizontal);
  stabilizerSlider_->setObjectName(QStringLiteral("stabilizer"));
  stabilizerSlider_->setRange(0, 100);
  stabilizerSlider_->setToolTip(tr("Lazy mouse: how far the brush trails the cursor, smoothing "
                                   "the stroke (0 follows the cursor exactly)"));
  stabilizerLabel_ = new QLabel;
  stabilizerLabel_->setMinimumWidth(
      stabilizerLabel_->fontMetrics().horizontalAdvance(QStringLiteral("100 %")));
  connect(stabilizerSlider_, &QSlider::valueChanged, this,
          [this](int percent) { state_.setStabilizer(static_cast<float>(percent) / 100.0f); });
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
    const unsigned bit = kAxes[k];
    connect(box, &QCheckBox::toggled, this, [this, bit](bool on) {
      const unsigned axes = state_.settings().symmetry;
      state_.setSymmetry(on ? axes | bit : axes & ~bit);
    });
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
  connect(keepDetailBox_, &QCheckBox::toggled, &state_, &BrushState::setKeepDetail);
  layout->addRow(keepDetailBox_);

  connect(&state_, &BrushState::changed, this, &StrokeOptionsBox::showValues);
  showValues();
}

void StrokeOptionsBox::showValues() {
  const BrushSettings s = state_.settings();
  const int percent = static_cast<int>(std::lround(s.stabilizer * 100.0f));
  const QSignalBlocker blockPressure(pressureCombo_), blockSlider(stabilizerSlider_),
      blockKeep(keepDetailBox_);
  pressureCombo_->setCurrentIndex(static_cast<int>(s.pressureTarget));
  stabilizerSlider_->setValue(percent);
  stabilizerLabel_->setText(QStringLiteral("%1 %").arg(percent));
  for (std::size_t k = 0; k < 3; ++k) {
    const QSignalBlocker block(symmetryBoxes_[k]);
    symmetryBoxes_[k]->setChecked((s.symmetry & kAxes[k]) != 0);
  }
  keepDetailBox_->setChecked(s.keepDetail);
}

} // namespace octaclay::app
