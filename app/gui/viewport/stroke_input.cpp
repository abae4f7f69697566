#include "stroke_input.h"

#include "camera_control.h"
#include "modeller.h"
#include "screen_radius.h"
#include "viewport_widget.h"

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

StrokeInput::StrokeInput(ViewportWidget& view) : view_(view) {}

std::optional<core::PickHit> StrokeInput::pressPick(QPointF p) const {
  if (std::optional<core::PickHit> hit = view_.pickAt(p)) return hit;
  const Modeller& modeller = view_.modeller();
  if (!modeller.session().hasDocument()) return std::nullopt;
  // The ring's radius on screen at the depth of the camera's focal point (the model, as the
  // views frame it).
  const double ring = viewBrushPixelRadius(
      view_,
      view_.placement().toLocal(toVec(view_.renderer()->GetActiveCamera()->GetFocalPoint())));
  // Rings of a third, two thirds and the whole radius, nearest first: the nearest hit wins.
  for (int k = 1; k <= 3; ++k) {
    const double r = ring * k / 3.0;
    const int around = 12 * k;
    for (int m = 0; m < around; ++m) {
      const double angle = 2.0 * std::numbers::pi * m / around;
      if (std::optional<core::PickHit> hit =
              view_.pickAt(p + QPointF(r * std::cos(angle), r * std::sin(angle))))
        return hit;
    }
  }
  return std::nullopt;
}

bool StrokeInput::begin(QPointF p, const core::PickHit& hit, Qt::KeyboardModifiers modifiers) {
  Modeller& modeller = view_.modeller();
  const BrushState& brush = modeller.brushState();
  StrokeStart start;
  start.brushId = (modifiers & Qt::ShiftModifier) ? "smooth" : brush.settings().brushId;
  start.settings = brush.settings();
  start.paintTarget = brush.paintTarget();
  start.sign = (modifiers & Qt::ControlModifier) ? -1.0f : 1.0f;
  start.eye = view_.placement().toLocal(toVec(view_.renderer()->GetActiveCamera()->GetPosition()));
  // The view radius becomes object units at the pressed point's depth, fixed for the stroke.
  if (start.settings.radiusUnit == RadiusUnit::View)
    start.objectRadius = viewBrushObjectRadius(view_, hit.position);
  if (!modeller.strokes().begin(start)) return false;
  stabilizer_.setStrength(start.settings.stabilizer);
  stabilizer_.begin({static_cast<float>(p.x()), static_cast<float>(p.y())});
  modeller.strokes().queue(StrokeMove::underPointer(pickedUv(hit), pressure()));
  hover_ = hit;
  return true;
}

void StrokeInput::moveTo(QPointF p) {
  if (!view_.modeller().session().stroking()) return;
  for (const Point2& q : stabilizer_.moveTo({static_cast<float>(p.x()), static_cast<float>(p.y())}))
    queuePoint({q.x, q.y});
  view_.update();
}

void StrokeInput::queuePoint(QPointF p) {
  StrokeDriver& strokes = view_.modeller().strokes();
  if (strokes.drags() && view_.width() > 0 && view_.height() > 0) {
    // A dragging brush follows the pointer's ray, on the model or off it.
    const QRectF view = view_.modelRect();
    if (p.x() >= view.width()) p.rx() -= view.width();
    const core::Ray ray = view_.placement().rayToLocal(core::cameraRay(
        pickCamera(*view_.renderer()->GetActiveCamera()), static_cast<int>(view.width()),
        static_cast<int>(view.height()), static_cast<float>(p.x()), static_cast<float>(p.y())));
    strokes.queue(StrokeMove::alongRay(ray.origin, ray.direction, pressure()));
    return;
  }
  const std::optional<core::PickHit> hit = view_.pickAt(p);
  if (!hit) return; // off the model: the stroke resumes where the pointer comes back
  hover_ = hit;
  strokes.queue(StrokeMove::underPointer(pickedUv(*hit), pressure()));
}

void StrokeInput::end(StrokeDriver::Relax relax) {
  view_.modeller().strokes().end(relax);
  view_.update();
}

} // namespace octaclay::app
