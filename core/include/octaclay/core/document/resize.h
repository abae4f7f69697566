#pragma once

#include "octaclay/core/document/document.h"

namespace octaclay::core {

/// The document at another resolution with the same parameterization: every layer (positions
/// with saliency, diffuse, feature, mask) resampled at sample (i, j)'s point (i·N/M, j·N/M) of
/// the old grid, read through the octahedral tiling (wrap()) so the surface goes on across the
/// seams. Up (M > N): Catmull-Rom interpolation (the old samples keep their values); down
/// (M < N): the Catmull-Rom kernel widened N/M times, a filter that keeps what the coarser grid
/// can hold, so that resizing up again comes back close to the original. Painted layers are
/// clamped to the values around each sample (no ringing at a paint edge); uniform layers stay
/// uniform. Identified samples get the bits of their canonical sample (seams exact). M = N
/// returns a copy. Throws Error(InvalidArgument) unless m is a power of two in 2 … 8192, and
/// Error(InvalidInput) for a document with non-finite positions. O(M² · max(1, N/M)²) time.
Document resizeDocument(const Document& document, int m);

} // namespace octaclay::core
