#pragma once

#include "octaclay/core/geometry/ray_pick.h"

#include <optional>

namespace octaclay::app {

class Modeller;

/// The scene object a world-space ray meets first (Alt+click): the nearest hit, in world
/// distance, among the visible objects, each picked in its own space (ObjectPlacement) with
/// core::pickRay: the edited one on its live surface (the session's mirror and tile bounds), the
/// others on their documents in the scene (tile bounds built for this pick). Its index, or
/// nullopt when the ray misses them all.
std::optional<int> pickObject(const Modeller& modeller, const core::Ray& worldRay);

} // namespace octaclay::app
