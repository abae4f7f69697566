#pragma once

#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

/// Makes identified samples equal again: each set of samples that are one vertex gets their
/// average (positions and saliency). Touches only the border of the image.
void seam(GeometryImage& image);

/// The largest distance between two samples identified with each other (0 when seamed).
float maxSeamGap(const GeometryImage& image);

} // namespace octaclay::core
