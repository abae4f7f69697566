#pragma once

#include "dab_pass.h"

// The plain pass kind ("pass": "layers", a body defining brush()): one pass per layer written.
namespace octaclay::gpu::detail {

/// One pass per layer the brush writes, each finished before the next: positions last, so
/// every other layer's pass reads the positions from before the dab (first for a brush that
/// reads the feature layer: its positions pass displaces by the change of it).
void runLayerPasses(DabPass& pass);

} // namespace octaclay::gpu::detail
