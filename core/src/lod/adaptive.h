#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace octaclay::core::detail {

/// A triangulation whose vertices are samples of the full image, dense where the surface bends
/// and sparse where it is flat: the right-triangle hierarchy (RTIN) over the octahedral image.
/// Its eight roots are the octahedron's faces (each quadrant halved by its anti-diagonal); a
/// triangle splits at its hypotenuse's midpoint sample, down to half cells. Every sample gets an
/// error: the largest over it and every sample whose split depends on it of its distance from
/// the plane of a triangle it splits, shared by identified samples, so keeping every sample
/// whose error is above a threshold yields a closed, conforming mesh (each kept sample's
/// parents are kept, on both sides of each seam). With a triangle target the distances are
/// weighted by √(2 · the triangle's area) (the least squared error for the count) and the
/// threshold keeps targetTriangles (= 2V − 4) or, where errors tie, the nearest count below;
/// with maxError > 0 (object units) they are plain distances and no sample within maxError of
/// its planes is kept.
struct AdaptiveTriangulation {
  TriangleMesh mesh; ///< welded (identified samples are one vertex), counter-clockwise outside
  /// Per triangle, its corners' image coordinates (x / N, y / N): every triangle lies in the
  /// image square, counter-clockwise, and together they tile it once.
  std::vector<std::array<Vec2f, 3>> cornerUv;
  /// Per vertex, the canonical sample it is.
  std::vector<Sample> vertexSample;
};

AdaptiveTriangulation adaptiveTriangulation(const GeometryImage& image, std::size_t targetTriangles,
                                            double maxError);

} // namespace octaclay::core::detail
