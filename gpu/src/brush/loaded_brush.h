#pragma once

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_objects.h"

#include <algorithm>
#include <array>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace octaclay::gpu::detail {

/// A brush the engine loaded: its manifest and body, its programs, and how its passes write.
struct LoadedBrush {
  BrushManifest manifest;
  std::string body;
  // Set when a pass overran the watchdog's limit: the brush's dabs throw it until reloaded.
  std::string broken;
  // The body defines brushLayers(): one program writes every layer (keyed as positions).
  bool allLayers = false;
  // "pass": "reparameterize": one program (keyed as positions) steps the offset field, then the
  // engine resamples every layer into its scratch.
  bool reparameterize() const { return manifest.pass == PassKind::Reparameterize; }
  // Per layer: its passes write the layer's texture in place instead of a scratch copy. Only
  // where nothing reads other texels of that layer: each texel is then read by the fragment
  // that writes it alone (the texture barrier rules).
  std::array<bool, 4> inPlace{};
  bool writesInPlace(core::EditLayer layer) const {
    return inPlace[static_cast<std::size_t>(layer)];
  }
  // Layers the blender mixes the body's (colour, amount) into: written in place, never read.
  bool mixes(core::EditLayer layer) const {
    return std::find(manifest.mix.begin(), manifest.mix.end(), layer) != manifest.mix.end();
  }
  // Whether a pass samples the paint layer (diffuse or feature) through its own unit: a
  // brushLayers() pass is given it unless mixed, a brush() pass samples what it reads.
  bool samples(core::EditLayer layer) const {
    return !mixes(layer) && (allLayers || manifest.readsLayer(layer));
  }
  // Whether every layer the brush writes is written in place: its passes may then discard
  // unweighted texels.
  bool allInPlace() const {
    return std::all_of(manifest.writes.begin(), manifest.writes.end(),
                       [this](core::EditLayer l) { return writesInPlace(l); });
  }
  // Whether a pass reads a texel that it also writes (a texture barrier must come first).
  bool readsWhatItWrites() const {
    return std::any_of(manifest.writes.begin(), manifest.writes.end(),
                       [this](core::EditLayer l) { return writesInPlace(l) && !mixes(l); });
  }
  // One per written layer (OCTACLAY_LAYER differs), mask kind (BRUSH_MASK_TEXTURE), the
  // values of the enum parameters (constants in the source) and batching (OCTACLAY_BATCH); all
  // but the defaults' variants are compiled on first use.
  std::map<std::tuple<core::EditLayer, bool, std::vector<int>, bool>, Program> programs;
};

} // namespace octaclay::gpu::detail
