#include "camera_control.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

core::Vec3f toVec(const double* d) {
  return {static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2])};
}

core::Camera pickCamera(vtkCamera& c) {
  core::Camera camera;
  camera.eye = toVec(c.GetPosition());
  camera.target = toVec(c.GetFocalPoint());
  camera.up = toVec(c.GetViewUp());
  camera.fovYDegrees = static_cast<float>(c.GetViewAngle());
  return camera;
}

std::array<float, 16> objectToClip(vtkCamera& camera, double aspect) {
  vtkMatrix4x4* m = camera.GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  std::array<float, 16> out{};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      out[static_cast<std::size_t>(col * 4 + row)] = static_cast<float>(m->GetElement(row, col));
  return out;
}

QPointF projectToView(vtkCamera& camera, const QRectF& view, core::Vec3f p) {
  const double aspect = view.height() > 0 ? view.width() / view.height() : 1.0;
  vtkMatrix4x4* m = camera.GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  const double in[4] = {p.x, p.y, p.z, 1.0};
  double out[4];
  m->MultiplyPoint(in, out);
  const double x = out[0] / out[3], y = out[1] / out[3];
  return {(x * 0.5 + 0.5) * view.width(), (0.5 - y * 0.5) * view.height()};
}

void orbitCamera(vtkCamera& camera, QPointF delta) {
  camera.Azimuth(-0.4 * delta.x());
  camera.Elevation(0.4 * delta.y());
  camera.OrthogonalizeViewUp();
}

void panCamera(vtkCamera& camera, QPointF delta, int viewHeight) {
  // Move eye and target together by the pixel size at the target's depth.
  double position[3], focal[3], up[3];
  camera.GetPosition(position);
  camera.GetFocalPoint(focal);
  camera.GetViewUp(up);
  const core::Vec3f eye = toVec(position), target = toVec(focal), vup = toVec(up);
  const core::Vec3f forward = core::normalize(target - eye);
  const core::Vec3f right = core::normalize(core::cross(forward, vup));
  const core::Vec3f upv = core::cross(right, forward);
  const float scale = 2.0f * core::length(target - eye) *
                      std::tan(static_cast<float>(camera.GetViewAngle()) * 3.14159265f / 360.0f) /
                      static_cast<float>(std::max(1, viewHeight));
  const core::Vec3f move = right * (-static_cast<float>(delta.x()) * scale) +
                           upv * (static_cast<float>(delta.y()) * scale);
  camera.SetPosition(eye.x + move.x, eye.y + move.y, eye.z + move.z);
  camera.SetFocalPoint(target.x + move.x, target.y + move.y, target.z + move.z);
}

} // namespace octaclay::app
