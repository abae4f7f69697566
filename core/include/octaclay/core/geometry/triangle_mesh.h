#pragma once

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::core {

/// An indexed triangle mesh: #V positions, #T triangles of three indices into them,
/// counter-clockwise seen from outside.
struct TriangleMesh {
  std::vector<Vec3f> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Axis-aligned bounding box; empty when min > max.
struct BoundingBox {
  Vec3f min{1, 1, 1}, max{-1, -1, -1};
  bool empty() const { return min.x > max.x; }
  Vec3f extent() const { return empty() ? Vec3f{} : max - min; }
  float diagonal() const { return length(extent()); }
  void extend(Vec3f p);
};

BoundingBox boundingBox(const TriangleMesh& mesh);

/// Signed volume enclosed (positive for outward orientation of a closed mesh).
double signedVolume(const TriangleMesh& mesh);

/// How thin triangle (a, b, c) is: its longest edge / the height onto it (longest² / twice the
/// area); 2 for half a square, infinity when the triangle has no area.
double aspectRatio(Vec3f a, Vec3f b, Vec3f c);

/// Combinatorial facts of an indexed triangle mesh.
struct MeshTopology {
  std::size_t vertices = 0;       ///< referenced by at least one triangle
  std::size_t unusedVertices = 0; ///< in positions, referenced by none
  std::size_t edges = 0;
  std::size_t triangles = 0;
  std::size_t boundaryEdges = 0;       ///< in one triangle
  std::size_t nonManifoldEdges = 0;    ///< in three or more, or twice in one direction
  std::size_t degenerateTriangles = 0; ///< repeated index or zero area
  long long euler = 0;                 ///< V − E + F over referenced vertices
  bool closed() const { return boundaryEdges == 0; }
  bool manifold() const { return nonManifoldEdges == 0; }
};

/// Counts edges by sorting half-edges: O(T log T) time, O(T) memory.
MeshTopology analyzeTopology(const TriangleMesh& mesh);

} // namespace octaclay::core
