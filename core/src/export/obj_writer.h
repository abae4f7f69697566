#pragma once

// The one OBJ writer of every export (full resolution, LOD, and the plain meshes of
// mesh_io.h): each position written once, texture coordinates split only in `vt`, streamed to
// the output in blocks; with a material, the MTL and the maps it names are written as one set.

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

/// A named object of the OBJ (`o NAME`): the positions (and normals) from firstPosition and the
/// triangles from firstTriangle, up to the next group's.
struct ObjGroup {
  std::string name;
  std::uint32_t firstPosition = 0, firstTriangle = 0;
};

/// What the OBJ holds. Positions and normals share one index set (`vn` k belongs to `v` k);
/// texture coordinates have their own, so a vertex can carry several across a seam while its
/// position is written once (the surface reads back closed).
struct ObjMesh {
  std::span<const Vec3f> positions; ///< `v`
  std::span<const Vec3f> normals;   ///< `vn`, one per position; or none
  std::span<const Vec2f> texcoords; ///< `vt`, as written (v axis up); or none
  std::span<const std::array<std::uint32_t, 3>> triangles; ///< into positions and normals
  /// Into texcoords, one per triangle; empty = the same indices as `triangles`.
  std::span<const std::array<std::uint32_t, 3>> texcoordTriangles;
  /// Named objects in order, the first starting at 0: each written as `o NAME`, its `v` (and
  /// `vn`), then its faces (indices stay global, as OBJ counts them). Empty: one unnamed mesh.
  /// Not with texcoords.
  std::span<const ObjGroup> groups;
};

/// A file the MTL names, already encoded (a PNG map).
struct ObjMap {
  std::filesystem::path path;
  std::vector<unsigned char> bytes;
};

/// What the OBJ says besides its mesh: a comment line (written after "# "), the MTL's file
/// name for `mtllib` and the material for `usemtl` (both left out when materialLibrary is empty).
struct ObjHeader {
  std::string comment;
  std::string materialLibrary;
  std::string material;
};

/// Stages the OBJ into `set` (the caller commits): `v`, `vt`, `vn`, then faces `f v/vt/vn`
/// (`f v/vt`, `f v//vn` or `f v` for what the mesh lacks), counted from 1, numbers in their
/// shortest round-trip form. Throws Error(InvalidArgument) when the normals' or texture
/// triangles' count disagrees or an index is out of range, Error(Io) when it cannot be written.
void stageObj(const ObjMesh& mesh, const ObjHeader& header, const std::filesystem::path& objPath,
              OutputSet& set);

/// Stages the maps, then the MTL text to mtlPath, then the OBJ (stageObj) into `set`; the
/// caller commits the set, so the previous OBJ, MTL and maps stay whole until every file was
/// written. Throws as stageObj (the files staged so far are dropped with the set).
void writeObjWithMaterial(const ObjMesh& mesh, const ObjHeader& header,
                          std::span<const ObjMap> maps, const std::string& mtl,
                          const std::filesystem::path& mtlPath,
                          const std::filesystem::path& objPath, OutputSet& set);

} // namespace octaclay::core::detail
