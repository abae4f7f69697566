// Based on: the "lazy mouse" / "lazy brush" string stabilizer of Blender's paint strokes
// (paint_stroke.cc, `paint_space_stroke_enabled` with "Stabilize Stroke") and Lazy Nezumi.

#include "stroke_stabilizer.h"

#include <algorithm>
#include <cmath>

namespace octaclay::app {

namespace {

// NaN would poison every later position, so it counts as the harmless end of the range.
float clampOrZero(float value, float lo, float hi) {
  if (!(value >= lo)) return lo;
  return std::min(value, hi);
}

} // namespace

StrokeStabilizer::StrokeStabilizer(float strength) {
  setStrength(strength);
}

void StrokeStabilizer::setStrength(float strength) {
  strength_ = clampOrZero(strength, 0.0f, 1.0f);
}

void StrokeStabilizer::setMaxLengthPixels(float pixels) {
  maxLength_ = std::isfinite(pixels) ? std::max(pixels, 0.0f) : 0.0f;
}

void StrokeStabilizer::begin(Point2 cursor) {
  brush_ = cursor;
  active_ = true;
}

std::vector<Point2> StrokeStabilizer::moveTo(Point2 cursor) {
  if (!active_) {
    begin(cursor);
    return {};
  }
  // Doubles, so "exactly L from the cursor" holds to float precision even far from the origin.
  const double dx = double(cursor.x) - double(brush_.x);
  const double dy = double(cursor.y) - double(brush_.y);
  const double distance = std::hypot(dx, dy);
  const double length = double(lengthPixels());
  if (distance <= length) return {};

  // The brush slides along the string until the string is taut again: L short of the cursor.
  const Point2 from = brush_;
  const Point2 to = length == 0.0 ? cursor
                                  : Point2{float(double(cursor.x) - dx / distance * length),
                                           float(double(cursor.y) - dy / distance * length)};

  // Steps measured on the rounded end point, with a millipixel to spare, so float rounding of
  // the points cannot push a gap past the promised spacing.
  const double travel = std::hypot(double(to.x) - double(from.x), double(to.y) - double(from.y));
  const auto steps = std::max<long>(
      1, static_cast<long>(std::ceil(travel / (double(kMaxDabSpacingPixels) - 1e-3))));
  std::vector<Point2> points;
  points.reserve(static_cast<std::size_t>(steps));
  for (long k = 1; k < steps; ++k) {
    const double t = double(k) / double(steps);
    points.push_back({float(double(from.x) + (double(to.x) - double(from.x)) * t),
                      float(double(from.y) + (double(to.y) - double(from.y)) * t)});
  }
  // The last point is the brush itself, not an interpolation that could round differently.
  points.push_back(to);
  brush_ = to;
  return points;
}

std::vector<Point2> StrokeStabilizer::finish() {
  active_ = false;
  return {};
}

} // namespace octaclay::app
