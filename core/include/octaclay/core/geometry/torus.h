#pragma once

#include "octaclay/core/geometry/geometry_image.h"

namespace octaclay::core {

/// A ring around the z axis: a tube of radius `minor` whose centre line is the circle of radius
/// `major` in the z = 0 plane. The default fits in [-1, 1]³.
struct Torus {
  float major = 0.7f;
  float minor = 0.3f;
};

/// The height H of a torus image W samples around the ring whose cells are about square on the
/// surface: W · minor / major rounded to a power of two, at least kMinTorusSize (and never more
/// than W). A thin ring gets few samples around its tube, as many per unit length as along it.
int torusHeight(const Torus& torus, int width);

/// The torus sampled on a W × H torus image: sample (i, j) at angle 2πi/W around the ring and
/// 2πj/H around the tube, so the image is periodic in both directions; column W and row H repeat
/// column and row 0 exactly. Triangles face outward. Throws Error(InvalidArgument) for sizes that
/// are not a valid torus grid, or radii that are not finite with 0 < minor < major.
GeometryImage makeTorus(const Torus& torus, int width, int height);

/// Signed distance from p to the torus's surface (negative inside), exact.
float torusDistance(const Torus& torus, Vec3f p);

} // namespace octaclay::core
