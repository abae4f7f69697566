#pragma once

#include "brush_settings.h"
#include "brush_variants.h"
#include "keep_detail_run.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/stroke.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::gpu {
class BrushCatalog;
class BrushEngine;
} // namespace octaclay::gpu

namespace octaclay::app {

/// How a stroke begins (SculptSession::beginStroke): the brush as the user set it and the view.
/// The viewport fills it from the Brushes panel and its camera, `octaclay-cli stroke` from its
/// options; everything after this is the session's.
struct StrokeStart {
  /// The brush to stroke with (Shift's smooth may differ from settings.brushId).
  std::string brushId;
  /// Radius (a fraction of the model's bounding-box diagonal as the stroke begins), strength,
  /// pressure target, symmetry and keep detail; the area, falloff and parameters apply when
  /// brushId is settings.brushId (else the manifest's). Fixed for the stroke.
  BrushSettings settings;
  /// Where colour paint goes (a brush writing only diffuse: the Layers dock's target).
  core::EditLayer paintTarget = core::EditLayer::Diffuse;
  float sign = 1; ///< negative inverts the brush (Ctrl)
  /// The camera's eye (object space): splats project from it through each dab's centre, drags
  /// move in the view plane through the stroke's start. Unset: along the dab's normal, and a
  /// scripted drag along its points.
  std::optional<core::Vec3f> eye;
  float spacing = 0; ///< between dabs, a fraction of the radius; 0: the brush's (dabSpacing)
  /// The radius in object units, fixed for the stroke: the viewport's view radius (pixels at
  /// the pressed point's depth, RadiusUnit::View). Unset: settings.radius × the diagonal.
  /// Must be finite and positive.
  std::optional<float> objectRadius;
};

/// One move of a stroke (SculptSession::moveTo): to a point of the image, along a pointer's ray
/// (dragging brushes after their first move) or to a point in object space (a dragging brush's
/// scripted drag), with pen pressure in [0, 1].
struct StrokeMove {
  enum class Kind { ImagePoint, PointerPoint, Ray, ObjectPoint };
  Kind kind = Kind::ImagePoint;
  core::Vec2f uv;                ///< ImagePoint: (u, v), each in [0, 1]
  core::Vec3f origin, direction; ///< Ray: object space; ObjectPoint: origin is the point
  float pressure = 1;

  /// To image point uv (a pick's interpolated (u, v) or a path's point).
  static StrokeMove toUv(core::Vec2f uv, float pressure = 1) {
    return {Kind::ImagePoint, uv, {}, {}, pressure};
  }
  /// To the image point of a pick under the pointer: consecutive ones are neighbours on the
  /// surface, so a jump of (u, v) crosses a seam (pointer_legs) instead of a walk across it.
  static StrokeMove underPointer(core::Vec2f uv, float pressure = 1) {
    return {Kind::PointerPoint, uv, {}, {}, pressure};
  }
  /// A dragging brush to where the pointer's ray meets the drag plane (gpu::StrokeSession::
  /// dragAlong).
  static StrokeMove alongRay(core::Vec3f origin, core::Vec3f direction, float pressure = 1) {
    return {Kind::Ray, {}, origin, direction, pressure};
  }
  /// A dragging brush to point (gpu::StrokeSession::dragTo).
  static StrokeMove toPoint(core::Vec3f point, float pressure = 1) {
    return {Kind::ObjectPoint, {}, point, {}, pressure};
  }
};

/// What one run of the queued moves did.
struct DabRun {
  int made = 0;      ///< dabs, mirrored ones included
  std::string error; ///< why a dab failed; empty if none did
};

/// How a stroke ended (SculptSession::finishStroke).
struct StrokeEnd {
  std::string label;      ///< the brush id; empty when nothing was recorded
  int dabs = 0;           ///< mirrored ones included
  double engineMs = 0;    ///< the brush engine's time and keep detail's, file I/O excluded
  double firstMoveMs = 0; ///< of engineMs, the first move's (its first dab): paid once
  int firstMoveDabs = 0;  ///< the dabs of that move
  gpu::StrokeSession::Phases phases; ///< where the dabs' time went
  std::size_t changedTiles = 0;      ///< tiles of the step (the stroke and its relaxation)
  std::size_t stepBytes = 0;         ///< memory the step holds (core::EditStep::computeBytes)
};

class SculptSession;

/// A stroke whose dabs are done and whose keep-detail relaxation is not yet solved
/// (SculptSession::concludeStroke).
class StrokeEnding {
public:
  ~StrokeEnding();
  /// Whether relax() has work to do (keep detail on, a sculpt brush that changed positions).
  bool needsRelaxation() const { return relaxes_; }
  /// Solves keep detail's relaxation over the session's CPU mirror: no GL, no session state, so
  /// any thread may run it while nothing writes the document.
  void relax();

private:
  friend class SculptSession;
  struct Parts;
  explicit StrokeEnding(std::unique_ptr<Parts> parts);
  std::unique_ptr<Parts> parts_;
  bool relaxes_ = false, solved_ = false;
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
  /// The brushes' catalog. Only valid if hasBrushes().
  const gpu::BrushCatalog& brushes() const { return *catalog_; }
  /// Compiles brush as its manifest declares it.
  void loadBrush(const gpu::BrushManifest& brush);
  /// The brushes were recompiled from their files (a reload): their variants are compiled anew
  /// when next used.
  void brushesReloaded(const std::vector<std::string>& ids);

