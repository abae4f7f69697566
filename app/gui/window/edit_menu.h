#pragma once

namespace octaclay::app {

class MainWindow;

/// Adds the Edit menu to window's menu bar: Undo and Redo naming the step they would take
/// (actionUndo, actionRedo: the window's HistoryList), History… and Preferences… (undo memory,
/// autosave).
void addEditMenu(MainWindow& window);

} // namespace octaclay::app
