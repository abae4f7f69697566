#pragma once

#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::core::detail {

/// A mesh exactly as its file holds it: every vertex in file order (used or not), polygons
/// fan-triangulated, nothing welded or dropped. readMesh goes through OpenMesh's half-edge
/// structure, which silently duplicates or drops the non-manifold faces and pinch vertices that
/// validation has to report, so validation reads the files itself.
struct RawMesh {
  TriangleMesh mesh;
  /// STL stores three corners per facet: vertices have to be welded by position.
  bool cornersPerFace = false;
  /// Faces with fewer than three corners (OBJ `f 1 2`, PLY/OFF lists of length 0–2): skipped.
  std::size_t shortFaces = 0;
  /// One RGBA colour in [0, 1] per vertex when the file gives every vertex one (PLY
  /// red/green/blue[/alpha] vertex properties, OBJ `v x y z r g b`); otherwise empty.
  std::vector<Vec4f> vertexColours;
  /// Per triangle of `mesh`, the (u, v) texture coordinates of its three corners when every
  /// face of an OBJ has them (`f v/vt …`); otherwise empty.
  std::vector<std::array<std::array<float, 2>, 3>> cornerUv;
  /// The first `map_Kd` image of the OBJ's material libraries, when that file exists and the
  /// faces have texture coordinates; otherwise empty.
  std::filesystem::path diffuseTexture;
  /// Attributes the file names but that could not be used (a missing .mtl or texture, partial
  /// colours), one sentence each: not errors, the geometry imports without them.
  std::vector<std::string> notes;
};

/// Reads an OBJ, PLY (ASCII and binary of either byte order), STL (ASCII and binary) or OFF
/// file. Every read is bounds-checked, so truncated or hostile files end in an Error, never in
/// a crash or a huge allocation. Face indices are checked against the vertex count.
/// Throws Error(Io) when the file cannot be opened or read, Error(InvalidArgument) for an
/// unknown extension, Error(InvalidInput) when the contents are malformed; messages start with
/// the path. Damaged or missing attributes (colours, texture coordinates, materials) are never
/// errors: they are dropped with a note.
RawMesh readRawMesh(const std::filesystem::path& path);

/// readRawMesh for contents already in memory (the fuzzers' entry): `text` is read as `format`,
/// `path` names the file in messages and, for OBJ, is where material libraries are looked for.
/// Throws Error(InvalidInput) as readRawMesh does.
RawMesh parseRawMesh(const std::filesystem::path& path, MeshFormat format, std::string_view text);

} // namespace octaclay::core::detail
