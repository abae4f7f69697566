#pragma once

// The CDF 9/7 lifting transform on the (N+1)² vertex-centred octahedral grid, with the grid
// extended across its border by the octahedral tiling (core/octahedral.h wrap): the transform
// sees a closed surface, never a seam. Level l works on the samples at multiples of 2^l; its
// odd multiples become details, its even multiples the next level's input. The tiling maps that
// lattice to itself keeping odd and even apart, and the lifting filters are symmetric, so a
// seamed plane (identified samples equal) gives seamed coefficients, bit for bit.

#include <span>

namespace octaclay::core::detail {

/// log2 N: the last level leaves one value, at the four (identified) corners.
int waveletLevels(int n);

/// In place on one plane of (N+1)² floats, row-major.
void forwardWavelet(std::span<float> plane, int n);
void inverseWavelet(std::span<float> plane, int n);
/// Undoes level `level` alone (levels above it undone already).
void inverseWaveletLevel(std::span<float> plane, int n, int level);

} // namespace octaclay::core::detail
