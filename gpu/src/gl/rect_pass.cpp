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

void RectPass::draw(std::span<const core::TexelRect> rects, std::span<const int> dabOfRect,
                    int width, int height) {
  if (rects.empty()) return;
  std::vector<GLint> data{width, height, 0, 0};
  for (std::size_t k = 0; k < rects.size(); ++k) {
    const core::TexelRect& r = rects[k];
    data.insert(data.end(), {r.x, r.y, r.width, r.height, dabOfRect[k], 0, 0, 0});
  }
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

const std::string& batchedRectsVertexShader() {
  static const std::string source = R"(#version 430 core
layout(std430, binding = 0) readonly buffer PassRects {
  ivec4 target; // width, height
  ivec4 rects[]; // per rectangle: x, y, width, height, then its dab's index (x)
};
// Per dab: nine vec4 (prelude.glsl's v_dab) and the centre texel (BrushEngine's uploadBatch).
struct BatchDab {
  vec4 values[9];
  ivec4 centreTexel;
};
layout(std430, binding = 1) readonly buffer BatchDabs { BatchDab batch[]; };
flat out vec4 v_dab[9];
flat out ivec4 v_dabTexel;
void main() {
  int k = gl_VertexID / 6;
  ivec4 r = rects[2 * k];
  const ivec2 corners[6] = ivec2[6](ivec2(0, 0), ivec2(1, 0), ivec2(0, 1),
                                    ivec2(1, 0), ivec2(1, 1), ivec2(0, 1));
  vec2 p = vec2(r.xy + corners[gl_VertexID % 6] * r.zw) / vec2(target.xy);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
  int dab = rects[2 * k + 1].x;
  v_dab = batch[dab].values;
  v_dabTexel = batch[dab].centreTexel;
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
