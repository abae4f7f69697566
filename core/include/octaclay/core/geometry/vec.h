#pragma once

#include <algorithm>
#include <cmath>

namespace octaclay::core {

/// A 2-vector of floats: image coordinates.
struct Vec2f {
  float x = 0, y = 0;
  friend bool operator==(Vec2f a, Vec2f b) = default;
};

/// A 3-vector of floats: positions and normals in object space.
struct Vec3f {
  float x = 0, y = 0, z = 0;

  friend Vec3f operator+(Vec3f a, Vec3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3f operator-(Vec3f a, Vec3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3f operator*(Vec3f a, float s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3f operator*(float s, Vec3f a) { return a * s; }
  Vec3f& operator+=(Vec3f b) { return *this = *this + b; }
  friend bool operator==(Vec3f a, Vec3f b) = default;
};

inline float dot(Vec3f a, Vec3f b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3f cross(Vec3f a, Vec3f b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline float length(Vec3f a) {
  return std::sqrt(dot(a, a));
}
/// Unit vector along a, at any scale float holds; the zero vector (or one that is not finite)
/// gives the zero vector.
inline Vec3f normalize(Vec3f a) {
  const float squared = dot(a, a);
  if (squared > 1e-30f && squared < 1e30f) return a * (1.0f / std::sqrt(squared));
  // Far from unit length the square underflows or overflows (a cross product of two edges of
  // a model 1e-12 or 1e13 across): scale by the largest component first.
  const float largest = std::max({std::abs(a.x), std::abs(a.y), std::abs(a.z)});
  if (!(largest > 0) || !std::isfinite(largest)) return {};
  const Vec3f b = a * (1.0f / largest);
  return b * (1.0f / length(b));
}

/// A texel of the position image: xyz position, w saliency (DESIGN.md).
struct Vec4f {
  float x = 0, y = 0, z = 0, w = 0;
  Vec3f xyz() const { return {x, y, z}; }
  friend bool operator==(Vec4f a, Vec4f b) = default;
};

} // namespace octaclay::core
