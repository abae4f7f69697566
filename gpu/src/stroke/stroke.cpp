#include "octaclay/gpu/stroke.h"

#include "stroke_settings_check.h"
#include "stroke_state.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/gpu/stroke_rules.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <vector>

namespace octaclay::gpu {

core::Sample nearestSample(const GpuDocument& document, core::Vec3f p) {
  const core::TileBounds& bounds = document.bounds();
  const core::GeometryImage& image = document.mirror().positions;
  float radius = 1e-3f * std::max(bounds.diagonal(), 1e-6f);
  for (;;) {
    float best = std::numeric_limits<float>::max();
    core::Sample found{};
    const std::vector<int> tiles = bounds.tilesNearSphere(p, radius);
    syncTiles(document, tiles);
    for (int t : tiles) {
      const core::TexelRect r = bounds.tileRect(t % bounds.tilesX(), t / bounds.tilesX());
      for (int j = r.y; j < r.y + r.height; ++j)
        for (int i = r.x; i < r.x + r.width; ++i) {
          const core::Vec3f d = image.at(i, j).xyz() - p;
          const float d2 = core::dot(d, d);
          if (d2 < best) best = d2, found = {i, j};
        }
    }
    if (best <= radius * radius) return found;
    radius *= 4; // nothing that close yet: widen the search
  }
}

StrokeSession::State::State(BrushEngine& e, GpuDocument& d, const BrushManifest& b,
                            StrokeSettings s)
    : engine(e), document(d), brush(b), settings(std::move(s)), undo(d, b.writes) {
  // Paint layers are read back once at the stroke's end, not after every dab: the stroke
  // itself reads only positions (and undo tiles before their first dab).
  document.deferPulls(true);
  engine.beginStroke(); // a reparameterize brush resamples once per stroke
}
StrokeSession::State::~State() {
  if (finished) return;
  try {
    engine.endStroke();
    document.deferPulls(false);
  } catch (...) { // an abandoned stroke: the textures stay right, only the mirror may lag
  }
}

// Whether the brush's passes read the dab's centre normal: the area normal, a sum over every
// cell the dab covers on the CPU, is computed only for those (a smooth dab's normal reaches no
// pass); the others get the point normal.
bool StrokeSession::State::usesCentreNormal() const {
  return engine.usesCentreNormal(document, brush.id, settings.parameters);
}

// Puts the layers back as they were before the stroke; the session is over.
void StrokeSession::State::abandon() {
  finished = abandoned = true;
  undo.restore();
  engine.endStroke();
  try {
    document.deferPulls(false);
  } catch (...) { // the restored texels are in the mirror and the textures already
  }
}

// The surface as it was when the stroke began, at image point (x, y) in samples: what the
// dabs' spacing is measured on, so that a stroke does not stretch its own spacing.
core::Vec3f StrokeSession::State::startPosition(double x, double y) const {
  const core::GridPoint p = surfacePointAt(document.mirror().positions.grid(), x, y);
  core::Vec3f sum;
  for (int k = 0; k < 3; ++k)
    sum += undo.positionBefore(p.corners[k]) * p.weights[k];
  return sum;
}

StrokeSession::StrokeSession(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                             StrokeSettings settings) {
  if (!engine.has(brush.id))
    throw core::Error(core::ErrorKind::UnknownId, "no brush named '" + brush.id + "' is loaded");
  detail::checkSettings(brush, settings);
  state_ = std::make_unique<State>(engine, document, brush, std::move(settings));
  state_->share = dabShare(brush, state_->settings.spacing);
  core::BoundingBox box;
  const core::TileBounds& bounds = document.bounds();
  for (int t = 0; t < bounds.tileCount(); ++t) {
    box.extend(bounds.box(t).min);
    box.extend(bounds.box(t).max);
  }
  if (const auto problem = core::sizeProblem(box))
    throw core::Error(core::ErrorKind::InvalidInput, "cannot sculpt this document: " + *problem);
  state_->centre = (box.min + box.max) * 0.5f;
  state_->diagonal = static_cast<double>(core::length(box.max - box.min));
}

StrokeSession::~StrokeSession() = default;

int StrokeSession::moveTo(core::Sample s, float radius, float strength, float pressure) {
  const int n = state_->document.grid().width, h = state_->document.grid().height;
  if (s.i < 0 || s.i > n || s.j < 0 || s.j > h)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "sample (" + std::to_string(s.i) + ", " + std::to_string(s.j) +
                          ") is outside the image (0 to " + std::to_string(n) + " in i, 0 to " +
                          std::to_string(h) + " in j)");
  return state_->moveTo({static_cast<double>(s.i), static_cast<double>(s.j)}, radius, strength,
                        pressure);
}

int StrokeSession::moveToUv(core::Vec2f uv, float radius, float strength, float pressure) {
  requirePathPoint(uv);
  const double n = state_->document.grid().width, h = state_->document.grid().height;
  return state_->moveTo({static_cast<double>(uv.x) * n, static_cast<double>(uv.y) * h}, radius,
                        strength, pressure);
}

void StrokeSession::continueFrom(core::Vec2f uv) {
  requirePathPoint(uv);
  State& st = *state_;
  if (!st.previous || st.brush.stroke == StrokeKind::Anchored) return;
  st.previous = {static_cast<double>(uv.x) * st.document.grid().width,
                 static_cast<double>(uv.y) * st.document.grid().height};
}

