// Helpers shared by the GL brush tests: built-in brushes loaded from the source tree and dabs
// placed on a sample of the current surface.
#pragma once

#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gpu_document.h"

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace octaclay::gpu::testing {

inline const std::filesystem::path kBuiltInBrushes =
    std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes";

inline std::string readFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

/// The built-in brush `id`'s manifest, optionally renamed (to load a variant beside it).
inline BrushManifest builtInManifest(const std::string& id) {
  return parseBrushManifest(kBuiltInBrushes / id / "manifest.json");
}

inline void loadBuiltIns(BrushEngine& engine) {
  for (const char* id :
       {"push", "inflate", "smooth", "flatten", "sphere-add", "sphere-subtract", "mask", "paint"}) {
    const BrushManifest manifest = builtInManifest(id);
    engine.load(manifest, readFile(manifest.shaderPath()));
  }
}

inline Dab dabAt(const core::GeometryImage& image, core::Sample s, float radius, float strength) {
  Dab dab;
  dab.centreTexel = s;
  dab.centre = image.at(s).xyz();
  dab.centreNormal = core::vertexNormal(image, s);
  dab.radius = radius;
  dab.strength = strength;
  return dab;
}

/// Every layer's texels as the document's mirror holds them (fill values expanded), in
/// EditLayer order: what sameBits compares.
inline std::vector<std::vector<float>> snapshot(const GpuDocument& document) {
  std::vector<std::vector<float>> layers;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask})
    layers.push_back(document.mirrorTexels(layer, document.whole()));
  return layers;
}

/// Whether two snapshots of layers (one float vector per layer) hold the same bits.
inline bool sameBits(const std::vector<std::vector<float>>& a,
                     const std::vector<std::vector<float>>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k)
    if (a[k].size() != b[k].size() ||
        std::memcmp(a[k].data(), b[k].data(), a[k].size() * sizeof(float)) != 0)
      return false;
  return true;
}

} // namespace octaclay::gpu::testing
