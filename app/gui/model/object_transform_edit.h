#pragma once

#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/geometry/vec.h"

#include <array>

namespace octaclay::app {

/// A world direction in double.
using Direction = std::array<double, 3>;

/// The edits the G / R / S gestures and the gizmo make to a core::ObjectTransform (issue 33),
/// about the object's origin (its translation), in double, rounded once to float. What a user
/// types is kept exactly: a typed 0.5 along X adds 0.5f to translation x, a typed 90 about Z adds
/// 90 to the Z angle, a typed factor 2 doubles the scale, each as one float operation. No Qt.

/// before moved by offset (scene units, world axes).
core::ObjectTransform translated(const core::ObjectTransform& before, core::Vec3f offset);

/// before turned by degrees about the world axis (0 = X, 1 = Y, 2 = Z) through its origin,
/// right-handed (positive turns counter-clockwise seen from the axis's tip). The Euler angles
/// (R = Rz · Ry · Rx) change by one addition where the turn is one of them: about Z always,
/// about Y when the Z angle is 0, about X when the Y and Z angles are 0; otherwise as
/// rotatedAbout.
core::ObjectTransform rotatedAboutWorldAxis(const core::ObjectTransform& before, int axis,
                                            double degrees);

/// before turned by degrees about the object's own axis (0 = X, 1 = Y, 2 = Z: R's column);
/// about its own X that is one addition to the X angle, otherwise as rotatedAbout.
core::ObjectTransform rotatedAboutLocalAxis(const core::ObjectTransform& before, int axis,
                                            double degrees);

/// before turned by degrees about the world direction axis (any length, not zero; the view's
/// axis for R without a constraint): the rotation Q · R converted back to Euler angles, each in
/// (-180°, 180°]. An axis of length zero leaves before as it is.
core::ObjectTransform rotatedAbout(const core::ObjectTransform& before, Direction axis,
                                   double degrees);

/// before with every scale component (axis -1) or the one of its own axis (0, 1, 2) times factor.
core::ObjectTransform scaled(const core::ObjectTransform& before, double factor, int axis = -1);

/// The object's own axis (0, 1, 2) whose world direction lies nearest the world axis: the one
/// S with an X / Y / Z constraint scales (a scale along a world axis the object is turned
/// against is no transform of this kind).
int localAxisNearest(const core::ObjectTransform& transform, int worldAxis);

/// The world direction (unit) of the object's own axis (0, 1, 2): R's column.
Direction localAxisDirection(const core::ObjectTransform& transform, int axis);

} // namespace octaclay::app
