#pragma once

#include <QDialog>

class QSpinBox;

namespace octaclay::app {

/// Edit ▸ Preferences: the memory Undo may hold (MiB, with what it holds now) and how often to
/// autosave (minutes, 0 = off). Shows the values given; the caller applies what was accepted.
class PreferencesDialog : public QDialog {
  Q_OBJECT
public:
  struct Values {
    int undoMiB = 256;
    int autosaveMinutes = 2;
  };
  /// inUse: the history's memory and steps now, shown under the undo memory.
  PreferencesDialog(Values values, int minUndoMiB, int maxUndoMiB, const QString& inUse,
                    QWidget* parent = nullptr);
  Values values() const;

private:
  QSpinBox* undoMemory_ = nullptr;
  QSpinBox* minutes_ = nullptr;
};

} // namespace octaclay::app
