#include "stroke_script.h"

#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/stroke_rules.h"

#include <cmath>
#include <string>

namespace octaclay::app {
namespace {

[[noreturn]] void badSetting(const std::string& message) {
  throw core::Error(core::ErrorKind::InvalidArgument, message);
}

} // namespace

StrokeEnd playStroke(SculptSession& session, const StrokeScript& script,
                     const std::function<void(int, int)>& progress) {
  if (script.path.empty()) badSetting("the stroke's path has no point");
  const gpu::BrushManifest* brush = session.brushes().find(script.start.brushId);
  if (!script.dragPoints.empty() && brush && brush->stroke != gpu::StrokeKind::Anchored &&
      brush->stroke != gpu::StrokeKind::Drag)
    badSetting("brush " + brush->id + " does not drag: it takes no drag points");
  for (const core::Vec3f& p : script.dragPoints)
    for (float v : {p.x, p.y, p.z})
      gpu::requireFinite("a drag point's coordinate", v);
  for (const auto& uv : script.path)
    gpu::requirePathPoint({uv[0], uv[1]});
  session.beginStroke(script.start);
  try {
    const int expected = session.expectDabs(script.path, script.dragPoints);
    if (progress)
      session.observeDabs([&progress, expected](int done) { progress(done, expected); });
    for (const auto& uv : script.path)
      session.moveTo(StrokeMove::toUv({uv[0], uv[1]}));
    for (const core::Vec3f& point : script.dragPoints)
      session.moveTo(StrokeMove::toPoint(point));
  } catch (...) {
    session.abandonStroke();
    throw;
  }
  return session.finishStroke();
}

} // namespace octaclay::app
