#pragma once

#include "octaclay/core/geometry/geometry_image.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace octaclay::core {

/// How evenly a geometry image's samples cover its surface (DESIGN.md, "Stretch").
struct StretchMap {
  int n = 0;
  /// Per texel, (N+1)² row-major: √(area around the sample), the area being a third of its
  /// incident triangles' (identified texels share one vertex and hold the same value).
  std::vector<float> spacing;
  /// Per texel: the largest singular value of the Jacobian from the image (one sample step) to
  /// the surface over the incident triangles, divided by the surface's mean sample spacing.
  /// 1 where the sample is as spread as the average, 4 where it is four times as stretched.
  std::vector<float> stretch;
};

/// The summary figures `octaclay-cli info` reports. Edges are the grid edges to the right and
/// down neighbours in the (N+1)² image.
struct StretchSummary {
  double medianEdge = 0;
  double longestEdge = 0;
  double longestOverMedian = 0; ///< longest edge ÷ median edge
  double p99OverMedian = 0;     ///< 99th-percentile edge ÷ median edge
  double shareOver4x = 0;       ///< fraction of samples whose spacing exceeds 4× the median
  double meanSpacing = 0;       ///< √(surface area / vertices)
};

StretchMap measureStretch(const GeometryImage& image);
StretchSummary summarizeStretch(const GeometryImage& image);

/// How a part of the surface (the vertices `inside` accepts, e.g. those farther than 1.5 from
/// the centre: a pulled limb) is sampled against the rest.
struct RegionSampling {
  std::size_t samples = 0;   ///< vertices inside (identified samples counted once)
  std::size_t vertices = 0;  ///< all vertices, N² + 2
  double areaShare = 0;      ///< the region's share of the surface area
  double sampleShare = 0;    ///< samples ÷ vertices
  double fairShare = 0;      ///< sampleShare ÷ areaShare: 1 when evenly sampled
  double spacingRatio = 0;   ///< region's mean spacing ÷ the rest's (√(area per sample) each)
};

/// Vertex areas as in StretchMap; a vertex belongs to the region when inside(its position).
RegionSampling regionSampling(const GeometryImage& image,
                              const std::function<bool(const Vec3f&)>& inside);

} // namespace octaclay::core
