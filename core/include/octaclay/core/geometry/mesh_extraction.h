#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"

namespace octaclay::core {

/// The welded, closed mesh of the image sampled every `step` samples (step 1 = full
/// resolution, M = N/step): M²+2 vertices, 2M² triangles, outward orientation. Identified
/// samples become one vertex (the canonical sample's position is used; seam() first if they
/// may differ). Throws Error(InvalidArgument) when step is not a power of two or N/step < 2.
/// A torus gives Mw·Mh vertices and 2·Mw·Mh triangles, closed, Euler characteristic 0 (column Mw
/// and row Mh are column and row 0; Mw, Mh ≥ 4); a plane (Mw+1)(Mh+1) vertices, 2·Mw·Mh
/// triangles and one boundary loop, Euler characteristic 1.
TriangleMesh extractMesh(const GeometryImage& image, int step = 1);

} // namespace octaclay::core
