#pragma once

// A dab's area normal on the GPU: a compute pass sums the area vectors of the triangles near the
// dab's centre per quarter of the tiles its sphere meets, and only those sums are read back, not
// the texels under the dab (the CPU loop read them back and walked them every dab).

#include "quarter_pass.h"

#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <span>

namespace octaclay::gpu::detail {

class AreaNormalPass {
public:
  /// Makes the program on first use. Throws GlError.
  AreaNormalPass() = default;
  /// The sum over the cells of tiles (indices into bounds) of positions, an RGBA32F texture of
  /// cells.x + 1 by cells.y + 1 samples; ball: the octahedral cell split. Waits for the passes
  /// that wrote positions. Throws GlError.
  AreaSum sum(const Texture& positions, const core::TileBounds& bounds, std::span<const int> tiles,
              std::array<int, 2> cells, bool ball, core::Vec3f centre, float radius);

private:
  QuarterPass pass_{"area_normal.glsl"};
};

} // namespace octaclay::gpu::detail
