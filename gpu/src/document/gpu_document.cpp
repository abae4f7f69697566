#include "octaclay/gpu/gpu_document.h"

#include "area_normal_pass.h"
#include "finite_check_pass.h"
#include "tile_bounds_pass.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::gpu {
namespace {

TextureFormat formatOf(core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Positions:
    return TextureFormat::Rgba32f; // float32 so edits and undo round-trip bit-exactly
  case core::EditLayer::Diffuse:
  case core::EditLayer::Feature:
    return TextureFormat::Rgba16f; // stored as half in the document anyway
  case core::EditLayer::Mask:
    return TextureFormat::R32f;
  }
  return TextureFormat::Rgba32f;
}

// Whether the driver renders on the CPU (its textures in the CPU's memory, a read-back a copy).
bool driverIsSoftware();

// Positions deferred by default where the driver is not a software rasterizer;
// $OCTACLAY_DEFER_POSITIONS = 1 or 0 overrides it (to run the modeller's tests both ways).
bool positionsDeferredByDefault() {
  if (const char* text = std::getenv("OCTACLAY_DEFER_POSITIONS")) {
    if (std::string(text) == "1") return true;
    if (std::string(text) == "0") return false;
  }
  return !driverIsSoftware();
}

bool driverIsSoftware() {
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  if (!renderer) return true;
  const std::string name(renderer);
  for (const char* soft : {"llvmpipe", "softpipe", "SwiftShader", "Software Rasterizer"})
    if (name.find(soft) != std::string::npos) return true;
  return false;
}

} // namespace

int GpuDocument::channels(core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Positions:
  case core::EditLayer::Diffuse:
    return 4;
  case core::EditLayer::Feature:
    return 3;
  case core::EditLayer::Mask:
    return 1;
  }
  return 4;
}

GpuDocument::Storage GpuDocument::makeStorage(const core::SampleGrid& grid) {
  // Textures are (W+1) × (H+1): a torus or plane may be W ≠ H (a thin ring sampled evenly).
  Storage storage;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask})
    storage[index(layer)] = Texture(grid.width + 1, grid.height + 1, formatOf(layer));
  return storage;
}

GpuDocument::GpuDocument(core::Document document, const std::function<void(float)>& progress)
    : GpuDocument(std::move(document), progress, Storage{}) {}

GpuDocument::GpuDocument(core::Document document, const std::function<void(float)>& progress,
                         Storage storage)
    : document_(std::move(document)), bounds_(document_.positions),
      deferPositions_(positionsDeferredByDefault()), software_(driverIsSoftware()) {
  const int side = document_.positions.side(), rows = document_.positions.rows();
  const Texture& ahead = storage[index(core::EditLayer::Positions)];
  const bool made = ahead.id() != 0;
  if (made && (ahead.width() != side || ahead.height() != rows))
    throw GlError("the textures made ahead are " + std::to_string(ahead.width()) + " × " +
                  std::to_string(ahead.height()) + ", the document needs " + std::to_string(side) +
                  " × " + std::to_string(rows));
  // Row bands: a caller on a GUI thread gets control back (progress) between them.
  const int band = std::max(1, (1 << 20) / side);
  const int steps = 4 * ((rows + band - 1) / band);
  int step = 0;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask}) {
    textures_[index(layer)] =
        made ? std::move(storage[index(layer)]) : Texture(side, rows, formatOf(layer));
    core::Layer* l = mirrorLayer(layer);
    // An unpainted layer on a real GPU: cleared there, nothing converted and sent. A software
    // rasterizer writes the texels on the CPU either way, and its band uploads are what give
    // a GUI caller its turns (modeller_render_test's open of an N = 4096 document).
    if (l && l->uniform() && !software_) {
      std::array<float, 4> value{};
      for (int k = 0; k < channels(layer); ++k)
        value[static_cast<std::size_t>(k)] = l->fill[static_cast<std::size_t>(k)];
      for (int y = 0; y < rows; y += band) {
        textures_[index(layer)].fill(value, {0, y, side, std::min(band, rows - y)});
        if (!progress) continue;
        glFinish(); // the band cleared before the caller gets control: no long wait at the end
        progress(static_cast<float>(++step) / static_cast<float>(steps));
      }
      note(layer, whole());
    } else {
      for (int y = 0; y < rows; y += band) {
        push(layer, {0, y, side, std::min(band, rows - y)});
        if (progress) progress(static_cast<float>(++step) / static_cast<float>(steps));
      }
    }
    // An unpainted layer's fill as the texture holds it (half floats round 0.8 to 0.7998), so
    // the mirror equals the texture bit for bit from the start.
    if (l && l->uniform()) {
      const std::vector<float> texel = textures_[index(layer)].read({0, 0, 1, 1});
      for (int k = 0; k < channels(layer); ++k)
        l->fill[k] = texel[k];
    }
  }
}

