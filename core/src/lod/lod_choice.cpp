// chooseLodMethod (lod.h): the image methods where the image samples a smooth surface evenly,
// the full-resolution collapse where it stretches (judged from a coarse copy of the image) or
// where the surface is rough sample to sample (judged from a sparse set of samples).
#include "detail/unit_scale.h"

#include "octaclay/core/lod/lod.h"
#include "octaclay/core/measure/stretch.h"

#include <algorithm>
#include <utility>
#include <vector>

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
  // A torus or plane has no adaptive hierarchy: its collapse (gridLod), wherever it stretches.
  if (image.topology() != Topology::Octahedral) return ResampleMethod::Collapse;
  if (const int e = detail::unitScaleExponent(image); e != 0)
    return chooseLodMethod(detail::scaledPositions(image, e), options);
  return imageStretches(coarseStretch(image)) || imageRoughness(image) > kSmoothRoughness
             ? ResampleMethod::Collapse
             : ResampleMethod::Adaptive;
}

double imageRoughness(const GeometryImage& image) {
  const int n = image.size(), far = 8, stride = std::max(far, n / 128);
  if (n < 4 * far) return 1;
  std::vector<double> nearBend, farBend;
  const auto bend = [&](int i, int j, int di, int dj) {
    const Vec3f a = image.at(i - di, j - dj).xyz(), b = image.at(i, j).xyz(),
                c = image.at(i + di, j + dj).xyz();
    const double chord = length(c - a);
    return chord > 0 ? double(length(a + c - b - b)) / chord : 0.0;
  };
  for (int j = far; j <= n - far; j += stride)
    for (int i = far; i <= n - far; i += stride)
      for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{0, 1}}) {
        nearBend.push_back(bend(i, j, di, dj));
        farBend.push_back(bend(i, j, far * di, far * dj));
      }
  const auto median = [](std::vector<double>& v) {
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  const double nearMedian = median(nearBend), farMedian = median(farBend);
  return farMedian > 0 ? far * nearMedian / farMedian : 1;
}

} // namespace octaclay::core
