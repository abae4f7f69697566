// The Mesh menu's whole-model operations: Even Out Samples, Remesh… and Resolution…, each run on
// a copy of the document off the GUI thread (progress and Cancel) and applied as one undo step.
#include "mesh_actions.h"

#include "document_actions.h"
#include "history_list.h"
#include "mesh_size_dialog.h"
#include "modeller.h"
#include "viewport_widget.h"

#include "octaclay/core/document/resize.h"
#include "octaclay/core/import/remesh.h"
#include "octaclay/core/relax/relax.h"

#include <QAction>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

#include <memory>
#include <stdexcept>
#include <tuple>

namespace octaclay::app {
namespace {

QString percentOf(double fraction) {
  return QStringLiteral("%1 %").arg(100 * fraction, 0, 'g', 2);
}

} // namespace

std::optional<MeshActions::MeshOutcome>
MeshActions::runMeshTask(const MeshTask& task, std::shared_ptr<TaskControl> control) {
  BackgroundTaskRunner& runner = parts_.documents->runner();
  // On the GPU (GL started), not just pending: the result is applied there.
  if (!parts_.viewport->glReady() || !parts_.modeller->hasDocument() ||
      parts_.viewport->stroking() || runner.busy())
    return std::nullopt;
  if (!control) control = std::make_shared<TaskControl>();
  // The copy is taken here, on the GUI thread; the worker never touches the viewport.
  auto source = std::make_shared<const core::Document>(parts_.modeller->document());
  auto outcome = std::make_shared<MeshOutcome>();
  // What tells that the model changed while the task ran (input reaches the viewport in the
  // moment before the progress dialog appears): applying the result would undo that change.
  const auto mark = [this] {
    return std::tuple(parts_.viewport->stroking(), parts_.viewport->stats().dabs,
                      parts_.history->index(), parts_.history->count(),
                      parts_.modeller->hasDocument() ? parts_.modeller->document().size() : 0);
  };
  const auto before = mark();
  // The menu item says how far the task is (the progress dialog appears after 100 ms).
  QAction* item = parts_.action(task.action);
  const QString itemText = item ? item->text() : QString();
  QTimer itemProgress;
  if (item) {
    item->setEnabled(false);
    const auto show = [item, control, verb = task.verb] {
      item->setText(tr("%1… %2 %").arg(verb).arg(qRound(100 * control->fraction.load())));
    };
    show();
    connect(&itemProgress, &QTimer::timeout, item, show);
    itemProgress.start(100);
  }
  const auto work = task.work;
  QString error = runner.run(
      task.progressLabel, [source, outcome, control, work] { *outcome = work(*source, *control); },
      control);
  itemProgress.stop();
  if (item) item->setText(itemText);
  updateActions();
  if (control->cancel) {
    parts_.statusBar->showMessage(task.cancelled, 8000);
    return std::nullopt;
  }
  if (error.isEmpty() && mark() != before) {
    parts_.statusBar->showMessage(
        tr("The model changed while %1; nothing was applied").arg(task.verb.toLower()), 8000);
    return std::nullopt;
  }
  if (!error.isEmpty()) {
    showMeshError(task.failure, error);
    return std::nullopt;
  }
  if (!outcome->changed) {
    parts_.statusBar->showMessage(tr("%1 left the model unchanged: %2")
                                      .arg(task.name, QString::fromStdString(outcome->reason)),
                                  15000);
    return std::nullopt;
  }
  return std::move(*outcome);
}

void MeshActions::showMeshError(const QString& failure, const QString& error) {
  const QString message = tr("%1: %2").arg(failure, error);
  parts_.statusBar->showMessage(message, 15000);
  auto* box = new QMessageBox(QMessageBox::Critical, tr("Octaclay"), message, QMessageBox::Ok,
                              parts_.window);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open(); // window-modal, does not block the caller
}

bool MeshActions::evenOutSamples(std::shared_ptr<TaskControl> control) {
  MeshTask task;
  task.action = QStringLiteral("actionEvenOutSamples");
  task.name = tr("Even Out");
  task.verb = tr("Evening out");
  task.progressLabel = tr("Evening out the samples…");
  task.cancelled = tr("Even out cancelled");
  task.failure = tr("Could not even out the samples");
  task.work = [](const core::Document& source, TaskControl& job) {
    // core::evenOut checks its own result: the document comes back unchanged, with the
    // reason, rather than moved beyond its tolerance or more stretched.
    core::EvenOutResult r = core::evenOut(source, {}, {}, [&job](float f) {
      job.fraction = f;
      return !job.cancel.load();
    });
    return MeshOutcome{std::move(r.document), r.changed, std::move(r.reason)};
  };
  std::optional<MeshOutcome> outcome = runMeshTask(task, std::move(control));
  if (!outcome) return false;
  bool recorded = false;
  try {
    recorded = parts_.modeller->applyChange(outcome->document, "Even Out Samples");
  } catch (const std::exception& e) {
    showMeshError(task.failure, QString::fromUtf8(e.what()));
    return false;
  }
  if (!recorded) {
    parts_.statusBar->showMessage(tr("The samples are already even"), 8000);
    return false;
  }
  parts_.statusBar->showMessage(tr("Samples evened out"), 5000);
  return true;
}

bool MeshActions::remesh(int n, std::shared_ptr<TaskControl> control) {
  if (!parts_.modeller->hasDocument()) return false;
  const int current = parts_.modeller->document().size();
  if (n == 0) n = current;
  MeshTask task;
  task.action = QStringLiteral("actionRemesh");
  task.name = tr("Remesh");
  task.verb = tr("Remeshing");
  task.progressLabel = tr("Remeshing the surface at N = %1 (every layer carried)…").arg(n);
  task.cancelled = tr("Remesh cancelled; the model is unchanged");
  task.failure = tr("Could not remesh");
  auto summary = std::make_shared<QString>();
  task.work = [n, summary](const core::Document& source, TaskControl& job) {
    core::RemeshResult r = core::remeshDocument(source, {.size = n}, [&job](float f) {
      job.fraction = f;
      return !job.cancel.load();
    });
    *summary = tr("longest edge %1× → %2× the median, surface moved %3 (RMS)")
                   .arg(r.before.longestOverMedian, 0, 'f', 1)
                   .arg(r.after.longestOverMedian, 0, 'f', 1)
                   .arg(percentOf(r.moved.rms));
    return MeshOutcome{std::move(r.document), r.changed, std::move(r.reason)};
  };
  std::optional<MeshOutcome> outcome = runMeshTask(task, std::move(control));
  if (!outcome) return false;
  if (!parts_.documents->replaceDocument(std::move(outcome->document),
                                         n == current ? tr("Remesh")
                                                      : tr("Remesh at N = %1").arg(n)))
    return false;
  parts_.statusBar->showMessage(tr("Remeshed at N = %1: %2").arg(n).arg(*summary), 15000);
  return true;
}

bool MeshActions::changeResolution(int n, std::shared_ptr<TaskControl> control) {
  if (!parts_.modeller->hasDocument()) return false;
  const int current = parts_.modeller->document().size();
  if (n == current) {
    parts_.statusBar->showMessage(tr("The model is already N = %1: nothing to resample").arg(n),
                                  8000);
    return false;
  }
  MeshTask task;
  task.action = QStringLiteral("actionResolution");
  task.name = tr("Resolution");
  task.verb = tr("Resampling");
  task.progressLabel = tr("Resampling every layer from N = %1 to N = %2…").arg(current).arg(n);
  task.cancelled = tr("Resolution change cancelled; the model is unchanged");
  task.failure = tr("Could not change the resolution");
  task.work = [n](const core::Document& source, TaskControl& job) {
    // One pass with no progress of its own: Cancel takes effect when it ends (the result is
    // dropped), which at most a few seconds at N = 8192.
    if (job.cancel) throw std::runtime_error("cancelled");
    // Checked as Remesh is: a coarser N that cannot hold a stretched part leaves the model
    // unchanged and says why.
    core::ResizeResult r = core::resizeAndCheck(source, {.size = n});
    job.fraction = 1.0f;
    return MeshOutcome{std::move(r.document), r.changed, std::move(r.reason)};
  };
  std::optional<MeshOutcome> outcome = runMeshTask(task, std::move(control));
  if (!outcome) return false;
  if (!parts_.documents->replaceDocument(std::move(outcome->document),
                                         tr("Resolution %1 → %2").arg(current).arg(n)))
    return false;
  parts_.statusBar->showMessage(tr("Resampled from N = %1 to N = %2").arg(current).arg(n), 8000);
  return true;
}

void MeshActions::openMeshSizeDialog(bool remeshing) {
  if (!parts_.modeller->hasDocument()) return;
  MeshSizeDialog dialog(remeshing ? MeshSizeDialog::Kind::Remesh : MeshSizeDialog::Kind::Resolution,
                        parts_.modeller->document().size(), parts_.window);
  if (dialog.exec() != QDialog::Accepted) return;
  if (remeshing)
    remesh(dialog.size());
  else
    changeResolution(dialog.size());
}

void MeshActions::updateActions() {
  const bool ready = parts_.viewport->glReady() && parts_.modeller->hasDocument() &&
                     !parts_.viewport->stroking() && !parts_.documents->runner().busy();
  for (const char* name : {"actionEvenOutSamples", "actionRemesh", "actionResolution"})
    if (QAction* a = parts_.action(QString::fromLatin1(name))) a->setEnabled(ready);
}

void MeshActions::addMenu(QMenuBar& bar) {
  const auto add = [](QMenu* menu, const QString& text, const char* name) {
    QAction* a = menu->addAction(text); // a child of the window's: MainWindow::action finds it
    a->setObjectName(name);
    return a;
  };
  QMenu* mesh = bar.addMenu(tr("&Mesh"));
  QAction* evenOut = add(mesh, tr("&Even Out Samples"), "actionEvenOutSamples");
  const QString evenOutTip =
      tr("Spread the samples evenly over the surface again, so stretched parts get detail back; "
         "the shape and paint stay put (if they would not, nothing changes and the status bar "
         "says why). Runs at once with progress and Cancel; one Undo brings the model back");
  evenOut->setToolTip(evenOutTip);
  evenOut->setStatusTip(evenOutTip);
  connect(evenOut, &QAction::triggered, this, [this] { evenOutSamples(); });
  QAction* remeshAction = add(mesh, tr("&Remesh…"), "actionRemesh");
  const QString remeshTip =
      tr("Give the surface a new, even sampling at a size you choose (the current one at "
         "first), every painted layer carried to the same surface points: for limbs pulled too "
         "far to even out. Asks first; progress and Cancel; one Undo brings the model back");
  remeshAction->setToolTip(remeshTip);
  remeshAction->setStatusTip(remeshTip);
  connect(remeshAction, &QAction::triggered, this, [this] { openMeshSizeDialog(true); });
  QAction* resolution = add(mesh, tr("Re&solution…"), "actionResolution");
  const QString resolutionTip =
      tr("Resample every layer at a finer or coarser N with the same parameterization: block "
         "out coarse, detail fine. Asks first; one Undo brings the model back");
  resolution->setToolTip(resolutionTip);
  resolution->setStatusTip(resolutionTip);
  connect(resolution, &QAction::triggered, this, [this] { openMeshSizeDialog(false); });
  mesh->setToolTipsVisible(true);
  connect(mesh, &QMenu::aboutToShow, this, &MeshActions::updateActions);
  updateActions();
}

} // namespace octaclay::app
