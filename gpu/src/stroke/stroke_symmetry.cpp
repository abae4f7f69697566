#include "stroke_symmetry.h"

#include "stroke_state.h"

#include <bit>

namespace octaclay::gpu {
namespace detail {

core::Vec3f mirrored(core::Vec3f p, core::Vec3f centre, unsigned axes) {
  if (axes & kSymmetryX) p.x = 2 * centre.x - p.x;
  if (axes & kSymmetryY) p.y = 2 * centre.y - p.y;
  if (axes & kSymmetryZ) p.z = 2 * centre.z - p.z;
  return p;
}

} // namespace detail

int StrokeSession::State::imagesPerDab() const {
  return 1 << std::popcount(settings.symmetry & 7u);
}

} // namespace octaclay::gpu