int StrokeSession::dragAlong(core::Vec3f origin, core::Vec3f direction, float radius,
                             float strength, float pressure) {
  if (!drags())
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "brush " + state_->brush.id + " does not drag (its \"stroke\" is \"" +
                          std::string(toManifestName(state_->brush.stroke)) + "\")");
  return state_->dragAlong(origin, direction, radius, strength, pressure);
}

int StrokeSession::dragTo(core::Vec3f point, float radius, float strength, float pressure) {
  if (!drags())
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "brush " + state_->brush.id + " does not drag (its \"stroke\" is \"" +
                          std::string(toManifestName(state_->brush.stroke)) + "\")");
  return state_->dragTo(point, radius, strength, pressure);
}

int StrokeSession::expectDabs(const std::vector<std::array<float, 2>>& path,
                              const std::vector<core::Vec3f>& dragPoints, float radius) const {
  State& st = *state_;
  for (const auto& uv : path)
    requirePathPoint({uv[0], uv[1]});
  requireFinite("the radius", radius);
  for (const core::Vec3f& p : dragPoints)
    st.requireDragReach(p);
  const double spacing = st.spacingFor(radius);
  const double n = st.document.grid().width, h = st.document.grid().height;
  const auto xy = [n, h](const std::array<float, 2>& uv) {
    return std::array<double, 2>{uv[0] * n, uv[1] * h};
  };
  double length = 0;
  if (st.brush.stroke != StrokeKind::Anchored)
    for (std::size_t k = 1; k < path.size(); ++k)
      length += st.walkLength(xy(path[k - 1]), xy(path[k]));
  if (!path.empty() && !dragPoints.empty()) {
    core::Vec3f from = st.startPosition(xy(path.front())[0], xy(path.front())[1]);
    for (const core::Vec3f& p : dragPoints) {
      // An anchored stroke dabs once per drag move; a drag stroke walks to each point.
      length += st.brush.stroke == StrokeKind::Anchored ? spacing : core::length(p - from);
      from = p;
    }
  }
  st.requireDabBudget(length, spacing);
  // The first point's dab, then one every spacing along the way.
  const int first = path.empty() ? 0 : 1;
  return st.imagesPerDab() * (first + static_cast<int>(std::floor(length / spacing)));
}

void StrokeSession::observeDabs(std::function<void(int)> observer) {
  state_->onDab = std::move(observer);
}

bool StrokeSession::drags() const {
  return state_->brush.stroke == StrokeKind::Anchored || state_->brush.stroke == StrokeKind::Drag;
}

std::vector<core::TexelRect> StrokeSession::takeTouched() {
  State& st = *state_;
  for (auto* touched : {&st.touchedTiles, &st.touchedSeams}) {
    std::sort(touched->begin(), touched->end());
    touched->erase(std::unique(touched->begin(), touched->end()), touched->end());
  }
  std::vector<core::TexelRect> tiles;
  tiles.reserve(st.touchedTiles.size());
  for (const auto& t : st.touchedTiles)
    tiles.push_back({t[0], t[1], t[2], t[3]});
  std::vector<core::TexelRect> touched = core::mergeRects(std::move(tiles));
  // The seaming pass also rewrites border samples identified with those the dabs reached.
  for (const auto& t : st.touchedSeams)
    touched.push_back({t[0], t[1], t[2], t[3]});
  st.touchedTiles.clear();
  st.touchedSeams.clear();
  return touched;
}

void StrokeSession::applyBetweenDabs(const core::EditStep& change) {
  State& st = *state_;
  if (st.abandoned || st.finished)
    throw std::logic_error("StrokeSession::applyBetweenDabs after the stroke ended");
  for (const core::TileChange& t : change.tiles)
    st.undo.coverTile(t.layer, t.tileX, t.tileY);
  const core::TileApplier apply = undoApplier(st.document);
  try {
    for (const core::TileChange& t : change.tiles) {
      t.apply(core::TileState::After, apply);
      st.touchedTiles.push_back({t.region.x, t.region.y, t.region.width, t.region.height});
    }
  } catch (...) { // all or nothing, as a failed dab
    st.abandon();
    throw;
  }
}

core::EditStep StrokeSession::recordSoFar(const std::string& label) const {
  return state_->undo.record(label);
}

int StrokeSession::dabs() const {
  return state_->dabs;
}

double StrokeSession::engineMs() const {
  return state_->engineMs;
}

double StrokeSession::firstMoveMs() const {
  return state_->firstMoveMs.value_or(0.0);
}

int StrokeSession::firstMoveDabs() const {
  return state_->firstMoveDabs;
}

StrokeSession::Phases StrokeSession::phases() const {
  return state_->phases;
}

core::EditStep StrokeSession::finish(const std::string& label) {
  State& st = *state_;
  if (st.abandoned) { // the layers are as before the stroke: nothing to undo
    core::EditStep nothing;
    nothing.label = label;
    nothing.imageSide = st.document.side();
    nothing.imageRows = st.document.rows() == st.document.side() ? 0 : st.document.rows();
    return nothing;
  }
  if (st.finished) throw std::logic_error("StrokeSession::finish called twice");
  try {
    // The watchdog for passes not waited for yet (a paint brush's last ones), before the
    // paint layers' pull reads what they wrote.
    st.engine.finishPasses();
  } catch (...) { // a pass overran: the stroke is undone, as when a dab fails
    st.abandon();
    throw;
  }
  st.finished = true;
  st.engine.endStroke();
  st.document.deferPulls(false);
  return st.undo.finish(label);
}

} // namespace octaclay::gpu
