#include "stroke_settings_check.h"
#include "stroke_state.h"
#include "value_text.h"

#include "octaclay/gpu/stroke_rules.h"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

// The drag (API 3): a dragging brush follows the pointer's ray through the plane across the
// view at the stroke's start; its dabs carry the drag since the start.
namespace octaclay::gpu {

core::Vec3f StrokeSession::State::dragAt(std::array<double, 2> xy) const {
  core::Vec3f v = startPosition(xy[0], xy[1]) - startPoint;
  return v - dragNormal * core::dot(v, dragNormal);
}

// A dragging brush's move to the drag that ray gives: where it meets the drag plane (through
// the stroke's start, across the view; across the start's normal without a view). An anchored
// stroke dabs once with it; a drag stroke walks there from its last drag in steps of the
// spacing (object units), carrying the remainder as walkTo does.
int StrokeSession::State::dragAlong(core::Vec3f origin, core::Vec3f direction, float radius,
                                    float strength, float pressure) {
  checkDragMove(radius, strength, pressure);
  for (float v : {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z})
    requireFinite("the drag's ray", v);
  const core::Vec3f plane = core::length(dragNormal) > 0 ? dragNormal : anchorNormal;
  const float facing = core::dot(direction, plane);
  if (std::abs(facing) < 1e-6f * core::length(direction)) return 0; // along the plane: no point
  const core::Vec3f point = origin + direction * (core::dot(startPoint - origin, plane) / facing);
  requireDragReach(point);
  core::Vec3f target = point - startPoint;
  return dragBy(target - plane * core::dot(target, plane), radius, strength, pressure);
}

// The same to a point in object space: the drag is from the stroke's start to it, projected
// into the view plane when the stroke has a view.
int StrokeSession::State::dragTo(core::Vec3f point, float radius, float strength, float pressure) {
  checkDragMove(radius, strength, pressure);
  for (float v : {point.x, point.y, point.z})
    requireFinite("the drag's point", v);
  requireDragReach(point);
  const core::Vec3f target = point - startPoint;
  return dragBy(target - dragNormal * core::dot(target, dragNormal), radius, strength, pressure);
}

void StrokeSession::State::checkDragMove(float radius, float strength, float pressure) const {
  if (abandoned) throw std::logic_error("StrokeSession: a drag after a dab failed");
  if (finished) throw std::logic_error("StrokeSession: a drag after finish()");
  if (!previous) throw std::logic_error("StrokeSession: a drag before the stroke's first move");
  requireFinite("the radius", radius);
  requireFinite("the strength", strength);
  requireFinite("the pressure", pressure);
}

int StrokeSession::State::dragBy(core::Vec3f target, float radius, float strength, float pressure) {
  const auto start = std::chrono::steady_clock::now();
  const int before = dabs;
  const std::array<double, 2> xy = *previous;
  if (brush.stroke == StrokeKind::Anchored) {
    dabAt(xy, radius, strength, pressure, target);
  } else {
    const double spacing = spacingFor(radius);
    const core::Vec3f from = lastDrag;
    const double length = core::length(target - from);
    travelled = std::min(travelled, spacing);
    requireDabBudget(length + travelled, spacing);
    double used = 0;
    while (travelled + (length - used) >= spacing) {
      used += spacing - travelled;
      travelled = 0;
      dabAt(xy, radius, strength, pressure,
            from + (target - from) * static_cast<float>(length > 0 ? used / length : 0.0));
    }
    travelled += length - used;
  }
  engineMs +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return dabs - before;
}

// Refuses a drag target farther than kMaxDragDiagonals from the model's centre.
void StrokeSession::State::requireDragReach(core::Vec3f point) const {
  // In double: a point at 1e30 squares past float's range.
  const double dx = double(point.x) - centre.x, dy = double(point.y) - centre.y,
               dz = double(point.z) - centre.z;
  const double away = std::sqrt(dx * dx + dy * dy + dz * dz);
  if (away <= kMaxDragDiagonals * diagonal) return;
  detail::badSetting("a drag point lies " + detail::shortNumber(away / diagonal) +
                     " diagonals from the model's centre; a drag reaches at most " +
                     detail::shortNumber(kMaxDragDiagonals) + " diagonals (the model is " +
                     detail::shortNumber(diagonal) + " across): drag within reach");
}

} // namespace octaclay::gpu
