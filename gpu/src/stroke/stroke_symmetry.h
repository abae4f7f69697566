#pragma once

#include "octaclay/core/geometry/vec.h"

// Symmetry: a dab's mirror images through the model's centre, one per combination of the
// stroke's mirror planes (kSymmetryX, Y, Z bits).
namespace octaclay::gpu::detail {

/// p mirrored through centre across each plane in axes.
core::Vec3f mirrored(core::Vec3f p, core::Vec3f centre, unsigned axes);

} // namespace octaclay::gpu::detail
