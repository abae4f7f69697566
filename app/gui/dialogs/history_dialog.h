#pragma once

#include <QDialog>

class QUndoStack;
class QUndoView;

namespace octaclay::app {

/// Edit ▸ History: the undo stack as a list (Qt's QUndoView), from "Model as opened or made" (or,
/// once the history's budget dropped the oldest steps, "Oldest kept step") to the newest step;
/// clicking a row undoes or redoes to that step. Non-modal, so the user can sculpt and watch the
/// list grow.
class HistoryDialog : public QDialog {
  Q_OBJECT
public:
  HistoryDialog(QUndoStack* stack, QWidget* parent = nullptr);
  QUndoView* view() const { return view_; }
  /// Relabels the first row and redraws the rows (after steps were marked dropped).
  void refresh();

private:
  QUndoStack* stack_;
  QUndoView* view_ = nullptr;
};

} // namespace octaclay::app
