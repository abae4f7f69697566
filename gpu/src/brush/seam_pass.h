#pragma once

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <vector>

// The seaming pass after a dab that reached the border: identified border samples made equal.
namespace octaclay::gpu::detail {

/// The seaming program (seam.glsl) for RectPass. Throws GlError.
Program seamProgram();

/// Seams layer over the runs (seamRuns): the pass writes the layer's scratch from the layer's
/// texture, then the runs are copied back into the texture. Leaves the scratch bound as target.
void seamLayer(const Program& seam, RectPass& rectPass, GpuDocument& document,
               core::EditLayer layer, const std::vector<core::TexelRect>& runs);

/// The parts of runs (seamRuns: one sample thick) that no rectangle of tiles holds, in
/// rectangles disjoint from tiles and from each other.
std::vector<core::TexelRect> uncoveredParts(const std::vector<core::TexelRect>& runs,
                                            const std::vector<core::TexelRect>& tiles);

} // namespace octaclay::gpu::detail
