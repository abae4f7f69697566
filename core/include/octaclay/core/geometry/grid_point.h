#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/sample_grid.h"

#include <array>

namespace octaclay::core {

/// A point of the octahedral plane as a blend of the three grid samples of the triangle it lies
/// in (the grid's own triangulation, so a blend of positions lies on the piecewise-linear
/// surface). Samples are wrapped into the grid.
struct GridPoint {
  std::array<Sample, 3> corners;
  std::array<float, 3> weights;
};

/// (x, y) in sample units of an N grid, anywhere in the tiled plane.
GridPoint locateGridPoint(int n, double x, double y);
/// The same on a grid of any topology: the torus's and plane's cells split along their
/// anti-diagonal, corners wrapped by the topology.
GridPoint locateGridPoint(const SampleGrid& grid, double x, double y);

/// image's position at p, interpolated linearly over its triangle.
Vec3f interpolatePosition(const GeometryImage& image, const GridPoint& p);

} // namespace octaclay::core
