#pragma once

#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

/// A cheap guess at which way a model faces about its up axis (+y), for the first view of an
/// imported or opened model. A face or a head carries more detail than a back, so the surface's
/// saliency (computed on the image at N = 128 at most) pulls its weighted centre towards the
/// front: returns the horizontal unit direction (y = 0) from the area-weighted centre towards
/// the saliency-weighted one, snapped to the nearest axis (a diagonal within 15° of one), or +z
/// (the default front) when that pull is under 8 % of the surface's horizontal spread (a sphere, a
/// symmetric part). A torus or plane image: +z.
Vec3f guessFacing(const GeometryImage& image);

} // namespace octaclay::core
