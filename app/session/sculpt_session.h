#pragma once

#include "brush_settings.h"
#include "brush_variants.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/stroke.h"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::gpu {
class BrushCatalog;
class BrushEngine;
class GpuDocument;
} // namespace octaclay::gpu

namespace octaclay::app {

/// What one run of the queued dabs did.
struct DabRun {
  int made = 0;                         ///< dabs, mirrored ones included
  std::vector<core::TexelRect> touched; ///< texels the dabs ran over (empty after an error)
  std::string error;                    ///< why a dab failed; empty if none did
};

/// One sculpting session, without widgets: the document on the GPU, the brushes it is edited
/// with, the stroke being made (its dab queue) and the edit history with undo and redo. The
/// modeller's viewport and `octaclay-cli stroke` both sculpt through it. Every call that
/// touches the GPU needs the brush engine's GL context current on the calling thread.
class SculptSession {
public:
  SculptSession();
  ~SculptSession();
  SculptSession(const SculptSession&) = delete;
  SculptSession& operator=(const SculptSession&) = delete;

  /// The brushes to sculpt with; both must outlive the session (or the next call).
  void setBrushes(gpu::BrushEngine& engine, const gpu::BrushCatalog& catalog);
  bool hasBrushes() const { return engine_ != nullptr; }
  /// Compiles brush as its manifest declares it.
  void loadBrush(const gpu::BrushManifest& brush);
  /// The brushes were recompiled from their files (a reload): their variants are compiled anew
  /// when next used.
  void brushesReloaded(const std::vector<std::string>& ids);

  /// Uploads document, replacing the current one, dropping the stroke being made and clearing
  /// the history; progress as gpu::GpuDocument's. If the upload throws, nothing changed.
  void setDocument(core::Document document, const std::function<void(float)>& progress = {});
  bool hasDocument() const { return document_ != nullptr; }
  /// The document on the GPU. Only valid if hasDocument().
  gpu::GpuDocument& gpuDocument() { return *document_; }
  const gpu::GpuDocument& gpuDocument() const { return *document_; }
  /// The document as edited so far (the CPU mirror), with the paint a stroke deferred read back
  /// first (GL current then). Only valid if hasDocument().
  const core::Document& document() const;
  /// The model's bounding-box diagonal (at least 1e-6; 1 without a document).
  float diagonal() const;
  /// Drops the stroke and the GPU document, e.g. before their GL context goes.
  void releaseGpu();

  /// Begins a stroke of brush id: with the settings' area, falloff and parameters when id is
  /// settings.brushId (else the manifest's), paint brushes writing paintTarget, inverted when
  /// sign is negative, splats projecting from eye. Radius and strength are read at each dab
  /// (runQueuedDabs). Throws (the message says why) if the brush is not loaded or will not
  /// compile; no stroke begins then. Precondition: a document, brushes and no stroke.
  void beginStroke(const std::string& id, const BrushSettings& settings,
                   core::EditLayer paintTarget, float sign, core::Vec3f eye);
  bool stroking() const { return stroke_ != nullptr; }
  /// Queues a move of the stroke to image point uv (a pick's interpolated (u, v), each in
  /// [0, 1]); pressure in [0, 1]. The stroke dabs along the way (gpu::StrokeSession::moveToUv).
  void queueDab(core::Vec2f uv, float pressure);
  /// Whether the stroke's brush drags (grab, snake hook: gpu::StrokeSession::drags()): after
  /// its first queueDab, the viewport queues the pointer's rays with queueDrag instead.
  bool strokeDrags() const;
  /// Queues a dragging brush's move to the pointer's ray (object space, gpu::StrokeSession::
  /// dragAlong).
  void queueDrag(core::Vec3f origin, core::Vec3f direction, float pressure);
  /// Makes the queued moves with the settings' current radius, strength and pressure target,
  /// then empties the queue. A failing dab (a GL error, the watchdog) ends the run with its
  /// error and the stroke with it: the layers are back as before the stroke, later dabs are
  /// dropped and finishStroke() records nothing.
  DabRun runQueuedDabs(const BrushSettings& settings);
  /// Ends the stroke and records it in history(), labelled with its brush id, which it returns;
  /// empty (nothing recorded) if it made no dab or changed nothing. When the result holds a
  /// non-finite value the layers are restored, nothing is recorded, the stroke is over and
  /// core::Error(InvalidInput) says where.
  std::string finishStroke();

