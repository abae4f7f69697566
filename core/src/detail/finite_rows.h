#pragma once

#include "octaclay/core/geometry/vec.h"

// A row of samples scanned in vector code for what every reader and `info` ask first.
namespace octaclay::core::detail {

/// How many of the count samples from row have a coordinate (x, y, z) that is not finite: a
/// count, not a flag, so the loop is vector code (an AVX2 copy is chosen at run time).
int nonFiniteSamples(const Vec4f* row, int count);

} // namespace octaclay::core::detail
