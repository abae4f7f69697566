#include "stretch_screenshot.h"

#include "image_output.h"
#include "layers_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "screenshot_support.h"
#include "viewport_widget.h"

#include "octaclay/core/measure/stretch.h"

#include <QFont>
#include <QImage>
#include <QPainter>

#include <cstdio>

namespace octaclay::app {
namespace {

// Each half of the picture, in pixels: wide, as the limb lies across it.
constexpr int kHalfWidth = 600, kHalfHeight = 400;

// The viewport as drawn now, cropped to the half's aspect around its centre (if the layout did
// not give it that size) and scaled to the half.
QImage grabHalf(ViewportWidget& view) {
  view.update();
  settleEvents(400);
  const QImage frame = view.grabFramebuffer();
  const double aspect = double(kHalfWidth) / kHalfHeight;
  int w = frame.width(), h = frame.height();
  if (w > h * aspect)
    w = int(h * aspect);
  else
    h = int(w / aspect);
  return frame.copy((frame.width() - w) / 2, (frame.height() - h) / 2, w, h)
      .scaled(kHalfWidth, kHalfHeight, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
}

// caption over the half's top left corner, white on a dark band so it reads on any background.
void drawCaption(QPainter& painter, int x, const QString& caption) {
  QFont font = painter.font();
  font.setPixelSize(22);
  painter.setFont(font);
  const QRect band(x, 0, kHalfWidth, 40);
  painter.fillRect(band, QColor(0, 0, 0, 150));
  painter.setPen(Qt::white);
  painter.drawText(band.adjusted(14, 0, -14, 0), Qt::AlignVCenter | Qt::AlignLeft, caption);
}

double longestOverMedian(const ViewportWidget& view) {
  return core::summarizeStretch(view.modeller().document().positions).longestOverMedian;
}

} // namespace

bool makeStretchScreenshot(MainWindow& window, const QString& imagePath,
                           StretchOperation operation) {
  ViewportWidget& view = *window.viewport();
  if (!waitForViewport(view)) return false;
  const bool remeshing = operation == StretchOperation::Remesh;
  // Drawn at the half's size, so the camera frames what the picture shows.
  view.setFixedSize(kHalfWidth, kHalfHeight);
  settleEvents(300);
  view.setLevelDivisor(1); // every sample: how they spread is what the picture is about
  window.layersPanel()->setPreview(LayersPanel::Preview::Stretch);
  if (remeshing) {
    // The creature from the front right and a little above (up +y, front +z).
    frameAlong(view, {1.0f, 0.35f, 0.75f}, {0, 1, 0}, 1.1);
  } else {
    // From the side (-y, a little above and in front), the +z limb pointing right (screen
    // right = view direction x up); zoomed as resetCamera() fits the bounding sphere in the
    // height and the limb runs across the width.
    frameAlong(view, {0.25f, -1.0f, 0.3f}, {-1, 0, 0}, 1.45);
  }
  const double before = longestOverMedian(view);
  const QImage beforeImage = grabHalf(view);

  const QString name = remeshing ? QStringLiteral("Mesh \u25B8 Remesh")
                                 : QStringLiteral("Mesh \u25B8 Even Out Samples");
  if (!(remeshing ? window.remesh() : window.evenOutSamples())) {
    std::fprintf(stderr, "octaclay: %s made no change: %s\n", qPrintable(name),
                 qPrintable(window.lastError()));
    return false;
  }
  const double after = longestOverMedian(view);
  const QImage afterImage = grabHalf(view);

  QImage out(2 * kHalfWidth, kHalfHeight, QImage::Format_RGB32);
  QPainter painter(&out);
  painter.setRenderHint(QPainter::Antialiasing);
  painter.setRenderHint(QPainter::TextAntialiasing);
  painter.drawImage(0, 0, beforeImage);
  painter.drawImage(kHalfWidth, 0, afterImage);
  painter.fillRect(kHalfWidth - 1, 0, 2, kHalfHeight, Qt::white);
  drawCaption(painter, 0,
              QStringLiteral("before: longest edge %1x the median").arg(before, 0, 'f', 0));
  drawCaption(painter, kHalfWidth, QStringLiteral("after %1: %2x").arg(name).arg(after, 0, 'f', 0));
  painter.end();
  std::printf("longest edge over the median: %.1f before, %.1f after %s\n", before, after,
              qPrintable(name));
  return saveImagePng(out, imagePath);
}

} // namespace octaclay::app
