#pragma once

#include <QDialog>

class QListView;

namespace octaclay::app {

class HistoryList;

/// Edit ▸ History: the modeller's one history as a list (HistoryList's rows), from "Model as opened
/// or made" (or, once the history's budget dropped the oldest steps, "Oldest kept step") to the
/// newest step; clicking a row undoes or redoes to that step. Non-modal, so the user can sculpt and
/// watch the list grow.
class HistoryDialog : public QDialog {
  Q_OBJECT
public:
  HistoryDialog(HistoryList* history, QWidget* parent = nullptr);
  QListView* view() const { return view_; }
  /// Selects the row of the state shown.
  void refresh();

private:
  HistoryList* history_;
  QListView* view_ = nullptr;
};

} // namespace octaclay::app
