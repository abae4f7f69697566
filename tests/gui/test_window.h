// The main window as the render tests open it: no recovery prompt, no autosave, no Quick
// Start, shown at 1000 × 700 with its viewport's GL ready.
#pragma once

#include "brush_panel.h"
#include "brush_state.h"
#include "main_window.h"
#include "modeller.h"
#include "viewport_widget.h"

#include <QImage>
#include <QTest>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

namespace octaclay::app::testing {

/// Null when the window was not exposed or its GL did not start within 10 s.
/// recoveryFolder: where autosaves would go (the options' own when empty).
inline std::unique_ptr<MainWindow> openTestWindow(const QString& recoveryFolder,
                                                  MainWindow::Options options = {}) {
  if (options.recoveryFolder.isEmpty()) options.recoveryFolder = recoveryFolder;
  options.askAboutRecovery = false;
  options.autosaveSeconds = 0;
  options.quickStartOnFirstRun = false;
  auto w = std::make_unique<MainWindow>(options);
  // The render tests size their brushes as a fraction of the model's diagonal (RadiusUnit::
  // Scene); a new user's view radius in pixels is tested where it is set (real_input's).
  w->brushState()->setRadiusUnit(RadiusUnit::Scene);
  w->resize(1000, 700);
  w->show();
  if (!QTest::qWaitForWindowExposed(w.get())) return nullptr;
  if (!QTest::qWaitFor([&] { return w->viewport()->glReady(); }, 10000)) return nullptr;
  QCoreApplication::processEvents(); // the layout's last moves, which the GL window may precede
  return w;
}

/// The window's positions layer, every texel's four floats row-major: for bit-exact checks.
/// Two pictures of one view compared on every step-th pixel of each step-th row: how many were
/// compared, how many differ by more than one 8-bit step in a channel, and the largest difference.
struct PixelDifference {
  int compared = 0, differing = 0, worst = 0;
};
inline PixelDifference comparePixels(const QImage& a, const QImage& b, int step = 1) {
  PixelDifference d;
  for (int y = 0; y < std::min(a.height(), b.height()); y += step)
    for (int x = 0; x < std::min(a.width(), b.width()); x += step) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      const int most = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                 std::abs(qBlue(p) - qBlue(q))});
      ++d.compared;
      d.differing += most > 1;
      d.worst = std::max(d.worst, most);
    }
  return d;
}

inline std::vector<float> positionsOf(const MainWindow& w) {
  const core::GeometryImage& image = w.viewport()->modeller().document().positions;
  std::vector<float> out;
  const int side = image.side();
  out.reserve(image.texelCount() * 4);
  for (int j = 0; j < image.rows(); ++j)
    for (int i = 0; i < side; ++i) {
      const auto p = image.at(i, j);
      out.insert(out.end(), {p.x, p.y, p.z, p.w});
    }
  return out;
}

inline bool bitEqual(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/// A push stroke (radius 5 %, strength 30 %) dragged 60 px left to right across the viewport's
/// centre, dy pixels below it, in 10 mouse moves.
inline void pushStrokeAcross(MainWindow& w, int dy) {
  w.brushState()->selectBrush("push");
  w.brushState()->setRadius(0.05f);
  w.brushState()->setStrength(0.3f);
  QWidget* view = w.viewport();
  const QPoint from(view->width() / 2 - 30, view->height() / 2 + dy);
  const QPoint to(view->width() / 2 + 30, view->height() / 2 + dy);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int k = 1; k <= 10; ++k)
    QTest::mouseMove(view, from + (to - from) * k / 10);
  QTest::mouseRelease(view, Qt::LeftButton, {}, to);
  // A release hands keep detail's relaxation to a worker: the step is in when it is.
  QTRY_VERIFY_WITH_TIMEOUT(!w.viewport()->stroking(), 20000);
}

} // namespace octaclay::app::testing
