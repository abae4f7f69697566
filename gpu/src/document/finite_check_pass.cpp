#include "finite_check_pass.h"

#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::gpu::detail {

bool FiniteCheckPass::allFinite(const Texture& texture, int channels, bool bounded,
                                float maxCoordinate, std::span<const core::TexelRect> rects) {
  std::vector<std::array<int, 4>> rows;
  for (const core::TexelRect& r : rects)
    for (int y = r.y; y < r.y + r.height; ++y)
      rows.push_back({r.x, y, r.width, 1});
  if (rows.empty()) return true;
  if (!program_.id()) {
    program_ =
        Program::compute("gpu/shaders/finite_check.glsl", builtInShader("finite_check.glsl"));
    rows_ = Buffer::create();
    flag_ = Buffer::create();
  }
  rows_.upload(std::as_bytes(std::span(rows)));
  const std::uint32_t clear = 0;
  flag_.upload(std::as_bytes(std::span(&clear, 1)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, rows_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, flag_.id());
  program_.use();
  glUniform1i(program_.uniform("u_layer"), 0);
  glUniform1i(program_.uniform("u_channels"), channels);
  glUniform1i(program_.uniform("u_bounded"), bounded ? 1 : 0);
  glUniform1f(program_.uniform("u_maxCoordinate"), maxCoordinate);
  glUniform1i(program_.uniform("u_rows"), static_cast<GLint>(rows.size()));
  GLint bound = 0; // the unit's texture, put back after: a caller's context keeps its state
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(GL_TEXTURE_2D, texture.id());
  glDispatchCompute(static_cast<GLuint>((rows.size() + 63) / 64), 1, 1);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::uint32_t flag = 0;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, flag_.id());
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof flag, &flag);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  checkGlError("the finite check");
  return flag == 0;
}

} // namespace octaclay::gpu::detail
