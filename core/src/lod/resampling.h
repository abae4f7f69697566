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

/// Throws Error(InvalidArgument) naming m unless it is a power of two with 2 ≤ m < n.
void requireLodSize(int n, int m);

} // namespace octaclay::core::detail
