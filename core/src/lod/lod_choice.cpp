// chooseLodMethod (lod.h): the image methods where the image samples the surface evenly, the
// full-resolution collapse where it stretches, judged from a coarse copy of the image.
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/measure/stretch.h"

#include <algorithm>

namespace octaclay::core {
namespace {

// The coarse copy's size: its edges are sums of full-resolution edges, so their ratios keep
// the image's stretch at 1/64 of the samples or fewer.
constexpr int kCoarseSize = 64;

} // namespace

StretchSummary coarseStretch(const GeometryImage& image) {
  const int n = image.size();
  const int m = std::min(kCoarseSize, n / 2);
  return m >= 2 ? summarizeStretch(resampleImage(image, m, ResampleMethod::Point))
                : summarizeStretch(image);
}

bool imageStretches(const StretchSummary& s) {
  return s.p99OverMedian > kEvenP99OverMedian || s.longestOverMedian > kEvenLongestOverMedian;
}

ResampleMethod chooseLodMethod(const GeometryImage& image, const LodOptions& options) {
  if (!options.autoMayCollapse) return ResampleMethod::SalientPoint;
  return imageStretches(coarseStretch(image)) ? ResampleMethod::Collapse : ResampleMethod::Adaptive;
}

} // namespace octaclay::core
