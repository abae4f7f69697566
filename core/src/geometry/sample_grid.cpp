#include "octaclay/core/geometry/sample_grid.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <string>

namespace octaclay::core {
namespace {

int floorMod(int a, int m) {
  const int r = a % m;
  return r < 0 ? r + m : r;
}

bool insideCells(const SampleGrid& grid, int i, int j) {
  return i >= 0 && j >= 0 && i < grid.width && j < grid.height;
}

} // namespace

bool isValidGrid(const SampleGrid& grid) {
  if (!isValidSize(grid.width) || !isValidSize(grid.height)) return false;
  switch (grid.topology) {
  case Topology::Octahedral:
    return grid.width == grid.height;
  case Topology::Torus:
    return grid.width >= kMinTorusSize && grid.height >= kMinTorusSize;
  case Topology::Plane:
    return true;
  }
  return false;
}

void requireValidGrid(const SampleGrid& grid) {
  if (isValidGrid(grid)) return;
  throw Error(ErrorKind::InvalidArgument, "invalid " + std::string(topologyName(grid.topology)) +
                                              " image size " + std::to_string(grid.width) + "x" +
                                              std::to_string(grid.height) +
                                              " (powers of two from 2 to 8192" +
                                              (grid.topology == Topology::Octahedral ? ", square"
                                               : grid.topology == Topology::Torus ? ", at least 4"
                                                                                  : "") +
                                              ")");
}

Sample wrap(const SampleGrid& grid, Sample s) {
  switch (grid.topology) {
  case Topology::Torus:
    return {floorMod(s.i, grid.width), floorMod(s.j, grid.height)};
  case Topology::Plane:
    return {std::clamp(s.i, 0, grid.width), std::clamp(s.j, 0, grid.height)};
  case Topology::Octahedral:
    break;
  }
  return wrap(grid.width, s);
}

int identifiedSamples(const SampleGrid& grid, Sample s, std::array<Sample, 4>& out) {
  switch (grid.topology) {
  case Topology::Torus: {
    // Column W is column 0 and row H is row 0: a border sample has its twin across the image,
    // a corner the other three corners.
    const int w = grid.width, h = grid.height;
    const bool sideI = s.i == 0 || s.i == w, sideJ = s.j == 0 || s.j == h;
    if (sideI && sideJ) {
      out = {Sample{0, 0}, Sample{w, 0}, Sample{0, h}, Sample{w, h}};
      return 4;
    }
    out[0] = s;
    if (sideI) {
      out[1] = {w - s.i, s.j};
      return 2;
    }
    if (sideJ) {
      out[1] = {s.i, h - s.j};
      return 2;
    }
    return 1;
  }
  case Topology::Plane:
    out[0] = s;
    return 1;
  case Topology::Octahedral:
    break;
  }
  return identifiedSamples(grid.width, s, out);
}

std::array<std::array<Sample, 3>, 2> cellTriangles(const SampleGrid& grid, int i, int j) {
  if (grid.topology == Topology::Octahedral) return cellTriangles(grid.width, i, j);
  const Sample a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
  return {{{a, b, d}, {b, c, d}}};
}

int incidentTriangles(const SampleGrid& grid, Sample s, std::array<std::array<Sample, 3>, 6>& out) {
  if (grid.topology == Topology::Octahedral) return incidentTriangles(grid.width, s, out);
  int count = 0;
  for (int dj = -1; dj <= 0; ++dj)
    for (int di = -1; di <= 0; ++di) {
      if (grid.topology == Topology::Plane && !insideCells(grid, s.i + di, s.j + dj)) continue;
      for (const auto& tri : cellTriangles(grid, s.i + di, s.j + dj))
        for (int k = 0; k < 3; ++k)
          if (tri[k] == s) out[count++] = {tri[k], tri[(k + 1) % 3], tri[(k + 2) % 3]};
    }
  return count;
}

long long vertexCount(Topology topology, int cellsWide, int cellsHigh) {
  const long long w = cellsWide, h = cellsHigh;
  switch (topology) {
  case Topology::Torus:
    return w * h;
  case Topology::Plane:
    return (w + 1) * (h + 1);
  case Topology::Octahedral:
    break;
  }
  return w * w + 2;
}

} // namespace octaclay::core
