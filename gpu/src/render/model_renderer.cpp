#include "octaclay/gpu/model_renderer.h"

#include "model_chunks.h"
#include "shader_sources.h"

#include "octaclay/core/error.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <array>
#include <vector>

namespace octaclay::gpu {
namespace {

// A pass over the positions: the prelude's uniforms, wrapTexel() and normalAt(), as a
// positions pass sees them, then the pass's body.
std::string positionsPassSource(const std::string& body) {
  return "#version 430 core\n#define LAYER_POSITIONS 0\n#define LAYER_DIFFUSE 1\n"
         "#define LAYER_FEATURE 2\n#define LAYER_MASK 3\n#define OCTACLAY_LAYER 0\n" +
         detail::builtInShader("prelude.glsl") + detail::builtInShader(body);
}

// A pass run from inside draw() renders elsewhere; the caller's frame (VTK's, which caches this
// state) needs its framebuffers, viewport and enables back.
class SavedTarget {
public:
  SavedTarget() {
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
    glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
    glGetIntegerv(GL_VIEWPORT, viewport_.data());
    for (std::size_t k = 0; k < kCaps.size(); ++k)
      enabled_[k] = glIsEnabled(kCaps[k]);
  }
  ~SavedTarget() {
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
    glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
    glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
    for (std::size_t k = 0; k < kCaps.size(); ++k)
      enabled_[k] ? glEnable(kCaps[k]) : glDisable(kCaps[k]);
  }
  SavedTarget(const SavedTarget&) = delete;
  SavedTarget& operator=(const SavedTarget&) = delete;

private:
  static constexpr std::array<GLenum, 4> kCaps{GL_BLEND, GL_DEPTH_TEST, GL_SCISSOR_TEST,
                                               GL_CULL_FACE};
  GLint drawFramebuffer_ = 0, readFramebuffer_ = 0;
  std::array<GLint, 4> viewport_{};
  std::array<GLboolean, 4> enabled_{};
};

// More stale rects than this and the next stretch pass redoes the whole map.
constexpr std::size_t kMaxStaleStretchRects = 1024;

std::vector<core::TexelRect> regions(std::span<const core::TexelRect> rects) {
  std::vector<core::TexelRect> out;
  out.reserve(rects.size());
  for (const core::TexelRect& r : rects)
    out.push_back({r.x, r.y, r.width, r.height});
  return out;
}

void bindTexture(int unit, const Texture& texture) {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture.id());
}

// Leaves no program or texture of a draw bound (VTK caches what it believes is bound).
void unbindAfterDraw() {
  for (int unit = 6; unit >= 0; --unit) {
    glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  glUseProgram(0);
}

} // namespace

ModelRenderer::ModelRenderer()
    : normalProgram_("normal map", rectsVertexShader(), positionsPassSource("normal_map.glsl")),

      vertexArray_(VertexArray::create()), indexBuffer_(Buffer::create()),
      chunks_(std::make_unique<detail::ModelChunks>()) {}

const Program& ModelRenderer::drawVariant(const Variant& v) {
  const int key = (v.diffuseTexture ? 1 : 0) | (v.featureTexture ? 2 : 0) | (v.maskTint ? 4 : 0) |
                  (v.reflection ? 8 : 0) | (v.preview << 4) | (v.lodVertices ? 1 << 8 : 0) |
                  (v.matcap ? 1 << 9 : 0) | (v.wireframe ? 1 << 10 : 0);
  const auto found = drawPrograms_.find(key);
  if (found != drawPrograms_.end()) return found->second;
  std::string source = "#version 430 core\n";
  if (v.diffuseTexture) source += "#define DIFFUSE_TEXTURE\n";
  if (v.featureTexture) source += "#define FEATURE_TEXTURE\n";
  if (v.maskTint) source += "#define MASK_TINT\n";
  if (v.reflection) source += "#define REFLECTION\n";
  if (v.lodVertices) source += "#define LOD_VERTICES\n";
  if (v.matcap) source += "#define MATCAP\n";
  if (v.wireframe) source += "#define WIREFRAME\n";
  source += "#define PREVIEW " + std::to_string(v.preview) + "\n";
  source += detail::builtInShader("model_fragment.glsl");
  return drawPrograms_
      .emplace(key, Program("model",
                            detail::builtInShader(v.lodVertices ? "model_lod_vertex.glsl"
                                                                : "model_vertex.glsl"),
                            source))
      .first->second;
}

ModelRenderer::~ModelRenderer() = default;

void ModelRenderer::setLevel(int n, int divisor) {
  if (divisor < 1 || (divisor & (divisor - 1)) != 0 || n % divisor != 0 || n / divisor < 2)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "level N/" + std::to_string(divisor) + " of N = " + std::to_string(n) +
                          " is not a power-of-two level with at least 2 cells a side");
  setLevel(core::SampleGrid{core::Topology::Octahedral, n, n}, divisor);
}

