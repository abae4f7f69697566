// The brush radius between the view's pixels and the model's units (RadiusUnit). The viewport
// converts once, at a stroke's press, at the depth of the point pressed, as Blender converts its
// view radius; the ring and the press's pick use the same conversion.

#include "screen_radius.h"

#include "camera_control.h"
#include "modeller.h"
#include "viewport_widget.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <numbers>

namespace octaclay::app {

ViewScaleCamera viewScaleCamera(vtkCamera& camera, double viewHeight) {
  ViewScaleCamera c;
  c.eye = toVec(camera.GetPosition());
  c.forward = core::normalize(toVec(camera.GetDirectionOfProjection()));
  c.fovYDegrees = static_cast<float>(camera.GetViewAngle());
  c.parallel = camera.GetParallelProjection() != 0;
  c.parallelScale = static_cast<float>(camera.GetParallelScale());
  c.viewHeight = static_cast<float>(viewHeight);
  return c;
}

float objectUnitsPerPixel(const ViewScaleCamera& camera, core::Vec3f p) {
  if (!(camera.viewHeight > 0)) return 0;
  float across = 0; // the view's height in object units at p
  if (camera.parallel) {
    across = 2 * camera.parallelScale;
  } else {
    const float depth = core::dot(p - camera.eye, camera.forward);
    const float halfAngle = camera.fovYDegrees * std::numbers::pi_v<float> / 360;
    across = 2 * depth * std::tan(halfAngle);
  }
  const float perPixel = across / camera.viewHeight;
  return std::isfinite(perPixel) && perPixel > 0 ? perPixel : 0;
}

float brushObjectRadius(const BrushSettings& settings, const ViewScaleCamera& camera, core::Vec3f p,
                        float diagonal) {
  if (settings.radiusUnit == RadiusUnit::Scene) return settings.radius * diagonal;
  return settings.radiusPixels * objectUnitsPerPixel(camera, p);
}

float brushPixelRadius(const BrushSettings& settings, const ViewScaleCamera& camera, core::Vec3f p,
                       float diagonal) {
  if (settings.radiusUnit == RadiusUnit::View) return settings.radiusPixels;
  const float perPixel = objectUnitsPerPixel(camera, p);
  return perPixel > 0 ? settings.radius * diagonal / perPixel : 0;
}

// p is in the active object's space, the camera in the world's: the view's scale is taken at p's
// world position, and world units become object units through the object's mean scale (exact
// for a uniform scale).
float viewBrushObjectRadius(const ViewportWidget& view, core::Vec3f p) {
  Modeller& modeller = view.modeller(); // brushState() has no const overload
  const ObjectPlacement placement = view.placement();
  const auto scale = static_cast<float>(placement.meanScale());
  return brushObjectRadius(modeller.brushState().settings(),
                           viewScaleCamera(*view.renderer()->GetActiveCamera(), view.height()),
                           placement.toWorld(p), modeller.modelDiagonal() * scale) /
         scale;
}

float viewBrushPixelRadius(const ViewportWidget& view, core::Vec3f p) {
  Modeller& modeller = view.modeller(); // brushState() has no const overload
  const ObjectPlacement placement = view.placement();
  return brushPixelRadius(modeller.brushState().settings(),
                          viewScaleCamera(*view.renderer()->GetActiveCamera(), view.height()),
                          placement.toWorld(p),
                          modeller.modelDiagonal() * static_cast<float>(placement.meanScale()));
}

} // namespace octaclay::app
