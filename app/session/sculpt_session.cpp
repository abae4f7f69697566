#include "sculpt_session.h"

#include "keep_detail_run.h"
#include "pointer_legs.h"

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
#include <unordered_map>

namespace octaclay::app {

struct SculptSession::ActiveStroke {
  StrokeStart start;
  float unit = 1;   // object units per radius fraction: the diagonal when the stroke began
  float radius = 0; // object units, before pressure: start.objectRadius or radius × unit
  gpu::BrushManifest manifest; // the stroke refers to it
  std::unique_ptr<gpu::StrokeSession> stroke;
  std::vector<StrokeMove> queue;
  bool failed = false; // a dab threw: the engine restored the layers, no more dabs
  float reach = 0;     // the largest radius a dab used (object units): keep-detail's margin
  KeepDetailRun keep;
  // The first and last image points moved to: keep detail holds the samples there.
  std::optional<std::array<float, 2>> first, last;
  std::function<void(int)> progress; // told the dab count after each dab (observeDabs)
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

void SculptSession::setDocument(core::Document document, const std::function<void(float)>& progress,
                                gpu::GpuDocument::Storage storage) {
  show(std::move(document), progress, std::move(storage));
  history_.clear();
}

void SculptSession::show(core::Document document, const std::function<void(float)>& progress,
                         gpu::GpuDocument::Storage storage) {
  auto uploaded =
      std::make_unique<gpu::GpuDocument>(std::move(document), progress, std::move(storage));
  stroke_.reset();
  document_ = std::move(uploaded);
  document_->setChangeFollower(follower_);
  document_->markAllChanged();
  publish(gpu::ChangeKind::NewDocument);
}

void SculptSession::replaceDocument(core::Document after, const std::string& label) {
  core::EditStep step;
  step.label = label;
  step.replacedBefore = std::make_shared<const core::Document>(document());
  step.replacedAfter = std::make_shared<const core::Document>(std::move(after));
  show(*step.replacedAfter);
  history_.record(std::move(step));
}

void SculptSession::setChangeFollower(std::function<void(const gpu::DocumentChange&)> follower) {
  follower_ = std::move(follower);
  if (document_) document_->setChangeFollower(follower_);
}

void SculptSession::publish(gpu::ChangeKind kind) {
  if (document_) document_->publishChanges(kind);
}

const core::Document& SculptSession::document() const {
  // Mid-stroke (picking, autosave, save): what the stroke deferred (paint; positions too on a
  // GPU) is read back first, by the GpuDocument's document().
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
  if (start.objectRadius && !(std::isfinite(*start.objectRadius) && *start.objectRadius > 0))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "the brush radius must be a positive, finite length (object units), not " +
                          std::to_string(*start.objectRadius));
  auto stroke = std::make_unique<ActiveStroke>();
  stroke->start = start;
  const BrushSettings& settings = start.settings;
  stroke->manifest =
      variants_.prepare(*engine_, *catalog_, start.brushId, settings, start.paintTarget);
  // Fixed for the stroke: a stroke that grows the model must not grow its own brush. Not
  // diagonal()'s floor: a model far below a unit across strokes as it does at unit scale
  // (gpu::StrokeSession refuses one too small for float).
  stroke->unit = document_->bounds().diagonal();
  stroke->radius = start.objectRadius ? *start.objectRadius : settings.radius * stroke->unit;
  gpu::StrokeSettings s;
  s.spacing = start.spacing;
  s.symmetry = settings.symmetry;
  if (start.brushId == settings.brushId) s.parameters = settings.parameters;
  s.viewEye = start.eye; // splats project from here, drags move across its view
  stroke->stroke = std::make_unique<gpu::StrokeSession>(*engine_, *document_, stroke->manifest, s);
  keepDetail_ = settings.keepDetail; // every topology (core/relax: the ball's and the grids')
  // After each dab: keep detail's relaxation as a dragging stroke goes, then the caller's
  // progress. The viewport's and the CLI's strokes both come through here.
  stroke->stroke->observeDabs([this, active = stroke.get()](int dabs) {
    active->keep.pinnedPath.clear();
    for (const auto& uv : {active->first, active->last})
      if (uv) active->keep.pinnedPath.push_back(*uv);
    relaxBetweenDabs(active->keep, *active->stroke, active->manifest, active->reach, dabs);
    if (active->progress) active->progress(dabs);
  });
  stroke_ = std::move(stroke);
}

bool SculptSession::strokeDrags() const {
  return stroke_ && stroke_->stroke->drags();
}

int SculptSession::moveTo(const StrokeMove& m) {
  struct Report { // also when the move throws: a failed dab restored the layers
    SculptSession& session;
    ~Report() { session.publish(gpu::ChangeKind::Dabs); }
  } report{*this};
  return move(m);
}

int SculptSession::move(const StrokeMove& move) {
  ActiveStroke& st = *stroke_;
  if (st.failed) return 0;
  const BrushSettings& settings = st.start.settings;
  // The strength as given: the stroke shares it out among its dabs (dabShare).
  float radius = st.radius;
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
    case StrokeMove::Kind::PointerPoint:
      // The start is held from the first dab on (keep detail relaxes between a drag's dabs).
      if (!st.first) st.first = {move.uv.x, move.uv.y};
      made = walkPointer(*st.stroke, document_->topology(),
                         move.kind == StrokeMove::Kind::PointerPoint ? st.last : std::nullopt,
                         move.uv, radius, strength);
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
    for (const StrokeMove& m : stroke_->queue)
      run.made += move(m);
  } catch (const std::exception& e) {
    run.error = e.what();
    stroke_->failed = true;
  }
  stroke_->queue.clear();
  publish(run.error.empty() ? gpu::ChangeKind::Dabs : gpu::ChangeKind::Applied);
  if (run.made > 0)
    lastDabMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count() /
                 run.made;
  return run;
}

