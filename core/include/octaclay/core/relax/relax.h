#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace octaclay::core {

/// Iteration counts above this are refused as absurd.
inline constexpr int kMaxRelaxIterations = 10000;

struct RelaxOptions {
  /// Sweeps over the finest level (coarser levels get more, up to 64 times as many); 0 means 1.
  int iterations = 0;
  /// Samples that keep their surface point (with those identified with them): the centres a
  /// scripted stroke addresses by (u, v), so the next stroke there finds the same spot.
  std::vector<Sample> pinned;
};

/// Called with the fraction done in [0, 1]; returning false cancels the work.
using RelaxProgress = std::function<bool(float)>;

/// The global even-out (DESIGN.md, "Stretch"): a reparameterization of the surface that moves
/// every sample in the image's own parameter domain toward where the surface is stretched, so
/// that grid edges become as even in length as one octahedral grid allows, then resamples every
/// layer (positions with saliency, diffuse, feature, mask) at the new parameter points from
/// `document`. Each new position lies on the old piecewise-linear surface; identified samples
/// stay bit-equal; no cell folds. Throws Error(InvalidArgument) for an iteration count outside
/// [0, kMaxRelaxIterations], Error(InvalidInput) for a document with non-finite positions,
/// Error(Cancelled) when progress returned false (document untouched: it is const).
Document evenOutSamples(const Document& document, const RelaxOptions& options = {},
                        const RelaxProgress& progress = {});

/// How far evenOut may move the surface and how it measures that.
struct EvenOutCheckOptions {
  double rmsTolerance = 1e-4;       ///< surface RMS move, fraction of the bounding-box diagonal
  double hausdorffTolerance = 1e-3; ///< surface Hausdorff move, fraction of the diagonal
  /// The steps tried, as fractions of the solved move, largest first (each resampled from the
  /// original, never from a previous try).
  std::vector<double> steps{1.0, 0.5, 0.25, 0.125};
  /// Random points per surface of the surface-distance measure (besides the vertices).
  std::size_t samplesPerSurface = 100'000;
};

/// What evenOut did and measured. The stretched part: the samples with an incident grid edge
/// over twice the median (before the even-out); after it, a sample counts when its parameter
/// point is nearest such a sample, i.e. when it shows the stretched part of the old surface.
struct EvenOutResult {
  Document document; ///< the evened-out document, or the input unchanged
  bool changed = false;
  std::string reason;           ///< why the document was left unchanged (empty when changed)
  double step = 0;              ///< the fraction of the solved move kept (0 when unchanged)
  int tries = 0;                ///< steps measured
  StretchSummary before, after; ///< after: of the document returned
  std::size_t stretchedBefore = 0, stretchedAfter = 0; ///< samples on the stretched part
  std::size_t vertices = 0;                            ///< N² + 2
  /// How far the surface moved: of the kept step, or of the last step tried when unchanged.
  SurfaceDistance moved;
};

/// Mesh ▸ Even Out Samples and `octaclay-cli relax`: evenOutSamples that checks its own result.
/// A step is kept only when the surface moves within the tolerances, the longest edge ÷ median
/// does not grow, the stretched part does not lose samples and one of the two improves (by
/// 1 %); otherwise the next, smaller step (the solved offsets scaled down) is tried, and when
/// none passes the document comes back unchanged with the reason. Throws as evenOutSamples
/// (Error(Cancelled) when progress returned false, at any point).
EvenOutResult evenOut(const Document& document, const RelaxOptions& options = {},
                      const EvenOutCheckOptions& check = {}, const RelaxProgress& progress = {});

/// How far keep-detail's relaxation reaches beyond the texels a stroke changed: this many brush
/// radii, counted in the surface's median grid edges (Chebyshev distance in samples, through the
/// seams), and at least kKeepDetailMinMargin samples: a 0.06-unit crease on the creature of
/// tests/creature_layout.h at N = 256 reaches 12 samples beyond its texels, a 0.2-unit snake
/// hook on the unit ball about 40 (four times as many at N = 1024). Three radii: a limb pushed out
/// with clicks of radius r draws on that much surface around it (fewer radii left its tip's
/// edges 20x the median and longer).
inline constexpr double kKeepDetailMarginRadii = 3.0;
inline constexpr int kKeepDetailMinMargin = 4;

/// keep-detail's margin in samples for a stroke of brush radius `radius` (object units; the
/// largest its dabs used) on `image`.
int keepDetailMargin(const GeometryImage& image, double radius);

/// The local relaxation behind "keep detail": the same flow around what a stroke changed.
/// `changed` marks the changed samples, (N+1)² row-major (a border sample and its copies alike).
/// A torus or plane ((W+1)×(H+1) samples) goes to its own flow and check
/// (core/src/relax/grid_keep_detail.h); what follows is the ball's.
/// Nothing happens unless one of their grid edges is stretched (over twice the surface's median
/// edge; from 1.5 times at coarse N). Then the samples within `margin` samples of a changed one
/// (Chebyshev distance on the tiled plane, so across the seams) move (pins and the four side
/// midpoints excepted) toward where the surface is stretched, onto what the stroke pulled, and
/// every other sample of every layer keeps its bits. The move is kept only within the
/// relaxation's tolerance: the surface moves by at most 0.01 % RMS and 0.1 % Hausdorff of the
/// bounding-box diagonal, measured over the cells that changed (each side's vertices and
/// area-weighted points against the other side's closest points; a cell whose corners moved by
/// less than half the Hausdorff tolerance counts with its corners' farthest move, a bound). Where
/// the full move takes a point farther than half the tolerance (the tip of a limb pulled far: the
/// surface's corners there), the samples there and around them are held and the flow solved again,
/// twice at most; the last solve's move is scaled back (1/2, 1/4, 1/8) if it must be, and the
/// largest step that fits is kept, else nothing moves. Returns the change as an undo step, the
/// document left as it is: the tiles of every layer the relaxation changes, before and after (empty
/// when nothing moved). Apply its After state to make the change (what keep-detail does on the
/// GPU). Throws like evenOutSamples, and Error(InvalidArgument) when `changed` is not (N+1)² long
/// or margin < 0. Samples beyond the margin keep their bits in every layer, and so do their normals
/// (which read their grid neighbours) beyond one sample more.
EditStep relaxChangedStep(const Document& document, const std::vector<std::uint8_t>& changed,
                          int margin, std::string label, const RelaxOptions& options = {});

/// relaxChangedStep with the changed texels given as rectangles (clipped to the image).
EditStep relaxRegionsStep(const Document& document, const std::vector<TexelRect>& regions,
                          int margin, std::string label, const RelaxOptions& options = {});

/// relaxRegionsStep applied to `document` in place; returns the rectangles of positions it
/// changed (empty when none).
std::vector<TexelRect> relaxRegions(Document& document, const std::vector<TexelRect>& regions,
                                    int margin, const RelaxOptions& options = {});

} // namespace octaclay::core
