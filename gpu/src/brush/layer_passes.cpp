#include "layer_passes.h"

#include "loaded_brush.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace octaclay::gpu::detail {

void runLayerPasses(DabPass& pass) {
  const BrushManifest& manifest = pass.brush.manifest;
  std::vector<core::EditLayer> order = manifest.writes;
  const bool readsFeature = std::find(manifest.reads.begin(), manifest.reads.end(),
                                      core::EditLayer::Feature) != manifest.reads.end();
  std::stable_partition(order.begin(), order.end(), [readsFeature](core::EditLayer l) {
    return (l != core::EditLayer::Positions) != readsFeature;
  });
  for (core::EditLayer layer : order) {
    const Program& program = pass.program(layer);
    const bool inPlace = pass.brush.writesInPlace(layer);
    (inPlace ? pass.document.texture(layer) : pass.document.scratch(layer)).bindAsTarget();
    pass.bindInputs(program, layer);
    if (inPlace) glTextureBarrier();
    pass.draw();
    pass.issued();
    pass.finishLayer(layer);
  }
}

} // namespace octaclay::gpu::detail
