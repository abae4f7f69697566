#pragma once

#include "brush_settings.h"

#include "octaclay/core/geometry/vec.h"

class vtkCamera;

namespace octaclay::app {

class ViewportWidget;

/// What the view's scale at a point depends on: the camera as the viewport draws with it.
struct ViewScaleCamera {
  core::Vec3f eye;
  core::Vec3f forward{0, 0, -1}; ///< unit, the direction of projection
  float fovYDegrees = 30;        ///< perspective: the vertical view angle
  bool parallel = false;
  float parallelScale = 1; ///< parallel: half the view's height in object units
  float viewHeight = 1;    ///< logical pixels
};

/// camera (a VTK camera) drawing a view viewHeight logical pixels high.
ViewScaleCamera viewScaleCamera(vtkCamera& camera, double viewHeight);

/// Object units per logical pixel at object-space point p, across the view: 2·d·tan(fov/2) /
/// height at depth d along the view direction (perspective), 2·scale / height (parallel).
/// 0 for a point at or behind the eye, or a degenerate camera.
float objectUnitsPerPixel(const ViewScaleCamera& camera, core::Vec3f p);

/// The brush radius in object units at point p, as settings measure it: radiusPixels ×
/// objectUnitsPerPixel (RadiusUnit::View; 0 where that is 0) or radius × diagonal (Scene).
float brushObjectRadius(const BrushSettings& settings, const ViewScaleCamera& camera, core::Vec3f p,
                        float diagonal);
/// The same radius in logical pixels at p: radiusPixels (View), or radius × diagonal over
/// objectUnitsPerPixel (Scene; 0 where that is 0).
float brushPixelRadius(const BrushSettings& settings, const ViewScaleCamera& camera, core::Vec3f p,
                       float diagonal);

/// brushObjectRadius and brushPixelRadius for view's brush settings (its modeller's BrushState),
/// camera and model at p (in the active object's space; the object radius in its units): what
/// the ring, the press's pick and a stroke's start use.
float viewBrushObjectRadius(const ViewportWidget& view, core::Vec3f p);
float viewBrushPixelRadius(const ViewportWidget& view, core::Vec3f p);

} // namespace octaclay::app
