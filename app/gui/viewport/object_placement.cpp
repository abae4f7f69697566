#include "object_placement.h"

#include <cmath>

namespace octaclay::app {
namespace {

using Matrix = std::array<double, 9>;

core::Vec3f multiply(const Matrix& m, double x, double y, double z) {
  return {static_cast<float>(m[0] * x + m[1] * y + m[2] * z),
          static_cast<float>(m[3] * x + m[4] * y + m[5] * z),
          static_cast<float>(m[6] * x + m[7] * y + m[8] * z)};
}

double determinant(const Matrix& m) {
  return m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) +
         m[2] * (m[3] * m[7] - m[4] * m[6]);
}

// transformProblem keeps every scale at least 1e-4 from zero: L is always invertible.
Matrix inverted(const Matrix& m) {
  const double d = determinant(m);
  return {(m[4] * m[8] - m[5] * m[7]) / d, (m[2] * m[7] - m[1] * m[8]) / d,
          (m[1] * m[5] - m[2] * m[4]) / d, (m[5] * m[6] - m[3] * m[8]) / d,
          (m[0] * m[8] - m[2] * m[6]) / d, (m[2] * m[3] - m[0] * m[5]) / d,
          (m[3] * m[7] - m[4] * m[6]) / d, (m[1] * m[6] - m[0] * m[7]) / d,
          (m[0] * m[4] - m[1] * m[3]) / d};
}

} // namespace

ObjectPlacement::ObjectPlacement() : ObjectPlacement(core::ObjectTransform{}) {}

ObjectPlacement::ObjectPlacement(const core::ObjectTransform& transform)
    : linear_(core::linearPart(transform)),
      inverse_(inverted(linear_)), translation_{transform.translation.x, transform.translation.y,
                                                transform.translation.z} {}

core::Vec3f ObjectPlacement::toWorld(core::Vec3f local) const {
  const core::Vec3f v = multiply(linear_, local.x, local.y, local.z);
  return {static_cast<float>(v.x + translation_[0]), static_cast<float>(v.y + translation_[1]),
          static_cast<float>(v.z + translation_[2])};
}

core::Vec3f ObjectPlacement::toLocal(core::Vec3f world) const {
  return multiply(inverse_, world.x - translation_[0], world.y - translation_[1],
                  world.z - translation_[2]);
}

core::Vec3f ObjectPlacement::directionToLocal(core::Vec3f world) const {
  return multiply(inverse_, world.x, world.y, world.z);
}

core::Vec3f ObjectPlacement::normalToWorld(core::Vec3f local) const {
  const Matrix& m = inverse_; // its transpose times the normal
  const double x = m[0] * local.x + m[3] * local.y + m[6] * local.z;
  const double y = m[1] * local.x + m[4] * local.y + m[7] * local.z;
  const double z = m[2] * local.x + m[5] * local.y + m[8] * local.z;
  const double sign = determinant(linear_) < 0 ? -1.0 : 1.0;
  const double length = std::sqrt(x * x + y * y + z * z);
  if (!(length > 0)) return {};
  return {static_cast<float>(sign * x / length), static_cast<float>(sign * y / length),
          static_cast<float>(sign * z / length)};
}

core::Ray ObjectPlacement::rayToLocal(const core::Ray& ray) const {
  return {toLocal(ray.origin), core::normalize(directionToLocal(ray.direction))};
}

core::BoundingBox ObjectPlacement::boxToWorld(const core::BoundingBox& box) const {
  core::BoundingBox out;
  if (box.empty()) return out;
  for (int corner = 0; corner < 8; ++corner)
    out.extend(toWorld({(corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                        (corner & 4) ? box.max.z : box.min.z}));
  return out;
}

std::array<double, 16> ObjectPlacement::objectToWorld() const {
  const Matrix& l = linear_;
  return {l[0], l[1], l[2], translation_[0], l[3], l[4], l[5], translation_[1],
          l[6], l[7], l[8], translation_[2], 0,    0,    0,    1};
}

double ObjectPlacement::meanScale() const {
  return std::cbrt(std::abs(determinant(linear_)));
}

} // namespace octaclay::app
