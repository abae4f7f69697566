#pragma once

// Vertex collapse (issue 7, thesis 4.4): OpenMesh's Decimater with quadric priorities, run on
// a closed genus-0 mesh (in practice the already small resampled LOD mesh).

#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace octaclay::core {

/// Which implementation collapses: OpenMesh's Decimater (a heap of per-vertex priorities, the
/// strict order of quadric errors) or our flat-array passes (src/lod/quadric_collapse.h: the
/// same checks, collapses in threshold passes, much faster on LOD meshes: docs/lod.md).
enum class CollapseEngine { Decimater, Fast };

struct VertexCollapseOptions {
  CollapseEngine engine = CollapseEngine::Decimater;
  /// Stop at this many triangles (0 = no count target). A closed mesh loses two triangles per
  /// collapse, so the result has the even count nearest above the target unless a bound
  /// below stops it first.
  std::size_t targetTriangles = 0;
  /// Refuse collapses whose quadric error exceeds (maxError × bounding-box diagonal)²; 0 = no
  /// bound. The error is Garland–Heckbert's, planes weighted by their triangle's area / the
  /// input's mean triangle area: on an even mesh, the sum of squared distances from the kept
  /// vertex to the planes of the triangles merged into it (both engines).
  double maxError = 0;
  /// Refuse a collapse that would turn any triangle's normal more than this away from the
  /// normal of the input triangle it is (CollapsedMesh::inputTriangle), or leave it without
  /// area: the bound holds for the result, not only for each step.
  float maxNormalTurnDegrees = 60;
  /// Measure that turn against the triangle as it was before each collapse instead of its
  /// input triangle: no fold at any step, but turns may add up. What a collapse of a noisy
  /// full-resolution mesh needs, whose tiny input triangles point every way (the scorpion at
  /// 1 % of 2N²: 7044 triangles left at 43.7 dB against the input, 5242 at 61.1 dB per
  /// collapse with 90°; bench_lod).
  bool normalTurnPerCollapse = false;
  /// Empty, or one weight per input vertex: each input triangle's plane then counts in the
  /// quadrics times the mean of its corners' weights (saliency weighting: collapses cost more
  /// where the weight is high, so detail stays there). Fast engine only.
  std::vector<float> vertexWeights;
  /// Refuse collapses that make a triangle's longest-edge / height ratio exceed this (unless
  /// it was already above it and does not get worse); 0 = no bound.
  float maxAspectRatio = 10;
  /// With maxAspectRatio set, a triangle may also get as thin as this many times its input
  /// triangle (CollapsedMesh::inputTriangle) was: where the input is already stretched (a
  /// geometry image's thin parts) the collapse keeps room to work. 0 = the bound alone.
  float maxAspectGrowth = 2;
  /// The mesh may be open (a plane's sheet; fast engine only): each boundary edge adds a plane
  /// through it, standing on its triangle, to its ends' quadrics (weighted 100× a face's), so
  /// the outline keeps its shape where the sheet is flat. An edge on the boundary collapses
  /// when its ends share one neighbour; allowCollapse must keep boundary vertices on the
  /// boundary (never into an interior vertex).
  bool openBoundary = false;
  /// When set, a collapse of vertex `from` into its neighbour `to` (indices into the input)
  /// is refused unless allowCollapse(from, to) is true.
  std::function<bool(std::uint32_t from, std::uint32_t to)> allowCollapse;
  /// When set, the texture coordinates of a triangle's corners (vertex indices of the input):
  /// a collapse is refused when any triangle it changes would get corner coordinates that are
  /// not counter-clockwise (so a texture never folds over).
  std::function<std::array<Vec2f, 3>(const std::array<std::uint32_t, 3>& triangle)>
      cornerCoordinates;
};

struct CollapsedMesh {
  /// Closed, manifold, genus 0 when the input is; counter-clockwise as the input. Vertices
  /// keep their input positions (halfedge collapses move no vertex).
  TriangleMesh mesh;
  /// For each vertex of mesh, its index in the input.
  std::vector<std::uint32_t> inputVertex;
  /// For each triangle of mesh, the input triangle it is (with one or more corners moved by
  /// collapses): its normal is within maxNormalTurnDegrees of that triangle's.
  std::vector<std::uint32_t> inputTriangle;
};

/// OpenMesh's Decimater with its quadric module (priority and optional error bound) and one
/// binary module of ours checking normals, triangle shape, texture folds and the veto (see
/// VertexCollapseOptions). Collapses vertices by increasing quadric error until the target or the
/// error bound is met or no legal collapse is left. Collapses that would break the mesh's
/// manifoldness or genus (OpenMesh's link condition) are refused; so is any collapse into a
/// tetrahedron. Throws Error(InvalidArgument) when targetTriangles is 1 … 4, maxError < 0 or
/// maxNormalTurnDegrees is not in (0, 180], Error(InvalidInput) when the mesh is not closed
/// and edge-manifold.
CollapsedMesh collapseVertices(const TriangleMesh& mesh, const VertexCollapseOptions& options);

} // namespace octaclay::core
