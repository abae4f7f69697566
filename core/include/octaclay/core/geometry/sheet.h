#pragma once

#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

/// The open sheets a plane-topology document starts from, both in the z = 0 plane, facing +z.
enum class Sheet {
  Square, ///< [-1, 1]², samples on a regular grid
  Disc, ///< the unit disc: the square mapped onto it (x√(1 − y²/2), y√(1 − x²/2)), so its
        ///< boundary samples lie on the circle
};

/// The sheet sampled on an N × N plane image. Throws Error(InvalidArgument) for an invalid size.
GeometryImage makeSheet(Sheet sheet, int n);

} // namespace octaclay::core
