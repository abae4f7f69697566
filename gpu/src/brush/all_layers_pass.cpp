#include "all_layers_pass.h"

#include "loaded_brush.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>

namespace octaclay::gpu::detail {

void AllLayersPass::run(DabPass& pass) {
  LoadedBrush& brush = pass.brush;
  GpuDocument& document = pass.document;
  const Program& program = pass.program(core::EditLayer::Positions);
  const std::array<core::EditLayer, 3> attached{core::EditLayer::Positions,
                                                core::EditLayer::Diffuse, core::EditLayer::Feature};
  if (!target_.id()) target_ = Framebuffer(document.scratch(core::EditLayer::Positions));
  target_.bind();
  std::array<GLenum, 3> drawBuffers{};
  for (std::size_t k = 0; k < attached.size(); ++k) {
    const bool written = std::find(brush.manifest.writes.begin(), brush.manifest.writes.end(),
                                   attached[k]) != brush.manifest.writes.end();
    // A layer whose texels the pass reads elsewhere goes to its scratch.
    const Texture& target = brush.writesInPlace(attached[k]) ? document.texture(attached[k])
                                                             : document.scratch(attached[k]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k),
                           GL_TEXTURE_2D, written ? target.id() : 0, 0);
    drawBuffers[k] = written ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k) : GL_NONE;
    if (brush.mixes(attached[k])) { // rgb = mix(rgb, out.rgb, out.a); alpha kept
      const auto buffer = static_cast<GLuint>(k);
      glEnablei(GL_BLEND, buffer);
      glBlendEquationi(buffer, GL_FUNC_ADD);
      glBlendFuncSeparatei(buffer, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
  }
  glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
  // u_layer: the positions (brushInputAt's value is the positions texel).
  pass.bindInputs(program, core::EditLayer::Positions);
  if (brush.readsWhatItWrites()) glTextureBarrier(); // earlier writes are visible
  pass.draw();
  for (core::EditLayer layer : brush.manifest.mix)
    glDisablei(GL_BLEND, static_cast<GLuint>(layer)); // attachment k holds layer k
  for (std::size_t k = 0; k < attached.size(); ++k)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k),
                           GL_TEXTURE_2D, 0, 0);
  checkGlError("brush " + brush.manifest.id + " pass");
  pass.issued();
  for (core::EditLayer layer : brush.manifest.writes)
    pass.finishLayer(layer);
}

} // namespace octaclay::gpu::detail
