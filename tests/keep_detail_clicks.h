#pragma once

// Keep detail's one-dab pulls and what each relaxation did, shared by keep_detail_test,
// grid_keep_detail_test and bench_relax: the push click they repeat, how far the session's last
// relaxation moved the surface the click left, and that the click undoes as one exact step.

#include "gpu/brush_test_support.h"
#include "sculpt_session.h"
#include "stroke_script.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/surface_distance.h"

namespace octaclay::testing {

/// One push dab at image point (u, v): radius 0.06 of the diagonal, strength 1, keep detail as
/// given.
inline app::StrokeScript pushClick(float u, float v, bool keepDetail = true) {
  app::StrokeScript s;
  s.start.brushId = s.start.settings.brushId = "push";
  s.start.settings.radius = 0.06f;
  s.start.settings.strength = 1.0f;
  s.start.settings.keepDetail = keepDetail;
  s.start.spacing = 1.0f;
  s.path = {{u, v}, {u, v}};
  return s;
}

/// The session's last relaxation: the document as the stroke alone left it (the relaxation's
/// tiles put back) and how far the relaxation moved that surface (200 000 samples a side).
struct RelaxationMove {
  core::Document stroked;
  core::SurfaceDistance moved;
};

inline RelaxationMove lastRelaxationMove(const app::SculptSession& session) {
  RelaxationMove out{session.document(), {}};
  const core::TileApplier apply = core::applierFor(out.stroked);
  for (const core::TileChange& t : session.lastRelaxation().tiles)
    t.apply(core::TileState::Before, apply);
  out.moved = core::compareSurfaces(core::extractMesh(out.stroked.positions),
                                    core::extractMesh(session.document().positions),
                                    {.samplesPerSurface = 200'000});
  return out;
}

/// After a click that relaxed (before: every layer before it), that undo brings back before and
/// redo the click bit for bit, the click and its relaxation one history step. nullptr when so,
/// else what failed.
inline const char* oneBitExactStep(app::SculptSession& session,
                                   const std::vector<std::vector<float>>& before) {
  const auto after = gpu::testing::snapshot(session.gpuDocument());
  const std::size_t steps = session.history().undoCount();
  if (!session.undo()) return "nothing to undo";
  if (!gpu::testing::sameBits(gpu::testing::snapshot(session.gpuDocument()), before))
    return "undo was not bit-exact";
  if (!session.redo()) return "nothing to redo";
  if (!gpu::testing::sameBits(gpu::testing::snapshot(session.gpuDocument()), after))
    return "redo was not bit-exact";
  if (session.history().undoCount() != steps) return "the click was more than one step";
  return nullptr;
}

} // namespace octaclay::testing
