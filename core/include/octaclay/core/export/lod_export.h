#pragma once

// The LOD written with its baked normal map, and the painted layers: OBJ + MTL + maps, or GLB.

#include "octaclay/core/document/document.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/normal_map.h"

#include <filesystem>
#include <vector>

namespace octaclay::core {

class OutputSet;

/// Writes the LOD as OBJ + MTL (normal map referenced as `norm` and `map_Bump`) with
/// the map beside it (`stem_normal.png`), or as GLB with the map embedded as normalTexture
/// (Tangent maps only; an Object map is written as an extension-free texture the viewer may
/// ignore; material.extras names it). The OBJ keeps the welded `v` and `vn` (so it reads back
/// closed) and splits seam vertices per cornerUv in its `vt` (v axis up: 1 − y/N); the GLB
/// splits them into separate vertices with POSITION, NORMAL, TANGENT (LodVertices' frame,
/// lod_vertices.h) and TEXCOORD_0 (x/N, y/N). Returns the files written: OBJ, MTL, map; or the GLB.
/// The files are written as one set (atomic_output.h): on failure the previous OBJ, MTL and map
/// all stay as they were. Throws Error(InvalidArgument) for another extension, an empty LOD or a
/// bad map, Error(Io) when a file cannot be written.
std::vector<std::filesystem::path> writeLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const std::filesystem::path& path);

/// writeLodMesh's files staged into `set`, for a caller that adds files or checks more before
/// it commits; returns them in writeLodMesh's order.
std::vector<std::filesystem::path> stageLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const std::filesystem::path& path, OutputSet& set);

/// writeLodMesh with the painted layers of `paint` (the document the LOD was made from; its
/// diffuse and feature layers), so the LOD carries what the full-resolution export carries
/// (textured_export.h): the layers resampled to the normal map's resolution over the same
/// texture coordinates (texel (x, y) at image position ((x + 0.5) / r, (y + 0.5) / r), bilinear).
/// The OBJ's MTL adds `map_Kd` (`stem_diffuse.png`, RGBA), `map_Ks` (`stem_specular.png`) and
/// `map_refl` / `map_Pm` (`stem_reflectivity.png`), returned after the normal map in that
/// order; the GLB's material adds baseColorTexture (diffuse) and metallicRoughnessTexture (G
/// roughness = 1 − specular, B metallic = reflectivity; both factors 1). Throws as writeLodMesh,
/// and Error(InvalidArgument) when a layer's texel count disagrees with paint's N.
std::vector<std::filesystem::path> writeLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const Document& paint,
                                                const std::filesystem::path& path);
std::vector<std::filesystem::path> stageLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const Document& paint,
                                                const std::filesystem::path& path, OutputSet& set);

} // namespace octaclay::core
