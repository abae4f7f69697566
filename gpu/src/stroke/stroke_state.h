#pragma once

#include "undo_capture.h"

#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/stroke.h"

#include <array>
#include <functional>
#include <optional>
#include <vector>

// A stroke's state (StrokeSession), its jobs each in a file of its own: the stroke as a whole
// (stroke.cpp), the walk along a path (stroke_walk.cpp), one dab and its mirror images
// (stroke_dab.cpp, stroke_symmetry.cpp), the drag (stroke_drag.cpp); the settings' checks are
// stroke_settings_check's.
namespace octaclay::gpu {

struct StrokeSession::State {
  State(BrushEngine& e, GpuDocument& d, const BrushManifest& b, StrokeSettings s);
  ~State();

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

  // The stroke as a whole (stroke.cpp).

  // Whether the brush's passes read the dab's centre normal: the area normal, a sum over every
  // cell the dab covers on the CPU, is computed only for those (a smooth dab's normal reaches no
  // pass); the others get the point normal.
  bool usesCentreNormal() const;

  // Puts the layers back as they were before the stroke; the session is over.
  void abandon();

  // The surface as it was when the stroke began, at image point (x, y) in samples: what the
  // dabs' spacing is measured on, so that a stroke does not stretch its own spacing.
  core::Vec3f startPosition(double x, double y) const;

  // The walk along a path (stroke_walk.cpp).

  // Moves the stroke to image point xy (in samples): the first move dabs there, later ones
  // walk from the previous point.
  int moveTo(std::array<double, 2> xy, float radius, float strength, float pressure);

  // Walks the straight segment from the previous point to b (image coordinates, in samples),
  // dabbing each time the distance since the last dab reaches spacing (object units). The
  // distance is exact on the start surface's triangles; the remainder carries to the next walk.
  void walkTo(std::array<double, 2> b, float radius, float strength, float pressure);

  // Between dabs at this radius, object units: the brush's spacing, and at most 1e4 dabs per
  // diagonal (a radius far below a sample would otherwise make dabs without end).
  double spacingFor(float radius) const;

  // The length of the straight walk a → b (image coordinates, in samples) on the surface as
  // the stroke began.
  double walkLength(std::array<double, 2> a, std::array<double, 2> b) const;

  // Refuses, before any dab of this move, a walk of `length` (object units) at `spacing` that
  // would take the stroke past kMaxStrokeDabs: a drag to infinity or a radius far below a
  // sample would otherwise dab without end.
  void requireDabBudget(double length, double spacing) const;

  // One dab and its mirror images (stroke_dab.cpp, stroke_symmetry.cpp).

  // One dab at image point (x, y) in samples and its mirror images, capturing the undo tiles
  // each may touch first. The centre and its normal are the current surface's there; a mirror
  // image is centred on the mirrored point with the mirrored normal, so a symmetric model gets
  // mirror-equal dabs.
  void dabAt(std::array<double, 2> xy, float radius, float strength, float pressure,
             std::optional<core::Vec3f> cursorDrag = std::nullopt);

  // A dab and its mirror images, one per symmetry plane combination.
  int imagesPerDab() const;

  // The drag (stroke_drag.cpp).

  // The drag at image point xy: from the stroke's start to the start surface there, in the
  // view plane (across dragNormal).
  core::Vec3f dragAt(std::array<double, 2> xy) const;

  // A dragging brush's move to the drag that ray gives: where it meets the drag plane (through
  // the stroke's start, across the view; across the start's normal without a view). An anchored
  // stroke dabs once with it; a drag stroke walks there from its last drag in steps of the
  // spacing (object units), carrying the remainder as walkTo does.
  int dragAlong(core::Vec3f origin, core::Vec3f direction, float radius, float strength,
                float pressure);

  // The same to a point in object space: the drag is from the stroke's start to it, projected
  // into the view plane when the stroke has a view.
  int dragTo(core::Vec3f point, float radius, float strength, float pressure);

  // Refuses a drag after the stroke ended, one before its first move (std::logic_error), and a
  // radius, strength or pressure that is not finite.
  void checkDragMove(float radius, float strength, float pressure) const;

  // Dabs towards target, the drag from the stroke's start: an anchored stroke once, a drag
  // stroke a spacing apart from its last drag. Returns the dabs made.
  int dragBy(core::Vec3f target, float radius, float strength, float pressure);

  // Refuses a drag target farther than kMaxDragDiagonals from the model's centre.
  void requireDragReach(core::Vec3f point) const;
};

} // namespace octaclay::gpu
