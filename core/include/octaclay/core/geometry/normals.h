#pragma once

#include "octaclay/core/geometry/geometry_image.h"

#include <vector>

namespace octaclay::core {

/// The unit normal at any sample: area-weighted average of its incident triangles' normals,
/// read through wrap() so samples on the seams get their true mesh neighbourhood.
Vec3f vertexNormal(const GeometryImage& image, Sample s);

/// vertexNormal for every grid sample, row-major (N+1)².
std::vector<Vec3f> computeNormals(const GeometryImage& image);

} // namespace octaclay::core