GpuDocument::~GpuDocument() = default;
GpuDocument::GpuDocument(GpuDocument&&) noexcept = default;
GpuDocument& GpuDocument::operator=(GpuDocument&&) noexcept = default;

const core::Document& GpuDocument::document() const {
  // The mirror is a cache of the textures: bringing it up to date changes nothing a reader sees.
  if (mirrorStale()) const_cast<GpuDocument*>(this)->syncMirror();
  return document_;
}

void GpuDocument::setPositionsDeferred(bool on) {
  syncMirror();
  deferPositions_ = on;
}

void GpuDocument::syncRegion(std::span<const core::TexelRect> rects) const {
  auto& self = const_cast<GpuDocument&>(*this); // as document(): the cache, not the document
  std::vector<std::uint8_t>& stale = self.staleBlocks_[index(core::EditLayer::Positions)];
  if (stale.empty()) return;
  const int side = document_.positions.side(), rows = document_.positions.rows();
  const int blocks = (side + kStaleBlock - 1) / kStaleBlock;
  for (const core::TexelRect& given : rects) {
    const int x0 = std::max(given.x, 0), y0 = std::max(given.y, 0);
    const int x1 = std::min(given.x + given.width, side),
              y1 = std::min(given.y + given.height, rows);
    if (x0 >= x1 || y0 >= y1) continue;
    for (int by = y0 / kStaleBlock; by <= (y1 - 1) / kStaleBlock; ++by)
      for (int bx = x0 / kStaleBlock; bx <= (x1 - 1) / kStaleBlock; ++bx) {
        std::uint8_t& flag = stale[static_cast<std::size_t>(by) * blocks + bx];
        if (!flag) continue;
        flag = 0;
        const int x = bx * kStaleBlock, y = by * kStaleBlock;
        self.readBack(core::EditLayer::Positions,
                      {x, y, std::min(kStaleBlock, side - x), std::min(kStaleBlock, rows - y)});
      }
  }
}

void GpuDocument::refreshBounds(std::span<const core::TexelRect> rects) {
  if (!boundsPass_) boundsPass_ = std::make_unique<detail::TileBoundsPass>();
  boundsPass_->refresh(textures_[index(core::EditLayer::Positions)], bounds_, rects);
}

bool GpuDocument::holdsOnlyFinite(core::EditLayer layer, std::span<const core::TexelRect> rects) {
  if (!finitePass_) finitePass_ = std::make_unique<detail::FiniteCheckPass>();
  return finitePass_->allFinite(textures_[index(layer)], channels(layer),
                                layer == core::EditLayer::Positions, core::kMaxCoordinate, rects);
}

AreaSum GpuDocument::areaSum(std::span<const int> tiles, core::Vec3f centre, float radius) const {
  if (!areaPass_) areaPass_ = std::make_unique<detail::AreaNormalPass>();
  const core::SampleGrid& g = grid();
  return areaPass_->sum(textures_[index(core::EditLayer::Positions)], bounds_, tiles,
                        {g.width, g.height}, topology() == core::Topology::Octahedral, centre,
                        radius);
}

Texture& GpuDocument::scratch(core::EditLayer layer) {
  Texture& twin = scratch_[index(layer)];
  if (twin.id() == 0) {
    // Made in the middle of a pass whose inputs are bound: the active unit keeps its texture.
    GLint bound = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &bound);
    twin = Texture(document_.positions.side(), document_.positions.rows(), formatOf(layer));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(bound));
  }
  return twin;
}

core::Layer* GpuDocument::mirrorLayer(core::EditLayer layer) {
  return const_cast<core::Layer*>(std::as_const(*this).mirrorLayer(layer));
}

const core::Layer* GpuDocument::mirrorLayer(core::EditLayer layer) const {
  switch (layer) {
  case core::EditLayer::Diffuse:
    return &document_.diffuse;
  case core::EditLayer::Feature:
    return &document_.feature;
  case core::EditLayer::Mask:
    return &document_.mask;
  case core::EditLayer::Positions:
    break;
  }
  return nullptr;
}

std::vector<float> GpuDocument::mirrorTexels(core::EditLayer layer, core::TexelRect rect) const {
  const int c = channels(layer);
  std::vector<float> texels(static_cast<std::size_t>(rect.width) * rect.height * c);
  const int side = document_.positions.side();
  for (int y = 0; y < rect.height; ++y)
    for (int x = 0; x < rect.width; ++x) {
      float* out = &texels[(static_cast<std::size_t>(y) * rect.width + x) * c];
      if (layer == core::EditLayer::Positions) {
        const core::Vec4f& t = document_.positions.at(rect.x + x, rect.y + y);
        out[0] = t.x, out[1] = t.y, out[2] = t.z, out[3] = t.w;
        continue;
      }
      const core::Layer& l = *mirrorLayer(layer);
      const std::size_t at = (static_cast<std::size_t>(rect.y + y) * side + rect.x + x) * c;
      for (int k = 0; k < c; ++k)
        out[k] = l.uniform() ? l.fill[k] : l.texels[at + k];
    }
  return texels;
}

