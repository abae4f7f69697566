#include "history_dialog.h"

#include "history_list.h"

#include <QListView>
#include <QVBoxLayout>

namespace octaclay::app {

HistoryDialog::HistoryDialog(HistoryList* history, QWidget* parent)
    : QDialog(parent), history_(history) {
  setObjectName(QStringLiteral("historyDialog"));
  setWindowTitle(tr("History"));
  view_ = new QListView(this);
  view_->setObjectName(QStringLiteral("historyView"));
  view_->setModel(history);
  view_->setSelectionMode(QAbstractItemView::SingleSelection);
  view_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  // Row 0 is the state before the oldest step, row k the state after step k: a click goes there.
  connect(view_, &QListView::clicked, this,
          [this](const QModelIndex& at) { history_->setIndex(at.row()); });
  connect(history, &QAbstractItemModel::modelReset, this, &HistoryDialog::refresh);
  view_->setToolTip(tr("Click a step to go back (or forward) to it"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(view_);
  resize(320, 420);
  refresh();
}

void HistoryDialog::refresh() {
  view_->setCurrentIndex(history_->index(history_->index(), 0));
}

} // namespace octaclay::app
