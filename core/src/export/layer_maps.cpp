// The painted layers as maps: a uniform layer gives a uniform map.

#include "export/layer_maps.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cstdint>

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
  return makeMap(doc.size(), 3, [&](std::size_t t, int c) {
    if (c == 0) return 1.0f;
    if (c == 1) return 1.0f - layerValue(doc.feature, t, 1);
    return layerValue(doc.feature, t, 2);
  });
}

} // namespace octaclay::core::detail
