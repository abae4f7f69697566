#include "quarter_pass.h"

#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <string>

namespace octaclay::gpu::detail {

const Program& QuarterPass::use() {
  if (!program_.id()) {
    program_ = Program::compute(std::string("gpu/shaders/") + shader_, builtInShader(shader_));
    quarters_ = Buffer::create();
    results_ = Buffer::create();
  }
  program_.use();
  return program_;
}

void QuarterPass::run(const Texture& positions, std::span<const std::array<int, 4>> quarters,
                      std::size_t bytesPerQuarter, std::vector<std::byte>& out, const char* what) {
  use();
  quarters_.upload(std::as_bytes(quarters));
  const std::size_t bytes = quarters.size() * bytesPerQuarter;
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, results_.id());
  if (resultBytes_ < bytes) {
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(bytes), nullptr,
                 GL_DYNAMIC_READ);
    resultBytes_ = bytes;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, quarters_.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, results_.id());
  glUniform1i(program_.uniform("u_positions"), 0);
  glUniform1i(program_.uniform("u_count"), static_cast<GLint>(quarters.size()));
  GLint bound = 0; // the unit's texture, put back after: a caller's context keeps its state
  glActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
  glBindTexture(GL_TEXTURE_2D, positions.id());
  glDispatchCompute(static_cast<GLuint>((quarters.size() + 63) / 64), 1, 1);
  glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  out.resize(bytes);
  glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(bytes), out.data());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 2, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 3, 0);
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
  checkGlError(what);
}

} // namespace octaclay::gpu::detail
