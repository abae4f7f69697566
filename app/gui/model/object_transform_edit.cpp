#include "object_transform_edit.h"

#include <cmath>
#include <numbers>

namespace octaclay::app {
namespace {

using Matrix = std::array<double, 9>; // row-major

float& component(core::Vec3f& v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

// A turn added to one Euler angle, kept within the transform's ±kMaxRotationDegrees.
float addDegrees(float angle, double degrees) {
  double sum = double(angle) + degrees;
  if (std::abs(sum) > core::kMaxRotationDegrees) sum = std::remainder(sum, 360.0);
  return static_cast<float>(sum);
}

Matrix rotationOf(const core::ObjectTransform& t) {
  core::ObjectTransform unit = t;
  unit.scale = {1.0f, 1.0f, 1.0f};
  return core::linearPart(unit);
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        m[r * 3 + c] += a[r * 3 + k] * b[k * 3 + c];
  return m;
}

// Rodrigues: the rotation by radians about unit axis a.
Matrix axisRotation(const Direction& a, double radians) {
  const double c = std::cos(radians), s = std::sin(radians), t = 1 - c;
  const double x = a[0], y = a[1], z = a[2];
  return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y, t * x * y + s * z, t * y * y + c,
          t * y * z - s * x, t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}

double degreesOf(double radians) {
  return radians * 180.0 / std::numbers::pi;
}

// The Euler angles (degrees) of R = Rz · Ry · Rx; at the poles (cos y = 0) Z is taken as 0.
core::Vec3f eulerOf(const Matrix& r) {
  const double sy = std::clamp(-r[6], -1.0, 1.0);
  const double y = std::asin(sy);
  if (std::abs(sy) < 1.0 - 1e-12) {
    return {static_cast<float>(degreesOf(std::atan2(r[7], r[8]))), static_cast<float>(degreesOf(y)),
            static_cast<float>(degreesOf(std::atan2(r[3], r[0])))};
  }
  // sy = ±1: r01 = ±sin(x ∓ z)... with z = 0, x from the first row's other two entries.
  const double x = sy > 0 ? std::atan2(r[1], r[2]) : std::atan2(-r[1], -r[2]);
  return {static_cast<float>(degreesOf(x)), static_cast<float>(degreesOf(y)), 0.0f};
}

} // namespace

core::ObjectTransform translated(const core::ObjectTransform& before, core::Vec3f offset) {
  core::ObjectTransform t = before;
  t.translation = {static_cast<float>(double(before.translation.x) + double(offset.x)),
                   static_cast<float>(double(before.translation.y) + double(offset.y)),
                   static_cast<float>(double(before.translation.z) + double(offset.z))};
  return t;
}

Direction localAxisDirection(const core::ObjectTransform& transform, int axis) {
  const Matrix r = rotationOf(transform);
  return {r[axis], r[3 + axis], r[6 + axis]};
}

core::ObjectTransform rotatedAboutWorldAxis(const core::ObjectTransform& before, int axis,
                                            double degrees) {
  const core::Vec3f& e = before.rotationDegrees;
  const bool oneAngle =
      axis == 2 || (axis == 1 && e.z == 0.0f) || (axis == 0 && e.y == 0.0f && e.z == 0.0f);
  if (oneAngle) {
    core::ObjectTransform t = before;
    component(t.rotationDegrees, axis) = addDegrees(component(t.rotationDegrees, axis), degrees);
    return t;
  }
  Direction a{0, 0, 0};
  a[std::size_t(axis)] = 1;
  return rotatedAbout(before, a, degrees);
}

core::ObjectTransform rotatedAboutLocalAxis(const core::ObjectTransform& before, int axis,
                                            double degrees) {
  if (axis == 0) { // R · Rx(θ) = Rz · Ry · Rx(x + θ)
    core::ObjectTransform t = before;
    t.rotationDegrees.x = addDegrees(t.rotationDegrees.x, degrees);
    return t;
  }
  return rotatedAbout(before, localAxisDirection(before, axis), degrees);
}

core::ObjectTransform rotatedAbout(const core::ObjectTransform& before, Direction axis,
                                   double degrees) {
  const double length = std::hypot(axis[0], axis[1], axis[2]);
  if (!(length > 0) || !std::isfinite(length)) return before;
  for (double& c : axis)
    c /= length;
  core::ObjectTransform t = before;
  t.rotationDegrees =
      eulerOf(multiply(axisRotation(axis, degrees * std::numbers::pi / 180.0), rotationOf(before)));
  return t;
}

core::ObjectTransform scaled(const core::ObjectTransform& before, double factor, int axis) {
  core::ObjectTransform t = before;
  for (int k = 0; k < 3; ++k)
    if (axis < 0 || axis == k)
      component(t.scale, k) = static_cast<float>(double(component(t.scale, k)) * factor);
  return t;
}

int localAxisNearest(const core::ObjectTransform& transform, int worldAxis) {
  const Matrix r = rotationOf(transform);
  int best = worldAxis;
  double most = -1;
  for (int k = 0; k < 3; ++k) {
    const double along = std::abs(r[worldAxis * 3 + k]); // column k's world-axis component
    if (along > most + 1e-9) {
      most = along;
      best = k;
    }
  }
  return best;
}

} // namespace octaclay::app
