#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"

#include <cstddef>
#include <functional>
#include <string>

namespace octaclay::core {

struct RemeshOptions {
  /// The new document's N; 0 keeps the current one.
  int size = 0;
  /// How far the surface may move, as fractions of its bounding-box diagonal, at the same or a
  /// finer N; a coarser N (M < N) allows (N/M)² as much (a chord's error grows with its square).
  /// Looser than the even-out's: a new sampling at the same N cuts sharp tips and creases by
  /// up to about half a new spacing (docs/import.md gives the figures of remeshed cases).
  double rmsTolerance = 5e-4;
  double hausdorffTolerance = 1e-2;
  /// Sharp tips and creases: an old vertex farther than this (a fraction of the diagonal) from
  /// the new surface pulls the new sample nearest it onto itself, so the new surface passes
  /// through it (the Hausdorff distance is set by such vertices). Infinity snaps none.
  double featureTolerance = 2.5e-4;
  /// Random points per surface of the surface-distance measure (besides the vertices).
  std::size_t samplesPerSurface = 100'000;
};

/// How well a carried layer kept its values: each old sample's value against the value the new
/// surface shows at the point closest to it (area-weighted over the old samples).
struct CarriedLayer {
  bool painted = false;   ///< false for a uniform layer (carried exactly, nothing measured)
  double meanError = 0;   ///< diffuse: mean CIE76 ΔE of the RGB as sRGB; else mean |Δ|
  double maxError = 0;    ///< the largest such error
  double shareWithin = 1; ///< share of the area whose error is ≤ 5 ΔE (diffuse) or ≤ 0.02
  /// The same share over the painted area alone: the old samples whose value differs from the
  /// layer's fill (1 when none does).
  double paintedShareWithin = 1;
  double paintedArea = 0; ///< that area's share of the surface
};

struct RemeshResult {
  Document document; ///< the remeshed document, or the input unchanged
  bool changed = false;
  std::string reason;           ///< why the document was left unchanged (empty when changed)
  StretchSummary before, after; ///< after: of the remeshed surface (also when refused)
  SurfaceDistance moved;        ///< old surface against the remeshed one
  CarriedLayer diffuse, feature, mask;
  int flipped = 0; ///< triangles the spherical map folds (refused when not 0)
  int snapped = 0; ///< new samples moved onto a sharp old vertex (RemeshOptions::featureTolerance)
  double parameterizeMs = 0, resampleMs = 0, measureMs = 0;
};

/// Mesh ▸ Remesh and `octaclay-cli remesh`: a new, even sampling of the document's surface.
/// The surface (extractMesh, turned outward) is parameterized over the sphere as `import` does
/// (parameterizeOnSphere), from N = 128 on coarse to fine along the image's
/// own grid: the grid of 64 parameterized whole, each finer level placed from the one below
/// and, up to 256, relaxed where it still moves (src/import/spherical_image.h); resampled
/// through the octahedron at the new N (locateOctahedralSamples), the new samples nearest the
/// old surface's sharp tips and creases moved onto them (RemeshOptions::featureTolerance), and
/// every layer carried from the old surface: each new sample lies on an old triangle and takes
/// its layers' values there, barycentrically (the closest point of the old surface is the
/// sample itself). Identified samples get equal bits. The result is
/// checked: when the surface moved beyond the tolerances, or the map folds, the document comes
/// back unchanged with the reason. progress (fraction done; false cancels) is called on the
/// caller's thread. Throws Error(InvalidArgument) for an invalid size, Error(InvalidInput) for a
/// document with non-finite positions, Error(Cancelled) when progress returned false.
RemeshResult remeshDocument(const Document& document, const RemeshOptions& options = {},
                            const std::function<bool(float)>& progress = {});

} // namespace octaclay::core
