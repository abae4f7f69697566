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
  /// the surface, the maximum over the incident triangles (so one stretched triangle is enough
  /// to flag its corners), divided by the surface's mean sample spacing.
  /// 1 where the sample is as spread as the average, 4 where it is four times as stretched.
  std::vector<float> stretch;
};

// Non-finite positions: a triangle with a non-finite corner (or whose area or stretch
// overflows a float) is skipped, as if it had no area; a texel whose incident triangles are
// all skipped has spacing 0 and stretch 0. Edges of non-finite length are left out of the
// summary; a vertex with a non-finite position is in neither part of a RegionSampling. Nothing
// throws. All of these run in O(N²) time on every hardware thread, with O(N²) memory.

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

/// Spacing and stretch of every texel. An empty image gives an empty map.
StretchMap measureStretch(const GeometryImage& image);
/// The summary of image's edges and spacings; all zero for an empty image.
/// A torus's or plane's: its W × H grid's edges along i and j and its mean spacing (measureStretch
/// and the per-sample figures are the ball's).
StretchSummary summarizeStretch(const GeometryImage& image);
/// √(surface area / (N² + 2)) (a torus's or plane's: over its own vertices):
/// StretchSummary::meanSpacing alone, what a stretch heat map
/// divides by.
double meanSpacing(const GeometryImage& image);

/// How a part of the surface (the vertices `inside` accepts, e.g. those farther than 1.5 from
/// the centre: a pulled limb) is sampled against the rest.
struct RegionSampling {
  std::size_t samples = 0;  ///< vertices inside (identified samples counted once)
  std::size_t vertices = 0; ///< all vertices, N² + 2
  double areaShare = 0;     ///< the region's share of the surface area
  double sampleShare = 0;   ///< samples ÷ vertices
  double fairShare = 0;     ///< sampleShare ÷ areaShare: 1 when evenly sampled (0: no area)
  double spacingRatio = 0;  ///< region's mean spacing ÷ the rest's (√(area per sample) each;
                            ///< 0 when either part is empty)
};

/// Vertex areas as in StretchMap; a vertex belongs to the region when inside(its position).
RegionSampling regionSampling(const GeometryImage& image,
                              const std::function<bool(const Vec3f&)>& inside);

} // namespace octaclay::core
