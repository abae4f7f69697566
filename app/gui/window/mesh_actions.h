#pragma once

#include "background_task.h"

#include "octaclay/core/document/document.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>
#include <string>

class QAction;
class QMenuBar;
class QStatusBar;
class QWidget;

namespace octaclay::app {

class DocumentActions;
class HistoryList;
class Modeller;
class ViewportWidget;

/// The Mesh menu's whole-model operations: Even Out Samples, Remesh… and Resolution…, each run
/// on a copy of the document off the GUI thread (the window's one BackgroundTaskRunner, progress
/// and Cancel, the menu item showing the fraction) and applied as one step of the history; every
/// other ending (cancelled, edited meanwhile, an error, unchanged with its reason) is reported.
/// GUI thread.
class MeshActions : public QObject {
  Q_OBJECT
public:
  /// What the operations work on; all must outlive this object.
  struct Parts {
    QWidget* window = nullptr; ///< parent of dialogs and message boxes
    QStatusBar* statusBar = nullptr;
    Modeller* modeller = nullptr;         ///< the document the operations read and replace
    ViewportWidget* viewport = nullptr;   ///< the stroke under way
    DocumentActions* documents = nullptr; ///< its runner, and replaceDocument
    HistoryList* history = nullptr;
    std::function<QAction*(const QString&)> action; ///< the window's action by object name
  };
  explicit MeshActions(Parts parts, QObject* parent = nullptr) : QObject(parent), parts_(parts) {}

  /// Adds the Mesh menu (after Edit, as in Blender) to bar: Even Out Samples, Remesh…,
  /// Resolution…, each with its tooltip, enabled as updateActions() says.
  void addMenu(QMenuBar& bar);

  /// Mesh ▸ Even Out Samples (see MainWindow::evenOutSamples).
  bool evenOutSamples(std::shared_ptr<TaskControl> control = nullptr);
  /// Mesh ▸ Remesh… at size n (0: the current N).
  bool remesh(int n = 0, std::shared_ptr<TaskControl> control = nullptr);
  /// Mesh ▸ Resolution… to n.
  bool changeResolution(int n, std::shared_ptr<TaskControl> control = nullptr);
  /// Mesh ▸ Remesh… (remeshing) or Mesh ▸ Resolution…: the MeshSizeDialog, then the task.
  void openMeshSizeDialog(bool remeshing);
  /// Enables the Mesh menu's actions when they can run (a document, no stroke, no task).
  void updateActions();

private:
  /// What a task made from the document: a new one, or the reason it is unchanged.
  struct MeshOutcome {
    core::Document document;
    bool changed = false;
    std::string reason;
  };
  struct MeshTask {
    QString action;        ///< the menu item's object name (shows the progress, disabled)
    QString name;          ///< "Remesh": "<name> left the model unchanged: <reason>"
    QString verb;          ///< "Remeshing": the menu item's "<verb>… 40 %"
    QString progressLabel; ///< the progress dialog's text
    QString cancelled;     ///< the status bar's message on cancel
    QString failure;       ///< "<failure>: <error>" in a message box on an error
    /// Runs on a worker thread with a copy of the document; writes control.fraction, polls
    /// control.cancel.
    std::function<MeshOutcome(const core::Document&, TaskControl&)> work;
  };
  /// Runs task and reports every ending but a changed model; the changed model is returned for
  /// the caller to apply as one step.
  std::optional<MeshOutcome> runMeshTask(const MeshTask& task,
                                         std::shared_ptr<TaskControl> control);
  void showMeshError(const QString& failure, const QString& error);

  Parts parts_;
};

} // namespace octaclay::app