  /// Uploads document, replacing the current one, dropping the stroke being made and clearing
  /// the history; progress as gpu::GpuDocument's, into `storage` when it was made ahead
  /// (GpuDocument::makeStorage). If the upload throws, nothing changed.
  void setDocument(core::Document document, const std::function<void(float)>& progress = {},
                   gpu::GpuDocument::Storage storage = {});
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

  // The one stroke door. The viewport feeds it pointer samples (queueMove, runQueuedMoves once
  // per frame), `octaclay-cli stroke` a path (playStroke in stroke_script.h): the same calls,
  // so the same stroke gives the same document bit for bit.

  /// Begins a stroke as start says: the brush compiled as the settings ask (BrushVariants), the
  /// radius (start.objectRadius, else a fraction of the diagonal) fixed. Throws (the message
  /// says why) if the brush is not loaded or will not compile, core::Error(InvalidArgument) for
  /// an objectRadius that is not finite and positive, and what gpu::StrokeSession's constructor
  /// throws (a parameter or view that is not finite or out of range, a model with no usable size);
  /// no stroke begins then. Precondition: a document, brushes and no stroke.
  void beginStroke(const StrokeStart& start);
  bool stroking() const { return stroke_ != nullptr; }
  /// Whether the stroke's brush drags (grab, snake hook: gpu::StrokeSession::drags()): after
  /// its first move, the viewport moves it along the pointer's rays.
  bool strokeDrags() const;
  /// Moves the stroke now: the dabs along the way at the stroke's radius and strength, scaled
  /// by move.pressure as the settings' pressure target says. Returns the dabs made. Throws what
  /// gpu::StrokeSession's moves throw; when a dab failed (a GL error, the watchdog) the layers
  /// are back as before the stroke, later moves make no dab and finishStroke() records nothing.
  /// Precondition: stroking().
  int moveTo(const StrokeMove& move);
  /// Queues a move for runQueuedMoves (the viewport: one run per frame).
  void queueMove(const StrokeMove& move);
  /// Makes the queued moves (moveTo), then empties the queue. A failing move ends the run with
  /// its error, as moveTo says.
  DabRun runQueuedMoves();
  /// About how many dabs moving along path and then dragging through dragPoints will make
  /// (gpu::StrokeSession::expectDabs), before any of it is done; throws
  /// core::Error(InvalidArgument) past gpu::kMaxStrokeDabs. Precondition: stroking().
  int expectDabs(const std::vector<std::array<float, 2>>& path,
                 const std::vector<core::Vec3f>& dragPoints) const;
  /// observer is told the stroke's dab count after each dab (a progress display).
  void observeDabs(std::function<void(int)> observer);
  /// Ends the stroke: keep detail relaxes what it stretched (when the start's settings ask and
  /// the brush sculpts), holding the samples at the stroke's first and last image points (where
  /// a press or a script's path begins and ends: a script that dabs there again, a limb pulled
  /// click by click, finds the same spot after the relaxation), and the stroke and its relaxation
  /// are recorded in history() as one step labelled with the brush id. Nothing is recorded when it
  /// made no dab or changed nothing. When the result holds a non-finite value the layers are
  /// restored, nothing is recorded, the stroke is over and core::Error(InvalidInput) says where.
  StrokeEnd finishStroke();
  /// finishStroke() in three steps, so that keep detail's relaxation (CPU work, ~0.5 s at
  /// N = 1024) can run beside the GUI: concludeStroke ends the dabs (GL current; null without a
  /// stroke), StrokeEnding::relax solves the relaxation (any thread, no GL; reads the CPU mirror,
  /// which nothing may write meanwhile), commitStroke applies it and records the step (GL
  /// current). finishStroke() is the three in a row, so both give the same document bit for bit.
  /// concludeStroke and commitStroke throw as finishStroke does.
  std::unique_ptr<StrokeEnding> concludeStroke();
  StrokeEnd commitStroke(std::unique_ptr<StrokeEnding> ending);
  /// Ends the stroke without recording it, the layers back as before it (a script refused
  /// part-way). Nothing happens without a stroke.
  void abandonStroke();

