#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"

#include <vector>

namespace octaclay::core::detail {

// The texels of region in layer, row-major, editLayerChannels(layer) floats each.
inline std::vector<float> tileTexels(const Document& doc, EditLayer layer, TexelRect region) {
  const std::size_t ch = static_cast<std::size_t>(editLayerChannels(layer));
  std::vector<float> out(static_cast<std::size_t>(region.width) *
                         static_cast<std::size_t>(region.height) * ch);
  const std::size_t side = static_cast<std::size_t>(doc.size() + 1);
  std::size_t o = 0;
  for (int j = region.y; j < region.y + region.height; ++j)
    for (int i = region.x; i < region.x + region.width; ++i) {
      const std::size_t t = static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i);
      if (layer == EditLayer::Positions) {
        const Vec4f& p = doc.positions.at(i, j);
        out[o++] = p.x, out[o++] = p.y, out[o++] = p.z, out[o++] = p.w;
        continue;
      }
      const Layer& l = layer == EditLayer::Diffuse   ? doc.diffuse
                       : layer == EditLayer::Feature ? doc.feature
                                                     : doc.mask;
      for (std::size_t c = 0; c < ch; ++c)
        out[o++] = l.uniform() ? l.fill[c] : l.texels[t * ch + c];
    }
  return out;
}

// Whether resampling doc's layer at other points can change it: not when the layer is uniform
// (it resamples to its own fill) or an absent mask.
inline bool resamplingChanges(const Document& doc, EditLayer layer) {
  switch (layer) {
  case EditLayer::Positions:
    return true;
  case EditLayer::Diffuse:
    return !doc.diffuse.uniform();
  case EditLayer::Feature:
    return !doc.feature.uniform();
  case EditLayer::Mask:
    return doc.hasMask && !doc.mask.uniform();
  }
  return true;
}

} // namespace octaclay::core::detail
