#pragma once

#include "octaclay/core/triangle_mesh.h"

#include <cstddef>
#include <filesystem>

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
};

/// Reads an OBJ, PLY (ASCII and binary of either byte order), STL (ASCII and binary) or OFF
/// file. Every read is bounds-checked, so truncated or hostile files end in an Error, never in
/// a crash or a huge allocation. Face indices are checked against the vertex count.
/// Throws Error(Io) when the file cannot be opened or read, Error(InvalidArgument) for an
/// unknown extension, Error(InvalidInput) when the contents are malformed; messages start with
/// the path.
RawMesh readRawMesh(const std::filesystem::path& path);

} // namespace octaclay::core::detail
