#include "octaclay/core/document/document_mirror.h"

#include <utility>

namespace octaclay::core {

namespace {

void transposeLayer(Layer& layer, int side) {
  if (layer.uniform()) return;
  const std::size_t channels = static_cast<std::size_t>(layer.channels);
  std::vector<float> out(layer.texels.size());
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t from = (static_cast<std::size_t>(j) * side + i) * channels;
      const std::size_t to = (static_cast<std::size_t>(i) * side + j) * channels;
      for (std::size_t c = 0; c < channels; ++c)
        out[to + c] = layer.texels[from + c];
    }
  layer.texels = std::move(out);
}

} // namespace

Document mirrorDocument(const Document& document, int axis) {
  Document result = document;
  const int side = document.positions.side();
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      Vec4f p = document.positions.at(j, i);
      (axis == 0 ? p.x : axis == 1 ? p.y : p.z) = -(axis == 0 ? p.x : axis == 1 ? p.y : p.z);
      result.positions.at(i, j) = p;
    }
  for (Layer* layer : {&result.diffuse, &result.feature, &result.mask})
    transposeLayer(*layer, side);
  return result;
}

} // namespace octaclay::core
