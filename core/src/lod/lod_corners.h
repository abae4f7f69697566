#pragma once

// What the ball's and the grid topologies' LODs share: each vertex's copies in the image, the
// corner coordinates of a triangle chosen from them, the collapse's options from an LOD's, the
// collapsed mesh's corner coordinates, the saliency weights and the refit's effort.

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/vertex_collapse.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

// The collapse method's refit leaves crease vertices (a triangle turned over 45° from their
// normal) alone: on the fandisk at 1 % of 2N², 71 dB with them moved, 84 dB with them kept;
// the armadillo keeps most of its refit gain (60.7 dB unrefit, 62.6 dB; bench_lod).
inline constexpr float kCollapseRefitCreaseDegrees = 45;
// The collapse method bounds each collapse's normal turn by 90° against the triangle before it
// (no fold) rather than 60° against the input triangle: the scorpion at 1 % of 2N² stopped at
// 7044 triangles, 18.9 dB below meshopt_simplify, and reaches 5242, 0.2 dB above it (bench_lod).
inline constexpr float kCollapseNormalTurnDegrees = 90;

/// For each vertex, the image coordinates of its copies (1, 2 or 4: a seam's or a torus wrap
/// line's twins), each (x / W, y / H) of the full image.
struct VertexCopies {
  std::array<Vec2f, 4> uv;
  int count = 0;
};

/// Per triangle, the copies of its corners that lie together: the combination with the
/// smallest perimeter² sum in the image.
std::array<Vec2f, 3> cornerCoordinates(const std::array<std::uint32_t, 3>& tri,
                                       const std::vector<VertexCopies>& copies);

/// The collapse's options from the LOD's (target, error bound, engine, turn and shape bounds),
/// corner coordinates from `copies`; the caller adds its seam veto.
VertexCollapseOptions collapseOptionsFor(const LodOptions& options,
                                         const std::vector<VertexCopies>& copies,
                                         bool normalTurnPerCollapse,
                                         std::vector<float> vertexWeights);

/// The collapsed mesh into lod, each triangle's corner coordinates from its vertices' copies.
void takeCollapsed(LodMesh& lod, CollapsedMesh collapsed, const std::vector<VertexCopies>& copies);

/// Every triangle of lod.mesh its corner coordinates (no collapse).
void setCornerCoordinates(LodMesh& lod, const std::vector<VertexCopies>& copies);

/// Per vertex (at sample sampleOf[v]), 1 + weight × its saliency; none when weight is 0 or the
/// image carries no saliency.
std::vector<float> saliencyWeights(const GeometryImage& image, const std::vector<Sample>& sampleOf,
                                   float weight);

/// The refit's Jacobi steps and sample stride for an LOD of `triangles` over `cells` image
/// cells (N² on the ball, W·H on a torus or plane).
int refitIterations(double cells, std::size_t triangles);
int refitStride(double cells, std::size_t triangles);

} // namespace octaclay::core::detail
