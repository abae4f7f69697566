#include "octaclay/gpu/stroke_rules.h"

#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <cmath>

namespace octaclay::gpu {

float dabSpacing(const BrushManifest& brush, float spacing) {
  return std::max(spacing > 0 ? spacing : brush.spacing, kMinDabSpacing);
}

float dabShare(const BrushManifest& brush, float spacing) {
  if (brush.category != Category::Sculpt) return 1.0f;
  return std::clamp(dabSpacing(brush, spacing), kMinDabSpacing, 1.0f);
}

SurfacePoint surfacePointAt(int n, double x, double y) {
  const int i = std::clamp(static_cast<int>(std::floor(x)), 0, n - 1);
  const int j = std::clamp(static_cast<int>(std::floor(y)), 0, n - 1);
  const float fx = static_cast<float>(x - i), fy = static_cast<float>(y - j);
  const core::Sample a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
  // The same split as core::cellTriangles: (a, b, d) + (b, c, d) or (a, b, c) + (a, c, d).
  if (core::cellSplit(n, i, j) == core::CellSplit::AntiDiagonal) {
    if (fx + fy <= 1) return {{a, b, d}, {1 - fx - fy, fx, fy}};
    return {{b, c, d}, {1 - fy, fx + fy - 1, 1 - fx}};
  }
  if (fx >= fy) return {{a, b, c}, {1 - fx, fx - fy, fy}};
  return {{a, c, d}, {1 - fy, fx, fy - fx}};
}

core::Vec3f interpolatePosition(const core::GeometryImage& image, const SurfacePoint& p) {
  core::Vec3f sum;
  for (int k = 0; k < 3; ++k)
    sum += image.at(p.corners[k]).xyz() * p.weights[k];
  return sum;
}

core::Vec3f interpolateNormal(const core::GeometryImage& image, const SurfacePoint& p) {
  core::Vec3f sum;
  for (int k = 0; k < 3; ++k)
    sum += core::vertexNormal(image, p.corners[k]) * p.weights[k];
  if (core::length(sum) > 1e-6f) return core::normalize(sum);
  const auto nearest = std::max_element(p.weights.begin(), p.weights.end()) - p.weights.begin();
  return core::vertexNormal(image, p.corners[static_cast<std::size_t>(nearest)]);
}

} // namespace octaclay::gpu
