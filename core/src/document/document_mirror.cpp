#include "octaclay/core/document/document_mirror.h"

#include <utility>

namespace octaclay::core {

namespace {

// A layer of columns × rows texels transposed into rows × columns.
void transposeLayer(Layer& layer, int columns, int rows) {
  if (layer.uniform()) return;
  const std::size_t channels = static_cast<std::size_t>(layer.channels);
  std::vector<float> out(layer.texels.size());
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      const std::size_t from = (static_cast<std::size_t>(j) * columns + i) * channels;
      const std::size_t to = (static_cast<std::size_t>(i) * rows + j) * channels;
      for (std::size_t c = 0; c < channels; ++c)
        out[to + c] = layer.texels[from + c];
    }
  layer.texels = std::move(out);
}

} // namespace

Document mirrorDocument(const Document& document, int axis) {
  const GeometryImage& from = document.positions;
  const int columns = from.side(), rows = from.rows();
  Document result = document;
  result.positions = GeometryImage(from.topology(), from.height(), from.width());
  for (int j = 0; j < rows; ++j)
    for (int i = 0; i < columns; ++i) {
      Vec4f p = from.at(i, j);
      float& mirrored = axis == 0 ? p.x : axis == 1 ? p.y : p.z;
      mirrored = -mirrored;
      result.positions.at(j, i) = p;
    }
  for (Layer* layer : {&result.diffuse, &result.feature, &result.mask})
    transposeLayer(*layer, columns, rows);
  return result;
}

} // namespace octaclay::core
