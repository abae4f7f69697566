#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <filesystem>
#include <optional>
#include <string_view>

namespace octaclay::core {

enum class MeshFormat { Obj, Ply, Stl, Off };

/// The format a path's extension names (.obj, .ply, .stl, .off, any case), or nullopt.
std::optional<MeshFormat> meshFormatFromPath(const std::filesystem::path& path);

/// Writes OBJ through the exports' OBJ writer (`v` and `f` only), PLY (binary), STL (binary) and
/// OFF through OpenMesh, atomically like writeDocument. Throws Error(InvalidInput) for
/// non-manifold triangles.
/// Throws Error(InvalidArgument) for an unknown extension, Error(Io) when writing fails.
void writeMesh(const TriangleMesh& mesh, const std::filesystem::path& path);

class OutputSet;

/// writeMesh's file staged into `set` (atomic_output.h), committed with the caller's others.
void stageMesh(const TriangleMesh& mesh, const std::filesystem::path& path, OutputSet& set);

/// Reads a triangle mesh through OpenMesh (polygons are triangulated). STL's repeated corners
/// are merged. Throws Error(Io) when unreadable, Error(InvalidInput) when empty or malformed.
TriangleMesh readMesh(const std::filesystem::path& path);

} // namespace octaclay::core
