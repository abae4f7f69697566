#include "history_dialog.h"

#include "stroke_command.h"

#include <QUndoStack>
#include <QUndoView>
#include <QVBoxLayout>

namespace octaclay::app {

HistoryDialog::HistoryDialog(QUndoStack* stack, QWidget* parent) : QDialog(parent), stack_(stack) {
  setObjectName(QStringLiteral("historyDialog"));
  setWindowTitle(tr("History"));
  view_ = new QUndoView(stack, this);
  view_->setObjectName(QStringLiteral("historyView"));
  refresh();
  connect(stack, &QUndoStack::indexChanged, this, &HistoryDialog::refresh);
  view_->setToolTip(tr("Click a step to go back (or forward) to it"));
  auto* layout = new QVBoxLayout(this);
  layout->addWidget(view_);
  resize(320, 420);
}

void HistoryDialog::refresh() {
  // Clicking the first row undoes every step; with the oldest dropped it reaches the state
  // before the oldest step kept, not the model as it was opened.
  view_->setEmptyLabel(oldestStepDropped(*stack_) ? tr("Oldest kept step")
                                                  : tr("Model as opened or made"));
}

} // namespace octaclay::app
