// The painted layers as maps: a uniform layer gives a uniform map.

#include "export/layer_maps.h"

#include "export/export_grid.h"

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

// A full-resolution map of (W+1)×(H+1) pixels: pixel (x, y) = value(texel index of layer
// sample (x, y)).
template <class Value> RasterImage makeMap(const SampleGrid& image, int channels, Value&& value) {
  RasterImage map;
  map.width = image.width + 1;
  map.height = image.height + 1;
  map.channels = channels;
  const std::size_t texels =
      static_cast<std::size_t>(map.width) * static_cast<std::size_t>(map.height);
  map.pixels.resize(texels * static_cast<std::size_t>(channels));
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < channels; ++c)
      map.pixels[t * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] =
          value(t, c);
  return map;
}

// Where each of `resolution` texels falls among `cells` + 1 samples: the sample below and the
// weight of the one above.
void texelCentres(int cells, int resolution, std::vector<std::size_t>& low,
                  std::vector<float>& weight) {
  low.resize(static_cast<std::size_t>(resolution));
  weight.resize(low.size());
  for (int x = 0; x < resolution; ++x) {
    const double at = (x + 0.5) * cells / resolution;
    const double below = std::min(std::floor(at), static_cast<double>(cells - 1));
    low[static_cast<std::size_t>(x)] = static_cast<std::size_t>(below);
    weight[static_cast<std::size_t>(x)] = static_cast<float>(at - below);
  }
}

// A map at resolution² texels over image coordinates: value(sample index, channel) blended
// bilinearly at each texel centre's position among the (W+1)×(H+1) samples.
template <class Value>
RasterImage resampledMap(const SampleGrid& image, int resolution, int channels, Value&& value) {
  if (resolution < 1)
    throw Error(ErrorKind::InvalidArgument,
                "cannot export a map of " + std::to_string(resolution) + " texels a side");
  RasterImage map;
  map.width = map.height = resolution;
  map.channels = channels;
  const std::size_t side = static_cast<std::size_t>(image.width) + 1;
  const auto ch = static_cast<std::size_t>(channels);
  map.pixels.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution) *
                    ch);
  std::vector<std::size_t> lowX, lowY;
  std::vector<float> weightX, weightY;
  texelCentres(image.width, resolution, lowX, weightX);
  texelCentres(image.height, resolution, lowY, weightY);
  for (std::size_t y = 0; y < lowY.size(); ++y)
    for (std::size_t x = 0; x < lowX.size(); ++x) {
      const std::size_t s00 = lowY[y] * side + lowX[x];
      const float wx = weightX[x], wy = weightY[y];
      for (int c = 0; c < channels; ++c) {
        const float top = value(s00, c) * (1 - wx) + value(s00 + 1, c) * wx;
        const float bottom = value(s00 + side, c) * (1 - wx) + value(s00 + side + 1, c) * wx;
        map.pixels[(y * lowX.size() + x) * ch + static_cast<std::size_t>(c)] =
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
  return makeMap(doc.positions.grid(), 4,
                 [&](std::size_t t, int c) { return layerValue(doc.diffuse, t, c); });
}

RasterImage featureMap(const Document& doc, int channel) {
  return makeMap(doc.positions.grid(), 1,
                 [&](std::size_t t, int) { return layerValue(doc.feature, t, channel); });
}

RasterImage metallicRoughnessMap(const Document& doc) {
  return makeMap(doc.positions.grid(), 3,
                 [&](std::size_t t, int c) { return metallicRoughness(doc, t, c); });
}

RasterImage diffuseMap(const Document& doc, int resolution) {
  requireLayer(doc.diffuse, doc.positions.grid());
  return resampledMap(doc.positions.grid(), resolution, 4,
                      [&](std::size_t t, int c) { return layerValue(doc.diffuse, t, c); });
}

RasterImage featureMap(const Document& doc, int channel, int resolution) {
  requireLayer(doc.feature, doc.positions.grid());
  return resampledMap(doc.positions.grid(), resolution, 1,
                      [&](std::size_t t, int) { return layerValue(doc.feature, t, channel); });
}

RasterImage metallicRoughnessMap(const Document& doc, int resolution) {
  requireLayer(doc.feature, doc.positions.grid());
  return resampledMap(doc.positions.grid(), resolution, 3,
                      [&](std::size_t t, int c) { return metallicRoughness(doc, t, c); });
}

} // namespace octaclay::core::detail
