#include "tile_bounds_pass.h"

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <vector>

namespace octaclay::gpu::detail {

void TileBoundsPass::refresh(const Texture& positions, core::TileBounds& bounds,
                             std::span<const core::TexelRect> rects) {
  const std::vector<int> tiles = bounds.tilesTouching(rects);
  if (tiles.empty()) return;
  std::vector<std::array<int, 4>> quarters;
  quarters.reserve(4 * tiles.size());
  for (int t : tiles)
    for (int q = 0; q < 4; ++q) {
      const core::TexelRect r = bounds.quarterRect(t % bounds.tilesX(), t / bounds.tilesX(), q);
      quarters.push_back({r.x, r.y, r.width, r.height});
    }
  const Program& program = pass_.use();
  glUniform2i(program.uniform("u_last"), positions.width() - 1, positions.height() - 1);
  std::vector<std::byte> read;
  pass_.run(positions, quarters, 2 * 4 * sizeof(float), read, "the tile bounds' reduction");
  std::vector<core::BoundingBox> result(quarters.size());
  for (std::size_t k = 0; k < result.size(); ++k) {
    std::array<float, 8> box;
    std::memcpy(box.data(), read.data() + k * sizeof box, sizeof box);
    result[k].min = {box[0], box[1], box[2]};
    result[k].max = {box[4], box[5], box[6]};
  }
  bounds.setQuarterBoxes(tiles, result);
}

} // namespace octaclay::gpu::detail
