#include "octaclay/gpu/saliency.h"

#include "shader_sources.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace octaclay::gpu {
namespace {

// The prelude's helpers (wrapTexel, fetchPositions, u_size) as a positions pass sees them.
std::string withPrelude(const std::string& pass) {
  return "#version 430 core\n#define LAYER_POSITIONS 0\n#define LAYER_DIFFUSE 1\n"
         "#define LAYER_FEATURE 2\n#define LAYER_MASK 3\n#define OCTACLAY_LAYER 0\n" +
         detail::builtInShader("prelude.glsl") + detail::builtInShader(pass);
}

void bindTexture(int unit, const Texture& texture) {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture.id());
}

Texture& sized(Texture& t, int side, TextureFormat format) {
  if (t.width() != side || t.format() != format) t = Texture(side, side, format);
  return t;
}

} // namespace

SaliencyPass::SaliencyPass()
    : normalProgram_("gpu/shaders/saliency_normal.glsl", rectsVertexShader(),
                     withPrelude("saliency_normal.glsl")),
      curvatureProgram_("gpu/shaders/saliency_curvature.glsl", rectsVertexShader(),
                        withPrelude("saliency_curvature.glsl")),
      blurProgram_("gpu/shaders/saliency_blur.glsl", rectsVertexShader(),
                   withPrelude("saliency_blur.glsl")),
      combineProgram_("gpu/shaders/saliency_combine.glsl", rectsVertexShader(),
                      "#version 430 core\n" + detail::builtInShader("saliency_combine.glsl")),
      seamProgram_("gpu/shaders/seam.glsl", rectsVertexShader(),
                   "#version 430 core\n" + detail::builtInShader("seam.glsl")) {}

std::vector<float> SaliencyPass::scalesFor(int n, const core::SaliencyOptions& options) {
  if (!options.scales.empty()) return options.scales;
  std::vector<float> scales;
  for (const float s : {1.0f, 2.0f, 4.0f, 8.0f, 16.0f})
    scales.push_back(std::max(1.0f, s * static_cast<float>(n) / 256.0f));
  return scales;
}

Texture& SaliencyPass::temporary(int slot, int side) {
  if (sums_.size() < 2) sums_.resize(2);
  return sized(sums_[static_cast<std::size_t>(slot)], side, TextureFormat::R32f);
}

const Texture& SaliencyPass::blurred(float sigma, int side, int n) {
  auto found = blurred_.find(sigma);
  if (found != blurred_.end()) return found->second;
  Texture& out = blurred_.emplace(sigma, Texture(side, side, TextureFormat::R32f)).first->second;
  const core::TexelRect all{0, 0, side, side};
  // The truncated (⌈2σ⌉ taps, at least 1) kernel, normalised as the CPU reference does.
  const int taps = std::max(1, static_cast<int>(std::ceil(2 * sigma)));
  std::vector<float> kernel(static_cast<std::size_t>(2 * taps + 1));
  float total = 0;
  for (int d = -taps; d <= taps; ++d)
    total += kernel[static_cast<std::size_t>(d + taps)] =
        std::exp(-0.5f * float(d * d) / (sigma * sigma));
  for (float& w : kernel)
    w /= total;
  if (!kernel_.id()) kernel_ = Buffer::create();
  kernel_.upload(std::as_bytes(std::span(kernel)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, kernel_.id());
  blurProgram_.use();
  glUniform1i(blurProgram_.uniform("u_size"), n);
  glUniform1i(blurProgram_.uniform("u_source"), 0);
  glUniform1i(blurProgram_.uniform("u_taps"), taps);
  sized(horizontal_, side, TextureFormat::R32f).bindAsTarget();
  bindTexture(0, curvature_);
  glUniform2i(blurProgram_.uniform("u_direction"), 1, 0);
  rectPass_.draw(std::span(&all, 1), side, side);
  out.bindAsTarget();
  bindTexture(0, horizontal_);
  glUniform2i(blurProgram_.uniform("u_direction"), 0, 1);
  rectPass_.draw(std::span(&all, 1), side, side);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return out;
}

void SaliencyPass::run(GpuDocument& document, const core::SaliencyOptions& options) {
  // Its blurs and seaming follow the ball's octahedral tiling (core/lod's saliency too).
  if (document.topology() != core::Topology::Octahedral)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      std::string("saliency is measured on octahedral (ball) images only; this is "
                                  "a ") +
                          std::string(core::topologyName(document.topology())));
  const int n = document.size(), side = n + 1;
  const core::TexelRect all{0, 0, side, side};
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, side, side);

  sized(normals_, side, TextureFormat::Rgba32f).bindAsTarget();
  normalProgram_.use();
  glUniform1i(normalProgram_.uniform("u_size"), n);
  glUniform1i(normalProgram_.uniform("u_positions"), 0);
  bindTexture(0, document.texture(core::EditLayer::Positions));
  rectPass_.draw(std::span(&all, 1), side, side);

  sized(curvature_, side, TextureFormat::R32f).bindAsTarget();
  curvatureProgram_.use();
  glUniform1i(curvatureProgram_.uniform("u_size"), n);
  glUniform1i(curvatureProgram_.uniform("u_normals"), 0);
  bindTexture(0, normals_);
  rectPass_.draw(std::span(&all, 1), side, side);

  // Running sum of the centre-surround terms, ping-ponged between two targets; starts at 0.
  blurred_.clear();
  int current = 0;
  temporary(0, side).bindAsTarget();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  temporary(1, side);
  for (float s : scalesFor(n, options)) {
    if (!(s > 0)) throw GlError("saliency scales must be positive");
    const Texture& fine = blurred(s, side, n);
    const Texture& coarse = blurred(2 * s, side, n);
    sums_[static_cast<std::size_t>(1 - current)].bindAsTarget();
    combineProgram_.use();
    glUniform1i(combineProgram_.uniform("u_fine"), 0);
    glUniform1i(combineProgram_.uniform("u_coarse"), 1);
    glUniform1i(combineProgram_.uniform("u_sum"), 2);
    bindTexture(0, fine);
    bindTexture(1, coarse);
    bindTexture(2, sums_[static_cast<std::size_t>(current)]);
    rectPass_.draw(std::span(&all, 1), side, side);
    current = 1 - current;
  }
  // Identified samples get one value: the seaming pass's average (symmetric, so exact).
  sums_[static_cast<std::size_t>(1 - current)].bindAsTarget();
  seamProgram_.use();
  glUniform1i(seamProgram_.uniform("u_source"), 0);
  glUniform2i(seamProgram_.uniform("u_cells"), n, n);
  glUniform1i(seamProgram_.uniform("u_topology"), 0);
  bindTexture(0, sums_[static_cast<std::size_t>(current)]);
  rectPass_.draw(std::span(&all, 1), side, side);
  current = 1 - current;
  for (int unit = 2; unit >= 0; --unit)
    bindTexture(unit, Texture());
  glUseProgram(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  checkGlError("saliency passes");
  blurred_.clear(); // not kept between runs: a run at N = 1024 holds six 4 MB images

  std::vector<float> saliency = sums_[static_cast<std::size_t>(current)].read(all);
  const float peak = *std::max_element(saliency.begin(), saliency.end());
  const float scale = peak > 0 ? 1.0f / peak : 0.0f;
  for (float& s : saliency)
    s *= scale;
  document.writeSaliency(saliency);
}

} // namespace octaclay::gpu
