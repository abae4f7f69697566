#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"

namespace octaclay::core {

/// The welded, closed mesh of the image sampled every `step` samples (step 1 = full
/// resolution, M = N/step): M²+2 vertices, 2M² triangles, outward orientation. Identified
/// samples become one vertex (the canonical sample's position is used; seam() first if they
/// may differ). Throws Error(InvalidArgument) when step is not a power of two or N/step < 2.
TriangleMesh extractMesh(const GeometryImage& image, int step = 1);

} // namespace octaclay::core
