// The viewport's side of the scene's objects (issue 33): Alt+click makes the object under the
// pointer the edited one; Shift+A finds the surface under it; a moved or changed object is
// drawn again.
#include "modeller.h"
#include "object_pick.h"
#include "viewport_frames.h"
#include "viewport_widget.h"

#include <vtkCamera.h>
#include <vtkRenderer.h>

namespace octaclay::app {

void ViewportWidget::selectObjectAt(QPointF p) {
  if (!modeller_.session().hasDocument() || width() <= 0 || height() <= 0) return;
  const QRectF view = modelRect();
  if (p.x() >= view.width()) p.rx() -= view.width();
  const std::optional<int> k =
      pickObject(modeller_, viewRay(*renderer()->GetActiveCamera(), view.size(), p));
  if (k && *k != modeller_.activeObject()) modeller_.setActiveObject(*k);
  update();
}

std::optional<SurfacePick> ViewportWidget::surfaceAt(QPointF p) const {
  if (!modeller_.session().hasDocument() || width() <= 0 || height() <= 0) return std::nullopt;
  const QRectF view = modelRect();
  if (p.x() >= view.width()) p.rx() -= view.width();
  const core::Ray ray = viewRay(*renderer()->GetActiveCamera(), view.size(), p);
  std::optional<SurfacePick> pick = pickSurface(modeller_, ray);
  // The side seen: a sheet's back, or a surface seen from inside, faces the viewer too.
  if (pick && core::dot(pick->normal, ray.direction) > 0) pick->normal = pick->normal * -1.0f;
  return pick;
}

void ViewportWidget::objectMoved(int k) {
  if (frames_->ready() && k != modeller_.activeObject()) frames_->objectsChanged();
  update();
}

} // namespace octaclay::app