int SculptSession::expectDabs(const std::vector<std::array<float, 2>>& path,
                              const std::vector<core::Vec3f>& dragPoints) const {
  return stroke_->stroke->expectDabs(path, dragPoints, stroke_->radius);
}

void SculptSession::observeDabs(std::function<void(int)> observer) {
  stroke_->progress = std::move(observer);
}

// What a stroke's end carries from its dabs to its record: the relaxation's inputs and result.
struct StrokeEnding::Parts {
  std::unique_ptr<SculptSession::ActiveStroke> stroke;
  const core::Document* mirror = nullptr; // the session's CPU mirror, read by relax()
  core::EditStep record;                  // the stroke's, before the relaxation
  StrokeEnd end;
  core::EditStep relaxation; // relax()'s result (no tiles: none)
};

StrokeEnding::StrokeEnding(std::unique_ptr<Parts> parts) : parts_(std::move(parts)) {}
StrokeEnding::~StrokeEnding() = default;

StrokeEnd SculptSession::finishStroke() {
  std::unique_ptr<StrokeEnding> ending = concludeStroke();
  if (!ending) return {};
  ending->relax();
  return commitStroke(std::move(ending));
}

std::unique_ptr<StrokeEnding> SculptSession::concludeStroke() {
  if (!stroke_) return nullptr;
  auto parts = std::make_unique<StrokeEnding::Parts>();
  parts->stroke = std::move(stroke_); // over even if finish throws
  struct Report { // finish restores the layers when it refuses a non-finite result
    SculptSession& session;
    ~Report() { session.publish(gpu::ChangeKind::StrokeEnd); }
  } report{*this};
  ActiveStroke& st = *parts->stroke;
  parts->end.dabs = st.stroke->dabs();
  parts->end.engineMs = st.stroke->engineMs();
  parts->end.firstMoveMs = st.stroke->firstMoveMs();
  parts->end.firstMoveDabs = st.stroke->firstMoveDabs();
  parts->end.phases = st.stroke->phases();
  lastRelaxation_ = std::move(st.keep.relaxations);
  parts->record = st.stroke->finish(st.start.brushId);
  parts->mirror = &document_->document();
  st.keep.pinnedPath.clear();
  for (const auto& uv : {st.first, st.last})
    if (uv) st.keep.pinnedPath.push_back(*uv);
  auto ending = std::unique_ptr<StrokeEnding>(new StrokeEnding(std::move(parts)));
  ending->relaxes_ = keepDetail_ && st.manifest.category == gpu::Category::Sculpt &&
                     ending->parts_->end.dabs > 0 && !ending->parts_->record.tiles.empty();
  return ending;
}

