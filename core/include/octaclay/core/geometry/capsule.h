#pragma once

#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

/// A capsule: a cylinder of radius `radius` whose axis runs along z from −length/2 to
/// +length/2, closed by two hemispheres of the same radius (so it spans length + 2·radius).
struct Capsule {
  float radius = 0.5f;
  float length = 1.0f; ///< of the cylinder between the hemispheres' centres; 0 is a sphere
};

/// The capsule sampled at (N+1)² with its samples spread evenly over its area, not a scaled
/// sphere: the grid's octahedron (|x| + |y| + |z| = 1, each face an affine image of a quarter of
/// the square, so every cell has the same area on it) is mapped onto the capsule by an
/// equal-area map. A ring |x| + |y| = s (the samples s·N/2 steps from the image's centre, or
/// from its corners for z < 0) goes to the height Z = ±H·(1 − s²), H = length/2 + radius (the
/// octahedron's area above that ring is s² of its half, and a capsule's area, like a sphere's
/// (Archimedes), grows evenly with the height along its axis); the position along the ring goes
/// to the angle around the axis. So every cell covers about the same area and the samples lie
/// evenly along the cylinder, as many per unit length in the middle as near the ends. Samples
/// lie exactly on the surface; seamed. The +z end is the image's centre, the −z end its corners.
/// Throws Error(InvalidArgument) for an invalid size, a radius that is not finite and > 0 or a
/// length that is not finite and ≥ 0.
GeometryImage makeCapsule(int n, const Capsule& capsule = {});

/// Signed distance from p to the capsule's surface (negative inside), exact.
float capsuleDistance(const Capsule& capsule, Vec3f p);

} // namespace octaclay::core
