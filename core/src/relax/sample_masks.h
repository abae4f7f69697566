#pragma once

#include "octaclay/core/geometry/geometry_image.h"

#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// The samples ((N+1)², row-major, 1 or 0) within `margin` samples of a changed one (changed:
/// (N+1)², non-zero where changed), by Chebyshev distance on the tiled octahedral plane, so
/// across the seams: every copy of a border sample reached is in. Where the changed samples'
/// box grown by `margin` stays off the image's border this is a box dilation by rows, then
/// columns, over that box (O(box) work); else grownMaskBySearch. The two give the same mask.
std::vector<std::uint8_t> grownMask(int n, const std::vector<std::uint8_t>& changed, int margin);

/// grownMask by a breadth-first search over the 8 neighbours, through the seams (O(mask × 8)).
std::vector<std::uint8_t> grownMaskBySearch(int n, const std::vector<std::uint8_t>& changed,
                                            int margin);

/// The cells (N × N, row-major, 1 or 0) with a corner within one sample of a free one (free:
/// (N+1)², non-zero where free; a corner at i - 1 … i + 2, j - 1 … j + 2 of cell (i, j)): every
/// cell that may move and the ring around them.
std::vector<std::uint8_t> cellsNearFree(int n, const std::vector<std::uint8_t>& free);

/// Whether a changed sample (changed: the image's (W+1)×(H+1), non-zero where changed) has a
/// grid edge, through the topology's wrap, over `limit` long: keep detail relaxes nothing else.
bool stretchedAt(const GeometryImage& image, const std::vector<std::uint8_t>& changed, float limit);

} // namespace octaclay::core::detail
