#include "objects_panel.h"

#include "modeller.h"
#include "object_list.h"

#include <QHeaderView>
#include <QPushButton>
#include <QTreeWidget>
#include <QVBoxLayout>

namespace octaclay::app {

ObjectsPanel::ObjectsPanel(Modeller& modeller, QWidget* parent)
    : QWidget(parent), modeller_(modeller) {
  list_ = new ObjectList(this);
  list_->setObjectName("objectsList");
  list_->setColumnCount(3);
  list_->setHeaderLabels({tr("Object"), tr("Shown"), tr("Locked")});
  list_->setRootIsDecorated(false);
  // The dock is as wide as Layers beside it: the list's own wish does not widen the dock area.
  list_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  list_->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed);
  list_->header()->setSectionResizeMode(Name, QHeaderView::Stretch);
  list_->header()->setSectionResizeMode(Visible, QHeaderView::ResizeToContents);
  list_->header()->setSectionResizeMode(Locked, QHeaderView::ResizeToContents);
  list_->header()->setStretchLastSection(false);
  delete_ = new QPushButton(tr("Delete"), this);
  delete_->setObjectName("deleteObjectButton");
  delete_->setToolTip(tr("Removes the edited object (not the last one)"));
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(4, 4, 4, 4);
  layout->addWidget(list_);
  layout->addWidget(delete_);

  connect(list_, &QTreeWidget::itemChanged, this, &ObjectsPanel::itemChanged);
  connect(list_, &QTreeWidget::currentItemChanged, this, &ObjectsPanel::rowActivated);
  connect(list_, &ObjectList::moveRequested, this, [this](int from, int to) {
    if (!modeller_.moveObject(from, to)) rebuild();
  });
  connect(delete_, &QPushButton::clicked, this, [this] {
    const QString why = modeller_.deleteActiveObject();
    if (!why.isEmpty()) emit message(why);
  });
  connect(&modeller_, &Modeller::sceneChanged, this, &ObjectsPanel::rebuild);
  connect(&modeller_, &Modeller::objectsChanged, this, &ObjectsPanel::rebuild);
  connect(&modeller_, &Modeller::activeObjectChanged, this, &ObjectsPanel::rebuild);
  rebuild();
}

void ObjectsPanel::rebuild() {
  rebuilding_ = true;
  // Rows are updated in place: this may run inside one of their own itemChanged signals.
  while (list_->topLevelItemCount() > modeller_.objectCount())
    delete list_->takeTopLevelItem(list_->topLevelItemCount() - 1);
  while (list_->topLevelItemCount() < modeller_.objectCount())
    new QTreeWidgetItem(list_);
  for (int k = 0; k < modeller_.objectCount(); ++k) {
    const core::SceneObject& object = modeller_.objectAt(k);
    QTreeWidgetItem* item = list_->topLevelItem(k);
    item->setText(Name, QString::fromStdString(object.name));
    item->setFlags(item->flags() | Qt::ItemIsEditable | Qt::ItemIsUserCheckable);
    item->setCheckState(Visible, object.visible ? Qt::Checked : Qt::Unchecked);
    item->setCheckState(Locked, object.locked ? Qt::Checked : Qt::Unchecked);
    item->setToolTip(Visible, tr("Shown in the view"));
    item->setToolTip(Locked, tr("Locked: not sculpted"));
  }
  // The selection stays while the edited object is the current row (a Ctrl+click made it so);
  // an object made the edited one elsewhere (Alt+click, Add) becomes the one row selected.
  if (QTreeWidgetItem* active = list_->topLevelItem(modeller_.activeObject());
      active && list_->currentItem() != active)
    list_->setCurrentItem(active);
  delete_->setEnabled(modeller_.objectCount() > 1);
  rebuilding_ = false;
}

std::vector<int> ObjectsPanel::selectedObjects() const {
  std::vector<int> rows = list_->selectedRows();
  if (rows.empty() && modeller_.objectCount() > 0) rows.push_back(modeller_.activeObject());
  return rows;
}

void ObjectsPanel::itemChanged(QTreeWidgetItem* item, int column) {
  if (rebuilding_) return;
  const int k = list_->indexOfTopLevelItem(item);
  if (column == Visible) {
    modeller_.setObjectVisible(k, item->checkState(Visible) == Qt::Checked);
  } else if (column == Locked) {
    modeller_.setObjectLocked(k, item->checkState(Locked) == Qt::Checked);
  } else if (column == Name) {
    const QString why = modeller_.renameObject(k, item->text(Name));
    if (!why.isEmpty()) {
      emit message(tr("Cannot rename: %1").arg(why));
      rebuild(); // the name it keeps
    }
  }
}

void ObjectsPanel::rowActivated() {
  if (rebuilding_) return;
  const int k = list_->indexOfTopLevelItem(list_->currentItem());
  if (k < 0 || k == modeller_.activeObject()) return;
  if (!modeller_.setActiveObject(k)) rebuild(); // refused: the edited one stays current
}

} // namespace octaclay::app
