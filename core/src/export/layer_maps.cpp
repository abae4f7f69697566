// The painted layers as maps: a uniform layer gives a uniform map.

#include "export/layer_maps.h"

#include "export/sample_grid.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace octaclay::core::detail {

namespace {

float layerValue(const Layer& layer, std::size_t texel, int channel) {
  return layer.uniform() ? layer.fill[static_cast<std::size_t>(channel)]
                         : layer.texels[texel * static_cast<std::size_t>(layer.channels) +
                                        static_cast<std::size_t>(channel)];
}

// A full-resolution map: pixel (x, y) = value(texel index of layer sample (x, y)).
template <class Value> RasterImage makeMap(int n, int channels, Value&& value) {
  RasterImage map;
  map.width = map.height = n + 1;
  map.channels = channels;
  const std::size_t texels = static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
  map.pixels.resize(texels * static_cast<std::size_t>(channels));
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < channels; ++c)
      map.pixels[t * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] =
          value(t, c);
  return map;
}

// A map at resolution² texels over image coordinates: value(sample index, channel) blended
// bilinearly at each texel centre's position among the (N+1)² samples.
template <class Value>
RasterImage resampledMap(int n, int resolution, int channels, Value&& value) {
  if (resolution < 1)
    throw Error(ErrorKind::InvalidArgument,
                "cannot export a map of " + std::to_string(resolution) + " texels a side");
  RasterImage map;
  map.width = map.height = resolution;
  map.channels = channels;
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  const auto ch = static_cast<std::size_t>(channels);
  map.pixels.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution) *
                    ch);
  // Where texel x falls between samples: the sample below and the weight of the one above.
  std::vector<std::size_t> low(static_cast<std::size_t>(resolution));
  std::vector<float> weight(low.size());
  for (int x = 0; x < resolution; ++x) {
    const double at = (x + 0.5) * n / resolution;
    const double below = std::min(std::floor(at), static_cast<double>(n - 1));
    low[static_cast<std::size_t>(x)] = static_cast<std::size_t>(below);
    weight[static_cast<std::size_t>(x)] = static_cast<float>(at - below);
  }
  for (std::size_t y = 0; y < low.size(); ++y)
    for (std::size_t x = 0; x < low.size(); ++x) {
      const std::size_t s00 = low[y] * side + low[x];
      const float wx = weight[x], wy = weight[y];
      for (int c = 0; c < channels; ++c) {
        const float top = value(s00, c) * (1 - wx) + value(s00 + 1, c) * wx;
        const float bottom = value(s00 + side, c) * (1 - wx) + value(s00 + side + 1, c) * wx;
        map.pixels[(y * low.size() + x) * ch + static_cast<std::size_t>(c)] =
            top * (1 - wy) + bottom * wy;
      }
    }
  return map;
}

float metallicRoughness(const Document& doc, std::size_t t, int c) {
  if (c == 0) return 1.0f;
  if (c == 1) return 1.0f - layerValue(doc.feature, t, 1);
  return layerValue(doc.feature, t, 2);
}

} // namespace

RasterImage diffuseMap(const Document& doc) {
  return makeMap(doc.size(), 4,
                 [&](std::size_t t, int c) { return layerValue(doc.diffuse, t, c); });
}

RasterImage featureMap(const Document& doc, int channel) {
  return makeMap(doc.size(), 1,
                 [&](std::size_t t, int) { return layerValue(doc.feature, t, channel); });
}

RasterImage metallicRoughnessMap(const Document& doc) {
  return makeMap(doc.size(), 3, [&](std::size_t t, int c) { return metallicRoughness(doc, t, c); });
}

RasterImage diffuseMap(const Document& doc, int resolution) {
  requireLayer(doc.diffuse, doc.size());
  return resampledMap(doc.size(), resolution, 4,
                      [&](std::size_t t, int c) { return layerValue(doc.diffuse, t, c); });
}

RasterImage featureMap(const Document& doc, int channel, int resolution) {
  requireLayer(doc.feature, doc.size());
  return resampledMap(doc.size(), resolution, 1,
                      [&](std::size_t t, int) { return layerValue(doc.feature, t, channel); });
}

RasterImage metallicRoughnessMap(const Document& doc, int resolution) {
  requireLayer(doc.feature, doc.size());
  return resampledMap(doc.size(), resolution, 3,
                      [&](std::size_t t, int c) { return metallicRoughness(doc, t, c); });
}

} // namespace octaclay::core::detail
