#pragma once

// The painted layers as the exports' maps: (W+1)×(H+1) pixels each for the full-resolution
// export (texel (x, y) = layer sample (x, y), top row first), or resampled over image coordinates
// for the LOD export, whose texture coordinates are those of its normal map.

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

/// The same maps at resolution² texels over image coordinates, as a baked NormalMap's: texel
/// (x, y) holds the layer at image position ((x + 0.5) / resolution, (y + 0.5) / resolution),
/// that is at sample ((x + 0.5)·W / resolution, (y + 0.5)·H / resolution), bilinear between the
/// four samples around it. Throws Error(InvalidArgument) when a layer's texel count disagrees
/// with the image.
RasterImage diffuseMap(const Document& doc, int resolution);
RasterImage featureMap(const Document& doc, int channel, int resolution);
RasterImage metallicRoughnessMap(const Document& doc, int resolution);

} // namespace octaclay::core::detail
