#pragma once

#include "dab_pass.h"

#include "octaclay/core/document/document.h"
#include "octaclay/gpu/gl_objects.h"

#include <array>
#include <vector>

// The pass kind of a reparameterize brush ("pass": "reparameterize"): the samples move within
// the surface and every layer is resampled, so a whole stroke moves the surface and its paint
// by one interpolation, not one per dab.
namespace octaclay::gpu::detail {

class ReparameterizePass {
public:
  /// What a dab resamples: the positions always; a paint layer only when painted (an unpainted
  /// one is its fill everywhere, which resampling keeps, and the mask would stop counting as
  /// unpainted).
  static std::vector<core::EditLayer> layersOf(const core::Document& mirror);

  /// The brush's iterations of its offset field over the dab's rects (each step reads the field
  /// so far and writes the next into the twin), then one resample of every layer in layers into
  /// its scratch from the layers as they were at the stroke's first such dab. Outside an open
  /// stroke the field is zero again after the dab; a pass that throws zeroes it too.
  void run(DabPass& pass, const std::vector<core::EditLayer>& layers, bool strokeOpen);

  /// The stroke is over: the field is zero again and its base layers forgotten.
  void endStroke();

private:
  /// Forgets the stroke's base layers and zeroes the offset field (where: its texels that may
  /// be non-zero).
  void reset(const std::vector<core::TexelRect>& where);

  /// The offset field (xy, samples) and its ping-pong twin, zero everywhere between strokes.
  std::array<Texture, 2> offsets_;
  /// The layers as they were at the stroke's first dab (positions, diffuse, feature, mask; a
  /// layer only once a dab resamples it), and whose they are.
  std::array<Texture, 4> base_;
  std::array<bool, 4> baseTaken_{};
  const GpuDocument* baseOf_ = nullptr;
  /// The resampling pass (compiled on first use) and its target: every layer's scratch as
  /// attachments 0 to 3.
  Program resampleProgram_;
  Framebuffer resampleTarget_;
};

} // namespace octaclay::gpu::detail
