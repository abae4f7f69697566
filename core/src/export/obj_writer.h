#pragma once

// The one OBJ writer of the exports (full resolution and LOD): an OBJ with its MTL and the
// maps the MTL names, written as a set.

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {
class OutputSet;
}

namespace octaclay::core::detail {

/// What the OBJ holds. Positions and normals share one index set (`vn` k belongs to `v` k);
/// texture coordinates have their own, so a vertex can carry several across a seam.
struct ObjMesh {
  std::span<const Vec3f> positions;                        ///< `v`
  std::span<const Vec3f> normals;                          ///< `vn`, one per position
  std::span<const Vec2f> texcoords;                        ///< `vt`, as written (v axis up)
  std::span<const std::array<std::uint32_t, 3>> triangles; ///< into positions and normals
  /// Into texcoords, one per triangle; empty = the same indices as `triangles`.
  std::span<const std::array<std::uint32_t, 3>> texcoordTriangles;
};

/// A file the MTL names, already encoded (a PNG map).
struct ObjMap {
  std::filesystem::path path;
  std::vector<unsigned char> bytes;
};

/// What the OBJ says besides its mesh: a comment line (written after "# "), the MTL's file
/// name for `mtllib` and the material for `usemtl`.
struct ObjHeader {
  std::string comment;
  std::string materialLibrary;
  std::string material;
};

/// Stages the maps, then the MTL text to mtlPath, then the OBJ (`f v/vt/v`, counted from 1,
/// numbers in their shortest round-trip form) into `set`; the caller commits the set, so the
/// previous OBJ, MTL and maps stay whole until every file was written. Throws Error(Io) when a
/// file cannot be written (the files staged so far are dropped with the set).
void writeObjWithMaterial(const ObjMesh& mesh, const ObjHeader& header,
                          std::span<const ObjMap> maps, const std::string& mtl,
                          const std::filesystem::path& mtlPath,
                          const std::filesystem::path& objPath, OutputSet& set);

} // namespace octaclay::core::detail
