#include "sparse_sampling_hint.h"

#include "modeller.h"
#include "screen_radius.h"
#include "viewport_widget.h"

#include "octaclay/core/measure/brush_sampling.h"

#include <QAction>
#include <QPushButton>
#include <QStatusBar>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

SparseSamplingHint::SparseSamplingHint(ViewportWidget* view, QStatusBar* bar, QAction* remesh,
                                       QObject* parent)
    : QObject(parent), view_(view), bar_(bar), button_(new QPushButton(tr("Remesh…"), bar)) {
  button_->setObjectName(QStringLiteral("sparseSamplingRemesh"));
  button_->setToolTip(tr("Mesh ▸ Remesh…: the whole surface sampled evenly again"));
  button_->setFocusPolicy(Qt::NoFocus); // the keys stay with the view
  button_->hide();
  bar_->addWidget(button_);
  if (remesh) connect(button_, &QPushButton::clicked, remesh, &QAction::trigger);
  // The button goes with the hint's message.
  connect(bar_, &QStatusBar::messageChanged, this, [this](const QString& text) {
    if (text != message_) {
      message_.clear();
      button_->hide();
    }
  });
  connect(view_, &ViewportWidget::strokePressed, this, &SparseSamplingHint::check);
}

void SparseSamplingHint::check(core::Vec2f uv) {
  if (!view_->modeller().hasDocument()) return;
  // The radius the press strokes with: in the view's unit, at the depth of the point pressed.
  const core::GeometryImage& positions = view_->modeller().document().positions;
  const int n = positions.size();
  const core::Vec4f at = positions.at(static_cast<int>(std::lround(uv.x * float(n))),
                                      static_cast<int>(std::lround(uv.y * float(n))));
  const double radius = viewBrushObjectRadius(*view_, at.xyz());
  const core::BrushSampling sampling = core::brushSampling(positions, uv, radius);
  lastSamples_ = sampling.samplesAcross;
  if (!sampling.sparse()) return;
  message_ = tr("Few samples here: %1 across the brush's radius (%2 or more shape the surface "
                "smoothly), so this stroke will be coarse. Preview ▸ Stretch shows where the "
                "samples are sparse; Remesh samples the surface evenly again.")
                 .arg(sampling.samplesAcross, 0, 'f', 1)
                 .arg(core::kMinSamplesAcrossRadius, 0, 'f', 0);
  bar_->showMessage(message_, 20000);
  button_->show();
}

} // namespace octaclay::app
