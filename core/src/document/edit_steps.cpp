#include "octaclay/core/document/edit_steps.h"

#include "document/tile_texels.h"

#include "octaclay/core/error.h"

#include <array>
#include <cstring>
#include <map>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace {

constexpr std::array<EditLayer, 4> kLayers{EditLayer::Positions, EditLayer::Diffuse,
                                           EditLayer::Feature, EditLayer::Mask};

bool meets(TexelRect a, const std::vector<TexelRect>& rects) {
  if (rects.empty()) return true;
  for (const TexelRect& b : rects)
    if (a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height)
      return true;
  return false;
}

} // namespace

EditStep recordDifference(const Document& before, const Document& after, std::string label,
                          const std::vector<TexelRect>& within) {
  if (!(before.positions.grid() == after.positions.grid()))
    throw Error(ErrorKind::InvalidArgument, "recordDifference: the documents differ in size");
  // A torus's or plane's W × H image: (W+1) texels a row, (H+1) rows.
  const int side = before.positions.side(), rows = before.positions.rows();
  EditStepRecorder recorder(side, rows);
  const int tilesX = EditStepRecorder::tilesPerSide(side),
            tilesY = EditStepRecorder::tilesPerSide(rows);
  for (EditLayer layer : kLayers) {
    if (layer == EditLayer::Mask && !before.hasMask && !after.hasMask) continue;
    for (int ty = 0; ty < tilesY; ++ty)
      for (int tx = 0; tx < tilesX; ++tx) {
        const TexelRect r = EditStepRecorder::tileRegion(side, rows, tx, ty);
        if (!meets(r, within)) continue;
        const std::vector<float> b = detail::tileTexels(before, layer, r),
                                 a = detail::tileTexels(after, layer, r);
        if (std::memcmp(b.data(), a.data(), b.size() * sizeof(float)) == 0) continue;
        recorder.addTile(layer, tx, ty, editLayerChannels(layer), b, a);
      }
  }
  return recorder.finish(std::move(label));
}

EditStep combineSteps(const EditStep& first, const EditStep& second, const Document& current,
                      std::string label) {
  const int side = current.positions.side(), rows = current.positions.rows();
  // Per (layer, tile): the change in each step, if any.
  std::map<std::array<int, 3>, std::pair<const TileChange*, const TileChange*>> tiles;
  for (const TileChange& t : first.tiles)
    tiles[{static_cast<int>(t.layer), t.tileY, t.tileX}].first = &t;
  for (const TileChange& t : second.tiles)
    tiles[{static_cast<int>(t.layer), t.tileY, t.tileX}].second = &t;
  EditStepRecorder recorder(side, rows);
  for (const auto& [key, changes] : tiles) {
    const EditLayer layer = static_cast<EditLayer>(key[0]);
    const TexelRect r = EditStepRecorder::tileRegion(side, rows, key[2], key[1]);
    const std::vector<float> after = detail::tileTexels(current, layer, r);
    std::vector<float> before = after;
    if (changes.second) changes.second->patch(TileState::Before, before);
    if (changes.first) changes.first->patch(TileState::Before, before);
    recorder.addTile(layer, key[2], key[1], editLayerChannels(layer), before, after);
  }
  return recorder.finish(std::move(label));
}

} // namespace octaclay::core
