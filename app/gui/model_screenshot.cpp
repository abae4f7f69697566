#include "model_screenshot.h"

#include "brush_panel.h"
#include "image_output.h"
#include "main_window.h"
#include "view_looks.h"
#include "viewport_widget.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QImage>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstdio>

namespace octaclay::app {
namespace {

void settle(int ms) {
  QElapsedTimer t;
  t.start();
  while (t.elapsed() < ms)
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

// From the front right and a little above (the model's up is +y, its front +z), at the
// distance resetCamera() fits the whole bounding box in.
void frameFromTheFrontRight(ViewportWidget& view) {
  view.resetCamera();
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  double focal[3];
  camera->GetFocalPoint(focal);
  const double distance = camera->GetDistance();
  const double dir[3] = {1.0, 0.35, 0.75}; // from the focal point to the eye
  const double len = std::sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
  camera->SetPosition(focal[0] + distance * dir[0] / len, focal[1] + distance * dir[1] / len,
                      focal[2] + distance * dir[2] / len);
  camera->SetViewUp(0, 1, 0);
  camera->OrthogonalizeViewUp();
  camera->Zoom(1.15);
  view.update();
}

} // namespace

bool makeModelScreenshot(MainWindow& window, const QString& brushId, const QString& imagePath) {
  ViewportWidget& view = *window.viewport();
  QElapsedTimer wait;
  wait.start();
  while (!view.glReady() && wait.elapsed() < 10000)
    settle(50);
  if (!view.glReady() || !view.hasDocument()) {
    std::fprintf(stderr, "octaclay: no OpenGL 4.3 context or no document: %s\n",
                 qPrintable(view.error()));
    return false;
  }
  if (!window.brushPanel()->selectBrush(brushId)) {
    std::fprintf(stderr, "octaclay: no brush '%s' for the screenshot\n", qPrintable(brushId));
    return false;
  }
  ViewLooks looks = view.looks(); // for this picture, not saved
  looks.material = QStringLiteral("clay");
  looks.gradient = true;
  view.setLooks(looks);
  frameFromTheFrontRight(view);
  settle(600); // status bar and panels catch up
  return saveImagePng(window.grab().toImage(), imagePath);
}

} // namespace octaclay::app
