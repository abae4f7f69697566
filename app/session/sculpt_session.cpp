#include "sculpt_session.h"

#include "octaclay/core/document/edit_steps.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/core/relax/relax.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gpu_document.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace octaclay::app {

struct SculptSession::ActiveStroke {
  StrokeStart start;
  float unit = 1; // object units per radius fraction: the diagonal when the stroke began
  gpu::BrushManifest manifest; // the stroke refers to it
  std::unique_ptr<gpu::StrokeSession> stroke;
  std::vector<StrokeMove> queue;
  bool failed = false; // a dab threw: the engine restored the layers, no more dabs
  float reach = 0;     // the largest radius a dab used (object units): keep-detail's margin
  // The first and last image points moved to: keep detail holds the samples there.
  std::optional<std::array<float, 2>> first, last;
};

SculptSession::SculptSession() = default;
SculptSession::~SculptSession() = default;

void SculptSession::setBrushes(gpu::BrushEngine& engine, const gpu::BrushCatalog& catalog) {
  engine_ = &engine;
  catalog_ = &catalog;
}

void SculptSession::loadBrush(const gpu::BrushManifest& brush) {
  engine_->load(brush, gpu::BrushCatalog::shaderSource(brush));
}

void SculptSession::brushesReloaded(const std::vector<std::string>& ids) {
  variants_.forget(ids);
}

void SculptSession::setDocument(core::Document document,
                                const std::function<void(float)>& progress) {
  auto uploaded = std::make_unique<gpu::GpuDocument>(std::move(document), progress);
  stroke_.reset();
  document_ = std::move(uploaded);
  history_.clear();
}

const core::Document& SculptSession::document() const {
  // Mid-stroke (autosave, save): the paint the stroke deferred is read back first.
  if (document_->mirrorStale()) document_->syncMirror();
  return document_->document();
}

float SculptSession::diagonal() const {
  return document_ ? std::max(document_->bounds().diagonal(), 1e-6f) : 1.0f;
}

void SculptSession::releaseGpu() {
  stroke_.reset();
  document_.reset();
}

void SculptSession::beginStroke(const StrokeStart& start) {
  auto stroke = std::make_unique<ActiveStroke>();
  stroke->start = start;
  const BrushSettings& settings = start.settings;
  stroke->manifest =
      variants_.prepare(*engine_, *catalog_, start.brushId, settings, start.paintTarget);
  // Fixed for the stroke: a stroke that grows the model must not grow its own brush. Not
  // diagonal()'s floor: a model far below a unit across strokes as it does at unit scale
  // (gpu::StrokeSession refuses one too small for float).
  stroke->unit = document_->bounds().diagonal();
  gpu::StrokeSettings s;
  s.spacing = start.spacing;
  s.symmetry = settings.symmetry;
  if (start.brushId == settings.brushId) s.parameters = settings.parameters;
  s.viewEye = start.eye; // splats project from here, drags move across its view
  stroke->stroke = std::make_unique<gpu::StrokeSession>(*engine_, *document_, stroke->manifest, s);
  keepDetail_ = settings.keepDetail;
  stroke_ = std::move(stroke);
}

bool SculptSession::strokeDrags() const {
  return stroke_ && stroke_->stroke->drags();
}

int SculptSession::moveTo(const StrokeMove& move) {
  ActiveStroke& st = *stroke_;
  if (st.failed) return 0;
  const BrushSettings& settings = st.start.settings;
  // The strength as given: the stroke shares it out among its dabs (dabShare).
  float radius = settings.radius * st.unit;
  float strength = settings.strength;
  if (settings.pressureTarget == PressureTarget::Radius)
    radius *= std::max(move.pressure, 0.05f);
  else if (settings.pressureTarget == PressureTarget::Strength)
    strength *= move.pressure;
  strength *= st.start.sign;
  st.reach = std::max(st.reach, radius);
  int made = 0;
  try {
    switch (move.kind) {
    case StrokeMove::Kind::ImagePoint:
      made = st.stroke->moveToUv(move.uv, radius, strength, 1.0f);
      if (!st.first) st.first = {move.uv.x, move.uv.y};
      st.last = {move.uv.x, move.uv.y};
      break;
    case StrokeMove::Kind::Ray:
      made = st.stroke->dragAlong(move.origin, move.direction, radius, strength, 1.0f);
      break;
    case StrokeMove::Kind::ObjectPoint:
      made = st.stroke->dragTo(move.origin, radius, strength, 1.0f);
      break;
    }
  } catch (...) { // a failed dab put the layers back; a refused move made none: no more moves
    st.failed = true;
    throw;
  }
  dabCount_ += made;
  return made;
}

