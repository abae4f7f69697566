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

Texture& sized(Texture& t, int width, int height, TextureFormat format) {
  if (t.width() != width || t.height() != height || t.format() != format)
    t = Texture(width, height, format);
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

std::vector<float> SaliencyPass::scalesFor(float n, const core::SaliencyOptions& options) {
  if (!options.scales.empty()) return options.scales;
  std::vector<float> scales;
  for (const float s : {1.0f, 2.0f, 4.0f, 8.0f, 16.0f})
    scales.push_back(std::max(1.0f, s * n / 256.0f));
  return scales;
}

void SaliencyPass::setGrid(const Program& program, const core::SampleGrid& grid) {
  glUniform1i(glGetUniformLocation(program.id(), "u_size"), grid.width);
  glUniform2i(glGetUniformLocation(program.id(), "u_cells"), grid.width, grid.height);
  glUniform1i(glGetUniformLocation(program.id(), "u_topology"), static_cast<int>(grid.topology));
}

Texture& SaliencyPass::temporary(int slot, int width, int height) {
  if (sums_.size() < 2) sums_.resize(2);
  return sized(sums_[static_cast<std::size_t>(slot)], width, height, TextureFormat::R32f);
}

const Texture& SaliencyPass::blurred(float sigma, const core::SampleGrid& grid) {
  auto found = blurred_.find(sigma);
  if (found != blurred_.end()) return found->second;
  const int width = grid.width + 1, height = grid.height + 1;
  Texture& out = blurred_.emplace(sigma, Texture(width, height, TextureFormat::R32f)).first->second;
  const core::TexelRect all{0, 0, width, height};
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
  setGrid(blurProgram_, grid);
  glUniform1i(blurProgram_.uniform("u_source"), 0);
  glUniform1i(blurProgram_.uniform("u_taps"), taps);
  sized(horizontal_, width, height, TextureFormat::R32f).bindAsTarget();
  bindTexture(0, curvature_);
  glUniform2i(blurProgram_.uniform("u_direction"), 1, 0);
  rectPass_.draw(std::span(&all, 1), width, height);
  out.bindAsTarget();
  bindTexture(0, horizontal_);
  glUniform2i(blurProgram_.uniform("u_direction"), 0, 1);
  rectPass_.draw(std::span(&all, 1), width, height);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return out;
}

void SaliencyPass::run(GpuDocument& document, const core::SaliencyOptions& options) {
  // Its passes read through the prelude's wrapTexel: the ball's octahedral tiling, a torus's
  // periods, a plane's boundary (core/lod's saliency alike).
  const core::SampleGrid& grid = document.grid();
  const int width = grid.width + 1, height = grid.height + 1;
  const core::TexelRect all{0, 0, width, height};
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, width, height);
  sized(normals_, width, height, TextureFormat::Rgba32f).bindAsTarget();
  normalProgram_.use();
  setGrid(normalProgram_, grid);
  glUniform1i(normalProgram_.uniform("u_positions"), 0);
  bindTexture(0, document.texture(core::EditLayer::Positions));
  rectPass_.draw(std::span(&all, 1), width, height);
  sized(curvature_, width, height, TextureFormat::R32f).bindAsTarget();
  curvatureProgram_.use();
  setGrid(curvatureProgram_, grid);
  glUniform1i(curvatureProgram_.uniform("u_normals"), 0);
  bindTexture(0, normals_);
  rectPass_.draw(std::span(&all, 1), width, height);
  // Running sum of the centre-surround terms, ping-ponged between two targets; starts at 0.
  blurred_.clear();
  int current = 0;
  temporary(0, width, height).bindAsTarget();
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  temporary(1, width, height);
  for (float s : scalesFor(core::saliencySamplesAcross(grid), options)) {
    if (!(s > 0)) throw GlError("saliency scales must be positive");
    const Texture& fine = blurred(s, grid);
    const Texture& coarse = blurred(2 * s, grid);
    sums_[static_cast<std::size_t>(1 - current)].bindAsTarget();
    combineProgram_.use();
    glUniform1i(combineProgram_.uniform("u_fine"), 0);
    glUniform1i(combineProgram_.uniform("u_coarse"), 1);
    glUniform1i(combineProgram_.uniform("u_sum"), 2);
    bindTexture(0, fine);
    bindTexture(1, coarse);
    bindTexture(2, sums_[static_cast<std::size_t>(current)]);
    rectPass_.draw(std::span(&all, 1), width, height);
    current = 1 - current;
  }
  // Identified samples get one value: the seaming pass's average (symmetric, so exact); a
  // plane's samples are each their own.
  sums_[static_cast<std::size_t>(1 - current)].bindAsTarget();
  seamProgram_.use();
  glUniform1i(seamProgram_.uniform("u_source"), 0);
  glUniform2i(seamProgram_.uniform("u_cells"), grid.width, grid.height);
  glUniform1i(seamProgram_.uniform("u_topology"), static_cast<int>(grid.topology));
  bindTexture(0, sums_[static_cast<std::size_t>(current)]);
  rectPass_.draw(std::span(&all, 1), width, height);
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
