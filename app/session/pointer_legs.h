#pragma once

// A pointer's move on the image, as the stroke walks it. Consecutive picks under a pointer lie
// close together on the surface, so a jump of their image points crosses a seam, walked to the
// edge and continued from its other side (the same surface points): a torus's wrap the short
// way, the ball's border where it folds ((u, 0) is (1 − u, 0), …). Walking the straight image
// segment instead dabbed across the image, far from the pointer.

#include "octaclay/core/geometry/topology.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/gpu/stroke.h"

#include <array>
#include <optional>
#include <vector>

namespace octaclay::app {

/// One leg: the stroke continues from `from` (when jumped: the same surface point as where the
/// last leg ended, or a seam's other side) without a dab, then walks to `to`.
struct PointerLeg {
  bool jumped = false;
  core::Vec2f from, to; ///< image points (u, v) in [0, 1]
};

/// The legs of a pointer's move from image point a to b on an image of the topology: one plain
/// leg unless it crosses a seam. On the ball, a move of more than a quarter of the image along
/// u or v crosses the border edge across which b lies nearest a, or, near none, is a jump.
std::vector<PointerLeg> pointerLegs(core::Topology topology, core::Vec2f a, core::Vec2f b);

/// Walks the stroke to image point b: along pointerLegs from the last pointer point when there
/// is one, else (the first point, or a path's point) straight; returns the dabs made.
int walkPointer(gpu::StrokeSession& stroke, core::Topology topology,
                std::optional<std::array<float, 2>> last, core::Vec2f b, float radius,
                float strength);

} // namespace octaclay::app
