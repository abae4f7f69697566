#pragma once

#include "dab_pass.h"

#include "octaclay/gpu/gl_objects.h"

// The pass kind of a body defining brushLayers() ("pass": "all-layers"): one pass writes every
// layer the brush writes.
namespace octaclay::gpu::detail {

class AllLayersPass {
public:
  /// The one pass: the written layers as colour attachments 0 to 2 (positions, diffuse,
  /// feature; a layer whose texels the pass reads elsewhere through its scratch, a mixed one
  /// blended), each read as it was before the dab; then each written layer is finished.
  void run(DabPass& pass);

private:
  /// The attachments' framebuffer, made on first use. The textures are attached for each dab
  /// and detached after it: it must not keep a document's textures alive, nor render into a
  /// texture that a whole-image swap makes a layer's.
  Framebuffer target_;
};

} // namespace octaclay::gpu::detail
