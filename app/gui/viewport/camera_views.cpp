#include "camera_views.h"

#include "camera_control.h"

#include <vtkCamera.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace octaclay::app {

ViewAxes viewAxes(ViewDirection direction) {
  switch (direction) {
  case ViewDirection::Front:
    return {{0, 0, 1}, {0, 1, 0}};
  case ViewDirection::Back:
    return {{0, 0, -1}, {0, 1, 0}};
  case ViewDirection::Right:
    return {{1, 0, 0}, {0, 1, 0}};
  case ViewDirection::Left:
    return {{-1, 0, 0}, {0, 1, 0}};
  case ViewDirection::Top:
    return {{0, 1, 0}, {0, 0, -1}};
  case ViewDirection::Bottom:
    return {{0, -1, 0}, {0, 0, 1}};
  }
  return {{0, 0, 1}, {0, 1, 0}};
}

namespace {

/// The eye at distance along towardEye from the focal point.
void placeEye(vtkCamera& camera, core::Vec3f towardEye, double distance) {
  const double* f = camera.GetFocalPoint();
  camera.SetPosition(f[0] + towardEye.x * distance, f[1] + towardEye.y * distance,
                     f[2] + towardEye.z * distance);
}

double tanHalfAngle(vtkCamera& camera) {
  return std::tan(camera.GetViewAngle() * std::numbers::pi / 360.0);
}

} // namespace

void setViewDirection(vtkCamera& camera, ViewDirection direction) {
  const ViewAxes axes = viewAxes(direction);
  placeEye(camera, axes.towardEye, camera.GetDistance());
  camera.SetViewUp(axes.up.x, axes.up.y, axes.up.z);
}

void setParallelProjection(vtkCamera& camera, bool parallel, double minEyeDistance) {
  if (bool(camera.GetParallelProjection()) == parallel) return;
  const core::Vec3f towardEye =
      core::normalize(toVec(camera.GetPosition()) - toVec(camera.GetFocalPoint()));
  if (parallel) {
    camera.SetParallelScale(camera.GetDistance() * tanHalfAngle(camera));
    placeEye(camera, towardEye, std::max(camera.GetDistance(), minEyeDistance));
  } else {
    placeEye(camera, towardEye, camera.GetParallelScale() / tanHalfAngle(camera));
  }
  camera.SetParallelProjection(parallel);
}

void setParallelProjectionAround(vtkCamera& camera, bool parallel, const std::array<double, 6>& b) {
  const double diagonal = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
  const core::Vec3f centre{static_cast<float>(b[0] + b[1]) / 2, static_cast<float>(b[2] + b[3]) / 2,
                           static_cast<float>(b[4] + b[5]) / 2};
  // Far enough back that the whole model lies in front of the eye.
  const core::Vec3f focal{static_cast<float>(camera.GetFocalPoint()[0]),
                          static_cast<float>(camera.GetFocalPoint()[1]),
                          static_cast<float>(camera.GetFocalPoint()[2])};
  setParallelProjection(camera, parallel, core::length(focal - centre) + diagonal);
}

} // namespace octaclay::app
