#pragma once

// A stroke's finite check on the GPU: a compute pass over the rectangles a stroke wrote sets one
// flag when a texel holds a value not to commit, and only that flag is read back, once per
// stroke, instead of every texel being checked on the CPU.

#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/gl_objects.h"

#include <span>

namespace octaclay::gpu::detail {

class FiniteCheckPass {
public:
  /// Whether every texel of rects in texture holds finite values in its first `channels`
  /// channels and, when bounded, an xyz within ±maxCoordinate (as the CPU's check compares:
  /// |v| ≤ maxCoordinate in float). Waits for the passes that wrote it. Throws GlError.
  bool allFinite(const Texture& texture, int channels, bool bounded, float maxCoordinate,
                 std::span<const core::TexelRect> rects);

private:
  Program program_; // made on first use
  Buffer rows_, flag_;
};

} // namespace octaclay::gpu::detail
