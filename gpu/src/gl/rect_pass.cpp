// Fragment passes over texel rectangles (RectPass) and over the whole viewport.
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gl_objects.h"

#include <epoxy/gl.h>

#include <span>
#include <string>
#include <vector>

namespace octaclay::gpu {

RectPass::RectPass() : rects_(Buffer::create()), vertexArray_(VertexArray::create()) {}

void RectPass::draw(std::span<const core::TexelRect> rects, int width, int height) {
  if (rects.empty()) return;
  std::vector<GLint> data{width, height, 0, 0};
  for (const core::TexelRect& r : rects)
    data.insert(data.end(), {r.x, r.y, r.width, r.height});
  rects_.upload(std::as_bytes(std::span(data)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, rects_.id());
  vertexArray_.bind();
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(6 * rects.size()));
  checkGlError("rectangle pass");
}

const std::string& rectsVertexShader() {
  static const std::string source = R"(#version 430 core
layout(std430, binding = 0) readonly buffer PassRects {
  ivec4 target; // width, height
  ivec4 rects[]; // x, y, width, height
};
void main() {
  ivec4 r = rects[gl_VertexID / 6];
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1),
                                    ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  vec2 p = vec2(r.xy + corners[gl_VertexID % 6] * r.zw) / vec2(target.xy);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";
  return source;
}

void drawFullscreenPass() {
  // Core profile needs a bound vertex array even when the vertex shader makes its own vertices.
  // Vertex arrays are not shared between contexts: this assumes one engine context per process.
  static GLuint vertexArray = 0;
  if (!vertexArray) glGenVertexArrays(1, &vertexArray);
  glBindVertexArray(vertexArray);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  checkGlError("full-screen pass");
}

const std::string& fullscreenVertexShader() {
  static const std::string source = R"(#version 430 core
out vec2 v_uv;
void main() {
  vec2 corner = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = corner;
  gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
)";
  return source;
}

} // namespace octaclay::gpu
