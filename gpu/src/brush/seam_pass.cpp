#include "seam_pass.h"

#include "shader_sources.h"
#include "texture_copy.h"

#include "octaclay/gpu/brush_engine.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstdint>

namespace octaclay::gpu {
namespace detail {

Program seamProgram() {
  return Program("gpu/shaders/seam.glsl", rectsVertexShader(),
                 "#version 430 core\n" + builtInShader("seam.glsl"));
}

void seamLayer(const Program& seam, RectPass& rectPass, GpuDocument& document,
               core::EditLayer layer, const std::vector<core::TexelRect>& runs) {
  // Into the scratch: after a whole-image swap the scratch is the old texture, free to
  // overwrite, and the seam pass reads the layer's texture.
  document.scratch(layer).bindAsTarget();
  seam.use();
  glUniform1i(seam.uniform("u_source"), 0);
  glUniform2i(seam.uniform("u_cells"), document.grid().width, document.grid().height);
  glUniform1i(seam.uniform("u_topology"), static_cast<int>(document.topology()));
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, document.texture(layer).id());
  rectPass.draw(runs, document.side(), document.rows());
  for (const core::TexelRect& run : runs)
    copyRect(document.scratch(layer), document.texture(layer), run);
}

std::vector<core::TexelRect> uncoveredParts(const std::vector<core::TexelRect>& runs,
                                            const std::vector<core::TexelRect>& tiles) {
  std::vector<core::TexelRect> parts;
  for (const core::TexelRect& run : runs) {
    const bool row = run.height == 1;
    const int length = row ? run.width : run.height;
    std::vector<std::uint8_t> covered(static_cast<std::size_t>(length), 0);
    for (const core::TexelRect& t : tiles) {
      if (row ? (run.y < t.y || run.y >= t.y + t.height) : (run.x < t.x || run.x >= t.x + t.width))
        continue;
      const int from = row ? t.x - run.x : t.y - run.y;
      const int to = from + (row ? t.width : t.height);
      for (int k = std::max(0, from); k < std::min(length, to); ++k)
        covered[static_cast<std::size_t>(k)] = 1;
    }
    for (int k = 0; k < length;) {
      if (covered[static_cast<std::size_t>(k)]) {
        ++k;
        continue;
      }
      int stop = k;
      while (stop < length && !covered[static_cast<std::size_t>(stop)])
        ++stop;
      parts.push_back(row ? core::TexelRect{run.x + k, run.y, stop - k, 1}
                          : core::TexelRect{run.x, run.y + k, 1, stop - k});
      k = stop;
    }
  }
  return parts;
}

} // namespace detail

// Runs along the border lines (the rows whole, the columns without their corners). Elsewhere
// identified samples are already equal, and the seaming pass would write them back unchanged.
std::vector<core::TexelRect> seamRuns(const std::vector<core::TexelRect>& tiles, int side,
                                      core::Topology topology) {
  return seamRuns(tiles, side, side, topology);
}

std::vector<core::TexelRect> seamRuns(const std::vector<core::TexelRect>& tiles, int side, int rows,
                                      core::Topology topology) {
  if (topology == core::Topology::Plane) return {}; // no seams
  const auto onBorder = [side, rows](const core::TexelRect& t) {
    return t.x == 0 || t.y == 0 || t.x + t.width == side || t.y + t.height == rows;
  };
  if (std::none_of(tiles.begin(), tiles.end(), onBorder)) return {}; // most dabs
  const int w = side - 1, h = rows - 1;
  // bottom, top (by i, side long); left, right (by j, rows long)
  std::array<std::vector<std::uint8_t>, 4> marked;
  for (int line = 0; line < 4; ++line)
    marked[static_cast<std::size_t>(line)].assign(static_cast<std::size_t>(line < 2 ? side : rows),
                                                  0);
  // The ball's partner of border sample k is N - k on the same side; the torus's is k on the
  // opposite side (row H is row 0, column W is column 0).
  const bool torus = topology == core::Topology::Torus;
  const auto mark = [&](std::size_t line, int begin, int end) {
    const int last = line < 2 ? w : h;
    for (int k = begin; k < end; ++k) {
      const auto at = static_cast<std::size_t>(k);
      marked[line][at] = 1;
      if (torus)
        marked[line ^ 1][at] = 1;
      else
        marked[line][static_cast<std::size_t>(last - k)] = 1;
    }
  };
  for (const core::TexelRect& t : tiles) {
    if (t.y == 0) mark(0, t.x, t.x + t.width);
    if (t.y + t.height == rows) mark(1, t.x, t.x + t.width);
    if (t.x == 0) mark(2, t.y, t.y + t.height);
    if (t.x + t.width == side) mark(3, t.y, t.y + t.height);
  }
  const bool corner = marked[0][0] || marked[1][0] || marked[2][0] || marked[3][0];
  for (int k : {0, 1})
    marked[k][0] = marked[k][static_cast<std::size_t>(w)] = corner;
  std::vector<core::TexelRect> runs;
  for (int line = 0; line < 4; ++line) {
    const bool row = line < 2;
    // columns leave the corners to rows
    const int begin = row ? 0 : 1, end = row ? side : h;
    for (int k = begin; k < end;) {
      if (!marked[static_cast<std::size_t>(line)][static_cast<std::size_t>(k)]) {
        ++k;
        continue;
      }
      int stop = k;
      while (stop < end && marked[static_cast<std::size_t>(line)][static_cast<std::size_t>(stop)])
        ++stop;
      const int at = line % 2 == 0 ? 0 : (row ? h : w);
      runs.push_back(row ? core::TexelRect{k, at, stop - k, 1}
                         : core::TexelRect{at, k, 1, stop - k});
      k = stop;
    }
  }
  return runs;
}

} // namespace octaclay::gpu
