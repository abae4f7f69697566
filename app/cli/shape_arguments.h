#pragma once

#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/torus.h"

#include <string>

namespace octaclay::app {

/// `--shape` as `new` and `add` take it: a base shape, torus, plane or disc. Throws
/// Error(InvalidArgument) for an unknown shape, and for capsule options (--radius, --length)
/// given to another shape.
void checkShapeArguments(const std::string& shape, bool capsuleOptionsGiven);

/// The image of shape at N = n: torusHeight 0 takes the height from the torus's radii. Throws
/// Error(InvalidArgument) for a torus smaller than core::kMinTorusSize, and what the makers
/// throw.
core::GeometryImage makeShapeImage(const std::string& shape, int n, const core::Capsule& capsule,
                                   const core::Torus& torus = {}, int torusHeight = 0);

} // namespace octaclay::app
