#pragma once

#include "octaclay/core/geometry/geometry_image.h"

#include <vector>

namespace octaclay::core {

/// The unit normal at any sample: area-weighted average of its incident triangles' normals,
/// read through wrap() so samples on the seams get their true mesh neighbourhood.
Vec3f vertexNormal(const GeometryImage& image, Sample s);

/// The unit normal at a sample from central differences of its four grid neighbours (read
/// through wrap()), as the GPU passes compute it: symmetric under the grid's turns, so a
/// symmetric tip gets its axis whatever its triangles' split; vertexNormal where the
/// differences are degenerate (a side midpoint, a collapsed neighbourhood).
Vec3f gridNormal(const GeometryImage& image, Sample s);

/// vertexNormal for every grid sample, row-major (N+1)².
std::vector<Vec3f> computeNormals(const GeometryImage& image);

} // namespace octaclay::core