  /// Runs a whole stroke along settings.path (runStroke's contract; radius in object units)
  /// with brush as loaded: the same rules as an interactive stroke (gpu/stroke_rules.h). It is
  /// not recorded in history(). progress, when set, is told (dabs made, dabs expected).
  gpu::StrokeResult strokeAlongPath(const gpu::BrushManifest& brush,
                                    const gpu::StrokeSettings& settings,
                                    const std::function<void(int, int)>& progress = {});

  /// Keep detail (on by default): after a sculpt stroke stretched the positions it changed, the
  /// samples within core::keepDetailMargin of the changed texels flow toward the stretch
  /// (core::relaxChangedStep); every other sample keeps its bits. A dragging stroke (snake hook)
  /// also relaxes as it goes (relaxBetweenDabs). The stroke and its relaxations are one undo
  /// step. Applies to finishStroke() and strokeAlongPath() alike.
  void setKeepDetail(bool on) { keepDetail_ = on; }
  bool keepDetail() const { return keepDetail_; }
  /// What keep-detail's relaxations changed in the last stroke, during it (a dragging brush)
  /// and after it, as one step (no tiles when none moved): its tiles are what to redraw. After a
  /// stroke relaxed only at its end, its Before side is the surface as the stroke left it
  /// (benchmarks measure how far it moved).
  const core::Stroke& lastRelaxation() const { return lastRelaxation_; }

  /// Makes `after` (same size) the document, on the GPU and the mirror, as one undo step
  /// labelled label (e.g. the global even-out); returns the texel rectangles it changed (empty:
  /// nothing differed, nothing recorded). Precondition: a document and no stroke.
  std::vector<core::TexelRect> applyChange(const core::Document& after, const std::string& label);

  core::EditHistory& history() { return history_; }
  const core::EditHistory& history() const { return history_; }
  /// Reverts / reapplies the newest stroke on the GPU and the mirror: the stroke stepped, or
  /// null if there is none (or no document, or a stroke is being made). Throws what the
  /// history's applier throws; the history is then unchanged.
  const core::Stroke* undo();
  const core::Stroke* redo();

  long long dabs() const { return dabCount_; }    ///< made since the session began
  double lastDabMs() const { return lastDabMs_; } ///< per dab, over the last run that dabbed

private:
  struct ActiveStroke;
  struct KeepDetailRun;

  /// Keep detail as a dragging stroke goes (snake hook): after its 4th dab, then each time its
  /// dab count doubles, the samples near what its dabs changed so far relax
  /// (core::relaxChangedStep), written into the stroke (gpu::StrokeSession::applyBetweenDabs)
  /// so that it stays one undo step. The modeller's stroke and strokeAlongPath call it alike.
  void relaxBetweenDabs(KeepDetailRun& run, gpu::StrokeSession& stroke,
                        const gpu::BrushManifest& brush, float radius, int dabs);
  /// The stroke's record, with the keep-detail relaxation applied and folded into it when on.
  // radius: the largest radius the stroke's dabs used (object units), which sets the margin.
  core::Stroke keepDetailAfter(core::Stroke record, const gpu::BrushManifest& brush, float radius,
                               KeepDetailRun& run);

  bool keepDetail_ = true;
  core::Stroke lastRelaxation_;
  gpu::BrushEngine* engine_ = nullptr;
  const gpu::BrushCatalog* catalog_ = nullptr;
  BrushVariants variants_;
  std::unique_ptr<gpu::GpuDocument> document_;
  std::unique_ptr<ActiveStroke> stroke_;
  core::EditHistory history_;
  long long dabCount_ = 0;
  double lastDabMs_ = 0;
};

/// The texel rectangles whose normals read the touched texels: each grown by one, plus the
/// image's borders when one reaches a border (neighbours across a seam sit on the opposite
/// one). side is N + 1.
std::vector<core::TexelRect> normalRectsAround(std::vector<core::TexelRect> touched, int side);
/// The texel rectangles a recorded stroke changed.
std::vector<core::TexelRect> changedRects(const core::Stroke& stroke);

} // namespace octaclay::app
