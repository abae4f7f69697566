#pragma once

// The one wording of "this result moved the surface too far", shared by every operation that
// checks its own result against a tolerance (Even Out, Remesh, Resize).

#include "octaclay/core/measure/surface_distance.h"

#include <string>

namespace octaclay::core::detail {

/// Why moved exceeds its tolerance, the RMS first: "the surface would move by 0.26 % of the
/// diagonal (Hausdorff; at most 0.2 %)"; empty when it is within both. Fractions of the
/// bounding-box diagonal.
std::string surfaceMovedTooFar(const SurfaceDistance& moved, double rmsTolerance,
                               double hausdorffTolerance);

} // namespace octaclay::core::detail
