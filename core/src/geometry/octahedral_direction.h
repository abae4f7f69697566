// The double-precision direction behind octahedralDirection, for base shapes whose surface
// points are computed along it before rounding to float.
#pragma once

namespace octaclay::core::detail {

struct Dir3d {
  double x, y, z;
};

/// The unit octahedron direction of sample (i, j) of an N grid, in double precision.
Dir3d octahedralDirectionD(int n, int i, int j);

} // namespace octaclay::core::detail
