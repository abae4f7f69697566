#include "stroke_state.h"
#include "stroke_symmetry.h"

#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/stroke_rules.h"

#include <algorithm>
#include <chrono>
#include <cmath>

// One dab of a stroke and its mirror images: centred on the current surface, its undo tiles
// captured before the engine's passes run.
namespace octaclay::gpu {

// One dab at image point (x, y) in samples and its mirror images, capturing the undo tiles
// each may touch first. The centre and its normal are the current surface's there; a mirror
// image is centred on the mirrored point with the mirrored normal, so a symmetric model gets
// mirror-equal dabs.
void StrokeSession::State::dabAt(std::array<double, 2> xy, float radius, float strength,
                                 float pressure, std::optional<core::Vec3f> cursorDrag) {
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
      d.centreNormal = areaNormals
                           ? areaNormal(document, d.centre, kAreaNormalRadius * radius, pointNormal)
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
      d.centre = detail::mirrored(p, centre, axesOf[k]);
      d.centreNormal = detail::mirrored(normal, {}, axesOf[k]);
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
    dab.drag = detail::mirrored(drag, {}, axesOf[k]);
    dab.strokeDelta = detail::mirrored(delta, {}, axesOf[k]);
    dab.strokeDirection = detail::mirrored(lastDirection, {}, axesOf[k]);
    if (settings.viewEye) dab.viewDirection = dab.centre - *settings.viewEye;
  }
  const auto reachOf = [&](std::size_t k) {
    return brush.stroke == StrokeKind::Anchored && !first
               ? anchorReach[k]
               : engine.reach(document, brush.id, images[k]);
  };
  // Before a dab's passes: its anchor kept, its tiles and their seam partners captured for undo.
  const auto prepare = [&](std::size_t k, const std::vector<core::TexelRect>& reach) {
    if (keepAnchors) {
      anchors.push_back(images[k]);
      anchorReach.push_back(reach);
    }
    for (const core::TexelRect& r : reach)
      undo.cover(r);
    for (const core::TexelRect& r : seamRuns(reach, document.side(), document.rows(),
                                             document.topology())) // the seaming pass's partners
      undo.cover(r);
  };
  const auto note = [&](std::size_t k, const DabResult& done) {
    for (const core::TexelRect& t : done.tiles)
      touchedTiles.push_back({t.x, t.y, t.width, t.height});
    for (const core::TexelRect& t : done.seams)
      touchedSeams.push_back({t.x, t.y, t.width, t.height});
    if (brush.stroke == StrokeKind::Drag) { // the tip moves as the dab's centre moved
      if (first) tips.push_back(images[k].centre);
      tips[k] += images[k].strokeDelta * (images[k].strength * images[k].pressure);
    }
  };
  // Mirror images whose passes cannot see each other's texels (their reaches on the surface
  // before any of them, as their centres are) run in one pass per layer.
  std::vector<std::vector<core::TexelRect>> reaches;
  if (images.size() > 1) {
    for (std::size_t k = 0; k < images.size(); ++k)
      reaches.push_back(reachOf(k));
    lap(at, phases.reachMs);
    if (!engine.batches(document, brush.id, images, reaches)) reaches.clear();
  }
  if (!reaches.empty()) {
    for (std::size_t k = 0; k < images.size(); ++k)
      prepare(k, reaches[k]);
    lap(at, phases.undoMs);
    std::vector<DabResult> done;
    try {
      done = engine.dabs(document, brush.id, images, std::move(reaches));
    } catch (...) { // a pass that failed or overran (the watchdog): all or nothing
      abandon();
      throw;
    }
    lap(at, phases.passesMs);
    for (std::size_t k = 0; k < images.size(); ++k)
      note(k, done[k]);
  } else {
    // One after another: each image's reach on the surface its predecessors left.
    for (std::size_t k = 0; k < images.size(); ++k) {
      std::vector<core::TexelRect> reach = reachOf(k);
      lap(at, phases.reachMs);
      prepare(k, reach);
      lap(at, phases.undoMs);
      DabResult done;
      try {
        done = engine.dab(document, brush.id, images[k], std::move(reach));
      } catch (...) { // a pass that failed or overran (the watchdog): all or nothing
        abandon();
        throw;
      }
      lap(at, phases.passesMs);
      note(k, done);
    }
  }
  dabs += static_cast<int>(images.size());
  if (onDab) onDab(dabs);
}

} // namespace octaclay::gpu