  /// Keep detail (on by default): after a sculpt stroke stretched the positions it changed, the
  /// samples within core::keepDetailMargin of the changed texels flow toward the stretch
  /// (core::relaxChangedStep); every other sample keeps its bits. A dragging stroke (snake hook)
  /// also relaxes as it goes (relaxBetweenDabs). The stroke and its relaxations are one undo
  /// step. Each stroke's StrokeStart settings say whether it applies; this is the last stroke's.
  bool keepDetail() const { return keepDetail_; }
  /// What keep-detail's relaxations changed in the last stroke, during it (a dragging brush)
  /// and after it, as one step (no tiles when none moved): its tiles are what to redraw. After a
  /// stroke relaxed only at its end, its Before side is the surface as the stroke left it
  /// (benchmarks measure how far it moved).
  const core::EditStep& lastRelaxation() const { return lastRelaxation_; }

  /// Makes `after` (same size) the document, on the GPU and the mirror, as one undo step
  /// labelled label (e.g. the global even-out); returns whether it recorded one (false: nothing
  /// differed). What it wrote reaches the change feed even when a tile fails. Precondition: a
  /// document and no stroke.
  bool applyChange(const core::Document& after, const std::string& label);

  /// Makes `after` (any N) the document as one history step labelled label (Remesh, Resolution,
  /// Import): the step holds both documents, so undo and redo bring either back bit for bit.
  /// Throws what the upload throws; nothing changed then. Precondition: a document, no stroke.
  void replaceDocument(core::Document after, const std::string& label);

  core::EditHistory& history() { return history_; }
  const core::EditHistory& history() const { return history_; }
  /// Reverts / reapplies the newest step on the GPU and the mirror (a replacing step uploads the
  /// document it brings back, published as NewDocument): the step, or
  /// null if there is none (or no document, or a stroke is being made). Throws what the
  /// history's applier throws; the history is then unchanged.
  const core::EditStep* undo();
  const core::EditStep* redo();

  /// The one follower of the document's changes (gpu::GpuDocument::setChangeFollower), kept
  /// across documents. The session reports after each of its calls that changed something:
  /// runQueuedMoves and moveTo (Dabs), finishStroke / commitStroke (StrokeEnd), abandonStroke
  /// and a failed run (Applied), undo / redo, applyChange (Applied), setDocument (NewDocument).
  void setChangeFollower(std::function<void(const gpu::DocumentChange&)> follower);

  long long dabs() const { return dabCount_; }    ///< made since the session began
  double lastDabMs() const { return lastDabMs_; } ///< per dab, over the last run that dabbed

private:
  friend class StrokeEnding;
  struct ActiveStroke;

  /// Keep detail as a dragging stroke goes (snake hook): after its 4th dab, then each time its
  /// dab count doubles, the samples near what its dabs changed so far relax
  /// (core::relaxChangedStep), written into the stroke (gpu::StrokeSession::applyBetweenDabs)
  /// so that it stays one undo step. Both doors reach it: beginStroke observes every dab.
  void relaxBetweenDabs(KeepDetailRun& run, gpu::StrokeSession& stroke,
                        const gpu::BrushManifest& brush, float radius, int dabs);

  /// Uploads document in place of the current one (published as NewDocument), the history
  /// kept: setDocument then clears it, a replacing step does not.
  void show(core::Document document, const std::function<void(float)>& progress = {},
            gpu::GpuDocument::Storage storage = {});
  /// moveTo without reporting the change (runQueuedMoves reports once for its run).
  int move(const StrokeMove& move);
  void publish(gpu::ChangeKind kind);

  std::function<void(const gpu::DocumentChange&)> follower_;
  bool keepDetail_ = true;
  core::EditStep lastRelaxation_;
  gpu::BrushEngine* engine_ = nullptr;
  const gpu::BrushCatalog* catalog_ = nullptr;
  BrushVariants variants_;
  std::unique_ptr<gpu::GpuDocument> document_;
  std::unique_ptr<ActiveStroke> stroke_;
  core::EditHistory history_;
  long long dabCount_ = 0;
  double lastDabMs_ = 0;
};

/// The texel rectangles whose normals read the touched texels: each grown by three (the normal
/// pass's widest reach), plus the
/// image's borders when one reaches a border (neighbours across a seam sit on the opposite
/// one). side is N + 1 (W + 1), rows H + 1 of a W × H image (0: side).
std::vector<core::TexelRect> normalRectsAround(std::vector<core::TexelRect> touched, int side,
                                               int rows = 0);
/// The texel rectangles a recorded stroke changed.
std::vector<core::TexelRect> changedRects(const core::EditStep& stroke);

} // namespace octaclay::app
