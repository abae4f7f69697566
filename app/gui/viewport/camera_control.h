#pragma once

#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/geometry/vec.h"

#include <QPointF>
#include <QRectF>
#include <QSizeF>

#include <array>

class vtkCamera;

namespace octaclay::app {

/// A VTK triple as a core vector.
core::Vec3f toVec(const double* d);
/// The camera as core's picking sees it.
core::Camera pickCamera(vtkCamera& camera);
/// The column-major object-to-clip matrix of camera for a view of this aspect (width / height),
/// for an object placed by objectToWorld (row-major 4 × 4, ObjectPlacement's; the identity
/// when absent).
std::array<float, 16> objectToClip(vtkCamera& camera, double aspect);
std::array<float, 16> objectToClip(vtkCamera& camera, double aspect,
                                   const std::array<double, 16>& objectToWorld);
/// Where world-space point p appears in view (logical pixels, y down).
QPointF projectToView(vtkCamera& camera, const QRectF& view, core::Vec3f p);

/// The ray through widget point p (logical pixels, y down) of a view this size, for a
/// perspective or a parallel projection (then from the eye's plane along the view direction).
core::Ray viewRay(vtkCamera& camera, QSizeF view, QPointF p);

/// How a drag orbits. Turntable turns about the model's up axis (+y) and the screen's horizontal,
/// so the up axis stays vertical on screen (a rolled camera is levelled first); trackball turns
/// about the camera's own axes and may roll the model.
enum class OrbitMode { Turntable, Trackball };

/// Turns the camera around its focal point by a pointer move (pixels): 0.4° a pixel.
void orbitCamera(vtkCamera& camera, QPointF delta, OrbitMode mode);
/// Moves eye and focal point together so the focal point follows a pointer move (pixels) in a
/// view viewHeight pixels high.
void panCamera(vtkCamera& camera, QPointF delta, int viewHeight);
/// Zooms by factor (> 1 closer) about anchor (object space), which keeps its place on screen:
/// eye and focal point move towards it (perspective), or sideways while the parallel scale
/// shrinks (parallel projection, the eye's depth kept so nothing is clipped).
void zoomCameraAt(vtkCamera& camera, core::Vec3f anchor, double factor);
/// Where ray (from the camera) meets the plane through the focal point facing the camera: what
/// a zoom anchors on where no surface is under the pointer.
core::Vec3f focalPlanePoint(vtkCamera& camera, const core::Ray& ray);

} // namespace octaclay::app
