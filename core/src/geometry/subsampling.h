#pragma once

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"

#include <string>

namespace octaclay::core::detail {

/// The grid size M = N/step of a subsampled image. Throws Error(InvalidArgument) unless step is
/// a power of two and M ≥ 2.
inline int subsampledSize(int n, int step) {
  requireValidSize(n);
  if (step < 1 || (step & (step - 1)) != 0 || n / step < kMinSize)
    throw Error(ErrorKind::InvalidArgument, "LOD step " + std::to_string(step) +
                                                " is invalid for size " + std::to_string(n) +
                                                ": use a power of two with N/step >= 2");
  return n / step;
}

} // namespace octaclay::core::detail
