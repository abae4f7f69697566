#pragma once

#include <vtkProp.h>

#include <array>
#include <functional>

class vtkRenderer;

namespace octaclay::app {

/// A VTK prop whose opaque pass calls back into the modeller, which draws the model with its
/// own GL (gpu::ModelRenderer) into VTK's render framebuffer: VTK keeps the camera, background,
/// depth buffer and any other actors, and the model needs no vtkPolyData copy.
class ModelProp : public vtkProp {
public:
  static ModelProp* New();
  vtkTypeMacro(ModelProp, vtkProp)

      /// Called with VTK's render framebuffer bound and its viewport set.
      std::function<void(vtkRenderer*)> draw;
  /// Object-space bounds (xmin, xmax, ymin, ymax, zmin, zmax), for camera reset and clipping.
  std::array<double, 6> bounds{-1, 1, -1, 1, -1, 1};

  double* GetBounds() override { return bounds.data(); }
  int RenderOpaqueGeometry(vtkViewport* viewport) override;
  vtkTypeBool HasTranslucentPolygonalGeometry() override { return 0; }

protected:
  ModelProp() = default;
  ~ModelProp() override = default;

private:
  ModelProp(const ModelProp&) = delete;
  void operator=(const ModelProp&) = delete;
};

} // namespace octaclay::app
