#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/measure/stretch.h"

namespace octaclay::core::detail {

/// summarizeStretch of a torus or plane image (W × H cells): the median, longest and
/// 99th-percentile grid edge along i and j, the share of those over 4× the median, and the mean
/// spacing √(area / vertices) over the cells split along their anti-diagonal.
StretchSummary summarizeGridStretch(const GeometryImage& image);

/// meanSpacing of a torus or plane image: √(surface area / vertices).
double gridMeanSpacing(const GeometryImage& image);

} // namespace octaclay::core::detail
