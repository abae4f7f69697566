#pragma once

namespace octaclay::app {

/// What the viewport shows: the full resolution, the level of detail, or both side by side
/// (full resolution left, level of detail right, one camera).
enum class LodDisplay { FullResolution, Lod, SideBySide };

} // namespace octaclay::app
