#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/tile_bounds.h"

#include <optional>

namespace octaclay::core {

struct Ray {
  Vec3f origin;
  Vec3f direction; ///< unit
};

/// A perspective camera looking from eye towards target.
struct Camera {
  Vec3f eye{0, 0, 4}, target{0, 0, 0}, up{0, 1, 0};
  float fovYDegrees = 45;
};

/// The ray through the centre of pixel (px, py) of a width × height view (py = 0 at the top).
Ray cameraRay(const Camera& camera, int width, int height, float px, float py);

/// Where a ray first meets the surface.
struct PickHit {
  float distance = 0; ///< along the ray
  Vec3f position;     ///< object space
  float u = 0, v = 0; ///< image coordinates in [0, 1] (u along columns), interpolated
  Sample sample;      ///< the nearest sample of the hit triangle
};

/// Nearest hit of the ray with the image's full-resolution mesh, or nullopt when it misses.
/// Visits only the tiles whose bounds the ray enters, nearest first, so a pick costs a few tiles'
/// triangles rather than a render pass.
std::optional<PickHit> pickRay(const GeometryImage& image, const TileBounds& bounds,
                               const Ray& ray);

} // namespace octaclay::core