int ModelRenderer::fittingDivisor(const core::SampleGrid& grid, int divisor) {
  divisor = std::max(1, divisor);
  while (divisor > 1 && (grid.width % divisor != 0 || grid.height % divisor != 0 ||
                         std::min(grid.width, grid.height) / divisor < 1 ||
                         std::max(grid.width, grid.height) / divisor < 2))
    divisor /= 2;
  return divisor;
}

void ModelRenderer::setLevel(const core::SampleGrid& grid, int divisor) {
  const int w = grid.width, h = grid.height;
  if (divisor < 1 || (divisor & (divisor - 1)) != 0 || w % divisor != 0 || h % divisor != 0 ||
      std::min(w, h) / divisor < 1 || std::max(w, h) / divisor < 2)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "level 1/" + std::to_string(divisor) + " of a " + std::to_string(w) + "x" +
                          std::to_string(h) +
                          " image is not a power-of-two level with at least 2 cells a side");
  if (grid == grid_ && divisor == divisor_) return;
  chunks_->reset(grid, divisor);
  chunksStale_ = true;
  const std::vector<std::uint32_t> indices = chunks_->indices();
  vertexArray_.bind();
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indexBuffer_.id());
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(indices.size() * sizeof(std::uint32_t)), indices.data(),
               GL_STATIC_DRAW);
  glBindVertexArray(0);
  checkGlError("uploading the level's triangles");
  n_ = w;
  grid_ = grid;
  divisor_ = divisor;
  indexCount_ = static_cast<long long>(indices.size());
}

