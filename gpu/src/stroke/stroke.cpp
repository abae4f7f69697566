#include "octaclay/gpu/stroke.h"

#include "undo_capture.h"
#include "value_text.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/stroke_rules.h"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <vector>

namespace octaclay::gpu {
namespace {

[[noreturn]] void badSetting(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

void checkParameter(const BrushParameter& p, const std::array<float, 4>& v) {
  const std::string name = "parameter '" + p.id + "'";
  const std::size_t used = p.type == ParameterType::Color ? 4 : 1;
  for (std::size_t c = 0; c < used; ++c)
    requireFinite(name.c_str(), v[c]);
  if (p.type == ParameterType::Material) return; // an index into the engine's materials
  for (std::size_t c = 0; c < used; ++c)
    if (!(v[c] >= p.min && v[c] <= p.max))
      badSetting(name + " = " + detail::valueText(v[c]) + " is outside [" +
                 detail::valueText(p.min) + ", " + detail::valueText(p.max) + "]");
}

void checkSettings(const BrushManifest& brush, const StrokeSettings& settings) {
  for (const auto& [id, value] : settings.parameters)
    if (const BrushParameter* p = brush.parameter(id)) checkParameter(*p, value);
  if (settings.viewEye) {
    requireFinite("the view's x", settings.viewEye->x);
    requireFinite("the view's y", settings.viewEye->y);
    requireFinite("the view's z", settings.viewEye->z);
  }
  requireFinite("the spacing", settings.spacing);
}

core::Vec3f mirrored(core::Vec3f p, core::Vec3f centre, unsigned axes) {
  if (axes & kSymmetryX) p.x = 2 * centre.x - p.x;
  if (axes & kSymmetryY) p.y = 2 * centre.y - p.y;
  if (axes & kSymmetryZ) p.z = 2 * centre.z - p.z;
  return p;
}

// The parameters t in (0, 1) at which from + t × delta crosses an integer.
void addCrossings(double from, double delta, std::vector<double>& ts) {
  if (delta == 0) return;
  const double lo = std::min(from, from + delta), hi = std::max(from, from + delta);
  for (double k = std::ceil(lo); k <= hi; ++k)
    if (const double t = (k - from) / delta; t > 0 && t < 1) ts.push_back(t);
}

// The parameters 0 = t0 < t1 < … < 1 that cut the segment a → b (image coordinates, in
// samples) where it crosses a cell's side or diagonal: the surface is linear between two.
std::vector<double> linearPieces(std::array<double, 2> a, std::array<double, 2> b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  std::vector<double> ts{0.0, 1.0};
  addCrossings(a[0], dx, ts);
  addCrossings(a[1], dy, ts);
  addCrossings(a[0] + a[1], dx + dy, ts); // anti-diagonals
  addCrossings(a[0] - a[1], dx - dy, ts); // main diagonals
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

std::string shortNumber(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

} // namespace

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

struct StrokeSession::State {
  State(BrushEngine& e, GpuDocument& d, const BrushManifest& b, StrokeSettings s)
      : engine(e), document(d), brush(b), settings(std::move(s)), undo(d, b.writes) {
    // Paint layers are read back once at the stroke's end, not after every dab: the stroke
    // itself reads only positions (and undo tiles before their first dab).
    document.deferPulls(true);
    engine.beginStroke(); // a reparameterize brush resamples once per stroke
  }
  ~State() {
    if (finished) return;
    try {
      engine.endStroke();
      document.deferPulls(false);
    } catch (...) { // an abandoned stroke: the textures stay right, only the mirror may lag
    }
  }

  BrushEngine& engine;
  GpuDocument& document;
  const BrushManifest& brush;
  StrokeSettings settings;
  core::Vec3f centre;  ///< of the bounding box at the stroke's start: symmetry mirrors through it
  double diagonal = 0; ///< of that bounding box
  detail::UndoCapture undo;
  float share = 1; ///< of the strength, per dab (dabShare)
  /// The last point walked, image coordinates in samples; none before the first move.
  std::optional<std::array<double, 2>> previous;
  double travelled = 0; ///< along the surface as it began, since the last dab
  int dabs = 0;
  double engineMs = 0;
  std::optional<double> firstMoveMs; ///< set by the first move that dabbed
  int firstMoveDabs = 0;
  StrokeSession::Phases phases;
  // Since the last takeTouched(), which sorts and deduplicates them (a set per dab costs more).
  std::vector<std::array<int, 4>> touchedTiles;
  std::vector<std::array<int, 4>> touchedSeams; ///< border runs seamed
  std::function<void(int)> onDab;               ///< told the dab count after each dab, if set
  bool finished = false;
  bool abandoned = false; ///< a dab failed and the stroke was undone

  // The drag (API 3): from the stroke-start surface point under the first path point to the one
  // under the current point, projected into the view plane (normal dragNormal) when a view is
  // given, else along the path.
  core::Vec3f startPoint, dragNormal;
  core::Vec3f anchorNormal;            ///< the surface normal at the stroke's first dab
  core::Vec3f lastDrag, lastDirection; ///< at the previous dab
  /// Drag strokes: where each dab image's centre now is (the tip the drag pulls). Anchored
  /// strokes: each image's first dab (its centre, normal and texel, measured on the stroke-start
  /// surface) and the tiles it reached there, which every later dab runs over again.
  std::vector<core::Vec3f> tips;
  std::vector<Dab> anchors;
  std::vector<std::vector<core::TexelRect>> anchorReach;

  // Whether the brush's passes read the dab's centre normal: the area normal, a sum over every
  // cell the dab covers on the CPU, is computed only for those (a smooth dab's normal reaches no
  // pass); the others get the point normal.
  bool usesCentreNormal() const {
    return engine.usesCentreNormal(document, brush.id, settings.parameters);
  }

  core::Vec3f dragAt(std::array<double, 2> xy) const {
    core::Vec3f v = startPosition(xy[0], xy[1]) - startPoint;
    return v - dragNormal * core::dot(v, dragNormal);
  }

  // Puts the layers back as they were before the stroke; the session is over.
  void abandon() {
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
  core::Vec3f startPosition(double x, double y) const {
    const core::GridPoint p = surfacePointAt(document.mirror().positions.grid(), x, y);
    core::Vec3f sum;
    for (int k = 0; k < 3; ++k)
      sum += undo.positionBefore(p.corners[k]) * p.weights[k];
    return sum;
  }

  // Walks the straight segment from the previous point to b (image coordinates, in samples),
  // dabbing each time the distance since the last dab reaches spacing (object units). The
  // distance is exact on the start surface's triangles; the remainder carries to the next walk.
  void walkTo(std::array<double, 2> b, float radius, float strength, float pressure) {
    const std::array<double, 2> a = *previous;
    const double spacing = spacingFor(radius);
    // The spacing shrank since the last walk (pen pressure on the radius): a dab is due now.
    travelled = std::min(travelled, spacing);
    const auto at = [&](double t) {
      return std::array<double, 2>{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
    };
    const std::vector<double> ts = linearPieces(a, b);
    std::vector<double> lengths(ts.size() - 1);
    double total = 0;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const auto p0 = at(ts[k]), p1 = at(ts[k + 1]);
      lengths[k] = core::length(startPosition(p1[0], p1[1]) - startPosition(p0[0], p0[1]));
      total += lengths[k];
    }
    requireDabBudget(total + travelled, spacing);
    previous = b;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const double t0 = ts[k], t1 = ts[k + 1];
      const double length = lengths[k];
      double used = 0; // of this piece, up to the last dab on it
      while (travelled + (length - used) >= spacing) {
        used += spacing - travelled;
        travelled = 0;
        const double f = length > 0 ? std::clamp(used / length, 0.0, 1.0) : 0.0;
        dabAt(at(t0 + (t1 - t0) * f), radius, strength, pressure);
      }
      travelled += length - used;
    }
  }

  // Between dabs at this radius, object units: the brush's spacing, and at most 1e4 dabs per
  // diagonal (a radius far below a sample would otherwise make dabs without end).
  double spacingFor(float radius) const {
    return std::max(static_cast<double>(dabSpacing(brush, settings.spacing)) * std::abs(radius),
                    1e-4 * diagonal);
  }

  // A dab and its mirror images, one per symmetry plane combination.
  int imagesPerDab() const { return 1 << std::popcount(settings.symmetry & 7u); }

  // The length of the straight walk a → b (image coordinates, in samples) on the surface as
  // the stroke began.
  double walkLength(std::array<double, 2> a, std::array<double, 2> b) const {
    const std::vector<double> ts = linearPieces(a, b);
    double total = 0;
    for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
      const double t0 = ts[k], t1 = ts[k + 1];
      total += core::length(startPosition(a[0] + t1 * (b[0] - a[0]), a[1] + t1 * (b[1] - a[1])) -
                            startPosition(a[0] + t0 * (b[0] - a[0]), a[1] + t0 * (b[1] - a[1])));
    }
    return total;
  }

  // Refuses, before any dab of this move, a walk of `length` (object units) at `spacing` that
  // would take the stroke past kMaxStrokeDabs: a drag to infinity or a radius far below a
  // sample would otherwise dab without end.
  void requireDabBudget(double length, double spacing) const {
    const double expected = dabs + imagesPerDab() * std::floor(length / spacing);
    if (expected <= kMaxStrokeDabs) return;
    badSetting("the stroke would make about " + shortNumber(expected) + " dabs (a path " +
               shortNumber(length / diagonal) + " diagonals long at a spacing of " +
               shortNumber(spacing / diagonal) + " diagonals); a stroke makes at most " +
               std::to_string(kMaxStrokeDabs) +
               ": use a larger spacing or radius, or a shorter path");
  }

  // Refuses a drag target farther than kMaxDragDiagonals from the model's centre.
  void requireDragReach(core::Vec3f point) const {
    // In double: a point at 1e30 squares past float's range.
    const double dx = double(point.x) - centre.x, dy = double(point.y) - centre.y,
                 dz = double(point.z) - centre.z;
    const double away = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (away <= kMaxDragDiagonals * diagonal) return;
    badSetting("a drag point lies " + shortNumber(away / diagonal) +
               " diagonals from the model's centre; a drag reaches at most " +
               shortNumber(kMaxDragDiagonals) + " diagonals (the model is " +
               shortNumber(diagonal) + " across): drag within reach");
  }

  // One dab at image point (x, y) in samples and its mirror images, capturing the undo tiles
  // each may touch first. The centre and its normal are the current surface's there; a mirror
  // image is centred on the mirrored point with the mirrored normal, so a symmetric model gets
  // mirror-equal dabs.
  void dabAt(std::array<double, 2> xy, float radius, float strength, float pressure,
             std::optional<core::Vec3f> cursorDrag = std::nullopt) {
    const auto began = std::chrono::steady_clock::now();
    const auto lap = [](std::chrono::steady_clock::time_point& from, double& into) {
      const auto now = std::chrono::steady_clock::now();
      into += std::chrono::duration<double, std::milli>(now - from).count();
      from = now;
    };
    const int n = document.grid().width, h = document.grid().height;
    // The mirror, each region synced before it is read: the rest may wait for its read-back.
    const core::GeometryImage& image = document.mirror().positions;
    const bool first = dabs == 0;
    if (first) {
      startPoint = startPosition(xy[0], xy[1]);
      if (settings.viewEye && core::length(startPoint - *settings.viewEye) > 0)
        dragNormal = core::normalize(startPoint - *settings.viewEye);
    }
    const core::Vec3f drag = cursorDrag ? *cursorDrag : dragAt(xy);
    const core::Vec3f delta = drag - lastDrag;
    if (core::length(delta) > 0) lastDirection = core::normalize(delta);
    lastDrag = drag;

    std::vector<Dab> images(1); // the dab, then its mirror images
    std::vector<unsigned> axesOf{0};
    for (unsigned axes = 1; axes < 8; ++axes)
      if ((axes & settings.symmetry) == axes) {
        images.emplace_back();
        axesOf.push_back(axes);
      }
    if (brush.stroke == StrokeKind::Anchored && !first) {
      images = anchors; // where the stroke began, measured on the surface as it was then
    } else if (brush.stroke == StrokeKind::Drag && !first) {
      const bool areaNormals = usesCentreNormal();
      for (std::size_t k = 0; k < images.size(); ++k) {
        Dab& d = images[k];
        d.centre = tips[k];
        d.centreTexel = nearestSample(document, d.centre);
        syncAround(document, d.centreTexel.i, d.centreTexel.j);
        const core::Vec3f pointNormal = core::vertexNormal(image, d.centreTexel);
        d.centreNormal =
            areaNormals ? areaNormal(document, d.centre, kAreaNormalRadius * radius, pointNormal)
                        : pointNormal;
      }
    } else {
      const core::GridPoint point = surfacePointAt(image.grid(), xy[0], xy[1]);
      syncAround(document, xy[0], xy[1]);
      const core::Vec3f p = core::interpolatePosition(image, point);
      const core::Vec3f pointNormal = interpolateNormal(image, point);
      // The first dab's normal is the stroke's anchor normal (a drag's plane) whatever the brush.
      const core::Vec3f normal =
          first || usesCentreNormal()
              ? areaNormal(document, p, kAreaNormalRadius * radius, pointNormal)
              : pointNormal;
      images[0].centre = p;
      images[0].centreNormal = normal;
      images[0].centreTexel = {std::clamp(static_cast<int>(std::lround(xy[0])), 0, n),
                               std::clamp(static_cast<int>(std::lround(xy[1])), 0, h)};
      for (std::size_t k = 1; k < images.size(); ++k) {
        Dab& d = images[k];
        d.centre = mirrored(p, centre, axesOf[k]);
        d.centreNormal = mirrored(normal, {}, axesOf[k]);
        d.centreTexel = nearestSample(document, d.centre);
      }
    }
    if (first) anchorNormal = images[0].centreNormal;
    auto at = began;
    lap(at, phases.centreMs);
    const bool keepAnchors = brush.stroke == StrokeKind::Anchored && first;
    for (std::size_t k = 0; k < images.size(); ++k) {
      Dab& dab = images[k];
      dab.radius = radius;
      dab.strength = strength * share;
      dab.pressure = pressure;
      dab.parameters = settings.parameters;
      dab.drag = mirrored(drag, {}, axesOf[k]);
      dab.strokeDelta = mirrored(delta, {}, axesOf[k]);
      dab.strokeDirection = mirrored(lastDirection, {}, axesOf[k]);
      if (settings.viewEye) dab.viewDirection = dab.centre - *settings.viewEye;
      std::vector<core::TexelRect> reach = brush.stroke == StrokeKind::Anchored && !first
                                               ? anchorReach[k]
                                               : engine.reach(document, brush.id, dab);
      lap(at, phases.reachMs);
      if (keepAnchors) {
        anchors.push_back(dab);
        anchorReach.push_back(reach);
      }
      for (const core::TexelRect& r : reach)
        undo.cover(r);
      for (const core::TexelRect& r : seamRuns(reach, document.side(), document.rows(),
                                               document.topology())) // the seaming pass's partners
        undo.cover(r);
      lap(at, phases.undoMs);
      DabResult done;
      try {
        done = engine.dab(document, brush.id, dab, std::move(reach));
      } catch (...) { // a pass that failed or overran (the watchdog): all or nothing
        abandon();
        throw;
      }
      lap(at, phases.passesMs);
      for (const core::TexelRect& t : done.tiles)
        touchedTiles.push_back({t.x, t.y, t.width, t.height});
      for (const core::TexelRect& t : done.seams)
        touchedSeams.push_back({t.x, t.y, t.width, t.height});
      if (brush.stroke == StrokeKind::Drag) { // the tip moves as the dab's centre moved
        if (first) tips.push_back(dab.centre);
        tips[k] += dab.strokeDelta * (dab.strength * dab.pressure);
      }
    }
    dabs += static_cast<int>(images.size());
    if (onDab) onDab(dabs);
  }

  // Moves the stroke to image point xy (in samples): the first move dabs there, later ones
  // walk from the previous point.
  int moveTo(std::array<double, 2> xy, float radius, float strength, float pressure) {
    if (abandoned) throw std::logic_error("StrokeSession::moveTo after a dab failed");
    if (finished) throw std::logic_error("StrokeSession::moveTo after finish()");
    requireFinite("the radius", radius);
    requireFinite("the strength", strength);
    requireFinite("the pressure", pressure);
    const auto start = std::chrono::steady_clock::now();
    const int before = dabs;
    if (!previous || brush.stroke == StrokeKind::Anchored) {
      // An anchored stroke makes one dab where it began, again for each move: no walk.
      if (!previous || xy != *previous) dabAt(xy, radius, strength, pressure);
      previous = xy;
    } else {
      walkTo(xy, radius, strength, pressure);
    }
    const double ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    engineMs += ms;
    if (!firstMoveMs && dabs > before) {
      firstMoveMs = ms;
      firstMoveDabs = dabs - before;
    }
    return dabs - before;
  }

  // A dragging brush's move to the drag that ray gives: where it meets the drag plane (through
  // the stroke's start, across the view; across the start's normal without a view). An anchored
  // stroke dabs once with it; a drag stroke walks there from its last drag in steps of the
  // spacing (object units), carrying the remainder as walkTo does.
  int dragAlong(core::Vec3f origin, core::Vec3f direction, float radius, float strength,
                float pressure) {
    checkDragMove(radius, strength, pressure);
    for (float v : {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z})
      requireFinite("the drag's ray", v);
    const core::Vec3f plane = core::length(dragNormal) > 0 ? dragNormal : anchorNormal;
    const float facing = core::dot(direction, plane);
    if (std::abs(facing) < 1e-6f * core::length(direction)) return 0; // along the plane: no point
    const core::Vec3f point = origin + direction * (core::dot(startPoint - origin, plane) / facing);
    requireDragReach(point);
    core::Vec3f target = point - startPoint;
    return dragBy(target - plane * core::dot(target, plane), radius, strength, pressure);
  }

  // The same to a point in object space: the drag is from the stroke's start to it, projected
  // into the view plane when the stroke has a view.
  int dragTo(core::Vec3f point, float radius, float strength, float pressure) {
    checkDragMove(radius, strength, pressure);
    for (float v : {point.x, point.y, point.z})
      requireFinite("the drag's point", v);
    requireDragReach(point);
    const core::Vec3f target = point - startPoint;
    return dragBy(target - dragNormal * core::dot(target, dragNormal), radius, strength, pressure);
  }

  void checkDragMove(float radius, float strength, float pressure) const {
    if (abandoned) throw std::logic_error("StrokeSession: a drag after a dab failed");
    if (finished) throw std::logic_error("StrokeSession: a drag after finish()");
    if (!previous) throw std::logic_error("StrokeSession: a drag before the stroke's first move");
    requireFinite("the radius", radius);
    requireFinite("the strength", strength);
    requireFinite("the pressure", pressure);
  }

  int dragBy(core::Vec3f target, float radius, float strength, float pressure) {
    const auto start = std::chrono::steady_clock::now();
    const int before = dabs;
    const std::array<double, 2> xy = *previous;
    if (brush.stroke == StrokeKind::Anchored) {
      dabAt(xy, radius, strength, pressure, target);
    } else {
      const double spacing = spacingFor(radius);
      const core::Vec3f from = lastDrag;
      const double length = core::length(target - from);
      travelled = std::min(travelled, spacing);
      requireDabBudget(length + travelled, spacing);
      double used = 0;
      while (travelled + (length - used) >= spacing) {
        used += spacing - travelled;
        travelled = 0;
        dabAt(xy, radius, strength, pressure,
              from + (target - from) * static_cast<float>(length > 0 ? used / length : 0.0));
      }
      travelled += length - used;
    }
    engineMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    return dabs - before;
  }
};

StrokeSession::StrokeSession(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                             StrokeSettings settings) {
  if (!engine.has(brush.id))
    throw core::Error(core::ErrorKind::UnknownId, "no brush named '" + brush.id + "' is loaded");
  checkSettings(brush, settings);
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
