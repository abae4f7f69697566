#pragma once

#include "octaclay/core/geometry_image.h"
#include "octaclay/core/triangle_mesh.h"
#include "octaclay/core/vertex_index.h"

namespace octaclay::core::detail {

/// Moves each vertex of the LOD mesh `lod` (extracted from an M grid numbered by `index`)
/// along its normal so that the piecewise-linear LOD surface fits the full-resolution image
/// in the least-squares sense: every full-resolution sample (x, y) (every `stride`-th in each
/// direction) is compared with the LOD surface at the same image coordinates (barycentric in
/// the LOD cell's triangle), and `iterations` Jacobi steps with the lumped hat-function mass
/// move each vertex by n·(Σ φ r)/(Σ φ), r the residual. Point sampling leaves the LOD's
/// chords inside convex parts; this centres them on the surface.
void refitToSurface(const GeometryImage& full, const VertexIndex& index, TriangleMesh& lod,
                    int stride, int iterations);

} // namespace octaclay::core::detail