void ModelRenderer::setEnvironment(const core::RasterImage& image) {
  if (image.channels != 4 && image.channels != 3)
    throw GlError("the environment map must be an RGB or RGBA image");
  std::vector<float> rgba;
  rgba.reserve(static_cast<std::size_t>(image.width) * image.height * 4);
  for (std::size_t k = 0; k < image.pixels.size(); k += static_cast<std::size_t>(image.channels))
    rgba.insert(rgba.end(), {image.pixels[k], image.pixels[k + 1], image.pixels[k + 2], 1.0f});
  environment_ = Texture(image.width, image.height, TextureFormat::Rgba16f);
  environment_.upload({0, 0, image.width, image.height}, rgba);
  glBindTexture(GL_TEXTURE_2D, environment_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glBindTexture(GL_TEXTURE_2D, 0);
  checkGlError("uploading the environment map");
}

void ModelRenderer::setMatcap(const core::RasterImage& image) {
  if ((image.channels != 4 && image.channels != 3) || image.width != image.height ||
      image.width < 2)
    throw GlError("a matcap must be a square RGB or RGBA image");
  std::vector<float> rgba;
  rgba.reserve(static_cast<std::size_t>(image.width) * image.height * 4);
  // Flipped: the image's top row is the sphere's top, a texture's first row its bottom.
  for (int y = image.height - 1; y >= 0; --y)
    for (int x = 0; x < image.width; ++x)
      rgba.insert(rgba.end(), {image.at(x, y, 0), image.at(x, y, 1), image.at(x, y, 2), 1.0f});
  matcap_ = Texture(image.width, image.height, TextureFormat::Rgba8);
  matcap_.upload({0, 0, image.width, image.height}, rgba);
  glBindTexture(GL_TEXTURE_2D, matcap_.id());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glBindTexture(GL_TEXTURE_2D, 0);
  checkGlError("uploading the matcap");
}

long long ModelRenderer::displayedTriangles() const {
  return indexCount_ / 3;
}

void ModelRenderer::refreshNormals(GpuDocument& document, std::span<const core::TexelRect> rects) {
  // Called between frames too (the change feed): VTK's cached state must find its framebuffer,
  // viewport and depth test as it left them, or the next frame draws without its depth test
  // (a torus's far side showed through its near one after every stroke).
  const SavedTarget saved;
  const int side = document.side(), rows = document.rows();
  // The stretch preview's map and mean spacing wait for its next draw (refreshStretch).
  meanSpacingStale_ = true;
  if (!stretchAllStale_) {
    staleStretch_.insert(staleStretch_.end(), rects.begin(), rects.end());
    if (staleStretch_.size() > kMaxStaleStretchRects) {
      stretchAllStale_ = true;
      staleStretch_.clear();
    }
  }
  if (normals_.width() != side || normals_.height() != rows) {
    normals_ = Texture(side, rows, TextureFormat::Rgba8);
    glBindTexture(GL_TEXTURE_2D, normals_.id());
    // Linear: between the displayed vertices each pixel blends the four nearest full-res normals.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glBindTexture(GL_TEXTURE_2D, 0);
    const core::TexelRect all = document.whole();
    rects = std::span(&all, 1);
    refreshNormals(document, rects); // the whole map once, then the caller's rects are inside it
    return;
  }
  if (rects.empty()) return;
  if (!chunksStale_ && grid_ == document.grid())
    chunks_->update(document.document().positions, rects);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  normals_.bindAsTarget();
  glViewport(0, 0, side, rows);
  normalProgram_.use();
  bindTexture(0, document.texture(core::EditLayer::Positions));
  glUniform1i(normalProgram_.uniform("u_positions"), 0);
  glUniform1i(normalProgram_.uniform("u_size"), document.size());
  glUniform2i(glGetUniformLocation(normalProgram_.id(), "u_cells"), document.grid().width,
              document.grid().height);
  glUniform1i(glGetUniformLocation(normalProgram_.id(), "u_topology"),
              static_cast<int>(document.topology()));
  glUniform3f(normalProgram_.uniform("u_centreNormal"), 0.0f, 0.0f, 1.0f);
  const std::vector<core::TexelRect> passRects = regions(rects);
  rectPass_.draw(passRects, side, rows);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  checkGlError("normal map pass");
}

void ModelRenderer::refreshAllNormals(GpuDocument& document) {
  const core::TexelRect all = document.whole();
  refreshNormals(document, std::span(&all, 1));
}

void ModelRenderer::refreshStretch(GpuDocument& document) {
  const int side = document.side(), rows = document.rows();
  if (meanSpacingStale_) {
    meanSpacing_ = core::meanSpacing(document.document().positions);
    meanSpacingStale_ = false;
  }
  if (stretch_.width() != side || stretch_.height() != rows) {
    stretch_ = Texture(side, rows, TextureFormat::R32f);
    glBindTexture(GL_TEXTURE_2D, stretch_.id());
    // Nearest: the figure belongs to a sample, not to the surface between samples.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindTexture(GL_TEXTURE_2D, 0);
    stretchAllStale_ = true;
  }
  std::vector<core::TexelRect> rects;
  if (stretchAllStale_)
    rects.push_back(document.whole());
  else
    rects = regions(staleStretch_);
  staleStretch_.clear();
  stretchAllStale_ = false;
  if (rects.empty()) return;
  if (!stretchProgram_.id())
    stretchProgram_ =
        Program("stretch map", rectsVertexShader(), positionsPassSource("stretch_map.glsl"));
  const SavedTarget saved;
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  stretch_.bindAsTarget();
  glViewport(0, 0, side, rows);
  stretchProgram_.use();
  bindTexture(0, document.texture(core::EditLayer::Positions));
  glUniform1i(stretchProgram_.uniform("u_positions"), 0);
  glUniform1i(stretchProgram_.uniform("u_size"), document.size());
  glUniform2i(glGetUniformLocation(stretchProgram_.id(), "u_cells"), document.grid().width,
              document.grid().height);
  glUniform1i(glGetUniformLocation(stretchProgram_.id(), "u_topology"),
              static_cast<int>(document.topology()));
  rectPass_.draw(rects, side, rows);
  glBindTexture(GL_TEXTURE_2D, 0);
  glUseProgram(0);
  checkGlError("stretch map pass");
}

const Program& ModelRenderer::prepareDraw(GpuDocument& document, const ModelView& view,
                                          bool lodVertices) {
  if (normals_.width() != document.side() || normals_.height() != document.rows()) {
    const SavedTarget saved;
    refreshAllNormals(document);
  }
  const bool stretch = view.preview == ModelView::Preview::Stretch;
  if (stretch) refreshStretch(document);
  const core::Document& d = document.document();
  const bool diffuseTexture = view.showDiffuse && !d.diffuse.uniform();
  const bool featureTexture = !d.feature.uniform();
  const bool maskTint =
      view.showMask && !d.mask.uniform() && view.preview == ModelView::Preview::Shaded;
  // Reflection only where something may reflect: a painted feature layer or a reflective fill.
  const bool reflection = environment_.id() != 0 && (featureTexture || d.feature.fill[2] > 0);
  const bool matcap =
      view.matcap && matcap_.id() != 0 && view.preview == ModelView::Preview::Shaded;
  const Program& p =
      drawVariant({diffuseTexture, featureTexture, maskTint, reflection && !matcap,
                   static_cast<int>(view.preview), lodVertices, matcap, view.wireframe});
  p.use();
  bindTexture(0, document.texture(core::EditLayer::Positions));
  bindTexture(1, normals_);
  bindTexture(2, document.texture(core::EditLayer::Diffuse));
  bindTexture(3, document.texture(core::EditLayer::Mask));
  bindTexture(4, document.texture(core::EditLayer::Feature));
  if (environment_.id()) bindTexture(5, environment_);
  glUniform1i(p.uniform("u_positions"), 0);
  glUniform1i(p.uniform("u_normals"), 1);
  glUniform1i(p.uniform("u_diffuse"), 2);
  glUniform1i(p.uniform("u_mask"), 3);
  glUniform1i(p.uniform("u_feature"), 4);
  glUniform1i(p.uniform("u_environment"), 5);
  if (matcap) {
    bindTexture(6, matcap_);
    glUniform1i(p.uniform("u_matcap"), 6);
    glUniform3f(p.uniform("u_viewRight"), view.viewRight.x, view.viewRight.y, view.viewRight.z);
    glUniform3f(p.uniform("u_viewUp"), view.viewUp.x, view.viewUp.y, view.viewUp.z);
  }
  if (stretch) {
    bindTexture(6, stretch_);
    glUniform1i(p.uniform("u_stretch"), 6);
    glUniform1f(p.uniform("u_meanSpacing"), static_cast<float>(meanSpacing_));
  }
  const std::array<float, 4> diffuseFill =
      view.showDiffuse ? d.diffuse.fill : std::array<float, 4>{0.8f, 0.78f, 0.74f, 1.0f};
  glUniform3f(p.uniform("u_diffuseFill"), diffuseFill[0], diffuseFill[1], diffuseFill[2]);
  glUniform3f(p.uniform("u_featureFill"), d.feature.fill[0], d.feature.fill[1], d.feature.fill[2]);
  glUniform1f(p.uniform("u_maskFill"), d.mask.fill[0]);
  glUniformMatrix4fv(p.uniform("u_objectToClip"), 1, GL_FALSE, view.objectToClip.data());
  if (!lodVertices) {
    glUniform1i(p.uniform("u_step"), divisor_);
    glUniform1i(p.uniform("u_side"), n_ / divisor_ + 1);
  }
  glUniform1i(p.uniform("u_imageSide"), document.side());
  glUniform2i(glGetUniformLocation(p.id(), "u_imageSize"), document.side(), document.rows());
  glUniform3f(p.uniform("u_eye"), view.eye.x, view.eye.y, view.eye.z);
  glUniform1i(p.uniform("u_showBrush"), view.showBrush);
  glUniform3f(p.uniform("u_brushCentre"), view.brushCentre.x, view.brushCentre.y,
              view.brushCentre.z);
  glUniform1f(p.uniform("u_brushRadius"), view.brushRadius);
  glUniform3f(p.uniform("u_brushColour"), view.brushColour[0], view.brushColour[1],
              view.brushColour[2]);
  return p;
}

void ModelRenderer::draw(GpuDocument& document, const ModelView& view) {
  if (indexCount_ == 0 || grid_ != document.grid())
    throw GlError("the model renderer's level was not set for this document");
  prepareDraw(document, view, false);
  if (chunksStale_) {
    chunks_->update(document.document().positions);
    chunksStale_ = false;
  }
  std::vector<std::intptr_t> offsets;
  std::vector<int> counts;
  chunks_->visibleRanges(view.eye, offsets, counts);
  std::vector<const void*> starts;
  drawnTriangles_ = 0;
  for (std::size_t k = 0; k < offsets.size(); ++k) {
    starts.push_back(reinterpret_cast<const void*>(offsets[k]));
    drawnTriangles_ += counts[k] / 3;
  }
  vertexArray_.bind();
  glMultiDrawElements(GL_TRIANGLES, counts.data(), GL_UNSIGNED_INT, starts.data(),
                      static_cast<GLsizei>(counts.size()));
  glBindVertexArray(0);
  unbindAfterDraw();
  checkGlError("drawing the model");
}

void ModelRenderer::setLodMesh(const core::LodMesh& lod) {
  // Five floats a corner: position, then image coordinates. Seam vertices get each triangle's
  // own copy of their image coordinates, so no triangle's texture spans the seam.
  std::vector<float> corners;
  corners.reserve(lod.mesh.triangles.size() * 15);
  for (std::size_t t = 0; t < lod.mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const core::Vec3f& p = lod.mesh.positions[lod.mesh.triangles[t][static_cast<std::size_t>(k)]];
      const core::Vec2f uv =
          t < lod.cornerUv.size() ? lod.cornerUv[t][static_cast<std::size_t>(k)] : core::Vec2f{};
      corners.insert(corners.end(), {p.x, p.y, p.z, uv.x, uv.y});
    }
  if (!lodVertexArray_.id()) {
    lodVertexArray_ = VertexArray::create();
    lodBuffer_ = Buffer::create();
    lodVertexArray_.bind();
    glBindBuffer(GL_ARRAY_BUFFER, lodBuffer_.id());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 5 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 5 * sizeof(float),
                          reinterpret_cast<const void*>(3 * sizeof(float)));
    glBindVertexArray(0);
  }
  glBindBuffer(GL_ARRAY_BUFFER, lodBuffer_.id());
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(corners.size() * sizeof(float)),
               corners.data(), GL_STREAM_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  checkGlError("uploading the level-of-detail mesh");
  lodTriangles_ = static_cast<long long>(lod.mesh.triangles.size());
}

void ModelRenderer::drawLod(GpuDocument& document, const ModelView& view) {
  if (lodTriangles_ == 0) return;
  prepareDraw(document, view, true);
  lodVertexArray_.bind();
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(3 * lodTriangles_));
  glBindVertexArray(0);
  unbindAfterDraw();
  checkGlError("drawing the level-of-detail mesh");
}

} // namespace octaclay::gpu
