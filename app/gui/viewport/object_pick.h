#pragma once

#include "octaclay/core/geometry/ray_pick.h"

#include <optional>

namespace octaclay::app {

class Modeller;

/// Where a world-space ray meets the scene's visible surface first.
struct SurfacePick {
  int object = 0;       ///< the object's index
  core::Vec3f position; ///< world space
  core::Vec3f normal;   ///< world space, unit, out of the surface
};

/// The visible surface a world-space ray meets first, each object picked in its own space
/// (ObjectPlacement) with core::pickRay: the edited one on its live surface (the session's mirror
/// and tile bounds), the others on their documents in the scene (tile bounds built for this
/// pick); the normal is the hit sample's grid normal. Nothing when the ray misses them all.
std::optional<SurfacePick> pickSurface(const Modeller& modeller, const core::Ray& worldRay);

/// The scene object a world-space ray meets first (Alt+click): pickSurface's object, or
/// nullopt when the ray misses them all.
std::optional<int> pickObject(const Modeller& modeller, const core::Ray& worldRay);

} // namespace octaclay::app