void SculptSession::queueMove(const StrokeMove& move) {
  stroke_->queue.push_back(move);
}

DabRun SculptSession::runQueuedMoves() {
  DabRun run;
  if (!stroke_ || stroke_->queue.empty()) return run;
  if (stroke_->failed) {
    stroke_->queue.clear();
    return run;
  }
  const auto start = std::chrono::steady_clock::now();
  try {
    for (const StrokeMove& move : stroke_->queue)
      run.made += moveTo(move);
    run.touched = stroke_->stroke->takeTouched();
  } catch (const std::exception& e) {
    run.error = e.what();
    stroke_->failed = true;
  }
  stroke_->queue.clear();
  if (run.made > 0)
    lastDabMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count() /
                 run.made;
  return run;
}

int SculptSession::expectDabs(const std::vector<std::array<float, 2>>& path,
                              const std::vector<core::Vec3f>& dragPoints) const {
  return stroke_->stroke->expectDabs(path, dragPoints,
                                     stroke_->start.settings.radius * stroke_->unit);
}

void SculptSession::observeDabs(std::function<void(int)> observer) {
  stroke_->stroke->observeDabs(std::move(observer));
}

StrokeEnd SculptSession::finishStroke() {
  StrokeEnd end;
  if (!stroke_) return end;
  const std::unique_ptr<ActiveStroke> ending = std::move(stroke_); // over even if finish throws
  const std::string label = ending->start.brushId;
  end.dabs = ending->stroke->dabs();
  end.engineMs = ending->stroke->engineMs();
  lastRelaxation_ = {};
  core::EditStep record = ending->stroke->finish(label);
  if (end.dabs > 0 && !record.tiles.empty()) {
    const auto start = std::chrono::steady_clock::now();
    std::vector<std::array<float, 2>> held;
    for (const auto& uv : {ending->first, ending->last})
      if (uv) held.push_back(*uv);
    record = keepDetailAfter(std::move(record), ending->manifest, ending->reach, held);
    end.engineMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  end.changedTiles = record.tiles.size();
  end.stepBytes = record.computeBytes();
  if (end.dabs == 0 || record.tiles.empty()) return end;
  history_.record(std::move(record));
  end.label = label;
  return end;
}

void SculptSession::abandonStroke() {
  if (!stroke_) return;
  const std::unique_ptr<ActiveStroke> ending = std::move(stroke_);
  core::EditStep record;
  try {
    record = ending->stroke->finish(ending->start.brushId);
  } catch (const core::Error&) { // a non-finite result: finish restored the layers itself
    return;
  }
  const core::TileApplier apply = gpu::undoApplier(*document_);
  for (auto t = record.tiles.rbegin(); t != record.tiles.rend(); ++t)
    t->apply(core::TileState::Before, apply);
}

namespace {

// The samples a stroke changed in the positions, to the texel ((N+1)², row-major): the
// relaxation after it reaches keepDetailMargin samples beyond them and no farther.
std::vector<std::uint8_t> changedSamples(const core::EditStep& record, int side) {
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(side) * static_cast<std::size_t>(side),
                                    0);
  bool any = false;
  for (const core::TileChange& t : record.tiles) {
    if (t.layer != core::EditLayer::Positions) continue;
    std::size_t at = 0;
    for (std::size_t r = 0; r + 1 < t.runs.size(); r += 2) {
      at += t.runs[r];
      for (std::size_t k = 0; k < t.runs[r + 1]; ++k, ++at) {
        const std::size_t i =
            static_cast<std::size_t>(t.region.x) + at % static_cast<std::size_t>(t.region.width);
        const std::size_t j =
            static_cast<std::size_t>(t.region.y) + at / static_cast<std::size_t>(t.region.width);
        changed[j * static_cast<std::size_t>(side) + i] = 1;
        any = true;
      }
    }
  }
  if (!any) changed.clear();
  return changed;
}

} // namespace

