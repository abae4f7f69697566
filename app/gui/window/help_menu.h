#pragma once

class QMainWindow;
class QMenu;
class QWidget;

namespace octaclay::app {

class HistoryList;

/// Adds the Help menu to window's menu bar: Keyboard and Mouse (Ctrl+/, the ShortcutSheet of
/// window), Quick Start (F1) and About. Each opens a non-modal dialog.
void addHelpMenu(QMainWindow& window);

/// Adds History… to menu (Edit): a HistoryDialog over stack, one per window, raised when open.
void addHistoryAction(QMenu& menu, HistoryList& history, QWidget& window);

/// The QSettings key recording that the Quick Start was shown once.
inline constexpr const char* kQuickStartShownKey = "help/quickStartShown";

/// On the first start (no kQuickStartShownKey in QSettings) opens the Quick Start over window,
/// non-modal, and records it, so it shows once. Returns whether it opened.
bool showQuickStartOnFirstRun(QWidget& window);

} // namespace octaclay::app
