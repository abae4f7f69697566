#pragma once

#include "object_list.h"

#include <QString>
#include <QWidget>

#include <vector>

class QPushButton;
class QTreeWidget;
class QTreeWidgetItem;

namespace octaclay::app {

class Modeller;

/// The Objects dock panel: the Modeller's scene, one row per object in order: its name
/// (double-click renames: unique, a valid name, else refused), whether it is shown and whether
/// it is locked (check boxes). Clicking a row makes that object the edited one; the edited one
/// is the current row, following Alt+click. Ctrl+click and Shift+click select several rows
/// (what Objects ▸ Merge merges); a row dragged to another place reorders the scene
/// (Modeller::moveObject), the edited object staying the edited one. Delete removes the edited
/// object (never the last). Refusals go out as message(). GUI thread.
class ObjectsPanel : public QWidget {
  Q_OBJECT

public:
  enum Column { Name = 0, Visible = 1, Locked = 2 };

  explicit ObjectsPanel(Modeller& modeller, QWidget* parent = nullptr);

  /// The rows (for tests): row k is object k.
  QTreeWidget* list() const { return list_; }
  QPushButton* deleteButton() const { return delete_; }
  /// The objects selected in the list, in the scene's order (the edited one when none is).
  std::vector<int> selectedObjects() const;

signals:
  /// Why something asked was refused (a name, a delete), for the status bar.
  void message(const QString& text);

private:
  void rebuild();
  void itemChanged(QTreeWidgetItem* item, int column);
  void rowActivated();

  Modeller& modeller_;
  ObjectList* list_ = nullptr;
  QPushButton* delete_ = nullptr;
  bool rebuilding_ = false;
};

} // namespace octaclay::app
