#pragma once

// What every reader (native .exr, .ocz, import) requires of a document before handing it on, so
// that `info`, `lod`, `stroke`, `export` and `compress` accept and refuse the same files.

#include "octaclay/core/document/document.h"

#include <optional>
#include <string>
#include <vector>

namespace octaclay::core {

/// Largest coordinate magnitude a document may hold: beyond it the bounding-box diagonal
/// (computed in float) overflows, and radii, bounds and error figures become infinite.
inline constexpr float kMaxCoordinate = 1e18f;

/// Why these positions cannot be a document's (a non-finite sample, or a coordinate so large
/// that the bounding box overflows float), or nothing when they are fine.
std::optional<std::string> positionsProblem(const GeometryImage& positions);

/// Why a layer stored in these channels is unusable (some but not all of its channels, e.g.
/// diffuse.R without diffuse.A), or nothing. The channel names are as in the .exr file.
std::optional<std::string> layerChannelsProblem(const std::vector<std::string>& channels);

} // namespace octaclay::core
