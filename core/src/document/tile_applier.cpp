// TileAppliers that write an edit history's texels back into CPU images: bits copied as they
// are, after checking that the region fits the image.

#include "document/edit_checks.h"

#include "octaclay/core/document/edit_history.h"

#include <algorithm>
#include <cstring>
#include <string>

namespace octaclay::core {

using detail::editLayerName;
using detail::invalidEdit;
using detail::texelArea;

namespace {

// Checks that region lies inside an image of side texels a row and `rows` rows (a torus's or
// plane's W+1 × H+1) and texels holds it with `channels` floats per texel.
void checkRegion(TexelRect region, int side, int rows, int channels, std::size_t floats) {
  if (region.width <= 0 || region.height <= 0 || region.x < 0 || region.y < 0 ||
      region.x > side - region.width || region.y > rows - region.height)
    invalidEdit("edit history: region (" + std::to_string(region.x) + ", " +
                std::to_string(region.y) + ") " + std::to_string(region.width) + "x" +
                std::to_string(region.height) + " is outside the " + std::to_string(side) + "x" +
                std::to_string(rows) +
                " image; apply strokes only to the image they were recorded on");
  if (floats != texelArea(region) * static_cast<std::size_t>(channels))
    invalidEdit("edit history: " + std::to_string(floats) + " floats given for a region of " +
                std::to_string(texelArea(region)) + " texels with " + std::to_string(channels) +
                " channels");
}

// Copies a row-major region of texels into a row-major image side texels wide of `channels` floats
// per texel, bits as they are.
void writeRegion(float* image, int side, int channels, TexelRect region,
                 std::span<const float> texels) {
  const std::size_t c = static_cast<std::size_t>(channels);
  const std::size_t rowFloats = static_cast<std::size_t>(region.width) * c;
  for (int row = 0; row < region.height; ++row) {
    const std::size_t dst =
        (static_cast<std::size_t>(region.y + row) * static_cast<std::size_t>(side) +
         static_cast<std::size_t>(region.x)) *
        c;
    std::memcpy(image + dst, texels.data() + static_cast<std::size_t>(row) * rowFloats,
                rowFloats * sizeof(float));
  }
}

} // namespace

TileApplier applierFor(GeometryImage& image) {
  return [&image](EditLayer layer, TexelRect region, std::span<const float> texels) {
    if (layer != EditLayer::Positions)
      invalidEdit(std::string("applierFor(GeometryImage&): cannot write the ") +
                  editLayerName(layer) + " layer into a position image; use applierFor(Document&)");
    checkRegion(region, image.side(), image.rows(), 4, texels.size());
    static_assert(sizeof(Vec4f) == 4 * sizeof(float));
    writeRegion(reinterpret_cast<float*>(image.texels().data()), image.side(), 4, region, texels);
  };
}

TileApplier applierFor(Document& doc) {
  return [&doc](EditLayer layer, TexelRect region, std::span<const float> texels) {
    if (layer == EditLayer::Positions) {
      applierFor(doc.positions)(layer, region, texels);
      return;
    }
    Layer& target = layer == EditLayer::Diffuse   ? doc.diffuse
                    : layer == EditLayer::Feature ? doc.feature
                                                  : doc.mask;
    const int side = doc.positions.side(), rows = doc.positions.rows();
    const int c = editLayerChannels(layer);
    if (target.channels != c)
      invalidEdit("applierFor(Document&): the document's " + target.name + " layer has " +
                  std::to_string(target.channels) + " channels, the edit " + std::to_string(c));
    checkRegion(region, side, rows, c, texels.size());
    const std::size_t texelCount = static_cast<std::size_t>(side) * static_cast<std::size_t>(rows);
    if (target.uniform()) {
      target.texels.resize(texelCount * static_cast<std::size_t>(c));
      for (std::size_t t = 0; t < texelCount; ++t)
        std::copy_n(target.fill.begin(), c,
                    target.texels.begin() + static_cast<std::ptrdiff_t>(t) * c);
    }
    if (target.texels.size() != texelCount * static_cast<std::size_t>(c))
      invalidEdit("applierFor(Document&): the " + target.name + " layer holds " +
                  std::to_string(target.texels.size()) + " floats, not " +
                  std::to_string(texelCount * static_cast<std::size_t>(c)) +
                  " for its image; the document is inconsistent");
    if (layer == EditLayer::Mask) doc.hasMask = true;
    writeRegion(target.texels.data(), side, c, region, texels);
  };
}

} // namespace octaclay::core
