#pragma once

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <optional>
#include <string>

namespace octaclay::core {

/// Where a scene object sits: world = translation + R · (scale ⊙ local).
///
/// The rotation is three Euler angles in degrees applied about the world's X, then Y, then Z
/// axis (R = Rz · Ry · Rx, Blender's default "XYZ" order), not a quaternion: it is what the CLI
/// takes (`--rotate x,y,z`) and what `objects` and the file's header show, so a typed value is
/// stored and read back bit for bit with no conversion; a mirror across a world plane is an
/// exact sign change of two angles (mirroredTransform); and a GLB node's quaternion is made
/// from it only at export (rotationQuaternion).
struct ObjectTransform {
  Vec3f translation{};           ///< scene units
  Vec3f rotationDegrees{};       ///< about X, then Y, then Z (degrees)
  Vec3f scale{1.0f, 1.0f, 1.0f}; ///< per local axis, non-zero (negative mirrors)
  friend bool operator==(const ObjectTransform&, const ObjectTransform&) = default;
};

/// Bounds a transform must keep (checked by transformProblem, on every read and every edit):
/// they keep a world position of any valid document (|p| ≤ 1e6, document_checks) finite in float.
inline constexpr float kMaxTranslation = 1.0e6f;
inline constexpr float kMaxRotationDegrees = 3600.0f; ///< ten turns either way
inline constexpr float kMinScale = 1.0e-4f;           ///< |scale| on each axis
inline constexpr float kMaxScale = 1.0e4f;

/// What is wrong with a transform ("scale y is 0: …"), or nothing when every component is
/// finite and within the bounds above.
std::optional<std::string> transformProblem(const ObjectTransform& transform);

/// The 3×3 linear part R · diag(scale), row-major, in double.
std::array<double, 9> linearPart(const ObjectTransform& transform);

/// The world position of a local point (computed in double, rounded once to float).
Vec3f applyTransform(const ObjectTransform& transform, Vec3f local);

/// The rotation as a unit quaternion {x, y, z, w} (glTF's order).
std::array<double, 4> rotationQuaternion(const ObjectTransform& transform);

/// The transform mirrored across the world plane through the origin normal to axis (0 = x,
/// 1 = y, 2 = z), for an object whose local geometry is mirrored across its own plane normal to
/// the same axis (mirrorDocument): translation's axis component and the two other rotation
/// angles change sign, the scale stays (positive scales stay positive, so the winding is kept
/// by the mirrored image, not by a negative scale). Exact: only signs change.
ObjectTransform mirroredTransform(const ObjectTransform& transform, int axis);

} // namespace octaclay::core
