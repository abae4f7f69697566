#include "octaclay/core/geometry/capsule.h"

#include "detail/parallel_rows.h"
#include "geometry/octahedral_direction.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

namespace octaclay::core {
namespace {

// A number as a message shows it: 6 significant digits (0, 1e-09, nan), not to_string's 0.000000.
std::string number(float value) {
  std::ostringstream text;
  text << value;
  return text.str();
}

// The point of the capsule that the equal-area map sends the octahedron point o (|o|₁ = 1) to.
Vec3f capsulePoint(const Capsule& capsule, detail::Dir3d d) {
  const double l1 = std::abs(d.x) + std::abs(d.y) + std::abs(d.z);
  const double x = d.x / l1, y = d.y / l1, z = d.z / l1;
  const double s = std::clamp(std::abs(x) + std::abs(y), 0.0, 1.0); // the ring, 1 − |z|
  const double r = capsule.radius, h = 0.5 * double(capsule.length), top = h + r;
  const double height = std::copysign(top * (1.0 - s * s), z);
  const double beyond = std::max(std::abs(height) - h, 0.0); // into a hemisphere
  const double ring = std::sqrt(std::max(r * r - beyond * beyond, 0.0));
  if (s <= 0) return {0.0f, 0.0f, float(height)};
  // The position along the ring |x| + |y| = s, a quarter per quadrant, as an angle.
  const double t = std::abs(y) / s; // 0 on the x axis, 1 on the y axis
  double quarter = x >= 0 ? (y >= 0 ? t : 4.0 - t) : (y >= 0 ? 2.0 - t : 2.0 + t);
  const double angle = quarter * 0.5 * std::numbers::pi;
  return {float(ring * std::cos(angle)), float(ring * std::sin(angle)), float(height)};
}

} // namespace

GeometryImage makeCapsule(int n, const Capsule& capsule) {
  requireValidSize(n);
  if (!(std::isfinite(capsule.radius) && capsule.radius > 0))
    throw Error(ErrorKind::InvalidArgument,
                "a capsule's radius must be a finite number above 0, not " +
                    number(capsule.radius));
  if (!(std::isfinite(capsule.length) && capsule.length >= 0))
    throw Error(ErrorKind::InvalidArgument,
                "a capsule's length must be a finite number, 0 or more, not " +
                    number(capsule.length));
  GeometryImage image(n);
  const int side = image.side();
  detail::parallelRows(side, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i < side; ++i) {
        const Vec3f p = capsulePoint(capsule, detail::octahedralDirectionD(n, i, j));
        image.at(i, j) = {p.x, p.y, p.z, 0.0f};
      }
  });
  seam(image);
  return image;
}

float capsuleDistance(const Capsule& capsule, Vec3f p) {
  const double h = 0.5 * double(capsule.length);
  const double z = std::clamp(double(p.z), -h, h);
  const double dx = p.x, dy = p.y, dz = double(p.z) - z;
  return float(std::sqrt(dx * dx + dy * dy + dz * dz) - double(capsule.radius));
}

} // namespace octaclay::core
