#pragma once

#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/geometry/vec.h"

#include <array>

namespace octaclay::app {

/// Where the edited object sits in the scene: its core::ObjectTransform (world = translation +
/// L · local, L = R · diag(scale)) as the viewport uses it. The camera lives in world space; the
/// document, its picking, brush ring, stroke and renderer in the object's own space; this turns
/// one into the other, in double. The identity when default-constructed.
class ObjectPlacement {
public:
  ObjectPlacement();
  explicit ObjectPlacement(const core::ObjectTransform& transform);

  core::Vec3f toWorld(core::Vec3f local) const;
  core::Vec3f toLocal(core::Vec3f world) const;
  /// A direction (or a vector between points) into the object's space: L⁻¹ · d, not normalized.
  /// A world-space camera axis a dotted with a world normal equals L⁻¹ a dotted with the local
  /// normal (before the normal's own renormalization), so this also carries the view's axes.
  core::Vec3f directionToLocal(core::Vec3f world) const;
  /// A local surface normal in world space: L⁻ᵀ · n, made unit (a mirroring L keeps the side).
  core::Vec3f normalToWorld(core::Vec3f local) const;
  /// A world ray in object space, its direction unit (distances along it in object units).
  core::Ray rayToLocal(const core::Ray& ray) const;
  /// The world box holding box's eight transformed corners.
  core::BoundingBox boxToWorld(const core::BoundingBox& box) const;
  /// The object-to-world matrix, row-major 4 × 4.
  std::array<double, 16> objectToWorld() const;
  /// World units per object unit: |det L|^(1/3), the scale itself when it is uniform.
  double meanScale() const;

private:
  std::array<double, 9> linear_{};  // L, row-major
  std::array<double, 9> inverse_{}; // L⁻¹
  std::array<double, 3> translation_{};
};

} // namespace octaclay::app
