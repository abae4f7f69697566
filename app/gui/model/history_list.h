#pragma once

#include <QAbstractListModel>
#include <QString>

#include <cstddef>
#include <cstdint>

namespace octaclay::core {
struct EditStep;
}

namespace octaclay::app {

class Modeller;

/// The one history (the modeller's SceneHistory: every object's strokes, operations and replaced
/// documents, and the scene's own steps) as the window shows it: Edit ▸ Undo and Redo with the
/// step's name, Edit ▸ History's list (row 0 the state before the oldest step, then a row per step)
/// and the saved state behind the title's "*". It holds no steps of its own; it reads the history
/// and follows Modeller::historyChanged. GUI thread.
class HistoryList : public QAbstractListModel {
  Q_OBJECT
public:
  explicit HistoryList(Modeller& modeller, QObject* parent = nullptr);
  using QAbstractListModel::index; // the model's rows, beside index() below

  /// Steps held, and how many of them are done (undoable): QUndoStack's count() and index().
  int count() const;
  int index() const;
  /// What step k (0 oldest) is called: "Stroke (push)", "Even Out Samples", "Remesh", "Add
  /// Sphere", "Move Head", …
  QString text(int k) const;
  QString undoText() const;
  QString redoText() const;
  bool canUndo() const;
  bool canRedo() const;
  void undo();
  void redo();
  /// Undoes or redoes until index() is k (a click in Edit ▸ History).
  void setIndex(int k);
  /// The shown state is the saved one from now on (a save).
  void setClean();
  /// Whether the shown state is the saved one.
  bool isClean() const;
  /// The shown state as a number a later one can be compared with (the autosave's).
  std::uint64_t position() const;
  /// Steps the history's budget dropped since the document was opened or made.
  std::size_t dropped() const;

  int rowCount(const QModelIndex& parent = {}) const override;
  QVariant data(const QModelIndex& index, int role) const override;

signals:
  void indexChanged(int index);
  void cleanChanged(bool clean);
  /// The budget dropped steps for the first time since the document was opened or made.
  void stepsStartedToDrop();

private:
  void historyChanged();
  QString label(const core::EditStep& step) const;

  Modeller& modeller_;
  std::uint64_t cleanPosition_ = 0; // the history's position() when saved (0: as opened)
  int lastIndex_ = 0;
  bool lastClean_ = true;
  std::size_t lastDropped_ = 0;
};

} // namespace octaclay::app
