#pragma once

#include "octaclay/core/document/edit_step.h"
#include "octaclay/core/geometry/vec.h"
#include "octaclay/gpu/brush_engine.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace octaclay::gpu {

class StrokeSession;

/// Mirror planes through the model's centre (bounding-box centre at the stroke's start).
enum SymmetryAxis : unsigned { kSymmetryNone = 0, kSymmetryX = 1, kSymmetryY = 2, kSymmetryZ = 4 };

/// The most dabs one stroke may make (mirrored ones included): a stroke that would make more is
/// refused before its walk (core::Error(InvalidArgument)), so no path, drag or spacing makes a
/// stroke without end.
inline constexpr int kMaxStrokeDabs = 100'000;

/// How far a drag may reach, in diagonals of the model's bounding box: a drag point farther
/// from the model's centre is refused (core::Error(InvalidArgument)).
inline constexpr double kMaxDragDiagonals = 100;

/// What a stroke's dabs share (StrokeSession); the radius, strength and pressure come with each
/// move.
struct StrokeSettings {
  float spacing = 0.0f; ///< between dabs, fraction of the radius; 0 → the brush's (dabSpacing)
  unsigned symmetry = kSymmetryNone;
  std::map<std::string, std::array<float, 4>> parameters;
  /// A camera's eye (object space): splats project from it through each dab's centre, and a
  /// drag moves in the view plane through its start. Unset: along each dab's centre normal, a
  /// drag across the start's normal (dragAlong) or as it is (dragTo).
  std::optional<core::Vec3f> viewEye;
};

/// The sample whose position is nearest to p (searching only tiles near p).
core::Sample nearestSample(const GpuDocument& document, core::Vec3f p);

} // namespace octaclay::gpu

namespace octaclay::gpu {

/// A stroke made interactively: the modeller feeds it the point under the pointer as the
/// pointer moves, and `octaclay-cli stroke` the points of its path, both through the modeller's
/// app::SculptSession; it dabs along the way by one set of rules (stroke_rules.h: spacing on the
/// surface as the stroke began, the remainder carried from one move to the next, symmetry, undo
/// captured over the whole stroke). Use it on the thread whose GL context is current; brush and
/// document must outlive it.
class StrokeSession {
public:
  /// Throws core::Error(UnknownId) for an unknown brush,
  /// core::Error(InvalidArgument) for a parameter, spacing or view that is not finite or a
  /// parameter outside its [min, max], core::Error(InvalidInput) for a model with no usable
  /// size (core::sizeProblem: a point, or smaller than float can resolve). Every move below
  /// throws core::Error(InvalidArgument) before dabbing when the stroke would pass
  /// kMaxStrokeDabs, or a drag would reach past kMaxDragDiagonals.
  StrokeSession(BrushEngine& engine, GpuDocument& document, const BrushManifest& brush,
                StrokeSettings settings);
  ~StrokeSession();
  StrokeSession(const StrokeSession&) = delete;
  StrokeSession& operator=(const StrokeSession&) = delete;

