#include "history_list.h"

#include "modeller.h"
#include "scene_history.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_library.h"

namespace octaclay::app {
namespace {} // namespace

HistoryList::HistoryList(Modeller& modeller, QObject* parent)
    : QAbstractListModel(parent), modeller_(modeller) {
  connect(&modeller_, &Modeller::historyChanged, this, &HistoryList::historyChanged);
}

int HistoryList::count() const {
  const SceneHistory& h = modeller_.history();
  return static_cast<int>(h.undoCount() + h.redoCount());
}

int HistoryList::index() const {
  return static_cast<int>(modeller_.history().undoCount());
}

QString HistoryList::label(const core::EditStep& step) const {
  const QString name = QString::fromStdString(step.label);
  // A stroke's step carries its brush's id: named as Edit ▸ Undo says it.
  gpu::BrushLibrary* library = modeller_.library();
  if (!step.replacesDocument() && library && library->catalog().find(step.label))
    return tr("Stroke (%1)").arg(name);
  return name;
}

QString HistoryList::text(int k) const {
  if (k < 0) return {};
  const SceneHistory& history = modeller_.history();
  const SceneHistory::Entry* entry = history.entryAt(static_cast<std::size_t>(k));
  if (!entry) return {};
  if (entry->scene) return QString::fromStdString(entry->scene->label);
  const core::EditStep* step = history.documentStepAt(static_cast<std::size_t>(k));
  return step ? label(*step) : QString();
}

QString HistoryList::undoText() const {
  return canUndo() ? text(index() - 1) : QString();
}

QString HistoryList::redoText() const {
  return canRedo() ? text(index()) : QString();
}

bool HistoryList::canUndo() const {
  return modeller_.canUndo() && !modeller_.strokes().stroking();
}

bool HistoryList::canRedo() const {
  return modeller_.canRedo() && !modeller_.strokes().stroking();
}

void HistoryList::undo() {
  modeller_.undoStroke();
}

void HistoryList::redo() {
  modeller_.redoStroke();
}

void HistoryList::setIndex(int k) {
  while (index() > k && modeller_.undoStroke()) {
  }
  while (index() < k && modeller_.redoStroke()) {
  }
}

void HistoryList::setClean() {
  cleanPosition_ = modeller_.history().position();
  historyChanged();
}

bool HistoryList::isClean() const {
  return modeller_.history().position() == cleanPosition_;
}

std::uint64_t HistoryList::position() const {
  return modeller_.history().position();
}

std::size_t HistoryList::dropped() const {
  return modeller_.history().dropped();
}

int HistoryList::rowCount(const QModelIndex& parent) const {
  return parent.isValid() ? 0 : count() + 1;
}

QVariant HistoryList::data(const QModelIndex& at, int role) const {
  if (!at.isValid() || at.row() > count()) return {};
  if (role == Qt::DisplayRole) {
    if (at.row() == 0) // undoing every step reaches this
      return dropped() > 0 ? tr("Oldest kept step") : tr("Model as opened or made");
    return text(at.row() - 1);
  }
  return {};
}

void HistoryList::historyChanged() {
  beginResetModel();
  endResetModel();
  const int now = index();
  const bool clean = isClean();
  const std::size_t droppedNow = dropped();
  if (now != lastIndex_) emit indexChanged(lastIndex_ = now);
  if (clean != lastClean_) emit cleanChanged(lastClean_ = clean);
  if (lastDropped_ == 0 && droppedNow > 0) emit stepsStartedToDrop();
  lastDropped_ = droppedNow;
}

} // namespace octaclay::app
