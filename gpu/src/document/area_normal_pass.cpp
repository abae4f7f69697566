#include "area_normal_pass.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstring>
#include <vector>

namespace octaclay::gpu::detail {

AreaSum AreaNormalPass::sum(const Texture& positions, const core::TileBounds& bounds,
                            std::span<const int> tiles, std::array<int, 2> cells, bool ball,
                            core::Vec3f centre, float radius) {
  if (tiles.empty()) return {};
  std::vector<std::array<int, 4>> quarters;
  quarters.reserve(4 * tiles.size());
  for (int t : tiles) {
    const auto first = static_cast<std::ptrdiff_t>(quarters.size());
    for (int q = 0; q < 4; ++q) {
      const core::TexelRect r = bounds.quarterRect(t % bounds.tilesX(), t / bounds.tilesX(), q);
      const std::array<int, 4> quarter{r.x, r.y, r.width, r.height};
      // A tile of one sample is its own four quarters: its cells count once.
      if (std::find(quarters.begin() + first, quarters.end(), quarter) == quarters.end())
        quarters.push_back(quarter);
    }
  }
  if (quarters.empty()) return {};
  const Program& program = pass_.use();
  glUniform2i(program.uniform("u_cells"), cells[0], cells[1]);
  glUniform1i(program.uniform("u_ball"), ball ? 1 : 0);
  glUniform3f(program.uniform("u_centre"), centre.x, centre.y, centre.z);
  glUniform1f(program.uniform("u_radius2"), radius * radius);
  std::vector<std::byte> read;
  pass_.run(positions, quarters, 4 * sizeof(float), read, "the area normal's reduction");
  std::vector<std::array<float, 4>> sums(quarters.size());
  std::memcpy(sums.data(), read.data(), read.size());
  // The quarters in their order, in double: the same sum on every run and driver that sums
  // each quarter alike.
  std::array<double, 3> total{};
  AreaSum result;
  for (const auto& s : sums) {
    for (int k = 0; k < 3; ++k)
      total[static_cast<std::size_t>(k)] += s[static_cast<std::size_t>(k)];
    result.triangles += static_cast<int>(s[3]);
  }
  result.sum = {static_cast<float>(total[0]), static_cast<float>(total[1]),
                static_cast<float>(total[2])};
  return result;
}

} // namespace octaclay::gpu::detail
