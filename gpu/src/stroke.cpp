#include "octaclay/gpu/stroke.h"

#include "undo_capture.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <set>
#include <stdexcept>

namespace octaclay::gpu {
namespace {

[[noreturn]] void badSetting(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

std::string formatValue(float v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  return std::to_string(v);
}

// NaN fails every comparison: each check is written so that it must pass, never so that it
// must fail.
void checkFinite(const char* what, float v) {
  if (!std::isfinite(v))
    badSetting(std::string(what) + " " + formatValue(v) + " is not a finite number");
}

void checkParameter(const BrushParameter& p, const std::array<float, 4>& v) {
  const std::string name = "parameter '" + p.id + "'";
  const std::size_t used = p.type == ParameterType::Color ? 4 : 1;
  for (std::size_t c = 0; c < used; ++c)
    checkFinite(name.c_str(), v[c]);
  if (p.type == ParameterType::Material) return; // an index into the engine's materials
  for (std::size_t c = 0; c < used; ++c)
    if (!(v[c] >= p.min && v[c] <= p.max))
      badSetting(name + " = " + formatValue(v[c]) + " is outside [" + formatValue(p.min) + ", " +
                 formatValue(p.max) + "]");
}

void checkSettings(const BrushManifest& brush, const StrokeSettings& settings) {
  for (const auto& [id, value] : settings.parameters)
    if (const BrushParameter* p = brush.parameter(id)) checkParameter(*p, value);
  if (settings.viewEye) {
    checkFinite("the view's x", settings.viewEye->x);
    checkFinite("the view's y", settings.viewEye->y);
    checkFinite("the view's z", settings.viewEye->z);
  }
  checkFinite("the spacing", settings.spacing);
}

core::Sample sampleAt(int n, std::array<float, 2> uv) {
  return {static_cast<int>(std::lround(uv[0] * static_cast<float>(n))),
          static_cast<int>(std::lround(uv[1] * static_cast<float>(n)))};
}

core::Vec3f mirrored(core::Vec3f p, core::Vec3f centre, unsigned axes) {
  if (axes & kSymmetryX) p.x = 2 * centre.x - p.x;
  if (axes & kSymmetryY) p.y = 2 * centre.y - p.y;
  if (axes & kSymmetryZ) p.z = 2 * centre.z - p.z;
  return p;
}

} // namespace

core::Sample nearestSample(const GpuDocument& document, core::Vec3f p) {
  const core::TileBounds& bounds = document.bounds();
  const core::GeometryImage& image = document.document().positions;
  float radius = 1e-3f * std::max(bounds.diagonal(), 1e-6f);
  for (;;) {
    float best = std::numeric_limits<float>::max();
    core::Sample found{};
    for (int t : bounds.tilesNearSphere(p, radius)) {
      const core::TexelRect r =
          bounds.tileRect(t % bounds.tilesPerSide(), t / bounds.tilesPerSide());
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

StrokeResult runStroke(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                       const StrokeSettings& settings) {
  if (settings.path.empty())
    throw core::Error(core::ErrorKind::InvalidArgument, "the stroke's path has no point");
  for (const auto& uv : settings.path)
    if (!(uv[0] >= 0 && uv[0] <= 1 && uv[1] >= 0 && uv[1] <= 1))
      throw core::Error(core::ErrorKind::InvalidArgument, "path point (" + std::to_string(uv[0]) +
                                                              ", " + std::to_string(uv[1]) +
                                                              ") is outside [0, 1]");
  // One session fed the path points: it walks the samples between them, so a scripted stroke
  // and an interactive one dab at the same places.
  const int n = document.size();
  StrokeSession session(engine, document, brush, settings);
  for (const auto& uv : settings.path)
    session.moveTo(sampleAt(n, uv), settings.radius, settings.strength, settings.pressure);
  StrokeResult result;
  result.dabs = session.dabs();
  result.engineMs = session.engineMs();
  result.undo = session.finish(brush.id);
  return result;
}

struct StrokeSession::State {
  State(BrushEngine& e, GpuDocument& d, const BrushManifest& b, StrokeSettings s)
      : engine(e), document(d), brush(b), settings(std::move(s)), undo(d, b.writes) {
    // Paint layers are read back once at the stroke's end, not after every dab: the stroke
    // itself reads only positions (and undo tiles before their first dab).
    document.deferPaintPulls(true);
    engine.beginStroke(); // a reparameterize brush resamples once per stroke
  }
  ~State() {
    if (finished) return;
    try {
      engine.endStroke();
      document.deferPaintPulls(false);
    } catch (...) { // an abandoned stroke: the textures stay right, only the mirror may lag
    }
  }

  BrushEngine& engine;
  GpuDocument& document;
  const BrushManifest& brush;
  StrokeSettings settings;
  core::Vec3f centre; ///< of the bounding box at the stroke's start: symmetry mirrors through it
  detail::UndoCapture undo;
  std::optional<core::Sample> previous; ///< the last sample walked; none before the first move
  float travelled = 0;                  ///< object-space distance since the last dab
  int dabs = 0;
  double engineMs = 0;
  std::set<std::array<int, 4>> touchedTiles; ///< since the last takeTouched(), deduplicated
  std::set<std::array<int, 4>> touchedSeams; ///< border runs seamed since the last takeTouched()
  bool finished = false;
  bool abandoned = false; ///< a dab failed and the stroke was undone

  // Puts the layers back as they were before the stroke; the session is over.
  void abandon() {
    finished = abandoned = true;
    undo.restore();
    engine.endStroke();
    try {
      document.deferPaintPulls(false);
    } catch (...) { // the restored texels are in the mirror and the textures already
    }
  }

  // One dab at s and its mirror images, capturing the undo tiles each may touch first.
  void dabAt(core::Sample s, float radius, float strength, float pressure) {
    const int n = document.size();
    std::vector<core::Sample> centres{s};
    const core::Vec3f p = document.document().positions.at(s).xyz();
    for (unsigned axes = 1; axes < 8; ++axes)
      if ((axes & settings.symmetry) == axes)
        centres.push_back(nearestSample(document, mirrored(p, centre, axes)));
    for (core::Sample c : centres) {
      Dab dab;
      dab.centreTexel = c;
      dab.centre = document.document().positions.at(c).xyz();
      dab.centreNormal = core::vertexNormal(document.document().positions, c);
      dab.radius = radius;
      dab.strength = strength;
      dab.pressure = pressure;
      dab.parameters = settings.parameters;
      if (settings.viewEye) dab.viewDirection = dab.centre - *settings.viewEye;
      std::vector<core::TexelRect> reach = engine.reach(document, brush.id, dab);
      for (const core::TexelRect& r : reach)
        undo.cover(r);
      for (const core::TexelRect& r : seamRuns(reach, n + 1)) // the seaming pass's partners
        undo.cover(r);
      DabResult done;
      try {
        done = engine.dab(document, brush.id, dab, std::move(reach));
      } catch (...) { // a pass that failed or overran (the watchdog): all or nothing
        abandon();
        throw;
      }
      for (const core::TexelRect& t : done.tiles)
        touchedTiles.insert({t.x, t.y, t.width, t.height});
      for (const core::TexelRect& t : done.seams)
        touchedSeams.insert({t.x, t.y, t.width, t.height});
      ++dabs;
    }
  }
};

StrokeSession::StrokeSession(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                             StrokeSettings settings) {
  if (!engine.has(brush.id))
    throw core::Error(core::ErrorKind::UnknownId, "no brush named '" + brush.id + "' is loaded");
  checkSettings(brush, settings);
  settings.path.clear();
  state_ = std::make_unique<State>(engine, document, brush, std::move(settings));
  core::BoundingBox box;
  const core::TileBounds& bounds = document.bounds();
  for (int t = 0; t < bounds.tilesPerSide() * bounds.tilesPerSide(); ++t) {
    box.extend(bounds.box(t).min);
    box.extend(bounds.box(t).max);
  }
  state_->centre = (box.min + box.max) * 0.5f;
}

StrokeSession::~StrokeSession() = default;

int StrokeSession::moveTo(core::Sample s, float radius, float strength, float pressure) {
  State& st = *state_;
  if (st.abandoned) throw std::logic_error("StrokeSession::moveTo after a dab failed");
  if (st.finished) throw std::logic_error("StrokeSession::moveTo after finish()");
  checkFinite("the radius", radius);
  checkFinite("the strength", strength);
  checkFinite("the pressure", pressure);
  const int n = st.document.size();
  if (s.i < 0 || s.i > n || s.j < 0 || s.j > n)
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "sample (" + std::to_string(s.i) + ", " + std::to_string(s.j) +
                          ") is outside the image (0 to " + std::to_string(n) + " each way)");
  const auto start = std::chrono::steady_clock::now();
  const int before = st.dabs;
  if (!st.previous) {
    st.dabAt(s, radius, strength, pressure);
    st.previous = s;
  } else {
    // Walk the segment one sample at a time, measuring distance on the current surface (which
    // the dabs along the way keep changing).
    const float spacing =
        (st.settings.spacing > 0 ? st.settings.spacing : st.brush.spacing) * std::abs(radius);
    const core::Sample a = *st.previous, b = s;
    const int steps = std::max(std::abs(b.i - a.i), std::abs(b.j - a.j));
    for (int step = 1; step <= steps; ++step) {
      const float t = static_cast<float>(step) / static_cast<float>(steps);
      const core::Sample here{
          a.i + static_cast<int>(std::lround(t * static_cast<float>(b.i - a.i))),
          a.j + static_cast<int>(std::lround(t * static_cast<float>(b.j - a.j)))};
      const core::GeometryImage& image = st.document.document().positions;
      st.travelled += core::length(image.at(here).xyz() - image.at(*st.previous).xyz());
      st.previous = here;
      if (st.travelled >= spacing) {
        st.dabAt(here, radius, strength, pressure);
        st.travelled = 0;
      }
    }
  }
  st.engineMs +=
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return st.dabs - before;
}

std::vector<core::TexelRect> StrokeSession::takeTouched() {
  State& st = *state_;
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

int StrokeSession::dabs() const {
  return state_->dabs;
}

double StrokeSession::engineMs() const {
  return state_->engineMs;
}

core::Stroke StrokeSession::finish(const std::string& label) {
  State& st = *state_;
  if (st.abandoned) { // the layers are as before the stroke: nothing to undo
    core::Stroke nothing;
    nothing.label = label;
    nothing.imageSide = st.document.size() + 1;
    return nothing;
  }
  if (st.finished) throw std::logic_error("StrokeSession::finish called twice");
  st.finished = true;
  st.engine.endStroke();
  st.document.deferPaintPulls(false);
  return st.undo.finish(label);
}

} // namespace octaclay::gpu
