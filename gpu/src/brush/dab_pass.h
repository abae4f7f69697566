#pragma once

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <functional>
#include <vector>

// What one dab's passes share (or one batch's: BrushEngine::dabs), whatever their kind:
// BrushEngine::runPasses sets it up (the tiles merged into rectangles, the GL state) and hands it
// to the brush's pass kind (layer_passes, all_layers_pass, reparameterize_pass).
namespace octaclay::gpu::detail {

struct LoadedBrush;

struct DabPass {
  GpuDocument& document;
  LoadedBrush& brush;
  const Dab& dab; ///< the dab (a batch's first: its values that every dab of it shares)
  /// What every pass draws: the tiles merged into few rectangles (and a torus's seam partners).
  const std::vector<core::TexelRect>& rects;
  bool maskTexture;              ///< the mask is painted: the programs sample it
  const std::vector<int>& enums; ///< the enum parameters' values (which program variant)
  RectPass& rectPass;
  /// Draws the bound program over rects: for a batch of dabs, each rectangle with its dab.
  std::function<void()> draw;
  /// The brush's program for a pass writing the layer, compiled on first use. Throws GlError.
  std::function<const Program&(core::EditLayer)> program;
  /// Uses the program and binds what a pass writing the layer reads: the prelude's uniforms,
  /// the layers, the material, the stroke-start positions. Leaves unit 0 active.
  std::function<void(const Program&, core::EditLayer)> bindInputs;
  /// A pass was just issued: fenced for the watchdog. Throws BrushTimeoutError.
  std::function<void()> issued;
  /// The layer's passes are done: their result goes back into the layer's texture, is seamed
  /// and noted as changed.
  std::function<void(core::EditLayer)> finishLayer;
};

} // namespace octaclay::gpu::detail