void StrokeEnding::relax() {
  if (!relaxes_ || solved_) return;
  solved_ = true;
  const auto start = std::chrono::steady_clock::now();
  SculptSession::ActiveStroke& st = *parts_->stroke;
  parts_->relaxation =
      relaxDabsSoFar(st.keep, *parts_->mirror, parts_->record, parts_->record.label, st.reach);
  parts_->end.engineMs +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

StrokeEnd SculptSession::commitStroke(std::unique_ptr<StrokeEnding> ending) {
  if (!ending) return {};
  StrokeEnding::Parts& parts = *ending->parts_;
  core::EditStep record = std::move(parts.record);
  if (!parts.relaxation.tiles.empty()) {
    const core::TileApplier apply = gpu::undoApplier(*document_);
    for (const core::TileChange& t : parts.relaxation.tiles)
      t.apply(core::TileState::After, apply);
    const core::Document& mirror = document_->document();
    lastRelaxation_ =
        lastRelaxation_.tiles.empty()
            ? parts.relaxation
            : core::combineSteps(lastRelaxation_, parts.relaxation, mirror, record.label);
    record = core::combineSteps(record, parts.relaxation, mirror, record.label);
    publish(gpu::ChangeKind::StrokeEnd);
  }
  StrokeEnd end = parts.end;
  end.changedTiles = record.tiles.size();
  end.stepBytes = record.computeBytes();
  if (end.dabs == 0 || record.tiles.empty()) return end;
  end.label = record.label;
  history_.record(std::move(record));
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
  } catch (const gpu::BrushTimeoutError&) { // an overrun pass: likewise
    return;
  }
  const core::TileApplier apply = gpu::undoApplier(*document_);
  for (auto t = record.tiles.rbegin(); t != record.tiles.rend(); ++t)
    t->apply(core::TileState::Before, apply);
  publish(gpu::ChangeKind::Applied);
}

void SculptSession::relaxBetweenDabs(KeepDetailRun& run, gpu::StrokeSession& stroke,
                                     const gpu::BrushManifest& brush, float radius, int dabs) {
  if (!keepDetail_ || brush.category != gpu::Category::Sculpt ||
      brush.stroke != gpu::StrokeKind::Drag || !run.relaxesAfter(dabs))
    return;
  const core::Document& document = document_->document();
  const core::EditStep step =
      relaxDabsSoFar(run, document, stroke.recordSoFar(brush.id), brush.id, radius);
  if (step.tiles.empty()) return;
  stroke.applyBetweenDabs(step);
  run.applied(step, document, brush.id);
}

bool SculptSession::applyChange(const core::Document& after, const std::string& label) {
  core::EditStep change = core::recordDifference(document_->document(), after, label);
  if (change.tiles.empty()) return false;
  struct Report { // also when a tile fails part-way: what was written is redrawn
    SculptSession& session;
    ~Report() { session.publish(gpu::ChangeKind::Applied); }
  } report{*this};
  const core::TileApplier apply = gpu::undoApplier(*document_);
  for (const core::TileChange& t : change.tiles)
    t.apply(core::TileState::After, apply);
  history_.record(std::move(change));
  return true;
}

const core::EditStep* SculptSession::undo() {
  if (!document_ || stroke_ || !history_.canUndo()) return nullptr;
  struct Report {
    SculptSession& session;
    ~Report() { session.publish(gpu::ChangeKind::Undo); }
  } report{*this};
  return history_.undo(gpu::undoApplier(*document_), [this](const core::Document& d) { show(d); });
}

const core::EditStep* SculptSession::redo() {
  if (!document_ || stroke_ || !history_.canRedo()) return nullptr;
  struct Report {
    SculptSession& session;
    ~Report() { session.publish(gpu::ChangeKind::Redo); }
  } report{*this};
  return history_.redo(gpu::undoApplier(*document_), [this](const core::Document& d) { show(d); });
}

std::vector<core::TexelRect> normalRectsAround(std::vector<core::TexelRect> touched, int side,
                                               int rows) {
  if (touched.empty()) return touched;
  if (rows == 0) rows = side;
  // A texel's normal reads its neighbours up to kNormalReach texels away (normal_map.glsl's
  // wide central differences where the four faces around it disagree): grow by that much.
  constexpr int kNormalReach = 3;
  bool border = false;
  for (core::TexelRect& r : touched) {
    const int x0 = std::max(0, r.x - kNormalReach), y0 = std::max(0, r.y - kNormalReach);
    const int x1 = std::min(side, r.x + r.width + kNormalReach),
              y1 = std::min(rows, r.y + r.height + kNormalReach);
    r = {x0, y0, x1 - x0, y1 - y0};
    border = border || x0 == 0 || y0 == 0 || x1 == side || y1 == rows;
  }
  constexpr int strip = kNormalReach + 1;
  if (border) // neighbours across a seam sit on the opposite border
    for (core::TexelRect r :
         {core::TexelRect{0, 0, side, strip}, core::TexelRect{0, rows - strip, side, strip},
          core::TexelRect{0, 0, strip, rows}, core::TexelRect{side - strip, 0, strip, rows}})
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
