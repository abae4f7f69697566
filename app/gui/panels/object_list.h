#pragma once

#include <QTreeWidget>

#include <vector>

namespace octaclay::app {

/// The Objects dock's rows: a tree widget whose rows are dragged to reorder and selected
/// several at once (Ctrl+click adds or removes a row, Shift+click a range). A drop does not move
/// the rows itself: it asks (moveRequested) and the scene's order, once changed, is shown again.
/// GUI thread.
class ObjectList : public QTreeWidget {
  Q_OBJECT

public:
  explicit ObjectList(QWidget* parent = nullptr);

  /// The selected rows, in order.
  std::vector<int> selectedRows() const;
  /// Where a row dropped at p (viewport pixels) would go in the order after the move of row
  /// `from`: the row under p's upper half takes its place, its lower half the place after it;
  /// below every row, the last place. -1 when it would not move.
  int dropTarget(int from, QPoint p) const;

signals:
  /// The user dropped row `from` so that it ends at position `to`.
  void moveRequested(int from, int to);

protected:
  void dropEvent(QDropEvent* event) override;

private:
  int dragged_ = -1;
  void startDrag(Qt::DropActions supported) override;
};

} // namespace octaclay::app