void GpuDocument::writeMirror(core::EditLayer layer, core::TexelRect rect,
                              std::span<const float> texels) {
  const int c = channels(layer);
  const int side = document_.positions.side();
  float* mirror = mirrorData(layer);
  const std::size_t rowFloats = static_cast<std::size_t>(rect.width) * c;
  for (int y = 0; y < rect.height; ++y)
    std::copy_n(&texels[y * rowFloats], rowFloats,
                mirror + (static_cast<std::size_t>(rect.y + y) * side + rect.x) * c);
  if (layer == core::EditLayer::Positions) bounds_.refresh(document_.positions, rect);
}

void GpuDocument::restore(core::EditLayer layer, core::TexelRect rect,
                          std::span<const float> texels) {
  syncMirror(); // else a later sync would read deferred regions over what is restored here
  writeMirror(layer, rect, texels);
  push(layer, rect);
}

void GpuDocument::restoreCopy(core::EditLayer layer, core::TexelRect rect,
                              std::span<const float> texels, const Texture& from, int fromX,
                              int fromY) {
  syncMirror(); // as restore()
  writeMirror(layer, rect, texels);
  note(layer, rect);
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, fromX, fromY, 0, textures_[index(layer)].id(),
                     GL_TEXTURE_2D, 0, rect.x, rect.y, 0, rect.width, rect.height, 1);
  checkGlError("restoring a tile from the undo pool");
}

void GpuDocument::push(core::EditLayer layer, core::TexelRect rect) {
  note(layer, rect);
  const core::Layer* l = mirrorLayer(layer);
  if (!l || !l->uniform()) { // straight from the mirror's memory
    const int c = channels(layer);
    const int side = document_.positions.side();
    const float* mirror = l ? l->texels.data() : &std::as_const(document_.positions).at(0, 0).x;
    textures_[index(layer)].uploadFrom(
        rect, mirror + (static_cast<std::size_t>(rect.y) * side + rect.x) * c, side, c);
    return;
  }
  std::vector<float> texels = mirrorTexels(layer, rect);
  Texture& texture = textures_[index(layer)];
  if (texture.channels() != channels(layer)) { // feature: 3 channels in an RGBA texture
    std::vector<float> rgba(static_cast<std::size_t>(rect.width) * rect.height * 4, 0.0f);
    for (std::size_t t = 0; t < rgba.size() / 4; ++t)
      for (int k = 0; k < 3; ++k)
        rgba[t * 4 + k] = texels[t * 3 + k];
    texels = std::move(rgba);
  }
  texture.upload(rect, texels);
}

void GpuDocument::readBack(core::EditLayer layer, core::TexelRect rect) {
  const int c = channels(layer);
  const int side = document_.positions.side();
  const std::size_t at = (static_cast<std::size_t>(rect.y) * side + rect.x) * c;
  textures_[index(layer)].readInto(rect, editedMirror(layer) + at, side, c);
}

void GpuDocument::changed(core::EditLayer layer, core::TexelRect rect) {
  changed(layer, std::span<const core::TexelRect>(&rect, 1));
}

void GpuDocument::changed(core::EditLayer layer, std::span<const core::TexelRect> rects) {
  for (const core::TexelRect& rect : rects)
    note(layer, rect);
  const bool positions = layer == core::EditLayer::Positions;
  if (!deferring_ || (positions && !deferPositions_)) {
    for (const core::TexelRect& rect : rects)
      readBack(layer, rect);
    // Once for all the rectangles: a dab's merged rows share tiles at their edges.
    if (positions) bounds_.refresh(document_.positions, rects);
    return;
  }
  if (positions)
    refreshBounds(rects); // the next pick and reach see the new surface; its texels wait
  else
    editedMirror(layer); // a uniform layer gets texels: brushes see it as painted from now on
  markStale(layer, rects);
}

void GpuDocument::markStale(core::EditLayer layer, std::span<const core::TexelRect> rects) {
  const int blocks = (document_.positions.side() + kStaleBlock - 1) / kStaleBlock;
  const int blockRows = (document_.positions.rows() + kStaleBlock - 1) / kStaleBlock;
  std::vector<std::uint8_t>& stale = staleBlocks_[index(layer)];
  stale.resize(static_cast<std::size_t>(blocks) * blockRows, 0);
  for (const core::TexelRect& rect : rects)
    for (int by = rect.y / kStaleBlock; by <= (rect.y + rect.height - 1) / kStaleBlock; ++by)
      for (int bx = rect.x / kStaleBlock; bx <= (rect.x + rect.width - 1) / kStaleBlock; ++bx)
        stale[static_cast<std::size_t>(by) * blocks + bx] = 1;
}

