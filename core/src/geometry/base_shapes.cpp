#include "octaclay/core/geometry/base_shapes.h"

#include "detail/parallel_rows.h"
#include "geometry/octahedral_direction.h"

#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/seaming.h"

#include <algorithm>
#include <cmath>
#include <functional>

namespace octaclay::core {
namespace {

constexpr double kCubeRounding = 0.2;
constexpr double kCylinderRounding = 0.1;

// Distance along the unit ray t·d (d ≥ 0 componentwise) from the origin to a box of half-size 1
// whose edges are rounded with radius r: the Minkowski sum of an inner box of half-size
// a = 1 − r and a ball of radius r. The components that stick out of the inner box at the hit
// are the k largest ones for some k; for each k solve |t·d_S − a| = r in closed form and keep
// the t at which exactly those k stick out.
template <std::size_t K> double rayToRoundedBox(std::array<double, K> d, double r) {
  const double a = 1.0 - r;
  std::sort(d.begin(), d.end(), std::greater<>());
  double sumD = 0, sumD2 = 0, t = 1.0 / d[0];
  for (std::size_t k = 0; k < K; ++k) {
    sumD += d[k];
    sumD2 += d[k] * d[k];
    const double count = double(k + 1);
    const double disc = a * a * sumD * sumD - sumD2 * (count * a * a - r * r);
    t = (a * sumD + std::sqrt(std::max(disc, 0.0))) / sumD2;
    if (k + 1 == K || t * d[k + 1] <= a) return t;
  }
  return t;
}

template <std::size_t K> double roundedBoxDistance(const std::array<double, K>& p, double r) {
  const double a = 1.0 - r;
  double outside = 0, inside = -1e300;
  for (double c : p) {
    const double q = std::abs(c) - a;
    outside += std::max(q, 0.0) * std::max(q, 0.0);
    inside = std::max(inside, q);
  }
  return std::sqrt(outside) + std::min(inside, 0.0) - r;
}

// Smooth noise on the unit sphere: a few plane waves with fixed directions and phases, with
// amplitudes summing to 1 so the value stays in [-1, 1].
double blobNoise(double x, double y, double z) {
  struct Wave {
    double dx, dy, dz, frequency, phase, amplitude;
  };
  static constexpr Wave waves[] = {
      {0.267, 0.534, 0.802, 2.0, 0.3, 0.35},    {-0.707, 0.0, 0.707, 3.0, 1.1, 0.25},
      {0.577, -0.577, 0.577, 4.0, 2.3, 0.2},    {0.0, 0.894, -0.447, 5.0, 0.7, 0.12},
      {-0.408, -0.816, -0.408, 7.0, 1.9, 0.08},
  };
  double value = 0;
  for (const Wave& w : waves)
    value += w.amplitude * std::sin(w.frequency * (w.dx * x + w.dy * y + w.dz * z) + w.phase);
  return value;
}

double blobRadius(double x, double y, double z) {
  return 0.85 + 0.15 * blobNoise(x, y, z);
}

using Dir = detail::Dir3d;

Vec3f surfacePoint(BaseShape shape, Dir d) {
  double t = 1.0;
  switch (shape) {
  case BaseShape::Sphere:
    break;
  case BaseShape::Cube:
    t = rayToRoundedBox<3>({std::abs(d.x), std::abs(d.y), std::abs(d.z)}, kCubeRounding);
    break;
  case BaseShape::Cylinder:
    t = rayToRoundedBox<2>({std::hypot(d.x, d.y), std::abs(d.z)}, kCylinderRounding);
    break;
  case BaseShape::Blob:
    t = blobRadius(d.x, d.y, d.z);
    break;
  case BaseShape::Capsule: // makeBaseShape samples it with makeCapsule
    break;
  }
  return {float(t * d.x), float(t * d.y), float(t * d.z)};
}

} // namespace

std::optional<BaseShape> parseBaseShape(std::string_view name) {
  for (BaseShape s : {BaseShape::Sphere, BaseShape::Cube, BaseShape::Cylinder, BaseShape::Blob,
                      BaseShape::Capsule})
    if (baseShapeName(s) == name) return s;
  return std::nullopt;
}

std::string_view baseShapeName(BaseShape shape) {
  switch (shape) {
  case BaseShape::Sphere:
    return "sphere";
  case BaseShape::Cube:
    return "cube";
  case BaseShape::Cylinder:
    return "cylinder";
  case BaseShape::Blob:
    return "blob";
  case BaseShape::Capsule:
    return "capsule";
  }
  return "sphere";
}

GeometryImage makeBaseShape(BaseShape shape, int n) {
  if (shape == BaseShape::Capsule) return makeCapsule(n, Capsule{});
  GeometryImage image(n);
  const int side = image.side();
  detail::parallelRows(side, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i < side; ++i) {
        const Vec3f p = surfacePoint(shape, detail::octahedralDirectionD(n, i, j));
        image.at(i, j) = {p.x, p.y, p.z, 0.0f};
      }
  });
  seam(image);
  return image;
}

float baseShapeDistance(BaseShape shape, Vec3f p) {
  const double x = p.x, y = p.y, z = p.z;
  const double r = std::sqrt(x * x + y * y + z * z);
  switch (shape) {
  case BaseShape::Sphere:
    return float(r - 1.0);
  case BaseShape::Cube:
    return float(roundedBoxDistance<3>({x, y, z}, kCubeRounding));
  case BaseShape::Cylinder:
    return float(roundedBoxDistance<2>({std::hypot(x, y), z}, kCylinderRounding));
  case BaseShape::Blob:
    return r > 0 ? float(r - blobRadius(x / r, y / r, z / r)) : -1.0f;
  case BaseShape::Capsule:
    return capsuleDistance(Capsule{}, p);
  }
  return 0;
}

} // namespace octaclay::core
