// The viewport's looks: the matcap or lit material, the wireframe overlay and the background.

#include "viewport_widget.h"

#include "octaclay/core/document/image_io.h"

#include <vtkCamera.h>
#include <vtkMatrix4x4.h>
#include <vtkRenderer.h>

namespace octaclay::app {

void ViewportWidget::setLooks(const ViewLooks& looks) {
  looks_ = looks;
  for (vtkRenderer* r : {renderer_.Get(), lodRenderer_.Get()}) {
    const QColor& top = looks.backgroundTop;
    const QColor& bottom = looks.gradient ? looks.backgroundBottom : looks.backgroundTop;
    // VTK's Background is the bottom of a gradient, Background2 its top.
    r->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    r->SetBackground2(top.redF(), top.greenF(), top.blueF());
    r->SetGradientBackground(looks.gradient);
  }
  update();
}

void ViewportWidget::applyLooks(gpu::ModelView& view, vtkRenderer* r) {
  view.wireframe = looks_.wireframe;
  if (looks_.material == "lit" || !model_) return;
  if (loadedMatcap_ != looks_.material) {
    loadedMatcap_ = looks_.material; // tried once: a broken file is reported, not retried
    try {
      model_->setMatcap(core::readImage(matcapPath(looks_.material).toStdString(), 3));
    } catch (const std::exception& e) {
      error_ = tr("Could not load the %1 matcap: %2").arg(looks_.material, e.what());
    }
  }
  view.matcap = model_->hasMatcap();
  // The view matrix's first two rows: the camera's right and up axes in object space.
  vtkMatrix4x4* m = r->GetActiveCamera()->GetViewTransformMatrix();
  view.viewRight = {float(m->GetElement(0, 0)), float(m->GetElement(0, 1)),
                    float(m->GetElement(0, 2))};
  view.viewUp = {float(m->GetElement(1, 0)), float(m->GetElement(1, 1)),
                 float(m->GetElement(1, 2))};
}

} // namespace octaclay::app
