#pragma once

#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/geometry/vec.h"

#include <QPointF>
#include <QRectF>

#include <array>

class vtkCamera;

namespace octaclay::app {

/// A VTK triple as a core vector.
core::Vec3f toVec(const double* d);
/// The camera as core's picking sees it.
core::Camera pickCamera(vtkCamera& camera);
/// The column-major object-to-clip matrix of camera for a view of this aspect (width / height).
std::array<float, 16> objectToClip(vtkCamera& camera, double aspect);
/// Where object-space point p appears in view (logical pixels, y down).
QPointF projectToView(vtkCamera& camera, const QRectF& view, core::Vec3f p);

/// Turns the camera around its focal point by a pointer move (pixels).
void orbitCamera(vtkCamera& camera, QPointF delta);
/// Moves eye and focal point together so the focal point follows a pointer move (pixels) in a
/// view viewHeight pixels high.
void panCamera(vtkCamera& camera, QPointF delta, int viewHeight);

} // namespace octaclay::app
