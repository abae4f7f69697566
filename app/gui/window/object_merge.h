#pragma once

#include "background_task.h"

#include <QObject>
#include <QString>

#include <memory>
#include <vector>

class QStatusBar;
class QWidget;

namespace octaclay::app {

class Modeller;
class ViewportWidget;

/// Objects ▸ Merge: objects of the scene become one closed octahedral object through the core
/// function `octaclay-cli merge` runs (core::mergeParts: a voxel union, parameterized again,
/// every layer carried from the object it came from), on a copy of their documents off the GUI
/// thread (its own BackgroundTaskRunner: a window-modal progress dialog with Cancel), then
/// Modeller::replaceObjects as one step ("Merge N Objects"). A refusal (a locked object, fewer
/// than two, a union of genus G, "these objects do not touch") is shown in a message box and the
/// status bar and changes nothing; so does Cancel. GUI thread.
class ObjectMerge : public QObject {
  Q_OBJECT
public:
  struct Parts {
    QWidget* window = nullptr; ///< parent of the progress dialog and message boxes
    QStatusBar* statusBar = nullptr;
    Modeller* modeller = nullptr;
    ViewportWidget* viewport = nullptr; ///< the stroke under way
  };
  explicit ObjectMerge(Parts parts, QObject* parent = nullptr);

  /// The objects Merge takes when `selected` are the Objects list's selected rows: those when
  /// two or more are selected, else every visible object (a newcomer who made a creature from
  /// parts and asks for Merge wants it whole).
  std::vector<int> chosenObjects(const std::vector<int>& selected) const;
  /// Merges objects (indices into the scene) at the largest N among them, named after the first
  /// (made unique), at the identity transform. control: progress and cancel (new when null;
  /// tests pass one to cancel). Returns whether the scene changed.
  bool merge(const std::vector<int>& objects, std::shared_ptr<TaskControl> control = nullptr);
  /// Why the last merge changed nothing (empty after a success): what the message box said.
  QString lastRefusal() const { return lastRefusal_; }

private:
  void refuse(const QString& why, bool box = true);

  Parts parts_;
  BackgroundTaskRunner runner_;
  QString lastRefusal_;
};

} // namespace octaclay::app
