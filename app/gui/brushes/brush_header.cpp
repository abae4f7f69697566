#include "brush_header.h"

#include "brush_value_store.h"
#include "radius_field.h"

#include "octaclay/gpu/stroke.h"

#include <QAction>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>

#include <algorithm>
#include <cmath>

namespace octaclay::app {
namespace {

constexpr std::array<unsigned, 3> kAxes{gpu::kSymmetryX, gpu::kSymmetryY, gpu::kSymmetryZ};

// The slider's range in unit.
std::array<double, 2> radiusRange(RadiusUnit unit) {
  return unit == RadiusUnit::View ? std::array<double, 2>{kMinRadiusPixels, kMaxRadiusPixels}
                                  : std::array<double, 2>{kMinRadius, kMaxRadius};
}

QSlider* makeSlider(const QString& name, int maximum, const QString& tip) {
  auto* slider = new QSlider(Qt::Horizontal);
  slider->setObjectName(name);
  slider->setRange(0, maximum);
  slider->setFixedWidth(140);
  slider->setToolTip(tip);
  return slider;
}

} // namespace

BrushHeader::BrushHeader(QWidget* parent) : QToolBar(tr("Brush settings"), parent) {
  setObjectName(QStringLiteral("BrushHeader"));
  setMovable(false);
  // Always there: no entry in the tool bars' context menu hides it.
  toggleViewAction()->setVisible(false);

  radius_ = makeSlider(QStringLiteral("headerRadius"), kRadiusSteps,
                       tr("Brush radius, in pixels of the view or percent of the model's size as "
                          "the Brushes dock says (F, then drag on the model)"));
  radiusLabel_ = new QLabel;
  radiusLabel_->setMinimumWidth(radiusLabel_->fontMetrics().horizontalAdvance("1000 px"));
  strength_ = makeSlider(QStringLiteral("headerStrength"), 100,
                         tr("How strongly the brush acts (Shift+F, then drag on the model)"));
  strengthLabel_ = new QLabel;
  strengthLabel_->setMinimumWidth(strengthLabel_->fontMetrics().horizontalAdvance("100 %"));
  addWidget(new QLabel(tr(" Radius ")));
  addWidget(radius_);
  addWidget(radiusLabel_);
  addSeparator();
  addWidget(new QLabel(tr(" Strength ")));
  addWidget(strength_);
  addWidget(strengthLabel_);
  addSeparator();
  addWidget(new QLabel(tr(" Symmetry ")));
  const std::array<QString, 3> names{QStringLiteral("X"), QStringLiteral("Y"), QStringLiteral("Z")};
  for (std::size_t k = 0; k < 3; ++k) {
    QAction* axis = addAction(names[k]);
    axis->setObjectName(QStringLiteral("headerSymmetry") + names[k]);
    axis->setCheckable(true);
    axis->setToolTip(tr("Mirror strokes across the model's %1 = 0 plane").arg(names[k]));
    connect(axis, &QAction::toggled, this, [this] {
      unsigned axes = 0;
      for (std::size_t j = 0; j < 3; ++j)
        if (symmetry_[j]->isChecked()) axes |= kAxes[j];
      emit symmetryEdited(axes);
    });
    symmetry_[k] = axis;
  }

  connect(radius_, &QSlider::valueChanged, this, [this](int position) {
    showLabels(positionToRadius(position, unit_), static_cast<float>(strength_->value()) / 100.0f);
    emit radiusEdited(positionToRadius(position, unit_));
  });
  connect(strength_, &QSlider::valueChanged, this, [this](int percent) {
    showLabels(positionToRadius(radius_->value(), unit_), static_cast<float>(percent) / 100.0f);
    emit strengthEdited(static_cast<float>(percent) / 100.0f);
  });
  setValues(RadiusUnit::Scene, BrushValues{}.radius, BrushValues{}.strength, 0);
}

void BrushHeader::setValues(RadiusUnit unit, float radius, float strength, unsigned symmetry) {
  unit_ = unit;
  {
    const QSignalBlocker blockRadius(radius_), blockStrength(strength_);
    radius_->setValue(radiusToPosition(radius, unit));
    strength_->setValue(static_cast<int>(std::lround(strength * 100.0f)));
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const QSignalBlocker block(symmetry_[k]);
    symmetry_[k]->setChecked((symmetry & kAxes[k]) != 0);
  }
  showLabels(radius, strength);
}

int BrushHeader::radiusToPosition(float radius, RadiusUnit unit) {
  const auto [lo, hi] = radiusRange(unit);
  const double r = std::clamp(double(radius), lo, hi);
  const double t = std::log(r / lo) / std::log(hi / lo);
  return static_cast<int>(std::lround(t * kRadiusSteps));
}

float BrushHeader::positionToRadius(int position, RadiusUnit unit) {
  const auto [lo, hi] = radiusRange(unit);
  const double t = double(std::clamp(position, 0, kRadiusSteps)) / kRadiusSteps;
  return static_cast<float>(lo * std::pow(hi / lo, t));
}

void BrushHeader::showLabels(float radius, float strength) {
  radiusLabel_->setText(radiusText(unit_, radius));
  strengthLabel_->setText(QStringLiteral("%1 %").arg(std::lround(strength * 100.0f)));
}

} // namespace octaclay::app