  /// Moves the stroke to image point uv (each in [0, 1]; a pick's interpolated (u, v)), walking
  /// the straight segment from the previous point. The first call dabs at uv. radius (object
  /// units), strength (fraction of the radius, per radius travelled for sculpt brushes) and
  /// pressure apply to the dabs this call makes (pen pressure varies along a stroke). Returns
  /// the number of dabs made, mirrored ones included. Throws core::Error(InvalidArgument) for a
  /// point outside [0, 1] or a radius, strength or pressure that is not finite. When a dab
  /// fails (GlError, BrushTimeoutError from the watchdog) the layers are restored from the undo
  /// capture before the error is rethrown; no move may follow, and finish() returns an empty
  /// record (nothing to undo).
  int moveToUv(core::Vec2f uv, float radius, float strength, float pressure = 1.0f);
  /// The stroke goes on from image point uv without a dab: the same surface point as the last
  /// one reached, across a seam (a torus's opposite edge), or a jump over one; the distance
  /// walked since the last dab is kept. Before the first move it does nothing. Throws
  /// core::Error(InvalidArgument) for a point outside [0, 1].
  void continueFrom(core::Vec2f uv);
  /// moveToUv at sample s's image point (s / N). Throws core::Error(InvalidArgument) for a
  /// sample outside the image, and what moveToUv throws.
  int moveTo(core::Sample s, float radius, float strength, float pressure = 1.0f);
  /// Whether the brush drags ("stroke" "anchored" or "drag"): after the first move (moveToUv,
  /// where the drag starts) the modeller moves it with dragAlong().
  bool drags() const;
  /// A dragging brush's move to the pointer's ray (object space; origin and direction): the drag
  /// is from the stroke's start to where the ray meets the view plane through it (across the
  /// start's normal without settings.viewEye). An anchored stroke dabs once with that drag, a
  /// drag stroke walks to it in steps of the spacing. A ray along the plane makes no dab. Returns
  /// the dabs made. Throws core::Error(InvalidArgument) for a brush that does not drag or a
  /// value that is not finite, std::logic_error before the first move.
  int dragAlong(core::Vec3f origin, core::Vec3f direction, float radius, float strength,
                float pressure = 1.0f);
  /// The same to a point in object space: the drag is from the stroke's start to point,
  /// projected into the view plane when settings.viewEye is set.
  int dragTo(core::Vec3f point, float radius, float strength, float pressure = 1.0f);
  /// About how many dabs moving along path (each pair in [0, 1]) and then dragging through
  /// dragPoints at this radius will make, before any of it is done. Throws
  /// core::Error(InvalidArgument) when that passes kMaxStrokeDabs or a drag point lies beyond
  /// kMaxDragDiagonals, so a scripted stroke is refused before its first dab.
  int expectDabs(const std::vector<std::array<float, 2>>& path,
                 const std::vector<core::Vec3f>& dragPoints, float radius) const;
  /// observer is told the stroke's dab count after each dab (a progress display).
  void observeDabs(std::function<void(int)> observer);
  /// Texel rectangles the dabs since the last call ran over (for redrawing), then forgets them.
  std::vector<core::TexelRect> takeTouched();

  /// Between dabs (e.g. from observeDabs' observer): makes `change`, an edit computed from the
  /// document as it is now (keep-detail's relaxation: tiles of any layer, before and after), part
  /// of the stroke. Its tiles are captured for undo first, then its After state is written to
  /// the mirror and the textures, and its tiles count as touched (takeTouched). finish()'s record
  /// and a failed dab's restore include it; the next dabs act on the changed surface.
  void applyBetweenDabs(const core::EditStep& change);
  /// The stroke's undo record so far (the captured tiles against the mirror now), labelled;
  /// the stroke goes on. No finite check (finish() makes it).
  core::EditStep recordSoFar(const std::string& label) const;

  int dabs() const;
  double engineMs() const;
  /// The engine time of the stroke's first move and the dabs it made (its first dab, and
  /// its mirror images): what a stroke pays once (programs compiled on first use, scratch
  /// textures made), apart from the sustained cost of the dabs after it.
  double firstMoveMs() const;
  int firstMoveDabs() const;
  /// Where the dabs' engine time went so far, summed over the dabs (the rest of engineMs() is
  /// the path's walk and the stroke's own bookkeeping).
  struct Phases {
    double centreMs = 0; ///< each dab's centre, normal (the area normal) and mirror images
    double reachMs = 0;  ///< the tiles each dab can change (BrushEngine::reach)
    double undoMs = 0;   ///< the undo capture of tiles not touched before
    double passesMs = 0; ///< the passes (BrushEngine::dab: brush, seam, tile bounds)
  };
  Phases phases() const;
  /// The stroke's undo record, labelled; the session must not be used afterwards. When a written
  /// layer now holds a non-finite value or a position beyond ±1e15, the layers are restored
  /// bit for bit and core::Error(InvalidInput) names the sample instead. A pass the watchdog had
  /// not waited for yet that overran its limit (BrushEngine::finishPasses) restores them too and
  /// throws BrushTimeoutError.
  core::EditStep finish(const std::string& label);

private:
  struct State;
  std::unique_ptr<State> state_;
};

} // namespace octaclay::gpu
