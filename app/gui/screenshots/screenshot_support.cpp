#include "screenshot_support.h"

#include "modeller.h"
#include "viewport_widget.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QPainter>
#include <QPixmap>
#include <QWidget>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cstdio>

namespace octaclay::app {

void settleEvents(int ms) {
  QElapsedTimer t;
  t.start();
  while (t.elapsed() < ms)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

QImage grabWithViewport(QWidget& window, ViewportWidget& view) {
  QPixmap picture = window.grab();
  QPainter painter(&picture);
  const QPoint origin = view.mapTo(&window, QPoint(0, 0));
  painter.drawImage(QRect(origin, view.size()), view.grabFramebuffer());
  for (QWidget* child : view.findChildren<QWidget*>(Qt::FindDirectChildrenOnly))
    if (child->isVisible() && !child->inherits("QWindowContainer")) // the labels
      child->render(&painter, origin + child->pos());
  painter.end();
  return picture.toImage();
}

bool waitForViewport(ViewportWidget& view) {
  QElapsedTimer wait;
  wait.start();
  while (!view.glReady() && wait.elapsed() < 10000)
    settleEvents(50);
  if (view.glReady() && view.modeller().hasDocument()) return true;
  std::fprintf(stderr, "octaclay: no OpenGL 4.3 context or no document: %s\n",
               qPrintable(view.error()));
  return false;
}

void frameAlong(ViewportWidget& view, core::Vec3f towardEye, core::Vec3f up, double zoom) {
  view.resetCamera();
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  double focal[3];
  camera->GetFocalPoint(focal);
  const double distance = camera->GetDistance();
  const core::Vec3f dir = core::normalize(towardEye);
  camera->SetPosition(focal[0] + distance * dir.x, focal[1] + distance * dir.y,
                      focal[2] + distance * dir.z);
  camera->SetViewUp(up.x, up.y, up.z);
  camera->OrthogonalizeViewUp();
  camera->Zoom(zoom);
  view.update();
}

} // namespace octaclay::app
