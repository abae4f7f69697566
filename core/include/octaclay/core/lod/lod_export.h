#pragma once

// Normal maps baked from the full-resolution image for an LOD mesh, and the LOD written with
// its map (OBJ + MTL + map, or GLB).

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/lod/lod.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace octaclay::core {

enum class NormalMapSpace {
  Object,  ///< the thesis's choice: the full-resolution object-space normal
  Tangent, ///< relative to the LOD's interpolated tangent frame (MikkTSpace-style)
};

/// "object", "tangent".
std::string_view normalMapSpaceName(NormalMapSpace space);
std::optional<NormalMapSpace> parseNormalMapSpace(std::string_view name);

/// A square normal map: resolution² unit normals, row-major, top row = image row 0.
struct NormalMap {
  NormalMapSpace space = NormalMapSpace::Object;
  int resolution = 0;
  std::vector<Vec3f> texels;
};

/// The LOD as a renderer's vertex buffer: mesh vertices split where their corners' image
/// coordinates differ (the octahedral seams), so each vertex has one texture coordinate.
///
/// Tangent frame (glTF's convention, what writeLodMesh writes as NORMAL and TANGENT): the
/// normal is the area-weighted average of the LOD's face normals at the welded vertex; the
/// tangent is the area-weighted dP/du of the incident triangles (u = image x, increasing to the
/// right), made orthogonal to the normal; the bitangent is cross(normal, tangent.xyz) · w, with
/// w = ±1 chosen so that it points towards decreasing v (image row 0, "up" in the image: glTF's
/// +Y, OpenGL's and Blender's "Y+" once OBJ's v axis is flipped). The octahedral map keeps
/// orientation, so w is −1 everywhere on a sane LOD. The GLB carries this frame as NORMAL and
/// TANGENT, so a glTF viewer decodes a Tangent map exactly; an OBJ has no tangents and viewers
/// derive their own (MikkTSpace in Blender: the same axes, slightly different averaging), so
/// tangent-space OBJ maps are close but not exact there.
struct LodVertices {
  std::vector<Vec3f> positions, normals;
  std::vector<std::array<float, 4>> tangents; ///< xyz unit tangent, w handedness (±1)
  std::vector<Vec2f> uvs;                     ///< image coordinates: (x / N, y / N)
  std::vector<std::uint32_t> welded;          ///< for each vertex, its index in lod.mesh
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Splits and frames the LOD's vertices. Throws Error(InvalidArgument) when cornerUv and the
/// mesh's triangles disagree in count.
LodVertices lodVertices(const LodMesh& lod);

/// Bakes the full-resolution normals of `full` for `lod`. Texture coordinates are image
/// coordinates, so texel (x, y) of an Object map is the full-resolution normal at image
/// position ((x + 0.5) / resolution, (y + 0.5) / resolution), interpolated over the
/// full-resolution triangle that holds it (so it is the normal the full mesh shades with
/// there). A Tangent map holds that normal in the LOD's interpolated frame (t, b, n of
/// LodVertices, interpolated and normalised per texel, as glTF viewers do): the unit vector x
/// with normalize(x.x·t + x.y·b + x.z·n) = the full-resolution normal. An Object map does not
/// depend on `lod`. Throws Error(InvalidArgument) for resolution < 2 or > 8192.
NormalMap bakeNormalMap(const GeometryImage& full, const LodMesh& lod, NormalMapSpace space,
                        int resolution);

/// Writes an 8-bit RGB PNG (n·0.5+0.5) for .png, a float32 RGB EXR for .exr; atomic.
/// Throws Error(InvalidArgument) for another extension, Error(Io) when it cannot be written.
void writeNormalMap(const NormalMap& map, const std::filesystem::path& path);

/// Writes the LOD as OBJ + MTL (normal map referenced as `norm` and `map_Bump`) with
/// the map beside it (`stem_normal.png`), or as GLB with the map embedded as normalTexture
/// (Tangent maps only; an Object map is written as an extension-free texture the viewer may
/// ignore; material.extras names it). The OBJ keeps the welded `v` and `vn` (so it reads back
/// closed) and splits seam vertices per cornerUv in its `vt` (v axis up: 1 − y/N); the GLB
/// splits them into separate vertices with POSITION, NORMAL, TANGENT (LodVertices' frame) and
/// TEXCOORD_0 (x/N, y/N). Returns the files written: OBJ, MTL, map; or the GLB. Each file is
/// written atomically, the OBJ last; on failure the files this call wrote are removed.
/// Throws Error(InvalidArgument) for another extension, an empty LOD or a bad map, Error(Io)
/// when a file cannot be written.
std::vector<std::filesystem::path> writeLodMesh(const LodMesh& lod, const NormalMap& map,
                                                const std::filesystem::path& path);

} // namespace octaclay::core
