#include "codecs/wavelet_quantizer.h"

#include "codecs/wavelet_bands.h"
#include "codecs/wavelet_transform.h"
#include "octaclay/core/octahedral.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace octaclay::core::detail {
namespace {

void setCorners(std::span<float> plane, int n, float value) {
  const auto w = static_cast<std::size_t>(n) + 1;
  plane[0] = plane[static_cast<std::size_t>(n)] = value;
  plane[static_cast<std::size_t>(n) * w] =
      plane[static_cast<std::size_t>(n) * w + static_cast<std::size_t>(n)] = value;
}

} // namespace

void quantizePlane(std::span<const float> coefficients, int n, float step,
                   std::span<std::int32_t> q) {
  const float inverse = 1.0f / step;
  for (std::size_t k = 0; k < coefficients.size(); ++k) {
    const float c = coefficients[k];
    const float magnitude = std::min(std::floor(std::abs(c) * inverse + kRoundingOffset),
                                     static_cast<float>(kMaxMagnitude - 1));
    const auto m = static_cast<std::int32_t>(magnitude);
    q[k] = c < 0 ? -m : m;
  }
  const auto w = static_cast<std::size_t>(n) + 1;
  q[0] = q[static_cast<std::size_t>(n)] = 0;
  q[static_cast<std::size_t>(n) * w] =
      q[static_cast<std::size_t>(n) * w + static_cast<std::size_t>(n)] = 0;
}

void reconstructPlane(std::span<const std::int32_t> q, int n, const ChannelCoding& coding,
                      std::span<float> out) {
  const float step = coding.step;
  for (std::size_t k = 0; k < q.size(); ++k) {
    const std::int32_t v = q[k];
    const float magnitude =
        v == 0 ? 0.0f : (static_cast<float>(std::abs(v)) + kReconstructionOffset) * step;
    out[k] = v < 0 ? -magnitude : magnitude;
  }
  setCorners(out, n, coding.dc);
  inverseWavelet(out, n);
  for (float& v : out)
    v += coding.centre;
  // The transform keeps identified samples equal, but make it so whatever the float rounding.
  const auto w = static_cast<std::size_t>(n) + 1;
  const auto copyFrom = [&](int i, int j) {
    std::array<Sample, 4> copies;
    const int count = identifiedSamples(n, {i, j}, copies);
    const float value = out[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)];
    for (int k = 1; k < count; ++k)
      out[static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].j) * w +
          static_cast<std::size_t>(copies[static_cast<std::size_t>(k)].i)] = value;
  };
  copyFrom(0, 0);
  for (int t = 1; t < n / 2 + 1; ++t) {
    if (2 * t == n) continue;
    copyFrom(t, 0);
    copyFrom(t, n);
    copyFrom(0, t);
    copyFrom(n, t);
  }
}

} // namespace octaclay::core::detail
