#include "stroke_driver.h"

#include "current_context.h"
#include "modeller.h"

#include <QTimer>
#include <QtConcurrent/QtConcurrentRun>

#include <utility>

namespace octaclay::app {

StrokeDriver::StrokeDriver(Modeller& modeller) : modeller_(modeller) {
  connect(&relaxation_, &QFutureWatcher<void>::finished, this, [this] {
    if (ending_) commit();
  });
}

StrokeDriver::~StrokeDriver() {
  relaxation_.waitForFinished();
}

bool StrokeDriver::begin(const StrokeStart& start) {
  SculptSession& session = modeller_.session();
  if (!modeller_.glReady() || !session.hasDocument()) return false;
  if (modeller_.activeLocked()) { // a locked object is not sculpted
    const auto& name = modeller_.objectAt(modeller_.activeObject()).name;
    emit modeller_.refused(tr("%1 is locked").arg(QString::fromStdString(name)));
    return false;
  }
  settle();                             // a second stroke waits for the first's relaxation
  if (session.stroking()) return false; // one at a time
  try {
    CurrentContext current(*modeller_.glHost()); // a changed area or falloff recompiles the brush
    session.beginStroke(start);
  } catch (const std::exception& e) {
    modeller_.fail(QString::fromUtf8(e.what()));
    return false;
  }
  return true;
}

void StrokeDriver::queue(const StrokeMove& move) {
  if (!modeller_.session().stroking()) return;
  modeller_.session().queueMove(move);
  if (runScheduled_) return;
  runScheduled_ = true;
  // After the pointer events already posted: their moves run together.
  QTimer::singleShot(0, this, [this] {
    if (runScheduled_) runQueued();
  });
}

int StrokeDriver::runQueued() {
  runScheduled_ = false;
  SculptSession& session = modeller_.session();
  if (!session.stroking()) return 0;
  DabRun run;
  {
    CurrentContext current(*modeller_.glHost(), CurrentContext::Mode::IfNotCurrent);
    modeller_.drainGlErrors();
    run = session.runQueuedMoves(); // its changes reach the followers through the feed
  }
  if (!run.error.empty()) modeller_.fail(QString::fromStdString(run.error));
  modeller_.glHost()->update();
  return run.made;
}

void StrokeDriver::end(Relax relax) {
  SculptSession& session = modeller_.session();
  if (!session.stroking()) {
    if (relax == Relax::Wait) settle();
    return;
  }
  runQueued();
  {
    CurrentContext current(*modeller_.glHost(), CurrentContext::Mode::IfNotCurrent);
    try {
      ending_ = session.concludeStroke();
    } catch (const std::exception& e) { // refused (non-finite result): the layers are back
      modeller_.fail(QString::fromUtf8(e.what()));
      ending_.reset();
      return;
    }
  }
  if (ending_ && ending_->needsRelaxation() && relax == Relax::Background) {
    inBackground_ = true;
    emit relaxingChanged(true);
    StrokeEnding* ending = ending_.get();
    relaxation_.setFuture(QtConcurrent::run([ending] { ending->relax(); }));
    return;
  }
  commit();
}

void StrokeDriver::settle() {
  if (!ending_) return;
  relaxation_.waitForFinished();
  commit();
}

void StrokeDriver::commit() {
  std::unique_ptr<StrokeEnding> ending = std::move(ending_);
  const bool wasRelaxing = std::exchange(inBackground_, false);
  QString label;
  {
    CurrentContext current(*modeller_.glHost(), CurrentContext::Mode::IfNotCurrent);
    try {
      ending->relax(); // nothing left to do when the worker solved it
      label = QString::fromStdString(modeller_.session().commitStroke(std::move(ending)).label);
    } catch (const std::exception& e) {
      modeller_.fail(QString::fromUtf8(e.what()));
    }
  }
  if (wasRelaxing) emit relaxingChanged(false);
  modeller_.strokeSettled(label);
}

bool StrokeDriver::stroking() const {
  return modeller_.session().stroking() || relaxing();
}

bool StrokeDriver::drags() const {
  return modeller_.session().strokeDrags();
}

} // namespace octaclay::app
