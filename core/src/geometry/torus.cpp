#include "octaclay/core/geometry/torus.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace octaclay::core {
namespace {

void requireTorus(const Torus& torus) {
  if (!(std::isfinite(torus.major) && std::isfinite(torus.minor) && torus.minor > 0 &&
        torus.minor < torus.major))
    throw Error(ErrorKind::InvalidArgument,
                "a torus needs finite radii with 0 < minor < major (got major " +
                    std::to_string(torus.major) + ", minor " + std::to_string(torus.minor) + ")");
}

} // namespace

int torusHeight(const Torus& torus, int width) {
  requireTorus(torus);
  const double wanted = double(width) * torus.minor / torus.major;
  int height = kMinTorusSize;
  while (height < width && double(height) * std::numbers::sqrt2 < wanted)
    height *= 2;
  return std::min(height, std::max(width, kMinTorusSize));
}

GeometryImage makeTorus(const Torus& torus, int width, int height) {
  requireTorus(torus);
  GeometryImage image(Topology::Torus, width, height);
  const double major = torus.major, minor = torus.minor;
  for (int j = 0; j <= height; ++j) {
    // Row H and column W are computed at angle 0, so they equal row and column 0 bit for bit.
    const double phi = 2.0 * std::numbers::pi * double(j % height) / double(height);
    const double ring = major + minor * std::cos(phi), z = minor * std::sin(phi);
    for (int i = 0; i <= width; ++i) {
      const double theta = 2.0 * std::numbers::pi * double(i % width) / double(width);
      image.at(i, j) = {float(ring * std::cos(theta)), float(ring * std::sin(theta)), float(z),
                        0.0f};
    }
  }
  return image;
}

float torusDistance(const Torus& torus, Vec3f p) {
  return float(std::hypot(std::hypot(double(p.x), double(p.y)) - torus.major, double(p.z)) -
               torus.minor);
}

} // namespace octaclay::core
