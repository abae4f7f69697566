// The viewport's strokes: pointer positions become the session's dabs, and what the dabs or
// an undo changed gets its normals and saliency refreshed.

#include "camera_control.h"
#include "current_context.h"
#include "viewport_widget.h"

#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace octaclay::app {
namespace {

// The pick's interpolated (u, v): its triangle test widens edges by a hair, so clamp.
core::Vec2f pickedUv(const core::PickHit& hit) {
  return {std::clamp(hit.u, 0.0f, 1.0f), std::clamp(hit.v, 0.0f, 1.0f)};
}

} // namespace

std::optional<core::PickHit> ViewportWidget::pressPick(QPointF p) const {
  if (std::optional<core::PickHit> hit = pickAt(p)) return hit;
  if (!session_.hasDocument()) return std::nullopt;
  // The ring's radius on screen at the depth of the camera's focal point (the model, as the
  // views frame it): the brush radius along the view's up.
  vtkCamera* camera = renderer_->GetActiveCamera();
  const core::Vec3f centre = toVec(camera->GetFocalPoint());
  const core::Vec3f up = core::normalize(toVec(camera->GetViewUp()));
  const QPointF a = project(centre),
                b = project(centre + up * (settings_.radius * session_.diagonal()));
  const double ring = std::hypot(b.x() - a.x(), b.y() - a.y());
  // Rings of a third, two thirds and the whole radius, nearest first: the nearest hit wins.
  for (int k = 1; k <= 3; ++k) {
    const double r = ring * k / 3.0;
    const int around = 12 * k;
    for (int m = 0; m < around; ++m) {
      const double angle = 2.0 * std::numbers::pi * m / around;
      if (std::optional<core::PickHit> hit =
              pickAt(p + QPointF(r * std::cos(angle), r * std::sin(angle))))
        return hit;
    }
  }
  return std::nullopt;
}

void ViewportWidget::beginStrokeAt(QPointF p, Qt::KeyboardModifiers modifiers) {
  if (const std::optional<core::PickHit> hit = pressPick(p)) beginStrokeAt(p, *hit, modifiers);
}

void ViewportWidget::beginStrokeAt(QPointF p, const core::PickHit& pressed,
                                   Qt::KeyboardModifiers modifiers) {
  if (!session_.hasDocument() || !library_ || session_.stroking()) return; // one at a time
  const std::optional<core::PickHit> hit = pressed;
  const std::string id = (modifiers & Qt::ShiftModifier) ? "smooth" : settings_.brushId;
  const float sign = (modifiers & Qt::ControlModifier) ? -1.0f : 1.0f;
  try {
    CurrentContext current(*this); // a changed area or falloff recompiles the brush
    StrokeStart start;
    start.brushId = id;
    start.settings = settings_;
    start.paintTarget = paintTarget_;
    start.sign = sign;
    start.eye = toVec(renderer_->GetActiveCamera()->GetPosition());
    session_.beginStroke(start);
  } catch (const std::exception& e) {
    fail(QString::fromUtf8(e.what()));
    return;
  }
  stabilizer_.begin({static_cast<float>(p.x()), static_cast<float>(p.y())});
  session_.queueMove(StrokeMove::toUv(pickedUv(*hit), tabletDown_ ? tabletPressure_ : 1.0f));
  hover_ = hit;
  update();
}

void ViewportWidget::continueStrokeTo(QPointF p) {
  if (!session_.stroking()) return;
  for (const Point2& q : stabilizer_.moveTo({static_cast<float>(p.x()), static_cast<float>(p.y())}))
    queueStrokePoint({q.x, q.y});
  update();
}

void ViewportWidget::queueStrokePoint(QPointF p) {
  if (session_.strokeDrags() && width() > 0 && height() > 0) {
    // A dragging brush follows the pointer's ray, on the model or off it.
    const QRectF view = modelRect();
    if (p.x() >= view.width()) p.rx() -= view.width();
    const core::Ray ray = core::cameraRay(
        pickCamera(*renderer_->GetActiveCamera()), static_cast<int>(view.width()),
        static_cast<int>(view.height()), static_cast<float>(p.x()), static_cast<float>(p.y()));
    session_.queueMove(
        StrokeMove::alongRay(ray.origin, ray.direction, tabletDown_ ? tabletPressure_ : 1.0f));
    return;
  }
  const std::optional<core::PickHit> hit = pickAt(p);
  if (!hit) return; // off the model: the stroke resumes where the pointer comes back
  hover_ = hit;
  session_.queueMove(StrokeMove::toUv(pickedUv(*hit), tabletDown_ ? tabletPressure_ : 1.0f));
}

