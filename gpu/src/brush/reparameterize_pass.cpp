#include "reparameterize_pass.h"

#include "brush_program.h"
#include "loaded_brush.h"
#include "texture_copy.h"
#include "texture_units.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

namespace octaclay::gpu::detail {

std::vector<core::EditLayer> ReparameterizePass::layersOf(const core::Document& mirror) {
  std::vector<core::EditLayer> layers{core::EditLayer::Positions};
  if (!mirror.diffuse.uniform()) layers.push_back(core::EditLayer::Diffuse);
  if (!mirror.feature.uniform()) layers.push_back(core::EditLayer::Feature);
  if (!mirror.mask.uniform()) layers.push_back(core::EditLayer::Mask);
  return layers;
}

void ReparameterizePass::reset(const std::vector<core::TexelRect>& where) {
  baseTaken_ = {};
  baseOf_ = nullptr;
  if (!offsets_[0].id()) return;
  const GLfloat zero[4] = {0, 0, 0, 0};
  glEnable(GL_SCISSOR_TEST);
  for (Texture& t : offsets_) {
    t.bindAsTarget();
    for (const core::TexelRect& r : where) {
      glScissor(r.x, r.y, r.width, r.height);
      glClearBufferfv(GL_COLOR, 0, zero);
    }
  }
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void ReparameterizePass::endStroke() {
  if (baseOf_) reset({core::TexelRect{0, 0, offsets_[0].width(), offsets_[0].height()}});
}

void ReparameterizePass::run(DabPass& pass, const std::vector<core::EditLayer>& layers,
                             bool strokeOpen) {
  GpuDocument& document = pass.document;
  const BrushManifest& manifest = pass.brush.manifest;
  const int side = document.side(), rows = document.rows();
  const core::TexelRect whole = document.whole();
  if (baseOf_ && baseOf_ != &document) reset({whole});
  if (offsets_[0].width() != side || offsets_[0].height() != rows) {
    for (Texture& t : offsets_)
      t = Texture(side, rows, TextureFormat::Rgba32f);
    reset({whole});
  }
  // The layers at the stroke's first dab: every dab of it resamples from them.
  baseOf_ = &document;
  for (core::EditLayer layer : layers) {
    const auto k = static_cast<std::size_t>(layer);
    if (baseTaken_[k]) continue;
    const Texture& current = document.texture(layer);
    if (base_[k].width() != side || base_[k].height() != rows ||
        base_[k].format() != current.format())
      base_[k] = Texture(side, rows, current.format());
    copyRect(current, base_[k], whole);
    baseTaken_[k] = true;
  }
  const auto bindBase = [&] {
    kPositionsUnit.bind(base_[0].id());
    kDiffuseUnit.bind(baseTaken_[1] ? base_[1].id() : 0);
    kFeatureUnit.bind(baseTaken_[2] ? base_[2].id() : 0);
    kMaskUnit.bind(baseTaken_[3] ? base_[3].id() : document.texture(core::EditLayer::Mask).id());
    kOffsetsUnit.bind(offsets_[0].id());
    glActiveTexture(GL_TEXTURE0);
  };
  try {
    // Steps: each reads the field so far (u_offsets) and writes the next into the twin over
    // rects. Elsewhere both hold the same field (zero outside the stroke's dabs).
    const Program& step = pass.program(core::EditLayer::Positions);
    pass.bindInputs(step, core::EditLayer::Positions);
    kPositionsUnit.bind(base_[0].id()); // current positions: the base at texel + offset
    for (int k = 0; k < manifest.iterations; ++k) {
      offsets_[1].bindAsTarget();
      kOffsetsUnit.bind(offsets_[0].id());
      glActiveTexture(GL_TEXTURE0);
      pass.rectPass.draw(pass.rects, side, rows);
      pass.issued();
      std::swap(offsets_[0], offsets_[1]);
    }
    for (const core::TexelRect& r : pass.rects) // the twin catches up for the stroke's next dab
      copyRect(offsets_[0], offsets_[1], r);
    checkGlError("brush " + manifest.id + " offset steps");

    // One resample of every layer from the base layers into their scratches.
    if (!resampleProgram_.id())
      resampleProgram_ =
          Program("gpu/shaders/resample.glsl", rectsVertexShader(), resampleSource());
    resampleProgram_.use();
    for (const BrushUnit& unit : kLayerUnits)
      glUniform1i(resampleProgram_.uniform(unit.sampler), unit.unit);
    glUniform1i(resampleProgram_.uniform("u_size"), document.size());
    glUniform2i(glGetUniformLocation(resampleProgram_.id(), "u_cells"), document.grid().width,
                document.grid().height);
    glUniform1i(glGetUniformLocation(resampleProgram_.id(), "u_topology"),
                static_cast<int>(document.topology()));
    bindBase();
    if (!resampleTarget_.id())
      resampleTarget_ = Framebuffer(document.scratch(core::EditLayer::Positions));
    resampleTarget_.bind();
    std::array<GLenum, 4> drawBuffers{GL_NONE, GL_NONE, GL_NONE, GL_NONE};
    for (core::EditLayer layer : layers) {
      const auto k = static_cast<std::size_t>(layer); // attachment k holds layer k
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k),
                             GL_TEXTURE_2D, document.scratch(layer).id(), 0);
      drawBuffers[k] = GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k);
    }
    glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    pass.rectPass.draw(pass.rects, side, rows);
    // Detached, as the brushLayers() target: no document texture stays attached.
    for (GLenum k = 0; k < 4; ++k)
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + k, GL_TEXTURE_2D, 0, 0);
    checkGlError("brush " + manifest.id + " resample");
    pass.issued();
  } catch (...) {
    reset({whole});
    throw;
  }
  kOffsetsUnit.bind(0);
  glActiveTexture(GL_TEXTURE0);
  if (!strokeOpen) reset(pass.rects); // a dab of its own: the field is zero again
}

} // namespace octaclay::gpu::detail
