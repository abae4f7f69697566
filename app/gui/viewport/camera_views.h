#pragma once

#include "octaclay/core/geometry/vec.h"

#include <array>

class vtkCamera;

namespace octaclay::app {

/// The standard views, Blender's numeric keypad keys in brackets. The model's up axis is +y and
/// its front faces +z: Front (1) looks along -z, Back (Ctrl+1) along +z, Right (3) from +x,
/// Left (Ctrl+3) from -x, all with +y up; Top (7) looks down -y with the front (+z) at the
/// bottom of the screen, Bottom (Ctrl+7) up +y with the front at the top.
enum class ViewDirection { Front, Back, Right, Left, Top, Bottom };

/// Where the camera sits seen from the focal point (unit) and which way is up on screen.
struct ViewAxes {
  core::Vec3f towardEye;
  core::Vec3f up;
};
ViewAxes viewAxes(ViewDirection direction);

/// Turns the camera to a standard view about its focal point, keeping the distance (and the
/// parallel scale): the zoom stays what it was, as in Blender.
void setViewDirection(vtkCamera& camera, ViewDirection direction);

/// Switches between perspective and parallel projection showing the focal plane at the same
/// size: the parallel scale is the perspective's half height there, and back. In parallel, the
/// eye moves back to at least minEyeDistance from the focal point so nothing in front of the old
/// eye is clipped (the picture does not change with the eye's depth then).
void setParallelProjection(vtkCamera& camera, bool parallel, double minEyeDistance);
/// setParallelProjection with the reach that keeps every point of bounds (xmin, xmax, ymin, …)
/// in front of the eye.
void setParallelProjectionAround(vtkCamera& camera, bool parallel,
                                 const std::array<double, 6>& bounds);

} // namespace octaclay::app
