#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstdint>
#include <limits>

namespace octaclay::core {

struct SurfaceDistanceOptions {
  /// Points sampled on each surface (besides its vertices), area-weighted.
  std::size_t samplesPerSurface = 1'000'000;
  /// At most this many of each surface's vertices are measured (every k-th, spread over it):
  /// a check over a large region need not query all of them.
  std::size_t maxVertices = std::numeric_limits<std::size_t>::max();
  std::uint64_t seed = 1;
  /// Work bound per closest-point query, in tree leaves (4 triangles each): a smooth surface
  /// needs a few; a self-intersecting tangle would need the whole tree for every query.
  std::uint32_t leavesPerQuery = 256;
  /// Work bound for the whole comparison, in tree leaves: when a pilot over a spread subset of
  /// the queries says they would visit more, only every k-th sample is measured (stride), so
  /// a tangle reports in seconds; smooth surfaces stay far below it and measure every sample.
  std::uint64_t leafBudget = 20'000'000;
};

/// Symmetric point-to-surface distance between two meshes, as fractions of the bounding-box
/// diagonal of `a`. PSNR = 20·log10(1 / rms).
struct SurfaceDistance {
  double rms = 0;       ///< over the samples of both directions together
  double hausdorff = 0; ///< max over both directions
  double psnr = 0;      ///< dB; +inf when rms is 0
  double diagonal = 0;  ///< of a's bounding box, object units
  std::size_t samples = 0;
  /// Queries that stopped at leavesPerQuery: their distances are upper bounds, so rms and
  /// hausdorff are too (never below the truth). 0: every figure is exact for its samples.
  std::size_t boundedQueries = 0;
  /// Every stride-th sample was measured (1: all of them; more when leafBudget bit). samples
  /// counts the ones measured.
  std::size_t stride = 1;
};

/// Samples each mesh's vertices and area-weighted random points and measures their distance
/// to the other mesh's triangles (an AABB tree answers the closest-point queries, each within
/// options.leavesPerQuery, so the cost is at most linear in the samples whatever the meshes).
/// Throws Error(InvalidInput) when either mesh has no triangles.
SurfaceDistance compareSurfaces(const TriangleMesh& a, const TriangleMesh& b,
                                const SurfaceDistanceOptions& options = {});

} // namespace octaclay::core
