#include "tile_bounds_pass.h"

#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <array>
#include <cstddef>
#include <vector>

namespace octaclay::gpu::detail {

void TileBoundsPass::refresh(const Texture& positions, core::TileBounds& bounds,
                             std::span<const core::TexelRect> rects) {
  const std::vector<int> tiles = bounds.tilesTouching(rects);
  if (tiles.empty()) return;
  if (!program_.id()) {
    program_ = Program::compute("gpu/shaders/tile_bounds.glsl", builtInShader("tile_bounds.glsl"));
    quarters_ = Buffer::create();
    boxes_ = Buffer::create();
  }
  std::vector<std::array<int, 4>> quarters;
  quarters.reserve(4 * tiles.size());
  for (int t : tiles)
    for (int q = 0; q < 4; ++q) {
      const core::TexelRect r = bounds.quarterRect(t % bounds.tilesX(), t / bounds.tilesX(), q);
      quarters.push_back({r.x, r.y, r.width, r.height});
    }
  quarters_.upload(std::as_bytes(std::span(quarters)));
  const std::size_t bytes = quarters.size() * 2 * 4 * sizeof(float);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, boxes_.id());
  if (boxBytes_ < bytes) {
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr,
                 GL_DYNAMIC_READ);
    boxBytes_ = bytes;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, quarters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, boxes_.id());
  program_.use();
  glUniform1i(program_.uniform("u_positions"), 0);
  glUniform2i(program_.uniform("u_last"), positions.width() - 1, positions.height() - 1);
  glUniform1i(program_.uniform("u_count"), static_cast<GLint>(quarters.size()));
  GLint bound = 0; // the unit's texture, put back after: a caller's context keeps its state
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(GL_TEXTURE_2D, positions.id());
  glDispatchCompute(static_cast<GLuint>((quarters.size() + 63) / 64), 1, 1);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::array<float, 8>> boxes(quarters.size());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), boxes.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  checkGlError("the tile bounds' reduction");
  std::vector<core::BoundingBox> result(boxes.size());
  for (std::size_t k = 0; k < boxes.size(); ++k) {
    result[k].min = {boxes[k][0], boxes[k][1], boxes[k][2]};
    result[k].max = {boxes[k][4], boxes[k][5], boxes[k][6]};
  }
  bounds.setQuarterBoxes(tiles, result);
}

} // namespace octaclay::gpu::detail
