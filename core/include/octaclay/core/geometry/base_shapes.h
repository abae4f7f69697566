#pragma once

#include "octaclay/core/geometry/geometry_image.h"

#include <optional>
#include <string_view>

namespace octaclay::core {

/// Analytic shapes a new document starts from. All fit in [-1, 1]³.
enum class BaseShape {
  Sphere,   ///< radius 1
  Cube,     ///< half-size 1, edges rounded with radius 0.2
  Cylinder, ///< radius 1, half-height 1, axis z, rims rounded with radius 0.1
  Blob,     ///< unit sphere displaced radially by smooth low-frequency noise (±~0.15)
  Capsule,  ///< radius 0.5, axis z from −1 to 1 (Capsule{0.5, 1}): a limb, sampled evenly along
            ///< it by makeCapsule's equal-area map (not projected radially)
};

std::optional<BaseShape> parseBaseShape(std::string_view name);
std::string_view baseShapeName(BaseShape shape);

/// The shape sampled at (N+1)²: each sample's octahedron direction is projected radially
/// onto the surface (the capsule: makeCapsule), so samples lie exactly on it. Seamed. Throws on
/// an invalid size.
GeometryImage makeBaseShape(BaseShape shape, int n);

/// Signed distance from p to the analytic surface (negative inside); exact for sphere, cube,
/// cylinder and capsule, radial distance for the blob.
float baseShapeDistance(BaseShape shape, Vec3f p);

} // namespace octaclay::core
