#include "octaclay/gpu/brush_engine.h"

#include "all_layers_pass.h"
#include "brush_inputs.h"
#include "brush_program.h"
#include "dab_pass.h"
#include "layer_passes.h"
#include "loaded_brush.h"
#include "pass_watchdog.h"
#include "reparameterize_pass.h"
#include "seam_pass.h"
#include "texture_copy.h"
#include "texture_units.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <tuple>

namespace octaclay::gpu {

using detail::assemble;
using detail::brushLog;
using detail::enumValues;

namespace {

// GL 4.5 or ARB_texture_barrier: a pass may read the texel it writes.
bool hasTextureBarrier() {
  return epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_texture_barrier");
}

// $OCTACLAY_PASS_TIME_LIMIT_MS when it is a number of milliseconds >= 0 (0: no watchdog),
// else 2 s. Lets a test (or a user on a slow GPU) change the limit of a command-line run.
std::chrono::nanoseconds defaultPassTimeLimit() {
  if (const char* text = std::getenv("OCTACLAY_PASS_TIME_LIMIT_MS")) {
    char* end = nullptr;
    const double ms = std::strtod(text, &end);
    if (end != text && *end == '\0' && ms >= 0 && ms <= 1e9)
      return std::chrono::nanoseconds(static_cast<std::int64_t>(ms * 1e6));
  }
  return std::chrono::seconds(2);
}

} // namespace

BrushEngine::BrushEngine()
    : passTimeLimit_(defaultPassTimeLimit()), watchdog_(std::make_unique<detail::PassWatchdog>()),
      seamProgram_(detail::seamProgram()), nearestMaps_(Sampler::repeating(false)),
      bilinearMaps_(Sampler::repeating(true)),
      allLayers_(std::make_unique<detail::AllLayersPass>()),
      reparameterize_(std::make_unique<detail::ReparameterizePass>()) {}

BrushEngine::~BrushEngine() = default;

void BrushEngine::load(const BrushManifest& given, const std::string& shaderSource) {
  auto brush = std::make_unique<LoadedBrush>();
  brush->manifest = given;
  // The catalog checked this when it loaded the brush; a manifest made otherwise (tests, a
  // caller's own) is held to the same contract here.
  try {
    detail::resolveShaderContract(brush->manifest, shaderSource);
  } catch (const BrushLoadError& e) {
    throw GlError("brush " + given.id + ": " + e.what());
  }
  const BrushManifest& manifest = brush->manifest;
  brush->body = shaderSource;
  brush->allLayers = manifest.pass == PassKind::AllLayers;
  if (brush->reparameterize()) {
    // Every layer is resampled into its scratch from the layers before the dab: none in place.
    program(*brush, core::EditLayer::Positions, false, enumValues(manifest, {}));
    brushes_[manifest.id] = std::move(brush);
    return;
  }
  if (hasTextureBarrier()) {
    // A layer is written in place unless the brush reads it ("reads": other texels of it);
    // the prelude's normals read the positions' neighbours.
    brush->inPlace[0] = !manifest.needsNormal() && !manifest.readsLayer(core::EditLayer::Positions);
    brush->inPlace[1] = !manifest.readsLayer(core::EditLayer::Diffuse);
    brush->inPlace[2] = !manifest.readsLayer(core::EditLayer::Feature);
    brush->inPlace[3] = !brush->allLayers && !manifest.readsLayer(core::EditLayer::Mask);
  }
  if (!manifest.mix.empty()) {
    const std::string file = manifest.shaderPath().string();
    for (core::EditLayer layer : manifest.mix) {
      const char* sampler = layer == core::EditLayer::Diffuse ? "u_diffuseLayer" : "u_featureLayer";
      if (manifest.readsLayer(layer))
        throw GlError("brush " + manifest.id + ": " + file + ": it mixes " +
                      std::string(toManifestName(layer)) + " (\"mix\"), so it cannot read " +
                      sampler + " (\"reads\"): the blender writes that layer during the pass");
      brush->inPlace[static_cast<std::size_t>(layer)] = true; // the blender reads the target
    }
  }
  for (core::EditLayer layer : manifest.writes)
    program(*brush, layer, false, enumValues(manifest, {}));
  brushes_[manifest.id] = std::move(brush); // only now: a failed reload keeps the old version
}

const Program& BrushEngine::program(LoadedBrush& brush, core::EditLayer layer, bool maskTexture,
                                    const std::vector<int>& enums, bool batched) {
  const auto key =
      std::tuple{brush.allLayers || brush.reparameterize() ? core::EditLayer::Positions : layer,
                 maskTexture, enums, batched};
  const auto found = brush.programs.find(key);
  if (found != brush.programs.end()) return found->second;
  const std::string file = brush.manifest.shaderPath().string();
  try {
    return brush.programs
        .emplace(key,
                 Program(file, batched ? batchedRectsVertexShader() : rectsVertexShader(),
                         assemble(brush.manifest, layer, brush.allLayers, maskTexture,
                                  brush.allLayers ? brush.allInPlace() : brush.writesInPlace(layer),
                                  enums, brush.body, batched)))
        .first->second;
  } catch (const GlError& e) {
    throw GlError("brush " + brush.manifest.id + ": " + brushLog(e.what(), file));
  }
}

bool BrushEngine::has(const std::string& id) const {
  return brushes_.count(id) > 0;
}

const std::string* BrushEngine::brokenReason(const std::string& id) const {
  const auto it = brushes_.find(id);
  return it != brushes_.end() && !it->second->broken.empty() ? &it->second->broken : nullptr;
}

bool BrushEngine::usesCentreNormal(const GpuDocument& document, const std::string& brushId,
                                   const std::map<std::string, std::array<float, 4>>& parameters) {
  const auto found = brushes_.find(brushId);
  if (found == brushes_.end())
    throw core::Error(core::ErrorKind::UnknownId, "no brush named '" + brushId + "' is loaded");
  LoadedBrush& brush = *found->second;
  const bool maskTexture = !document.mirror().mask.uniform();
  const std::vector<int> enums = enumValues(brush.manifest, parameters);
  for (core::EditLayer layer : brush.manifest.writes) {
    const Program& pass = program(brush, layer, maskTexture, enums);
    for (const char* name :
         {"u_centreNormal", "u_projectionDir", "u_projectionRight", "u_projectionUp"})
      if (pass.uniform(name) >= 0) return true;
  }
  return false;
}

void BrushEngine::passIssued(const LoadedBrush& brush) {
  watchdog_->submitted(passTimeLimit_, brush.manifest.id);
  checkOverrun(watchdog_->keepWithin(1, passTimeLimit_));
}

void BrushEngine::awaitPasses() {
  checkOverrun(watchdog_->keepWithin(0, passTimeLimit_));
}

void BrushEngine::finishPasses() {
  awaitPasses();
}

void BrushEngine::checkOverrun(const std::string* overran) {
  if (!overran) return;
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  const auto found = brushes_.find(*overran);
  const std::string shader =
      found != brushes_.end() ? found->second->manifest.shaderPath().string() : *overran;
  std::string reason = shader + ": a pass took longer than " +
                       detail::describeLimit(passTimeLimit_) + " (brush " + *overran +
                       " is marked broken until it is loaded again)";
  if (found != brushes_.end()) found->second->broken = reason;
  throw BrushTimeoutError(reason);
}

DabResult BrushEngine::dab(GpuDocument& document, const std::string& brushId, const Dab& dab) {
  return this->dab(document, brushId, dab, reach(document, brushId, dab));
}

DabResult BrushEngine::dab(GpuDocument& document, const std::string& brushId, const Dab& dab,
                           std::vector<core::TexelRect> tiles) {
  DabResult result;
  result.tiles = std::move(tiles);
  if (result.tiles.empty()) return result;
  LoadedBrush& brush = *brushes_.at(brushId);
  if (!brush.broken.empty()) throw BrushTimeoutError(brush.broken);
  const int side = document.side(), rows = document.rows();
  for (const core::TexelRect& t : result.tiles)
    result.texels += static_cast<std::size_t>(t.width) * t.height;
  result.seams = seamRuns(result.tiles, side, rows, document.topology());

  // A torus's pass computes column W and row H as columns and rows 0 (identifiedTexel), so it
  // writes identified samples equal itself when it runs over both: its rects take the partners
  // the tiles miss, and no seaming pass follows (on a CPU rasterizer that pass, its target
  // switch and copies cost 13 % of a dab across the wrap). A ball's partners are mirrored, not
  // translated: its seams stay a pass of their own, as do a reparameterize brush's.
  const bool seamsInPass = document.topology() == core::Topology::Torus && !brush.reparameterize();
  std::vector<core::TexelRect> rects = core::mergeRects(result.tiles);
  if (seamsInPass)
    for (const core::TexelRect& part : detail::uncoveredParts(result.seams, result.tiles))
      rects.push_back(part);
  runPasses(document, brush, {&dab, 1}, rects, {},
            seamsInPass ? std::vector<core::TexelRect>{} : result.seams, result.seams);
  return result;
}

std::vector<DabResult> BrushEngine::dabs(GpuDocument& document, const std::string& brushId,
                                         std::span<const Dab> dabs,
                                         std::vector<std::vector<core::TexelRect>> tiles) {
  std::vector<DabResult> results;
  if (!batches(document, brushId, dabs, tiles)) {
    for (std::size_t k = 0; k < dabs.size(); ++k)
      results.push_back(dab(document, brushId, dabs[k], std::move(tiles[k])));
    return results;
  }
  LoadedBrush& brush = *brushes_.at(brushId);
  // Each dab's tiles merged on their own: a rectangle holds one dab's texels.
  std::vector<core::TexelRect> rects;
  std::vector<int> rectDabs;
  for (std::size_t k = 0; k < dabs.size(); ++k) {
    DabResult result;
    result.tiles = std::move(tiles[k]);
    for (const core::TexelRect& t : result.tiles)
      result.texels += static_cast<std::size_t>(t.width) * t.height;
    for (const core::TexelRect& r : core::mergeRects(result.tiles)) {
      rects.push_back(r);
      rectDabs.push_back(static_cast<int>(k));
    }
    results.push_back(std::move(result));
  }
  runPasses(document, brush, dabs, rects, rectDabs, {}, {});
  return results;
}

bool BrushEngine::batches(const GpuDocument& document, const std::string& brushId,
                          std::span<const Dab> dabs,
                          const std::vector<std::vector<core::TexelRect>>& tiles) const {
  const auto found = brushes_.find(brushId);
  if (dabs.size() < 2 || dabs.size() > kMaxBatch || tiles.size() != dabs.size() ||
      found == brushes_.end() || !found->second->broken.empty())
    return false;
  const BrushManifest& manifest = found->second->manifest;
  // A reparameterize step keeps its field between dabs; a material is bound per dab; the
  // parameters are one program's uniforms and enum constants.
  if (manifest.pass == PassKind::Reparameterize) return false;
  for (const BrushParameter& p : manifest.parameters)
    if (p.type == ParameterType::Material) return false;
  for (const Dab& d : dabs)
    if (d.parameters != dabs[0].parameters) return false;
  // Each dab's tiles, grown by what its pass may read around them, clear of the border (no
  // seaming pass) and of every other dab's. A brush that reads no layer ("reads") reads its own
  // texel and, for its normals, the eight around it; one that reads some may read as far again
  // as its tiles reach (smooth reads the eight around, relax and the mask brushes their texel).
  const bool readsAround = !manifest.reads.empty();
  std::vector<core::TexelRect> reads;
  for (const std::vector<core::TexelRect>& dabTiles : tiles) {
    if (dabTiles.empty() ||
        !seamRuns(dabTiles, document.side(), document.rows(), document.topology()).empty())
      return false;
    int x0 = dabTiles[0].x, y0 = dabTiles[0].y, x1 = x0, y1 = y0;
    for (const core::TexelRect& t : dabTiles) {
      x0 = std::min(x0, t.x), y0 = std::min(y0, t.y);
      x1 = std::max(x1, t.x + t.width), y1 = std::max(y1, t.y + t.height);
    }
    const int w = readsAround ? x1 - x0 : 1, h = readsAround ? y1 - y0 : 1;
    reads.push_back({x0 - w, y0 - h, x1 - x0 + 2 * w, y1 - y0 + 2 * h});
  }
  for (std::size_t a = 0; a < reads.size(); ++a)
    for (std::size_t b = a + 1; b < reads.size(); ++b) {
      const core::TexelRect &p = reads[a], &q = reads[b];
      if (p.x < q.x + q.width && q.x < p.x + p.width && p.y < q.y + q.height &&
          q.y < p.y + p.height)
        return false;
    }
  return true;
}

void BrushEngine::runPasses(GpuDocument& document, LoadedBrush& brush, std::span<const Dab> dabs,
                            const std::vector<core::TexelRect>& rects,
                            const std::vector<int>& rectDabs,
                            const std::vector<core::TexelRect>& seamed,
                            const std::vector<core::TexelRect>& seams) {
  const Dab& dab = dabs[0];
  const bool batched = !rectDabs.empty();
  const bool maskTexture = !document.mirror().mask.uniform();
  const std::vector<int> enums = enumValues(brush.manifest, dab.parameters);
  const int side = document.side(), rows = document.rows();
  std::vector<core::TexelRect> changedRects = rects; // what a pass changes: rects and seams
  changedRects.insert(changedRects.end(), seams.begin(), seams.end());
  if (brush.manifest.needsStrokeStart()) {
    if (!strokeOpen_) strokeStartOf_ = nullptr; // a dab of its own is a stroke of its own
    captureStrokeStart(document);
  }

  // The material samplers would override the filtering of whatever VTK binds to those units.
  struct MaterialUnitsRelease {
    ~MaterialUnitsRelease() { releaseMaterialUnits(); }
  } releaseMaterialUnits;
  // The modeller's context carries VTK's and Qt's state: passes must not blend, test or cull.
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, side, rows);
  const auto bindInputs = [&](const Program& pass, core::EditLayer layer) {
    pass.use();
    detail::setUniforms(pass, brush.manifest, document, layer, dab);
    if (batched) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, batchDabs_.id());
    detail::bindLayers(document, layer, brush.samples(core::EditLayer::Diffuse),
                       brush.samples(core::EditLayer::Feature));
    bindMaterial(pass, brush.manifest, document, dab);
    if (brush.manifest.needsStrokeStart()) {
      detail::kStrokeStartUnit.bind(strokeStart_.id());
      glActiveTexture(GL_TEXTURE0);
    }
  };
  // The layer's scratch holds the pass's result over rects: back into the layer's texture,
  // seamed, and into the mirror.
  const auto finishLayer = [&](core::EditLayer layer) {
    // The watchdog before the CPU reads the layer back, and before the copies below: a driver
    // may run those on the CPU at once, behind the pass.
    if (document.readsAtOnce(layer)) awaitPasses();
    if (brush.writesInPlace(layer)) {
      // The pass wrote the layer's texture itself.
    } else if (rects.size() == 1 && rects[0] == document.whole()) {
      document.swapScratch(layer);
    } else {
      for (const core::TexelRect& r : rects)
        detail::copyRect(document.scratch(layer), document.texture(layer), r);
    }
    if (!seamed.empty()) detail::seamLayer(seamProgram_, rectPass_, document, layer, seamed);
    checkGlError("brush " + brush.manifest.id + " pass");

    document.changed(layer, changedRects);
  };

  // A batch's values, once for every layer's pass (bindInputs binds them).
  if (batched) detail::uploadBatch(batchDabs_, brush.manifest, document, dabs);
  // The brush's pass kind draws; each layer it wrote is finished through finishLayer.
  detail::DabPass pass{document,
                       brush,
                       dab,
                       rects,
                       maskTexture,
                       enums,
                       rectPass_,
                       [&] {
                         if (batched)
                           rectPass_.draw(rects, rectDabs, side, rows);
                         else
                           rectPass_.draw(rects, side, rows);
                       },
                       [&](core::EditLayer layer) -> const Program& {
                         return program(brush, layer, maskTexture, enums, batched);
                       },
                       bindInputs,
                       [&] { passIssued(brush); },
                       finishLayer};
  switch (brush.manifest.pass) {
  case PassKind::Reparameterize: {
    const std::vector<core::EditLayer> layers =
        detail::ReparameterizePass::layersOf(document.mirror());
    reparameterize_->run(pass, layers, strokeOpen_);
    for (core::EditLayer layer : layers)
      finishLayer(layer);
    break;
  }
  case PassKind::AllLayers:
    allLayers_->run(pass);
    break;
  case PassKind::Layers:
    detail::runLayerPasses(pass);
    break;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void BrushEngine::captureStrokeStart(GpuDocument& document) {
  if (strokeStartOf_ == &document) return;
  const int side = document.side(), rows = document.rows();
  const Texture& positions = document.texture(core::EditLayer::Positions);
  if (strokeStart_.width() != side || strokeStart_.height() != rows ||
      strokeStart_.format() != positions.format())
    strokeStart_ = Texture(side, rows, positions.format());
  detail::copyRect(positions, strokeStart_, document.whole());
  strokeStartOf_ = &document;
}

void BrushEngine::endStroke() {
  strokeOpen_ = false;
  strokeStartOf_ = nullptr;
  reparameterize_->endStroke();
}

} // namespace octaclay::gpu
