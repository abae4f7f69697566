#include "edit_menu.h"

#include "help_menu.h"
#include "history_list.h"
#include "main_window.h"
#include "modeller.h"
#include "preferences_dialog.h"
#include "shortcut_sheet.h"

#include <QAction>
#include <QMenuBar>

namespace octaclay::app {
namespace {

QString mib(std::size_t bytes) {
  return QString::number(double(bytes) / (1 << 20), 'f', 1);
}

void askPreferences(MainWindow& window) {
  const SceneHistory& h = window.modeller()->history();
  PreferencesDialog dialog({window.undoBudgetMiB(), window.autosaveSeconds() / 60},
                           MainWindow::kMinUndoMiB, MainWindow::kMaxUndoMiB,
                           MainWindow::tr("%1 MiB in use now (%2 steps)")
                               .arg(mib(h.bytes()))
                               .arg(h.undoCount() + h.redoCount()),
                           &window);
  if (dialog.exec() != QDialog::Accepted) return;
  const PreferencesDialog::Values v = dialog.values();
  if (v.undoMiB != window.undoBudgetMiB()) window.setUndoBudgetMiB(v.undoMiB);
  window.setAutosaveSeconds(v.autosaveMinutes * 60);
}

} // namespace

void addEditMenu(MainWindow& window) {
  QMenu* edit = window.menuBar()->addMenu(MainWindow::tr("&Edit"));
  HistoryList* history = window.undoStack();
  // Edit ▸ Undo and Redo name the step they would take (HistoryList: the modeller's history).
  auto* undo = new QAction(MainWindow::tr("&Undo"), &window);
  auto* redo = new QAction(MainWindow::tr("&Redo"), &window);
  const auto name = [history, undo, redo] {
    undo->setEnabled(history->canUndo());
    undo->setText(history->canUndo() ? MainWindow::tr("&Undo %1").arg(history->undoText())
                                     : MainWindow::tr("&Undo"));
    redo->setEnabled(history->canRedo());
    redo->setText(history->canRedo() ? MainWindow::tr("&Redo %1").arg(history->redoText())
                                     : MainWindow::tr("&Redo"));
  };
  name();
  QObject::connect(history, &QAbstractItemModel::modelReset, undo, name);
  QObject::connect(undo, &QAction::triggered, history, &HistoryList::undo);
  QObject::connect(redo, &QAction::triggered, history, &HistoryList::redo);
  undo->setObjectName("actionUndo");
  undo->setProperty(kSheetTextProperty, MainWindow::tr("Undo")); // its text names the step
  undo->setShortcut(QKeySequence::Undo);
  redo->setObjectName("actionRedo");
  redo->setProperty(kSheetTextProperty, MainWindow::tr("Redo"));
  // Both keys everywhere; QKeySequence::Redo is one of them on each platform, and an action
  // holding the same key twice makes Qt drop it as ambiguous.
  redo->setShortcuts(
      {QKeySequence(MainWindow::tr("Ctrl+Shift+Z")), QKeySequence(MainWindow::tr("Ctrl+Y"))});
  edit->addAction(undo);
  edit->addAction(redo);
  addHistoryAction(*edit, *history, window);
  edit->addSeparator();
  QAction* preferences = edit->addAction(MainWindow::tr("&Preferences…"));
  preferences->setObjectName("actionPreferences");
  QObject::connect(preferences, &QAction::triggered, &window,
                   [&window] { askPreferences(window); });
}

} // namespace octaclay::app
