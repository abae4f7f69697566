// The main window as the render tests open it: no recovery prompt, no autosave, no Quick
// Start, shown at 1000 × 700 with its viewport's GL ready.
#pragma once

#include "main_window.h"
#include "viewport_widget.h"

#include <QTest>

#include <memory>

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
  w->resize(1000, 700);
  w->show();
  if (!QTest::qWaitForWindowExposed(w.get())) return nullptr;
  if (!QTest::qWaitFor([&] { return w->viewport()->glReady(); }, 10000)) return nullptr;
  return w;
}

} // namespace octaclay::app::testing
