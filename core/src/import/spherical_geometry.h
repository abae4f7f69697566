#pragma once

// Small geometric helpers shared by the spherical parameterization's stages.

#include <Eigen/Geometry>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace octaclay::core::detail {

using Vec3d = Eigen::Vector3d;
using Tri = std::array<int, 3>;
using Points = std::vector<Vec3d>;

inline double orientation(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return a.dot(b.cross(c));
}

inline double triangleArea(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

inline double triangleArea(const Points& x, const Tri& t) {
  return triangleArea(x[t[0]], x[t[1]], x[t[2]]);
}

// The map is handed out in float: a triangle counts as flipped when its corners rounded to
// float are not positively oriented, so that tiny triangles cannot flip in the conversion.
// The round trip goes through a volatile: GCC 12 at -O3 was seen to drop double → float → double
// round trips once inlined (the corners came back unrounded), which let triangles pass here that
// the stored floats flip.
inline double roundedToFloat(double v) {
  const volatile float f = static_cast<float>(v);
  return static_cast<double>(f);
}

inline Vec3d roundedToFloat(const Vec3d& p) {
  return Vec3d(roundedToFloat(p.x()), roundedToFloat(p.y()), roundedToFloat(p.z()));
}

inline bool flipped(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return orientation(a, b, c) <= 0 ||
         orientation(roundedToFloat(a), roundedToFloat(b), roundedToFloat(c)) <= 0;
}

inline bool flipped(const Points& s, const Tri& t) {
  return flipped(s[t[0]], s[t[1]], s[t[2]]);
}

// flipped() with a margin above the rounding error of the orientation of unit vectors (a few
// 1e-16), so that a triangle accepted here is positive however its orientation is evaluated:
// from any corner, in double or from the stored floats. Without it a vertex moved less than a
// float's resolution from a neighbour leaves a triangle whose sign depends on the evaluation.
inline bool flippedWithMargin(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  constexpr double margin = 4e-15;
  return orientation(a, b, c) <= margin ||
         orientation(roundedToFloat(a), roundedToFloat(b), roundedToFloat(c)) <= margin;
}

// Per-triangle stretch of the map from the (flat) sphere triangle p to the surface triangle q
// in the notation of Sander et al. 2001: meanSquare = (a + c) / 2, maxSquare = Γ²; both NaN
// when p is flipped.
struct TriangleStretch {
  double meanSquare = 0, maxSquare = 0;
};

inline TriangleStretch triangleStretch(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2,
                                       const Vec3d& q0, const Vec3d& q1, const Vec3d& q2) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (flipped(p0, p1, p2)) return {nan, nan};
  const Vec3d e1 = p1 - p0, e2 = p2 - p0;
  const Vec3d normal = e1.cross(e2);
  const double twiceArea = normal.norm();
  const double l1 = e1.norm();
  if (twiceArea <= 0 || l1 <= 0) return {nan, nan};
  const Vec3d ex = e1 / l1, ey = (normal / twiceArea).cross(ex);
  // Parameter coordinates (s, t): p0 = (0, 0), p1 = (l1, 0), p2 = (s2, t2).
  const double s2 = e2.dot(ex), t2 = e2.dot(ey);
  const Vec3d ss = (q0 * (0 - t2) + q1 * t2 + q2 * 0.0) / twiceArea;
  const Vec3d st = (q0 * (s2 - l1) + q1 * (0 - s2) + q2 * l1) / twiceArea;
  const double a = ss.dot(ss), b = ss.dot(st), c = st.dot(st);
  const double root = std::sqrt((a - c) * (a - c) + 4 * b * b);
  return {0.5 * (a + c), 0.5 * (a + c + root)};
}

} // namespace octaclay::core::detail
