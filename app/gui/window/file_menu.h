#pragma once

#include "main_window.h"

class QMenu;

namespace octaclay::app {

/// Adds the File menu to window's menu bar: New… (shape and detail), Open…, Import Mesh… (asks
/// the detail), Open Recent, Save, Save As…, Save Compressed…, Export Mesh… (asks the level),
/// Save Image… (asks the size and background) and Quit, each asking about unsaved changes where
/// it would replace the model and taking its path from the window's chooser. The questions are
/// asked only without a file chooser set (tests set one). Returns the Open Recent menu, which
/// the window fills.
QMenu* addFileMenu(MainWindow& window);

/// The file dialog for request over window, opening at dir; empty when cancelled.
QString askFilePath(MainWindow& window, MainWindow::FileRequest request, const QString& dir);

} // namespace octaclay::app
