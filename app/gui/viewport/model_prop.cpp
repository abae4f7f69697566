#include "model_prop.h"

#include <vtkObjectFactory.h>
#include <vtkRenderer.h>

namespace octaclay::app {

vtkStandardNewMacro(ModelProp);

int ModelProp::RenderOpaqueGeometry(vtkViewport* viewport) {
  auto* renderer = vtkRenderer::SafeDownCast(viewport);
  if (!renderer || !draw || !GetVisibility()) return 0;
  draw(renderer);
  return 1;
}

} // namespace octaclay::app
