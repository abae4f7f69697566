#pragma once

// Per-channel range figures the lossy codecs scale their quantizers and bounds by.

#include "octaclay/core/codec/codec.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace octaclay::core::detail {

struct ChannelRange {
  float min = 0, max = 0;
  float span() const { return max - min; }
  float largestMagnitude() const { return std::max(std::abs(min), std::abs(max)); }
};

inline std::vector<ChannelRange> channelRanges(const FloatImage& image) {
  std::vector<ChannelRange> ranges(image.channels);
  const std::size_t c = static_cast<std::size_t>(image.channels);
  for (std::size_t k = 0; k < c && k < image.texels.size(); ++k)
    ranges[k] = {image.texels[k], image.texels[k]};
  for (std::size_t k = 0; k < image.texels.size(); ++k) {
    ChannelRange& r = ranges[k % c];
    r.min = std::min(r.min, image.texels[k]);
    r.max = std::max(r.max, image.texels[k]);
  }
  return ranges;
}

/// Copies channel c of an interleaved image into its own plane.
inline std::vector<float> channelPlane(const FloatImage& image, int c) {
  const std::size_t count = image.texels.size() / image.channels;
  std::vector<float> plane(count);
  for (std::size_t k = 0; k < count; ++k)
    plane[k] = image.texels[k * image.channels + c];
  return plane;
}

} // namespace octaclay::core::detail
