#include "history_dialog.h"

#include <QUndoView>
#include <QVBoxLayout>

namespace octaclay::app {

HistoryDialog::HistoryDialog(QUndoStack* stack, QWidget* parent) : QDialog(parent) {
  setObjectName(QStringLiteral("historyDialog"));
  setWindowTitle(tr("History"));
  view_ = new QUndoView(stack, this);
  view_->setObjectName(QStringLiteral("historyView"));
  view_->setEmptyLabel(tr("Model as opened or made"));
  view_->setToolTip(tr("Click a step to go back (or forward) to it"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(view_);
  resize(320, 420);
}

} // namespace octaclay::app
