#include "area_normal_pass.h"

#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace octaclay::gpu::detail {

AreaSum AreaNormalPass::sum(const Texture& positions, const core::TileBounds& bounds,
                            std::span<const int> tiles, std::array<int, 2> cells, bool ball,
                            core::Vec3f centre, float radius) {
  if (tiles.empty()) return {};
  if (!program_.id()) {
    program_ = Program::compute("gpu/shaders/area_normal.glsl", builtInShader("area_normal.glsl"));
    quarters_ = Buffer::create();
    sums_ = Buffer::create();
  }
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
  quarters_.upload(std::as_bytes(std::span(quarters)));
  const std::size_t bytes = quarters.size() * 4 * sizeof(float);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, sums_.id());
  if (sumBytes_ < bytes) {
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr,
                 GL_DYNAMIC_READ);
    sumBytes_ = bytes;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, quarters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, sums_.id());
  program_.use();
  glUniform1i(program_.uniform("u_positions"), 0);
  glUniform2i(program_.uniform("u_cells"), cells[0], cells[1]);
  glUniform1i(program_.uniform("u_ball"), ball ? 1 : 0);
  glUniform3f(program_.uniform("u_centre"), centre.x, centre.y, centre.z);
  glUniform1f(program_.uniform("u_radius2"), radius * radius);
  glUniform1i(program_.uniform("u_count"), static_cast<GLint>(quarters.size()));
  GLint bound = 0; // the unit's texture, put back after: a caller's context keeps its state
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(GL_TEXTURE_2D, positions.id());
  glDispatchCompute(static_cast<GLuint>((quarters.size() + 63) / 64), 1, 1);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<std::array<float, 4>> sums(quarters.size());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), sums.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  checkGlError("the area normal's reduction");
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
