#include "octaclay/core/document/object_transform.h"

#include <cmath>
#include <numbers>

namespace octaclay::core {

namespace {

constexpr const char* kAxisNames[3] = {"x", "y", "z"};

float component(Vec3f v, int axis) {
  return axis == 0 ? v.x : axis == 1 ? v.y : v.z;
}

double radians(float degrees) {
  return static_cast<double>(degrees) * std::numbers::pi / 180.0;
}

std::string text(float value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%g", static_cast<double>(value));
  return buffer;
}

} // namespace

std::optional<std::string> transformProblem(const ObjectTransform& t) {
  for (int axis = 0; axis < 3; ++axis) {
    const float move = component(t.translation, axis);
    const float turn = component(t.rotationDegrees, axis);
    const float scale = component(t.scale, axis);
    const std::string a = kAxisNames[axis];
    if (!std::isfinite(move) || !std::isfinite(turn) || !std::isfinite(scale))
      return "the transform holds a value that is not a finite number (translation, rotation or "
             "scale " +
             a + ")";
    if (std::abs(move) > kMaxTranslation)
      return "translation " + a + " = " + text(move) + " is beyond ±" + text(kMaxTranslation);
    if (std::abs(turn) > kMaxRotationDegrees)
      return "rotation " + a + " = " + text(turn) + " degrees is beyond ±" +
             text(kMaxRotationDegrees);
    if (!(std::abs(scale) >= kMinScale) || std::abs(scale) > kMaxScale)
      return "scale " + a + " = " + text(scale) + " is not within " + text(kMinScale) + " .. " +
             text(kMaxScale) + " (either sign)";
  }
  return std::nullopt;
}

std::array<double, 9> linearPart(const ObjectTransform& t) {
  const double cx = std::cos(radians(t.rotationDegrees.x)),
               sx = std::sin(radians(t.rotationDegrees.x));
  const double cy = std::cos(radians(t.rotationDegrees.y)),
               sy = std::sin(radians(t.rotationDegrees.y));
  const double cz = std::cos(radians(t.rotationDegrees.z)),
               sz = std::sin(radians(t.rotationDegrees.z));
  // R = Rz · Ry · Rx.
  const double r[9] = {cz * cy,
                       cz * sy * sx - sz * cx,
                       cz * sy * cx + sz * sx,
                       sz * cy,
                       sz * sy * sx + cz * cx,
                       sz * sy * cx - cz * sx,
                       -sy,
                       cy * sx,
                       cy * cx};
  const double s[3] = {t.scale.x, t.scale.y, t.scale.z};
  std::array<double, 9> m{};
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col)
      m[row * 3 + col] = r[row * 3 + col] * s[col];
  return m;
}

Vec3f applyTransform(const ObjectTransform& t, Vec3f p) {
  const auto m = linearPart(t);
  const double x = p.x, y = p.y, z = p.z;
  return {static_cast<float>(t.translation.x + m[0] * x + m[1] * y + m[2] * z),
          static_cast<float>(t.translation.y + m[3] * x + m[4] * y + m[5] * z),
          static_cast<float>(t.translation.z + m[6] * x + m[7] * y + m[8] * z)};
}

std::array<double, 4> rotationQuaternion(const ObjectTransform& t) {
  // q = qz · qy · qx, each a half-angle rotation about its axis.
  const double hx = radians(t.rotationDegrees.x) / 2, hy = radians(t.rotationDegrees.y) / 2,
               hz = radians(t.rotationDegrees.z) / 2;
  const double cx = std::cos(hx), sx = std::sin(hx), cy = std::cos(hy), sy = std::sin(hy),
               cz = std::cos(hz), sz = std::sin(hz);
  return {sx * cy * cz - cx * sy * sz, cx * sy * cz + sx * cy * sz, cx * cy * sz - sx * sy * cz,
          cx * cy * cz + sx * sy * sz};
}

ObjectTransform mirroredTransform(const ObjectTransform& t, int axis) {
  // M · (T + R S p) with M = diag(−1 on axis) is M T + (M R M) · S · (M p): the mirrored
  // rotation M R M is the same Euler angles with the two angles about the other axes negated.
  ObjectTransform result = t;
  auto flip = [](float& v) { v = 0.0f - v; }; // 0 stays +0
  if (axis == 0) {
    flip(result.translation.x);
    flip(result.rotationDegrees.y);
    flip(result.rotationDegrees.z);
  } else if (axis == 1) {
    flip(result.translation.y);
    flip(result.rotationDegrees.x);
    flip(result.rotationDegrees.z);
  } else {
    flip(result.translation.z);
    flip(result.rotationDegrees.x);
    flip(result.rotationDegrees.y);
  }
  return result;
}

} // namespace octaclay::core
