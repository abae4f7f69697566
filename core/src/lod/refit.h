#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <vector>

namespace octaclay::core::detail {

/// Moves each vertex of `lod` along its normal so that the LOD surface fits the full-resolution
/// image in the least-squares sense. Each LOD triangle covers the full-resolution samples that
/// its corner image coordinates (cornerUv, one per triangle, (x / W, y / H), counter-clockwise,
/// tiling the image square) enclose; every `stride`-th sample (x, y) in each direction is compared
/// with the LOD surface at the same image coordinates (barycentric in its triangle), and
/// `iterations` Jacobi steps with the lumped hat-function mass move each vertex by
/// n·(Σ φ r)/(Σ φ), r the residual, φ the vertex's barycentric weight. Vertices sampled from
/// the surface leave their chords inside convex parts and outside concave ones; this centres
/// the chords on the surface.
/// With maxTurnDegrees > 0, a vertex with a triangle around it whose normal is more than that
/// from the vertex's averaged normal stays: least squares along an averaged normal pulls the
/// vertices of a sharp crease off it (14 dB lost on the fandisk at 1 %, bench_lod).
void refitToSurface(const GeometryImage& full, const std::vector<std::array<Vec2f, 3>>& cornerUv,
                    TriangleMesh& lod, int stride, int iterations, float maxTurnDegrees = 0);

} // namespace octaclay::core::detail
