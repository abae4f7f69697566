#include "model_screenshot.h"

#include "brush_state.h"
#include "image_output.h"
#include "main_window.h"
#include "screenshot_support.h"
#include "view_looks.h"
#include "viewport_widget.h"

#include <QImage>

#include <cstdio>

namespace octaclay::app {
bool makeModelScreenshot(MainWindow& window, const QString& brushId, const QString& imagePath) {
  ViewportWidget& view = *window.viewport();
  if (!waitForViewport(view)) return false;
  if (!window.brushState()->selectBrush(brushId)) {
    std::fprintf(stderr, "octaclay: no brush '%s' for the screenshot\n", qPrintable(brushId));
    return false;
  }
  ViewLooks looks = view.looks(); // for this picture, not saved
  looks.material = QStringLiteral("clay");
  looks.gradient = true;
  view.setLooks(looks);
  // From the front right and a little above (up +y, front +z).
  frameAlong(view, {1.0f, 0.35f, 0.75f}, {0, 1, 0}, 1.15);
  settleEvents(600); // status bar and panels catch up
  return saveImagePng(grabWithViewport(window, view), imagePath);
}

} // namespace octaclay::app
