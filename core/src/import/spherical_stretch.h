#pragma once

// Sander et al.'s L2 stretch energy with its analytic gradient, and the local descent of one
// vertex on the sphere that the spherical parameterization's relaxation stages share (Sander,
// Snyder, Gortler & Hoppe, "Texture mapping progressive meshes", SIGGRAPH 2001).

#include "import/spherical_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

namespace octaclay::core::detail {

// The stretch energy of one triangle, surface area × (a + c)/2 of the map from the sphere
// triangle p to the surface triangle q (the summand of the L2 stretch), written as
// A_q · Σ_k (u_k · v_k) |Q_k|² / (2 o²) with u_k, v_k the sphere triangle's edge vectors at
// corner k, Q_k the surface edge opposite it and o = det(p0, p1, p2). For a small triangle o is
// twice its flat area and this is Sander et al.'s formula; o also goes to zero where three far
// apart points approach one great circle, a triangle degenerate on the sphere whose flat chord
// triangle stays fat, so the energy keeps a barrier there too. Infinite when p is flipped (in
// double or after rounding to float, with a margin), so that a descent never flips a triangle.
// With `gradient0`, also its gradient with respect to p0 in space (not projected onto the
// sphere's tangent plane).
inline double stretchEnergy(const Vec3d& p0, const Vec3d& p1, const Vec3d& p2, const Vec3d& q0,
                            const Vec3d& q1, const Vec3d& q2, Vec3d* gradient0 = nullptr) {
  constexpr double infinity = std::numeric_limits<double>::infinity();
  if (flippedWithMargin(p0, p1, p2)) return infinity;
  const Vec3d a = p1 - p0, b = p2 - p0, c = p2 - p1;
  const Vec3d p1xp2 = p1.cross(p2);
  const double o = p0.dot(p1xp2);
  if (!(o > 0)) return infinity;
  const double w0 = (q2 - q1).squaredNorm(), w1 = (q0 - q2).squaredNorm(),
               w2 = (q1 - q0).squaredNorm();
  const double area = 0.5 * (q1 - q0).cross(q2 - q0).norm();
  const double sum = a.dot(b) * w0 - a.dot(c) * w1 + b.dot(c) * w2;
  const double energy = area * sum / (2 * o * o);
  if (gradient0) {
    const Vec3d dSum = -(a + b) * w0 + c * (w1 - w2);
    *gradient0 = (area / (2 * o * o)) * (dSum - (2 * sum / o) * p1xp2);
  }
  return energy;
}

// One triangle around the vertex being moved: (v, a, b) counter-clockwise seen from outside,
// with the surface positions of v, a and b.
struct RingFace {
  int a = 0, b = 0;
  Vec3d qv, qa, qb;
};

// The energy of v's triangles with v at p (infinite when one flips), and with `gradient` the
// gradient with respect to p in space. With `power` ≠ 1, each triangle's term is A·m^power with m =
// (a + c)/2 its mean squared stretch instead of A·m: a power above 1 weighs the most stretched
// triangles more, towards the L∞ stretch.
inline double ringStretchEnergy(const Points& s, std::span<const RingFace> ring, const Vec3d& p,
                                Vec3d* gradient = nullptr, double power = 1) {
  double energy = 0;
  if (gradient) gradient->setZero();
  Vec3d g;
  for (const RingFace& f : ring) {
    double e = stretchEnergy(p, s[f.a], s[f.b], f.qv, f.qa, f.qb, gradient ? &g : nullptr);
    if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
    if (power != 1) {
      const double area = 0.5 * (f.qa - f.qv).cross(f.qb - f.qv).norm();
      if (!(area > 0)) continue;
      // pow(m, 1) is m exactly: the common power 2 without a call to pow.
      const double scale = power == 2 ? e / area : std::pow(e / area, power - 1);
      e *= scale;
      g *= power * scale;
    }
    energy += e;
    if (gradient) *gradient += g;
  }
  return energy;
}

// One step of v down the gradient of its ring's stretch energy on the sphere, with a halving
// line search from `step` (per vertex, adapted: doubled after a success, the last tried length
// after a failure). Never flips a triangle. Returns the energy decrease (0 when v did not move).
inline double descend(Points& s, int v, std::span<const RingFace> ring, double& step,
                      double power = 1) {
  const Vec3d p = s[v];
  Vec3d gradient;
  const double e0 = ringStretchEnergy(s, ring, p, &gradient, power);
  if (!std::isfinite(e0)) return 0;
  gradient -= gradient.dot(p) * p;
  const double norm = gradient.norm();
  if (!(norm > 0) || !std::isfinite(norm)) return 0;
  double shortest = std::numeric_limits<double>::infinity(), longest = 0;
  for (const RingFace& f : ring) {
    const double d = (s[f.a] - p).norm();
    shortest = std::min(shortest, d);
    longest = std::max(longest, d);
  }
  if (!(shortest > 0)) return 0;
  const Vec3d direction = -gradient / norm;
  double t = std::clamp(step, 1e-6 * shortest, 0.5 * longest);
  for (int attempt = 0; attempt < 40 && t > 1e-9 * shortest; ++attempt, t *= 0.5) {
    const Vec3d q = (p + t * direction).normalized();
    const double e = ringStretchEnergy(s, ring, q, nullptr, power);
    if (e < e0) {
      s[v] = q;
      step = 2 * t;
      return e0 - e;
    }
  }
  step = t;
  return 0;
}

} // namespace octaclay::core::detail
