#pragma once

// The tile bounds from the GPU: a compute pass reduces the positions texture to the min/max box
// of each quarter of the tiles a change moved (core::TileBounds's quarters), and only those
// boxes (24 bytes a quarter) are read back, not the texels.

#include "quarter_pass.h"

#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/gpu/gl_objects.h"

#include <span>

namespace octaclay::gpu::detail {

class TileBoundsPass {
public:
  /// Makes the program on first use. Throws GlError.
  TileBoundsPass() = default;
  /// Recomputes the boxes of bounds' tiles that a change of rects moved (tilesTouching) from
  /// positions (an RGBA32F texture of the (N+1)² image), as TileBounds::refresh would from the
  /// image itself. Waits for the passes that wrote positions (reads their result). Throws
  /// GlError.
  void refresh(const Texture& positions, core::TileBounds& bounds,
               std::span<const core::TexelRect> rects);

private:
  QuarterPass pass_{"tile_bounds.glsl"};
};

} // namespace octaclay::gpu::detail
