#include "merge/map_rotation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace octaclay::core::detail {
namespace {

using Rotation = std::array<double, 9>; // row-major

struct Piece {
  double x, y, z;   // the triangle's centroid direction on the sphere (unit)
  double solid;     // its sphere area
  std::size_t part; // its first corner's
};

double halton(std::uint32_t index, std::uint32_t base) {
  double f = 1, r = 0;
  for (; index > 0; index /= base) {
    f /= base;
    r += f * double(index % base);
  }
  return r;
}

// Shoemake's uniform random rotation from three numbers in [0, 1).
Rotation rotationFrom(double u1, double u2, double u3) {
  const double a = std::sqrt(1 - u1), b = std::sqrt(u1);
  const double t1 = 2 * std::numbers::pi * u2, t2 = 2 * std::numbers::pi * u3;
  const double w = a * std::sin(t1), x = a * std::cos(t1), y = b * std::sin(t2),
               z = b * std::cos(t2);
  return {1 - 2 * (y * y + z * z), 2 * (x * y - z * w),     2 * (x * z + y * w),
          2 * (x * y + z * w),     1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
          2 * (x * z - y * w),     2 * (y * z + x * w),     1 - 2 * (x * x + y * y)};
}

// A rotation by angle about the axis (ax, ay, az) (unit).
Rotation axisAngle(double ax, double ay, double az, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
  return {t * ax * ax + c,      t * ax * ay - s * az, t * ax * az + s * ay,
          t * ax * ay + s * az, t * ay * ay + c,      t * ay * az - s * ax,
          t * ax * az - s * ay, t * ay * az + s * ax, t * az * az + c};
}

Rotation multiply(const Rotation& a, const Rotation& b) {
  Rotation r{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        r[std::size_t(i * 3 + j)] += a[std::size_t(i * 3 + k)] * b[std::size_t(k * 3 + j)];
  return r;
}

// The least part's estimated fair share under rotation r.
double leastShare(const std::vector<Piece>& pieces, const std::vector<double>& areaShare,
                  const Rotation& r, std::vector<double>& samples) {
  std::fill(samples.begin(), samples.end(), 0.0);
  double total = 0;
  for (const Piece& p : pieces) {
    const double x = r[0] * p.x + r[1] * p.y + r[2] * p.z;
    const double y = r[3] * p.x + r[4] * p.y + r[5] * p.z;
    const double z = r[6] * p.x + r[7] * p.y + r[8] * p.z;
    const double l1 = std::abs(x) + std::abs(y) + std::abs(z);
    const double s = p.solid / (l1 * l1 * l1);
    samples[p.part] += s;
    total += s;
  }
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < samples.size(); ++k)
    if (areaShare[k] >= 1e-3) least = std::min(least, samples[k] / total / areaShare[k]);
  return least;
}

} // namespace

MapRotationEstimate rotateMapForEvenParts(const TriangleMesh& mesh,
                                          std::span<const std::uint16_t> vertexPart,
                                          std::size_t partCount, SphericalMap& map) {
  std::vector<Piece> pieces;
  pieces.reserve(mesh.triangles.size());
  std::vector<double> areaShare(partCount, 0.0);
  double area = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3f a = map.sphere[t[0]], b = map.sphere[t[1]], c = map.sphere[t[2]];
    const Vec3f centre = a + b + c;
    const double len = double(length(centre));
    if (!(len > 0)) continue;
    const std::size_t part = vertexPart[t[0]];
    pieces.push_back({centre.x / len, centre.y / len, centre.z / len,
                      0.5 * double(length(cross(b - a, c - a))), part});
    const Vec3f p = mesh.positions[t[0]], q = mesh.positions[t[1]], r = mesh.positions[t[2]];
    const double surface = 0.5 * double(length(cross(q - p, r - p)));
    areaShare[part] += surface;
    area += surface;
  }
  if (!(area > 0)) return {};
  for (double& s : areaShare)
    s /= area;

  std::vector<double> samples(partCount);
  const Rotation identity{1, 0, 0, 0, 1, 0, 0, 0, 1};
  MapRotationEstimate estimate;
  estimate.before = estimate.after = leastShare(pieces, areaShare, identity, samples);
  Rotation best = identity;
  const auto consider = [&](const Rotation& r) {
    const double share = leastShare(pieces, areaShare, r, samples);
    if (share > estimate.after) estimate.after = share, best = r;
  };
  for (std::uint32_t k = 1; k <= 512; ++k)
    consider(rotationFrom(halton(k, 2), halton(k, 3), halton(k, 5)));
  for (const double degrees : {12.0, 4.0}) {
    const Rotation centre = best;
    for (std::uint32_t k = 1; k <= 64; ++k) {
      // An axis spread over the sphere and an angle up to `degrees`.
      const double z = 2 * halton(k, 2) - 1, phi = 2 * std::numbers::pi * halton(k, 3);
      const double rho = std::sqrt(std::max(0.0, 1 - z * z));
      consider(multiply(axisAngle(rho * std::cos(phi), rho * std::sin(phi), z,
                                  degrees * std::numbers::pi / 180 * halton(k, 5)),
                        centre));
    }
  }
  if (best == identity) return estimate;

  SphericalMap turned = map;
  for (Vec3f& s : turned.sphere) {
    const double x = s.x, y = s.y, z = s.z;
    const Vec3f r{float(best[0] * x + best[1] * y + best[2] * z),
                  float(best[3] * x + best[4] * y + best[5] * z),
                  float(best[6] * x + best[7] * y + best[8] * z)};
    s = normalize(r);
  }
  measureSphericalMap(mesh, turned);
  if (turned.flipped > map.flipped) {
    estimate.after = estimate.before;
    return estimate;
  }
  map = std::move(turned);
  return estimate;
}

} // namespace octaclay::core::detail
