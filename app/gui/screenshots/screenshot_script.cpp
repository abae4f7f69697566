#include "screenshot_script.h"

#include "brush_state.h"
#include "image_output.h"
#include "main_window.h"
#include "modeller.h"
#include "screenshot_support.h"
#include "view_looks.h"
#include "viewport_widget.h"

#include <QImage>
#include <QtMath>

#include <cstdio>

namespace octaclay::app {
namespace {

// A stroke along a screen-space curve through the viewport centre.
bool stroke(ViewportWidget& view, const QString& brush, float radius, float strength,
            const std::function<QPointF(double)>& curve) {
  BrushState& state = view.modeller().brushState();
  if (!state.selectBrush(brush)) return false;
  state.setRadius(radius);
  state.setStrength(strength);
  if (brush == "paint") state.setArea(gpu::AreaMode::Volume);
  view.beginStrokeAt(curve(0));
  if (!view.stroking()) return false;
  for (int k = 1; k <= 60; ++k) {
    view.continueStrokeTo(curve(k / 60.0));
    view.repaint();
  }
  view.endStroke();
  return true;
}

} // namespace

bool makeScreenshot(MainWindow& window, const QString& imagePath) {
  ViewportWidget& view = *window.viewport();
  if (!waitForViewport(view)) return false;
  const QPointF c(view.width() / 2.0, view.height() / 2.0);
  const double r = std::min(view.width(), view.height()) * 0.28;
  bool ok = true;
  window.brushState()->selectBrush("push");
  ok = ok && stroke(view, "push", 0.035f, -0.35f, [&](double t) {
         return c + QPointF(-0.8 * r + 1.6 * r * t, 0.3 * r * std::sin(t * 2 * M_PI));
       });
  for (int k = 0; k < 3; ++k) {
    const QPointF at = c + QPointF((k - 1) * 0.55 * r, -0.55 * r);
    ok = ok && stroke(view, "inflate", 0.03f, 0.5f, [&](double t) {
           return at + QPointF(3 * std::cos(t * 6), 3 * std::sin(t * 6));
         });
  }
  ok = ok && stroke(view, "paint", 0.05f, 0.6f, [&](double t) {
         return c +
                QPointF(0.6 * r * std::cos(M_PI * (1 + t)), 0.6 * r * std::sin(M_PI * t) + 0.4 * r);
       });
  // Bricks laid in one stroke: relief, colour and shine together.
  ok = ok && stroke(view, "splat", 0.07f, 0.8f, [&](double t) {
         return c + QPointF(0.1 * r + 0.5 * r * t, 0.05 * r - 0.45 * r * t);
       });
  if (!ok) {
    std::fprintf(stderr, "octaclay: a screenshot stroke failed: %s\n", qPrintable(view.error()));
    return false;
  }
  // The README shows a matcap: clay, on a gradient (set for this picture, not saved).
  ViewLooks looks = view.looks();
  looks.material = QStringLiteral("clay");
  looks.gradient = true;
  view.setLooks(looks);
  settleEvents(600); // status bar and panels catch up
  const QImage image = grabWithViewport(window, view);
  return saveImagePng(image, imagePath);
}

} // namespace octaclay::app
