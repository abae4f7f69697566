#include "octaclay/core/geometry/grid_point.h"

#include <cmath>

namespace octaclay::core {

GridPoint locateGridPoint(int n, double x, double y) {
  const double fi = std::floor(x), fj = std::floor(y);
  const int i = static_cast<int>(fi), j = static_cast<int>(fj);
  const double u = x - fi, v = y - fj;
  GridPoint p;
  auto set = [&](Sample a, Sample b, Sample c, double wa, double wb, double wc) {
    p.corners = {wrap(n, a), wrap(n, b), wrap(n, c)};
    p.weights = {static_cast<float>(wa), static_cast<float>(wb), static_cast<float>(wc)};
  };
  const Sample a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
  if (cellSplit(n, i, j) == CellSplit::AntiDiagonal) {
    if (u + v <= 1)
      set(a, b, d, 1 - u - v, u, v);
    else
      set(c, d, b, u + v - 1, 1 - u, 1 - v);
  } else if (u >= v) {
    set(a, b, c, 1 - u, u - v, v);
  } else {
    set(a, c, d, 1 - v, u, v - u);
  }
  return p;
}

GridPoint locateGridPoint(const SampleGrid& grid, double x, double y) {
  if (grid.topology == Topology::Octahedral) return locateGridPoint(grid.width, x, y);
  const double fi = std::floor(x), fj = std::floor(y);
  const int i = static_cast<int>(fi), j = static_cast<int>(fj);
  const double u = x - fi, v = y - fj;
  const Sample a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
  GridPoint p;
  if (u + v <= 1) {
    p.corners = {wrap(grid, a), wrap(grid, b), wrap(grid, d)};
    p.weights = {float(1 - u - v), float(u), float(v)};
  } else {
    p.corners = {wrap(grid, c), wrap(grid, d), wrap(grid, b)};
    p.weights = {float(u + v - 1), float(1 - u), float(1 - v)};
  }
  return p;
}

Vec3f interpolatePosition(const GeometryImage& image, const GridPoint& p) {
  Vec3f sum{0, 0, 0};
  for (std::size_t k = 0; k < 3; ++k)
    sum = sum + image.at(p.corners[k]).xyz() * p.weights[k];
  return sum;
}

} // namespace octaclay::core
