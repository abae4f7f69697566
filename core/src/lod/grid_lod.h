#pragma once

#include "octaclay/core/lod/lod.h"

namespace octaclay::core::detail {

/// generateLod for a torus or plane image (W × H cells): the image resampled by a power of two
/// d to (W/d) × (H/d) cells, where M = max(W, H)/d (options.size, or chosen from the target as
/// on the ball); its grid mesh; collapsed with the wrap lines' (torus) or boundary's (plane)
/// rules; refit. Adaptive and Auto (when it may collapse) are the collapse of the full grid.
/// Throws Error(InvalidArgument) when M is not a power of two below max(W, H) or leaves fewer
/// cells across the shorter side than the topology needs (4 for a torus, 2 for a plane).
LodMesh gridLod(const GeometryImage& image, const LodOptions& options);

} // namespace octaclay::core::detail
