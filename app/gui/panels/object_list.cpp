#include "object_list.h"

#include <QDropEvent>

#include <algorithm>

namespace octaclay::app {

ObjectList::ObjectList(QWidget* parent) : QTreeWidget(parent) {
  setSelectionMode(QAbstractItemView::ExtendedSelection);
  setDragEnabled(true);
  setAcceptDrops(true);
  setDropIndicatorShown(true);
  setDragDropMode(QAbstractItemView::InternalMove);
  setDefaultDropAction(Qt::MoveAction);
}

std::vector<int> ObjectList::selectedRows() const {
  std::vector<int> rows;
  for (QTreeWidgetItem* item : selectedItems())
    if (const int k = indexOfTopLevelItem(item); k >= 0) rows.push_back(k);
  std::sort(rows.begin(), rows.end());
  return rows;
}

int ObjectList::dropTarget(int from, QPoint p) const {
  const int count = topLevelItemCount();
  if (from < 0 || from >= count) return -1;
  // The insertion point among the rows as they are, 0 … count.
  int insertAt = count;
  if (QTreeWidgetItem* under = itemAt(p)) {
    const int row = indexOfTopLevelItem(under);
    insertAt = p.y() < visualItemRect(under).center().y() ? row : row + 1;
  }
  const int to = insertAt > from ? insertAt - 1 : insertAt;
  return to == from ? -1 : to;
}

void ObjectList::startDrag(Qt::DropActions supported) {
  // The row pressed is the one dragged (with several selected, the current one).
  dragged_ = indexOfTopLevelItem(currentItem());
  QTreeWidget::startDrag(supported);
  dragged_ = -1;
}

void ObjectList::dropEvent(QDropEvent* event) {
  // Qt's own move would take the rows apart and make them children of the row dropped on; the
  // scene's order is the truth, so the drop only asks, and nothing is removed after the drag.
  const int from = event->source() == this ? dragged_ : -1;
  const int to = dropTarget(from, event->position().toPoint());
  event->setDropAction(Qt::IgnoreAction);
  event->ignore();
  if (to >= 0) emit moveRequested(from, to);
}

} // namespace octaclay::app
