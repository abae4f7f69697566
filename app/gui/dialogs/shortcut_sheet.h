#pragma once

#include <QDialog>
#include <QKeySequence>
#include <QList>
#include <QString>

class QAction;
class QTableWidget;

namespace octaclay::app {

/// The dynamic property whose string, when an action has it, is the action's words in the sheet:
/// for actions whose text changes with what they would do (Undo names the step, "Undo Stroke
/// (crease)").
inline constexpr const char* kSheetTextProperty = "sheetText";

/// One action of a window that has a shortcut, as Help ▸ Keyboard and Mouse lists it.
struct ShortcutEntry {
  QAction* action = nullptr;
  QString where; ///< its menu path, e.g. "Edit", or "Window" outside menus
  QString text;  ///< kSheetTextProperty, else the action's text without '&' and the trailing '…'
  QList<QKeySequence> keys; ///< every shortcut it answers to
  QString keysText() const; ///< keys in native text, joined with ", "
};

/// Every QAction under window (findChildren, and the actions of its menus) with at least one
/// shortcut, each once, in menu order (actions outside menus last).
QList<ShortcutEntry> collectShortcuts(const QWidget& window);

/// Help ▸ Keyboard and Mouse: one table of every shortcut of window (collectShortcuts, read
/// when the sheet is made, so it cannot drift from the actions) followed by the viewport's
/// gestures and own keys (viewportGestures()). Columns: keys or gesture, what it does, where
/// (the menu, or "Viewport"). Long descriptions wrap within their column, so every row shows
/// whole without scrolling sideways.
class ShortcutSheet : public QDialog {
  Q_OBJECT
public:
  explicit ShortcutSheet(const QWidget& window, QWidget* parent = nullptr);
  QTableWidget* table() const { return table_; }

private:
  QTableWidget* table_ = nullptr;
};

} // namespace octaclay::app
