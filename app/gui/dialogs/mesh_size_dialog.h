#pragma once

#include <QDialog>

class QComboBox;
class QLabel;

namespace octaclay::app {

/// Mesh ▸ Remesh… and Mesh ▸ Resolution…: says what the operation will do to the current model
/// and asks for the new N (powers of two within eight times the current one, 2 … 8192), the
/// current N chosen at first. GUI thread.
class MeshSizeDialog : public QDialog {
  Q_OBJECT
public:
  enum class Kind { Remesh, Resolution };
  MeshSizeDialog(Kind kind, int currentSize, QWidget* parent = nullptr);

  /// The N chosen.
  int size() const;
  /// Chooses n if it is offered; false otherwise.
  bool setSize(int n);
  /// The sizes offered, smallest first.
  QList<int> sizes() const;
  /// What the dialog says the operation does (for the chosen N).
  QString description() const;

private:
  void describe();

  Kind kind_;
  int current_;
  QComboBox* sizes_;
  QLabel* description_;
};

} // namespace octaclay::app
