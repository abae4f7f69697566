// The Help menu, Edit ▸ History and the Quick Start of a first start.

#include "help_menu.h"

#include "about_dialog.h"
#include "history_dialog.h"
#include "quick_start_dialog.h"
#include "shortcut_sheet.h"

#include <QAction>
#include <QMainWindow>
#include <QMenu>
#include <QMenuBar>
#include <QSettings>

namespace octaclay::app {
namespace {

// Shows a dialog that lives until closed, non-modal.
void showOwned(QDialog* dialog) {
  dialog->setAttribute(Qt::WA_DeleteOnClose);
  dialog->show();
  dialog->raise();
  dialog->activateWindow();
}

void openQuickStart(QWidget& window) {
  if (auto* open = window.findChild<QuickStartDialog*>()) {
    open->raise();
    return;
  }
  showOwned(new QuickStartDialog(&window));
}

} // namespace

void addHelpMenu(QMainWindow& window) {
  QMenu* help = window.menuBar()->addMenu(QObject::tr("&Help"));
  QAction* sheet = help->addAction(QObject::tr("&Keyboard and Mouse…"));
  sheet->setObjectName(QStringLiteral("actionShortcuts"));
  sheet->setShortcut(QKeySequence(QObject::tr("Ctrl+/")));
  QObject::connect(sheet, &QAction::triggered, &window,
                   [&window] { showOwned(new ShortcutSheet(window, &window)); });
  QAction* quick = help->addAction(QObject::tr("&Quick Start"));
  quick->setObjectName(QStringLiteral("actionQuickStart"));
  quick->setShortcut(QKeySequence(QObject::tr("F1")));
  QObject::connect(quick, &QAction::triggered, &window, [&window] { openQuickStart(window); });
  help->addSeparator();
  QAction* about = help->addAction(QObject::tr("&About Octaclay"));
  about->setObjectName(QStringLiteral("actionAbout"));
  about->setMenuRole(QAction::AboutRole);
  QObject::connect(about, &QAction::triggered, &window, [&window] { showAbout(&window); });
}

void addHistoryAction(QMenu& menu, HistoryList& stack, QWidget& window) {
  QAction* history = menu.addAction(QObject::tr("&History…"));
  history->setObjectName(QStringLiteral("actionHistory"));
  history->setStatusTip(QObject::tr("Every step you can undo; click one to go back to it"));
  QObject::connect(history, &QAction::triggered, &window, [&stack, &window] {
    if (auto* open = window.findChild<HistoryDialog*>()) {
      open->raise();
      open->activateWindow();
      return;
    }
    showOwned(new HistoryDialog(&stack, &window));
  });
}

bool showQuickStartOnFirstRun(QWidget& window) {
  QSettings settings;
  if (settings.value(QLatin1String(kQuickStartShownKey), false).toBool()) return false;
  settings.setValue(QLatin1String(kQuickStartShownKey), true);
  openQuickStart(window);
  return true;
}

} // namespace octaclay::app
