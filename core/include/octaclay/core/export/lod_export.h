#pragma once

// The LOD written with its baked normal map: OBJ + MTL + map, or GLB.

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

} // namespace octaclay::core
