#pragma once

#include "octaclay/core/document/document.h"

namespace octaclay::core {

/// The document mirrored across its own plane normal to axis (0 = x, 1 = y, 2 = z) through the
/// origin, still facing outward: every position's axis component changes sign, which alone would
/// turn the surface inside out (a mirror reverses the winding), so the image and every layer are
/// also transposed (sample (i, j) ↔ (j, i)). The transpose maps the octahedral grid onto itself
/// with its cell diagonals and seam pairs and reverses the winding back; each layer's texels
/// follow their positions. Exact: positions change only in sign and place. The mirror duplicate
/// of a scene object is mirrorDocument with mirroredTransform (object_transform.h).
Document mirrorDocument(const Document& document, int axis);

} // namespace octaclay::core
