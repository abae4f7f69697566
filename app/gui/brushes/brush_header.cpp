#include "brush_header.h"

#include "brush_value_store.h"

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
                       tr("Brush radius, in percent of the model's size (F, then drag on the "
                          "model)"));
  radiusLabel_ = new QLabel;
  radiusLabel_->setMinimumWidth(radiusLabel_->fontMetrics().horizontalAdvance("100.0 %"));
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
    showLabels(positionToRadius(position), static_cast<float>(strength_->value()) / 100.0f);
    emit radiusEdited(positionToRadius(position));
  });
  connect(strength_, &QSlider::valueChanged, this, [this](int percent) {
    showLabels(positionToRadius(radius_->value()), static_cast<float>(percent) / 100.0f);
    emit strengthEdited(static_cast<float>(percent) / 100.0f);
  });
  setValues(BrushValues{}.radius, BrushValues{}.strength, 0);
}

void BrushHeader::setValues(float radius, float strength, unsigned symmetry) {
  {
    const QSignalBlocker blockRadius(radius_), blockStrength(strength_);
    radius_->setValue(radiusToPosition(radius));
    strength_->setValue(static_cast<int>(std::lround(strength * 100.0f)));
  }
  for (std::size_t k = 0; k < 3; ++k) {
    const QSignalBlocker block(symmetry_[k]);
    symmetry_[k]->setChecked((symmetry & kAxes[k]) != 0);
  }
  showLabels(radius, strength);
}

int BrushHeader::radiusToPosition(float radius) {
  const float r = std::clamp(radius, kMinRadius, kMaxRadius);
  const double t = std::log(double(r) / kMinRadius) / std::log(double(kMaxRadius) / kMinRadius);
  return static_cast<int>(std::lround(t * kRadiusSteps));
}

float BrushHeader::positionToRadius(int position) {
  const double t = double(std::clamp(position, 0, kRadiusSteps)) / kRadiusSteps;
  return static_cast<float>(kMinRadius * std::pow(double(kMaxRadius) / kMinRadius, t));
}

void BrushHeader::showLabels(float radius, float strength) {
  radiusLabel_->setText(QStringLiteral("%1 %").arg(double(radius) * 100.0, 0, 'f', 1));
  strengthLabel_->setText(QStringLiteral("%1 %").arg(std::lround(strength * 100.0f)));
}

} // namespace octaclay::app
