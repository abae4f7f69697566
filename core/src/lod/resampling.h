#pragma once

#include "octaclay/core/lod/lod.h"

#include <vector>

namespace octaclay::core::detail {

/// The resampled, seamed image and, for every sample (i, j) of its (M+1)² grid at index
/// j·(M+1)+i, the full-resolution image coordinates (x, y) (in samples, 0 … N) that sample
/// stands for: the chosen sample for the point methods, the grid position (i·N/M, j·N/M) for
/// the average ones. Identified LOD samples get identified full-resolution coordinates.
struct ResampledImage {
  GeometryImage image;
  std::vector<Vec2f> source;
};

ResampledImage resampleWithSources(const GeometryImage& image, int m, ResampleMethod method);

/// Weight of the salient-average method: the saliency plus a floor, so that flat footprints
/// (saliency 0 everywhere) fall back to the plain average.
inline constexpr float kSaliencyFloor = 1.0f / 64.0f;

/// The mean of the footprint (2·hi+1) × (2·hj+1) around centre, each sample read by
/// read(Sample), weight 1 inside and ½ on its rim rows and columns (so neighbouring footprints'
/// weights sum to one; a half-width of 0: that axis's centre alone), times (saliency +
/// kSaliencyFloor) when salient. The ball's and the grid topologies' average methods.
template <class Read>
Vec4f footprintMean(Sample centre, int hi, int hj, bool salient, Read&& read) {
  double sx = 0, sy = 0, sz = 0, sw = 0, total = 0;
  for (int dj = -hj; dj <= hj; ++dj) {
    const double wj = hj > 0 && (dj == -hj || dj == hj) ? 0.5 : 1.0;
    for (int di = -hi; di <= hi; ++di) {
      const double wi = hi > 0 && (di == -hi || di == hi) ? 0.5 : 1.0;
      const Vec4f& t = read(Sample{centre.i + di, centre.j + dj});
      const double w = wi * wj * (salient ? t.w + kSaliencyFloor : 1.0);
      sx += w * t.x;
      sy += w * t.y;
      sz += w * t.z;
      sw += w * t.w;
      total += w;
    }
  }
  const double inv = 1.0 / total;
  return {float(sx * inv), float(sy * inv), float(sz * inv), float(sw * inv)};
}

/// Throws Error(InvalidArgument) naming m unless it is a power of two with 2 ≤ m < n.
void requireLodSize(int n, int m);

} // namespace octaclay::core::detail
