#include "octaclay/core/geometry/seaming.h"

#include <algorithm>

namespace octaclay::core {
namespace {

// Calls f(canonical sample) once for every vertex that has more than one sample.
template <class F> void forEachSeamVertex(int n, F&& f) {
  f(Sample{0, 0});
  for (int k = 1; k < n / 2; ++k) {
    f(Sample{0, k});
    f(Sample{n, k});
    f(Sample{k, 0});
    f(Sample{k, n});
  }
}

// The torus's: the corner, then each column-0 and row-0 sample with its twin across the image.
template <class F> void forEachTorusSeamVertex(const SampleGrid& grid, F&& f) {
  f(Sample{0, 0});
  for (int j = 1; j < grid.height; ++j)
    f(Sample{0, j});
  for (int i = 1; i < grid.width; ++i)
    f(Sample{i, 0});
}

// Calls f(canonical sample) once for every vertex of the image's topology that has more than
// one sample (none on a plane).
template <class F> void forEachSeamVertexOf(const SampleGrid& grid, F&& f) {
  if (grid.topology == Topology::Octahedral)
    forEachSeamVertex(grid.width, f);
  else if (grid.topology == Topology::Torus)
    forEachTorusSeamVertex(grid, f);
}

} // namespace

void seam(GeometryImage& image) {
  const SampleGrid& grid = image.grid();
  std::array<Sample, 4> same;
  forEachSeamVertexOf(grid, [&](Sample s) {
    const int count = identifiedSamples(grid, s, same);
    Vec4f sum{};
    for (int k = 0; k < count; ++k) {
      const Vec4f& t = image.at(same[k]);
      sum = {sum.x + t.x, sum.y + t.y, sum.z + t.z, sum.w + t.w};
    }
    const float inv = 1.0f / static_cast<float>(count);
    const Vec4f mean{sum.x * inv, sum.y * inv, sum.z * inv, sum.w * inv};
    for (int k = 0; k < count; ++k)
      image.at(same[k]) = mean;
  });
}

float maxSeamGap(const GeometryImage& image) {
  const SampleGrid& grid = image.grid();
  std::array<Sample, 4> same;
  float gap = 0;
  forEachSeamVertexOf(grid, [&](Sample s) {
    const int count = identifiedSamples(grid, s, same);
    for (int k = 1; k < count; ++k)
      gap = std::max(gap, length(image.at(same[k]).xyz() - image.at(same[0]).xyz()));
  });
  return gap;
}

} // namespace octaclay::core
