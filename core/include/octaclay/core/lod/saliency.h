#pragma once

// Mesh saliency of the geometry image (thesis 4.3; Lee et al. 2005): where the surface's
// curvature differs from its surroundings. The salient LOD methods (lod.h) read it from the
// position image's alpha; the GPU pass (gpu/saliency.h) computes the same values.

#include "octaclay/core/geometry/geometry_image.h"

#include <vector>

namespace octaclay::core {

/// The saliency formula, exactly (the GPU pass must match it; N is the image's samples across,
/// √(W·H): the ball's N; all reads of a sample outside the grid go through the grid's wrap(), so
/// the ball's octahedral tiling and a torus's periods are seamless and a plane's boundary is
/// clamped onto):
///  1. n(s): vertexNormal (normals.h), the area-weighted normal of the incident triangles.
///  2. curvature c(s) = ¼ Σ over the four axis neighbours q = s ± (1, 0), s ± (0, 1) of
///     1 − n(s)·n(q) (the change of normal at distance one sample).
///  3. G(c, σ): c blurred with the normalised Gaussian exp(−d²/2σ²), truncated at radius
///     ⌈2σ⌉ samples, separably (rows then columns, each read through wrap(); the tilings'
///     symmetries, half-turns and translations, and a plane's clamping map rows onto rows, so
///     this is the exact 2-D blur of the tiled field).
///  4. saliency(s) = Σ over scales σ of |G(c, σ)(s) − G(c, 2σ)(s)| (centre-surround at several
///     radii, Lee et al. 2005), then divided by its maximum over the image (all zero stays zero).
///  5. Identified samples take their canonical sample's value (they agree up to rounding; a
///     torus's canonical sample is the one below column W and row H; a plane has none).
struct SaliencyOptions {
  /// The centre scales σ in samples. Empty = {1, 2, 4, 8, 16} × N/256, each at least 1.
  std::vector<float> scales;
};

/// CPU reference of the GPU saliency pass: writes each sample's saliency (formula above),
/// normalised to [0, 1] over the image, into the position image's alpha. Every topology (the
/// ball, a torus, a plane). O(W·H Σσ) time.
void computeSaliency(GeometryImage& image, const SaliencyOptions& options = {});

/// The N of the default scales: √(W·H) of the grid (the ball's N).
float saliencySamplesAcross(const SampleGrid& grid);

} // namespace octaclay::core
