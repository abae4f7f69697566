// The stretch summary and mean spacing of a torus or plane image (grid_stretch.h): its own
// W × H cells, whatever their shape, where the ball's figures read a square N grid.
#include "measure/grid_stretch.h"

#include "detail/parallel_rows.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace octaclay::core::detail {
namespace {

// Twice the area of cell (i, j)'s two triangles (a, b, d) and (b, c, d).
double twiceCellArea(const GeometryImage& image, int i, int j) {
  const Vec3f a = image.at(i, j).xyz(), b = image.at(i + 1, j).xyz(),
              c = image.at(i + 1, j + 1).xyz(), d = image.at(i, j + 1).xyz();
  return double(length(cross(b - a, d - a))) + double(length(cross(d - c, b - c)));
}

double surfaceArea(const GeometryImage& image) {
  std::vector<double> rows(static_cast<std::size_t>(image.height()), 0.0);
  parallelRows(image.height(), [&](int j0, int j1) {
    for (int j = j0; j < j1; ++j)
      for (int i = 0; i < image.width(); ++i)
        rows[static_cast<std::size_t>(j)] += 0.5 * twiceCellArea(image, i, j);
  });
  double total = 0;
  for (const double r : rows)
    total += r;
  return total;
}

} // namespace

double gridMeanSpacing(const GeometryImage& image) {
  const double vertices = double(vertexCount(image.topology(), image.width(), image.height()));
  return vertices > 0 ? std::sqrt(surfaceArea(image) / vertices) : 0.0;
}

StretchSummary summarizeGridStretch(const GeometryImage& image) {
  StretchSummary summary;
  std::vector<float> edges(2 * static_cast<std::size_t>(image.width()) *
                           static_cast<std::size_t>(image.height()));
  parallelRows(image.height(), [&](int j0, int j1) {
    for (int j = j0; j < j1; ++j)
      for (int i = 0; i < image.width(); ++i) {
        const Vec3f a = image.at(i, j).xyz();
        float* e = &edges[2 * (static_cast<std::size_t>(j) * image.width() + i)];
        e[0] = length(image.at(i + 1, j).xyz() - a);
        e[1] = length(image.at(i, j + 1).xyz() - a);
      }
  });
  if (edges.empty()) return summary;
  summary.longestEdge = *std::max_element(edges.begin(), edges.end());
  const double over4xOf = [&] {
    const auto k = static_cast<std::ptrdiff_t>(edges.size() / 2);
    std::nth_element(edges.begin(), edges.begin() + k, edges.end());
    return double(edges[static_cast<std::size_t>(k)]);
  }();
  summary.medianEdge = over4xOf;
  const auto k99 = static_cast<std::ptrdiff_t>(0.99 * double(edges.size() - 1));
  std::nth_element(edges.begin(), edges.begin() + k99, edges.end());
  if (summary.medianEdge > 0) {
    summary.longestOverMedian = summary.longestEdge / summary.medianEdge;
    summary.p99OverMedian = double(edges[static_cast<std::size_t>(k99)]) / summary.medianEdge;
    summary.shareOver4x =
        double(std::count_if(edges.begin(), edges.end(),
                             [&](float e) { return double(e) > 4 * summary.medianEdge; })) /
        double(edges.size());
  }
  summary.meanSpacing = gridMeanSpacing(image);
  return summary;
}

} // namespace octaclay::core::detail
