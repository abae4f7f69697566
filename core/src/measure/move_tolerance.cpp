#include "measure/move_tolerance.h"

#include <cstdio>

namespace octaclay::core::detail {
namespace {

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", 100 * fraction);
  return text;
}

std::string movedBy(double distance, const char* measure, double tolerance) {
  return "the surface would move by " + percent(distance) + " of the diagonal (" + measure +
         "; at most " + percent(tolerance) + ")";
}

} // namespace

std::string surfaceMovedTooFar(const SurfaceDistance& moved, double rmsTolerance,
                               double hausdorffTolerance) {
  if (moved.rms > rmsTolerance) return movedBy(moved.rms, "RMS", rmsTolerance);
  if (moved.hausdorff > hausdorffTolerance)
    return movedBy(moved.hausdorff, "Hausdorff", hausdorffTolerance);
  return {};
}

} // namespace octaclay::core::detail
