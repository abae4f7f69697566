// A stroke along a path for the GL brush tests, played straight through gpu::StrokeSession:
// its path points (moveToUv), then its drag points (dragTo). The modeller and octaclay-cli
// stroke through app::SculptSession's one door (app/session/stroke_script.h), which makes these
// same StrokeSession calls; these tests check the engine's stroke below it.
#pragma once

#include "octaclay/core/document/edit_step.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/stroke.h"

#include <array>
#include <string>
#include <vector>

namespace octaclay::gpu::testing {

/// A scripted stroke: the settings its dabs share, and what each move takes.
struct PathStroke : StrokeSettings {
  std::string brush;                      ///< the id tests look the manifest up by
  std::vector<std::array<float, 2>> path; ///< (u, v) in [0, 1]; one point is one dab
  float radius = 0.1f;                    ///< object units
  float strength = 0.5f;                  ///< fraction of the radius
  float pressure = 1.0f;
  std::vector<core::Vec3f> dragPoints; ///< a dragging brush's points after the path
};

struct StrokeResult {
  int dabs = 0;        ///< including mirrored dabs
  double engineMs = 0; ///< GPU passes, seaming and mirror updates
  core::EditStep undo; ///< the tiles the stroke changed, before and after
};

/// Plays stroke through a StrokeSession and finishes it, labelled with brush's id. Throws what
/// the session throws (a failed dab restores the layers first; finish() restores them when the
/// result is not finite).
inline StrokeResult strokeAlongPath(BrushEngine& engine, GpuDocument& document,
                                    const BrushManifest& brush, const PathStroke& stroke) {
  StrokeSession session(engine, document, brush, stroke);
  session.expectDabs(stroke.path, stroke.dragPoints, stroke.radius);
  for (const auto& uv : stroke.path)
    session.moveToUv({uv[0], uv[1]}, stroke.radius, stroke.strength, stroke.pressure);
  for (const core::Vec3f& point : stroke.dragPoints)
    session.dragTo(point, stroke.radius, stroke.strength, stroke.pressure);
  StrokeResult result;
  result.dabs = session.dabs();
  result.engineMs = session.engineMs();
  result.undo = session.finish(brush.id);
  return result;
}

} // namespace octaclay::gpu::testing
