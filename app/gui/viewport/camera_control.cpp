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

std::array<float, 16> objectToClip(vtkCamera& camera, double aspect,
                                   const std::array<double, 16>& objectToWorld) {
  vtkMatrix4x4* m = camera.GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  std::array<float, 16> out{};
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col) {
      double sum = 0; // in double, rounded once
      for (int k = 0; k < 4; ++k)
        sum += m->GetElement(row, k) * objectToWorld[static_cast<std::size_t>(k * 4 + col)];
      out[static_cast<std::size_t>(col * 4 + row)] = static_cast<float>(sum);
    }
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

namespace {

void setVec(double* d, core::Vec3f v) {
  d[0] = v.x;
  d[1] = v.y;
  d[2] = v.z;
}

/// v turned by angle (radians) about unit axis (Rodrigues).
core::Vec3f rotate(core::Vec3f v, core::Vec3f axis, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + core::cross(axis, v) * s + axis * (core::dot(axis, v) * (1 - c));
}

void turntableOrbit(vtkCamera& camera, QPointF delta) {
  const core::Vec3f focal = toVec(camera.GetFocalPoint());
  core::Vec3f offset = toVec(camera.GetPosition()) - focal;
  const core::Vec3f forward = core::normalize(offset * -1.0f);
  const core::Vec3f worldUp{0, 1, 0};
  // Levelled: the screen's horizontal made horizontal in the model (a trackball's roll undone),
  // on the side it points to now, so an upside-down view stays so.
  const core::Vec3f current = core::cross(forward, toVec(camera.GetViewUp()));
  core::Vec3f right = core::cross(forward, worldUp);
  if (core::length(right) < 1e-4f) // looking straight along y: any horizontal is level
    right = {current.x, 0, current.z};
  else if (core::dot(right, current) < 0)
    right = right * -1.0f;
  if (core::length(right) < 1e-4f) return;
  right = core::normalize(right);
  constexpr float kRadiansPerPixel = 0.4f * 3.14159265f / 180.0f;
  const float azimuth = -kRadiansPerPixel * static_cast<float>(delta.x());
  offset = rotate(offset, worldUp, azimuth);
  right = rotate(right, worldUp, azimuth);
  offset = rotate(offset, right, -kRadiansPerPixel * static_cast<float>(delta.y()));
  const core::Vec3f up = core::normalize(core::cross(right, core::normalize(offset * -1.0f)));
  double position[3], viewUp[3];
  setVec(position, focal + offset);
  setVec(viewUp, up);
  camera.SetPosition(position);
  camera.SetViewUp(viewUp);
}

} // namespace

core::Ray viewRay(vtkCamera& camera, QSizeF view, QPointF p) {
  const int width = std::max(1, static_cast<int>(view.width()));
  const int height = std::max(1, static_cast<int>(view.height()));
  const core::Camera c = pickCamera(camera);
  const auto px = static_cast<float>(p.x()), py = static_cast<float>(p.y());
  if (!camera.GetParallelProjection()) return core::cameraRay(c, width, height, px, py);
  const core::Vec3f forward = core::normalize(c.target - c.eye);
  const core::Vec3f right = core::normalize(core::cross(forward, c.up));
  const core::Vec3f up = core::cross(right, forward);
  const auto scale = static_cast<float>(camera.GetParallelScale());
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float x = (2.0f * (px + 0.5f) / static_cast<float>(width) - 1.0f) * scale * aspect;
  const float y = (1.0f - 2.0f * (py + 0.5f) / static_cast<float>(height)) * scale;
  return {c.eye + right * x + up * y, forward};
}

void orbitCamera(vtkCamera& camera, QPointF delta, OrbitMode mode) {
  if (mode == OrbitMode::Turntable) {
    turntableOrbit(camera, delta);
    return;
  }
  camera.Azimuth(-0.4 * delta.x());
  camera.Elevation(0.4 * delta.y());
  camera.OrthogonalizeViewUp();
}

void zoomCameraAt(vtkCamera& camera, core::Vec3f anchor, double factor) {
  if (!(factor > 0)) return;
  const core::Vec3f eye = toVec(camera.GetPosition()), focal = toVec(camera.GetFocalPoint());
  double position[3], focalPoint[3];
  if (camera.GetParallelProjection()) {
    const core::Vec3f forward = core::normalize(focal - eye);
    const core::Vec3f v = focal - anchor;
    const core::Vec3f sideways = v - forward * core::dot(v, forward);
    const core::Vec3f shift = sideways * static_cast<float>(1.0 / factor - 1.0);
    setVec(position, eye + shift);
    setVec(focalPoint, focal + shift);
    camera.SetParallelScale(camera.GetParallelScale() / factor);
  } else {
    const auto s = static_cast<float>(1.0 / factor);
    setVec(position, anchor + (eye - anchor) * s);
    setVec(focalPoint, anchor + (focal - anchor) * s);
  }
  camera.SetPosition(position);
  camera.SetFocalPoint(focalPoint);
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
  const float halfHeight =
      camera.GetParallelProjection()
          ? static_cast<float>(camera.GetParallelScale())
          : core::length(target - eye) *
                std::tan(static_cast<float>(camera.GetViewAngle()) * 3.14159265f / 360.0f);
  const float scale = 2.0f * halfHeight / static_cast<float>(std::max(1, viewHeight));
  const core::Vec3f move = right * (-static_cast<float>(delta.x()) * scale) +
                           upv * (static_cast<float>(delta.y()) * scale);
  camera.SetPosition(eye.x + move.x, eye.y + move.y, eye.z + move.z);
  camera.SetFocalPoint(target.x + move.x, target.y + move.y, target.z + move.z);
}

core::Vec3f focalPlanePoint(vtkCamera& camera, const core::Ray& ray) {
  const core::Vec3f forward =
      core::normalize(toVec(camera.GetFocalPoint()) - toVec(camera.GetPosition()));
  const float along = std::max(core::dot(ray.direction, forward), 1e-3f);
  return ray.origin + ray.direction * (static_cast<float>(camera.GetDistance()) / along);
}

} // namespace octaclay::app
