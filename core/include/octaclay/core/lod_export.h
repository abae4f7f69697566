#pragma once

// Normal maps baked from the full-resolution image for an LOD mesh, and the LOD written with
// its map (OBJ + MTL + map, or GLB).

#include <octaclay/core/geometry_image.h>
#include <octaclay/core/lod.h>

#include <filesystem>
#include <vector>

namespace octaclay::core {

enum class NormalMapSpace {
  Object,  ///< the thesis's choice: the full-resolution object-space normal
  Tangent, ///< relative to the LOD's interpolated tangent frame (MikkTSpace-style)
};

/// A square normal map: resolution² unit normals, row-major, top row = image row 0.
struct NormalMap {
  NormalMapSpace space = NormalMapSpace::Object;
  int resolution = 0;
  std::vector<Vec3f> texels;
};

/// Bakes the full-resolution normals of `full` for `lod`. Texture coordinates are image
/// coordinates, so texel (x, y) of an Object map is the full-resolution normal at image
/// position ((x + 0.5) / resolution, (y + 0.5) / resolution). Throws Error(InvalidArgument)
/// for resolution < 2 or > 8192.
NormalMap bakeNormalMap(const GeometryImage& full, const LodMesh& lod, NormalMapSpace space,
                        int resolution);

/// Writes an 8-bit RGB PNG (n·0.5+0.5) for .png, a float32 RGB EXR for .exr; atomic.
/// Throws Error(InvalidArgument) for another extension, Error(Io) when it cannot be written.
void writeNormalMap(const NormalMap& map, const std::filesystem::path& path);

/// Writes the LOD as OBJ + MTL (normal map referenced as `norm`/`bump` and `map_Bump`) with
/// the map beside it (`stem_normal.png`), or as GLB with the map embedded as normalTexture
/// (Tangent maps only; an Object map is written as an extension-free texture the viewer may
/// ignore). The mesh's seam vertices are split per cornerUv. Returns the files written.
std::vector<std::filesystem::path> writeLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const std::filesystem::path& path);

} // namespace octaclay::core