bool GpuDocument::mirrorStale() const {
  return std::any_of(staleBlocks_.begin(), staleBlocks_.end(),
                     [](const std::vector<std::uint8_t>& s) { return !s.empty(); });
}

void GpuDocument::deferPulls(bool on) {
  deferring_ = on;
  if (!on) syncMirror();
}

void GpuDocument::syncMirror() {
  const int side = document_.positions.side(), rows = document_.positions.rows();
  const int blocks = (side + kStaleBlock - 1) / kStaleBlock;
  const int blockRows = (rows + kStaleBlock - 1) / kStaleBlock;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask}) {
    std::vector<std::uint8_t>& stale = staleBlocks_[index(layer)];
    if (stale.empty()) continue;
    // Runs of stale blocks along each block row, one read each.
    for (int by = 0; by < blockRows; ++by)
      for (int bx = 0; bx < blocks;) {
        if (!stale[static_cast<std::size_t>(by) * blocks + bx]) {
          ++bx;
          continue;
        }
        int end = bx;
        while (end < blocks && stale[static_cast<std::size_t>(by) * blocks + end])
          ++end;
        const int x = bx * kStaleBlock, y = by * kStaleBlock;
        // The tile bounds are current already (refreshed from the GPU after each pass).
        readBack(layer,
                 {x, y, std::min(end * kStaleBlock, side) - x, std::min(kStaleBlock, rows - y)});
        bx = end;
      }
    stale.clear();
  }
}

float* GpuDocument::editedMirror(core::EditLayer layer) {
  if (layer == core::EditLayer::Mask) document_.hasMask = true; // a painted mask is saved
  return mirrorData(layer);
}

float* GpuDocument::mirrorData(core::EditLayer layer) {
  core::Layer* l = mirrorLayer(layer);
  if (!l) return &document_.positions.at(0, 0).x;
  if (l->uniform()) { // the first edit of a layer gives it texels
    const int c = channels(layer);
    l->texels.resize(document_.positions.texelCount() * static_cast<std::size_t>(c));
    for (std::size_t k = 0; k < static_cast<std::size_t>(c); ++k)
      l->texels[k] = l->fill[k];
    // Doubling copies: a 4096 layer's fill is the first stroke's pause otherwise.
    for (std::size_t done = c; done < l->texels.size(); done *= 2)
      std::copy_n(l->texels.begin(), std::min(done, l->texels.size() - done),
                  l->texels.begin() + static_cast<std::ptrdiff_t>(done));
  }
  return l->texels.data();
}

void GpuDocument::writeSaliency(std::span<const float> saliency) {
  syncMirror(); // the whole mirror goes back to the texture below: nothing may wait in it
  std::span<core::Vec4f> texels = document_.positions.texels();
  if (saliency.size() != texels.size())
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "saliency has " + std::to_string(saliency.size()) + " values for " +
                          std::to_string(texels.size()) + " samples");
  for (std::size_t k = 0; k < texels.size(); ++k)
    texels[k].w = saliency[k];
  push(core::EditLayer::Positions, whole()); // the mirror's texels, now with the saliency
}

void GpuDocument::note(core::EditLayer layer, core::TexelRect rect) {
  std::vector<core::TexelRect>& rects = unpublished_[index(layer)];
  rects.push_back(rect);
  // A long stroke between publications: keep the list short. Merged again only once it has
  // doubled since the last merge, so a list that merges to more than 256 (a stroke's quarter
  // tiles) is not sorted again at every rectangle.
  std::size_t& merged = mergedCount_[index(layer)];
  if (rects.size() > std::max<std::size_t>(256, 2 * merged)) {
    rects = core::mergeRects(std::move(rects));
    merged = rects.size();
  }
}

void GpuDocument::markAllChanged() {
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask})
    unpublished_[index(layer)] = {whole()};
}

bool GpuDocument::publishChanges(ChangeKind kind) {
  bool any = false;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask}) {
    std::vector<core::TexelRect> rects = std::move(unpublished_[index(layer)]);
    unpublished_[index(layer)].clear();
    mergedCount_[index(layer)] = 0;
    if (rects.empty()) continue;
    any = true;
    if (follower_) follower_({kind, layer, core::mergeRects(std::move(rects))});
  }
  return any;
}

core::TileApplier undoApplier(GpuDocument& document) {
  return [&document](core::EditLayer layer, core::TexelRect region, std::span<const float> texels) {
    document.restore(layer, region, texels);
  };
}

} // namespace octaclay::gpu