void ViewportWidget::endStroke() {
  if (!session_.stroking()) return;
  // Finish now rather than at the next paint: the document and undo must be complete when
  // the caller (a mouse release, a test, a save) looks.
  {
    CurrentContext current(*this);
    drainGlErrors();
    runQueuedDabs();
    finishStroke();
  }
  update();
}

int ViewportWidget::runQueuedDabs() {
  DabRun run = session_.runQueuedMoves();
  if (!run.error.empty()) {
    fail(QString::fromStdString(run.error));
    refreshAllNormals(); // the engine put the layers back as they were before the stroke
    return run.made;
  }
  try {
    if (run.made > 0) surfaceEdited();
    refreshNormalsAround(std::move(run.touched));
  } catch (const std::exception& e) {
    fail(QString::fromUtf8(e.what()));
  }
  return run.made;
}

void ViewportWidget::finishStroke() {
  std::string label;
  try {
    label = session_.finishStroke().label;
  } catch (const std::exception& e) { // refused (non-finite result): the layers are back
    fail(QString::fromUtf8(e.what()));
    refreshAllNormals();
    return;
  }
  if (label.empty()) return;
  if (!session_.lastRelaxation().tiles.empty()) {
    // Keep-detail moved samples beyond the dabs' reach: their normals were not refreshed with
    // the dabs (stale ones showed as flat tents, cracks and speckled fringes).
    try {
      surfaceEdited();
      refreshNormalsAround(changedRects(session_.lastRelaxation()));
    } catch (const std::exception& e) {
      fail(QString::fromUtf8(e.what()));
    }
  }
  refreshSaliency(); // at stroke end: the whole image's normalisation may have changed
  emit strokeFinished(QString::fromStdString(label));
  emit surfaceChanged();
}

void ViewportWidget::refreshNormalsAround(std::vector<core::TexelRect> touched) {
  if (touched.empty() || !session_.hasDocument()) return;
  gpu::GpuDocument& document = session_.gpuDocument();
  model_->refreshNormals(document, normalRectsAround(std::move(touched), document.size() + 1));
}

void ViewportWidget::refreshAllNormals() {
  if (!session_.hasDocument()) return;
  const int side = session_.gpuDocument().size() + 1;
  try {
    surfaceEdited();
    refreshNormalsAround({core::TexelRect{0, 0, side, side}});
  } catch (const std::exception& e) {
    fail(QString::fromUtf8(e.what()));
  }
}

bool ViewportWidget::applyChange(const core::Document& after, const std::string& label) {
  if (!session_.hasDocument() || session_.stroking()) return false;
  bool recorded = false;
  {
    CurrentContext current(*this);
    drainGlErrors();
    std::vector<core::TexelRect> changed;
    try {
      changed = session_.applyChange(after, label);
    } catch (const std::exception&) {
      refreshAllNormals(); // the layers may be partly written
      update();
      emit surfaceChanged();
      throw;
    }
    recorded = !changed.empty();
    if (recorded) {
      try {
        refreshNormalsAround(std::move(changed));
        surfaceEdited();
        refreshSaliency();
      } catch (const std::exception& e) { // the step is recorded; only the drawing failed
        fail(QString::fromUtf8(e.what()));
      }
    }
  }
  update();
  if (recorded) emit surfaceChanged();
  return recorded;
}

bool ViewportWidget::undoStroke() {
  return stepHistory(true);
}

bool ViewportWidget::redoStroke() {
  return stepHistory(false);
}

bool ViewportWidget::stepHistory(bool undo) {
  if (!session_.hasDocument() || !(undo ? canUndo() : canRedo()) || session_.stroking())
    return false;
  const core::EditStep* s = nullptr;
  {
    CurrentContext current(*this);
    try {
      s = undo ? session_.undo() : session_.redo();
      if (s) {
        refreshNormalsAround(changedRects(*s));
        surfaceEdited();
        refreshSaliency();
      }
    } catch (const std::exception& e) {
      fail(QString::fromUtf8(e.what()));
    }
  }
  update();
  if (s) emit surfaceChanged();
  return s != nullptr;
}

} // namespace octaclay::app
