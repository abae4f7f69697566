#include "octaclay/core/lod/facing.h"

#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/saliency.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace octaclay::core {
namespace {

constexpr int kGuessSize = 128;
constexpr double kMinPull = 0.08; // of the horizontal spread

} // namespace

Vec3f guessFacing(const GeometryImage& image) {
  // The saliency is the ball's (octahedral): a torus or plane faces the default front.
  if (image.topology() != Topology::Octahedral) return {0, 0, 1};
  // The image's level of kGuessSize (every step-th sample), as the point LOD takes it.
  GeometryImage level =
      image.size() > kGuessSize ? resampleImage(image, kGuessSize, ResampleMethod::Point) : image;
  computeSaliency(level);
  const int n = level.size();
  // Area-weighted and saliency-weighted sums of x and z (each vertex once, but for the seams'
  // duplicates: they shift both centres alike).
  double area = 0, x = 0, z = 0, xx = 0, zz = 0, weight = 0, sx = 0, sz = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vec3f p = level.positionWrapped({i, j});
      const Vec3f du = level.positionWrapped({i + 1, j}) - level.positionWrapped({i - 1, j});
      const Vec3f dv = level.positionWrapped({i, j + 1}) - level.positionWrapped({i, j - 1});
      const double a = length(cross(du, dv));
      const double s = a * level.at(i, j).w;
      area += a;
      x += a * p.x;
      z += a * p.z;
      xx += a * p.x * p.x;
      zz += a * p.z * p.z;
      weight += s;
      sx += s * p.x;
      sz += s * p.z;
    }
  const Vec3f front{0, 0, 1};
  if (!(area > 0) || !(weight > 0)) return front;
  const double cx = x / area, cz = z / area;
  const double spread = std::sqrt(std::max(0.0, xx / area - cx * cx + zz / area - cz * cz));
  const double px = sx / weight - cx, pz = sz / weight - cz;
  if (!(std::hypot(px, pz) >= kMinPull * spread) || !(spread > 0)) return front;
  // The nearest axis, or a diagonal (a three-quarter view) where the pull is within 15° of one.
  const double quarter = std::numbers::pi / 2, angle = std::atan2(px, pz);
  const double diagonal = (std::floor(angle / quarter) + 0.5) * quarter;
  const double snapped =
      std::abs(angle - diagonal) < quarter / 6 ? diagonal : std::round(angle / quarter) * quarter;
  return {static_cast<float>(std::sin(snapped)), 0, static_cast<float>(std::cos(snapped))};
}

} // namespace octaclay::core
