#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"

#include <cstddef>
#include <string>

namespace octaclay::core {

/// The document at another resolution with the same parameterization: every layer (positions
/// with saliency, diffuse, feature, mask) resampled at sample (i, j)'s point (i·N/M, j·N/M) of
/// the old grid, read through the octahedral tiling (wrap()) so the surface goes on across the
/// seams. Up (M > N): Catmull-Rom interpolation (the old samples keep their values), each new
/// position kept within a tenth of the old median edge of the old surface (the kernel swings
/// out beside a stretched part's long edges); down (M < N): halved N/M times, each time by the
/// low-pass filter of the lifting scheme whose prediction is that Catmull-Rom interpolation, so
/// that resizing up and down again gives the original back (to float rounding, where the limit
/// did not act) and resizing down then up comes back close. Painted layers are clamped to the
/// values around each sample (no ringing at a paint edge); uniform layers stay uniform.
/// Identified samples get the bits of their canonical sample (seams exact). M = N returns a
/// copy. Throws Error(InvalidArgument) unless m is a power of two in 2 … 8192, and
/// Error(InvalidInput) for a document with non-finite positions. O(M² + N²) time.
/// A torus or plane (W × H) gets width m and height H·m/W, read through its own wrap (a
/// torus's periods, a plane's clamped boundary), column W and row H of a torus its column and
/// row 0 bit for bit; Error(InvalidArgument) when that grid is not valid for the topology.
Document resizeDocument(const Document& document, int m);

struct ResizeOptions {
  int size = 0; ///< the new N
  /// How far the surface may move, as fractions of its bounding-box diagonal, at a finer N:
  /// Remesh's tolerances (a smooth surface resampled finer is rounder than its old chords by their
  /// sagitta: 0.014 % RMS for a sphere from N = 64); a coarser N (M < N) allows (N/M)² as much
  /// (a chord's error grows with its square).
  double rmsTolerance = 5e-4;
  double hausdorffTolerance = 1e-2;
  /// Random points per surface of the surface-distance measure (besides the vertices).
  std::size_t samplesPerSurface = 200'000;
};

struct ResizeResult {
  Document document; ///< the resized document, or the input unchanged
  bool changed = false;
  std::string reason;           ///< why the document was left unchanged (empty when changed)
  StretchSummary before, after; ///< after: of the resized surface (also when refused)
  SurfaceDistance moved;        ///< old surface against the resized one
};

/// Mesh ▸ Resolution and `octaclay-cli resize`: resizeDocument, then the result checked: when the
/// surface moved beyond the tolerances (a coarser N cannot hold a stretched part's few samples)
/// or a position is not finite, the document comes back unchanged with the reason. Throws as
/// resizeDocument does.
ResizeResult resizeAndCheck(const Document& document, const ResizeOptions& options);

} // namespace octaclay::core
