#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstdint>

namespace octaclay::core {

struct SurfaceDistanceOptions {
  /// Points sampled on each surface (besides its vertices), area-weighted.
  std::size_t samplesPerSurface = 1'000'000;
  std::uint64_t seed = 1;
};

/// Symmetric point-to-surface distance between two meshes, as fractions of the bounding-box
/// diagonal of `a`. PSNR = 20·log10(1 / rms).
struct SurfaceDistance {
  double rms = 0;       ///< over the samples of both directions together
  double hausdorff = 0; ///< max over both directions
  double psnr = 0;      ///< dB; +inf when rms is 0
  double diagonal = 0;  ///< of a's bounding box, object units
  std::size_t samples = 0;
};

/// Samples each mesh's vertices and area-weighted random points and measures their distance
/// to the other mesh's triangles (an AABB tree answers the closest-point queries).
/// Throws Error(InvalidInput) when either mesh has no triangles.
SurfaceDistance compareSurfaces(const TriangleMesh& a, const TriangleMesh& b,
                                const SurfaceDistanceOptions& options = {});

} // namespace octaclay::core
