#pragma once

// Normal maps baked from the full-resolution image for an LOD mesh (thesis 4.1), and written
// on their own as PNG or EXR. export/lod_export.h writes the LOD with its map.

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/core/lod/lod.h"

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

/// Bakes the full-resolution normals of `full` for `lod`. Texture coordinates are image
/// coordinates, so texel (x, y) of an Object map is the full-resolution normal at image
/// position ((x + 0.5) / resolution, (y + 0.5) / resolution), interpolated over the
/// full-resolution triangle that holds it (so it is the normal the full mesh shades with
/// there). A Tangent map holds that normal in the LOD's interpolated frame (t, b, n of
/// LodVertices in lod_vertices.h, interpolated and normalised per texel, as glTF viewers do): the
/// unit vector x with normalize(x.x·t + x.y·b + x.z·n) = the full-resolution normal. An Object map
/// does not depend on `lod`. Throws Error(InvalidArgument) for resolution < 2 or > 8192.
NormalMap bakeNormalMap(const GeometryImage& full, const LodMesh& lod, NormalMapSpace space,
                        int resolution);

/// Writes an 8-bit RGB PNG (n·0.5+0.5) for .png, a float32 RGB EXR for .exr; atomic.
/// Throws Error(InvalidArgument) for another extension, Error(Io) when it cannot be written.
void writeNormalMap(const NormalMap& map, const std::filesystem::path& path);

class OutputSet;

/// writeNormalMap's file staged into `set` (atomic_output.h), committed with the caller's others.
void stageNormalMap(const NormalMap& map, const std::filesystem::path& path, OutputSet& set);

} // namespace octaclay::core
