#pragma once

// The painted layers as the exports' maps, (N+1)² pixels each (texel (x, y) = layer sample
// (x, y), top row first), and their 8-bit PNG encoding.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/image_io.h"

#include <vector>

namespace octaclay::core::detail {

/// RGBA: the diffuse layer.
RasterImage diffuseMap(const Document& doc);

/// Grey: one channel of the feature layer (0 height, 1 specular, 2 reflectivity).
RasterImage featureMap(const Document& doc, int channel);

/// glTF's metallic-roughness texture: G roughness = 1 − specular, B metallic = reflectivity;
/// R is unused by the core material (occlusion would read it), so it is 1.
RasterImage metallicRoughnessMap(const Document& doc);

} // namespace octaclay::core::detail