core::EditStep SculptSession::keepDetailAfter(core::EditStep record,
                                              const gpu::BrushManifest& brush, float radius,
                                              const std::vector<std::array<float, 2>>& pinnedPath) {
  lastRelaxation_ = {};
  if (!keepDetail_ || brush.category != gpu::Category::Sculpt || record.tiles.empty())
    return record;
  const int n = document_->size();
  const std::vector<std::uint8_t> changed = changedSamples(record, n + 1);
  if (changed.empty()) return record;
  core::RelaxOptions options;
  for (const auto& uv : pinnedPath)
    options.pinned.push_back({static_cast<int>(std::lround(uv[0] * static_cast<float>(n))),
                              static_cast<int>(std::lround(uv[1] * static_cast<float>(n)))});
  lastRelaxation_ = core::relaxChangedStep(
      document_->document(), changed,
      core::keepDetailMargin(document_->document().positions, radius), record.label, options);
  if (lastRelaxation_.tiles.empty()) return record;
  const core::TileApplier apply = gpu::undoApplier(*document_);
  for (const core::TileChange& t : lastRelaxation_.tiles)
    t.apply(core::TileState::After, apply);
  return core::combineSteps(record, lastRelaxation_, document_->document(), record.label);
}

std::vector<core::TexelRect> SculptSession::applyChange(const core::Document& after,
                                                        const std::string& label) {
  core::EditStep change = core::recordDifference(document_->document(), after, label);
  if (change.tiles.empty()) return {};
  const core::TileApplier apply = gpu::undoApplier(*document_);
  for (const core::TileChange& t : change.tiles)
    t.apply(core::TileState::After, apply);
  std::vector<core::TexelRect> rects = changedRects(change);
  history_.record(std::move(change));
  return rects;
}

const core::EditStep* SculptSession::undo() {
  if (!document_ || stroke_ || !history_.canUndo()) return nullptr;
  return history_.undo(gpu::undoApplier(*document_));
}

const core::EditStep* SculptSession::redo() {
  if (!document_ || stroke_ || !history_.canRedo()) return nullptr;
  return history_.redo(gpu::undoApplier(*document_));
}

std::vector<core::TexelRect> normalRectsAround(std::vector<core::TexelRect> touched, int side) {
  if (touched.empty()) return touched;
  bool border = false;
  for (core::TexelRect& r : touched) {
    // A texel's normal reads its neighbours: grow by one.
    const int x0 = std::max(0, r.x - 1), y0 = std::max(0, r.y - 1);
    const int x1 = std::min(side, r.x + r.width + 1), y1 = std::min(side, r.y + r.height + 1);
    r = {x0, y0, x1 - x0, y1 - y0};
    border = border || x0 == 0 || y0 == 0 || x1 == side || y1 == side;
  }
  if (border) // neighbours across a seam sit on the opposite border
    for (core::TexelRect r :
         {core::TexelRect{0, 0, side, 2}, core::TexelRect{0, side - 2, side, 2},
          core::TexelRect{0, 0, 2, side}, core::TexelRect{side - 2, 0, 2, side}})
      touched.push_back(r);
  return core::mergeRects(touched);
}

std::vector<core::TexelRect> changedRects(const core::EditStep& stroke) {
  std::vector<core::TexelRect> rects;
  for (const core::TileChange& t : stroke.tiles)
    rects.push_back(t.region);
  return rects;
}

} // namespace octaclay::app
