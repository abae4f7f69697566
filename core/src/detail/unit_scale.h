#pragma once

// Work in the model's own units (issue 34): LOD (resampling, saliency, roughness, collapse,
// refit) and the wavelet codec's step search hold thresholds and float squares that assume a
// model about a unit across. A model far from that scale is worked on scaled by a power of two,
// which is exact in float, and the result is scaled back: a model x 1e13 gives the triangles
// and the error a model x 1 gives.

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"

namespace octaclay::core::detail {

/// e such that diagonal times 2^e lies in [1, 2), or 0 when it already lies within [1/256, 256]
/// (or is not a positive finite number).
int unitScaleExponent(double diagonal);
/// The same for the image's bounding-box diagonal.
int unitScaleExponent(const GeometryImage& image);

/// The image with x, y and z times 2^exponent (exact); w (saliency) as it was.
GeometryImage scaledPositions(const GeometryImage& image, int exponent);

/// mesh's positions times 2^exponent (exact).
void scaleMesh(TriangleMesh& mesh, int exponent);

} // namespace octaclay::core::detail
