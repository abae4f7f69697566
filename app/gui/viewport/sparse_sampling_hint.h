#pragma once

#include "octaclay/core/geometry/vec.h"

#include <QObject>
#include <QPointF>

class QAction;
class QPushButton;
class QStatusBar;

namespace octaclay::app {

class ViewportWidget;

/// Issue 30, item 1: before a brush acts where the surface's samples are too sparse for it
/// (core::brushSampling: fewer than core::kMinSamplesAcrossRadius across its radius, as at the
/// tip of a limb pulled far in one stroke), the status bar says why the result will be coarse,
/// names Preview ▸ Stretch (which shows where) and offers Remesh (a "Remesh…" button that
/// triggers Mesh ▸ Remesh…). It follows the viewport's strokePressed (the press's own pick,
/// before the first dab); nothing else changes. GUI thread.
class SparseSamplingHint : public QObject {
  Q_OBJECT
public:
  SparseSamplingHint(ViewportWidget* view, QStatusBar* bar, QAction* remesh, QObject* parent);

  /// The samples across the brush's radius at the last press that checked (0 before any).
  double lastSamplesAcross() const { return lastSamples_; }

private:
  void check(core::Vec2f uv);

  ViewportWidget* view_;
  QStatusBar* bar_;
  QPushButton* button_;
  QString message_; // the hint shown, while it is
  double lastSamples_ = 0;
};

} // namespace octaclay::app
