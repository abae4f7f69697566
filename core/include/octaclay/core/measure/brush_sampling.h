#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/vec.h"

#include <limits>

namespace octaclay::core {

/// Fewer samples than this across a brush's radius, in the sparsest direction, and the brush's
/// result is coarse: it moves a few samples far apart (the tip of a limb pulled far in one
/// stroke), so Inflate crumples into shards there. The modeller says so before the brush acts.
inline constexpr double kMinSamplesAcrossRadius = 3.0;

/// How a geometry image samples its surface where a brush lands (issue 30, item 1).
struct BrushSampling {
  /// The longest grid edge among the samples around the point, object units.
  double longestEdge = 0;
  /// radius ÷ longestEdge: about how many samples lie across the brush's radius in the
  /// sparsest direction there (+infinity when every edge there has length 0).
  double samplesAcross = std::numeric_limits<double>::infinity();
  bool sparse() const { return samplesAcross < kMinSamplesAcrossRadius; }
};

/// The sampling a brush of `radius` (object units, >= 0) meets at image point uv ((u, v) in
/// [0, 1], u along the image's columns; clamped): the grid edges (to the right and lower
/// neighbours, through the seams) of the samples within two samples of uv's nearest sample, the
/// longest of them, and the radius in units of it. A pure function of the positions: 25 samples
/// read, no allocation. Non-finite edges are left out.
BrushSampling brushSampling(const GeometryImage& image, Vec2f uv, double radius);

} // namespace octaclay::core
