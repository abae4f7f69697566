#include "autosaver.h"

#include <QtConcurrent/QtConcurrentRun>

#include <exception>

namespace octaclay::app {

Autosaver::Autosaver(RecoveryStore& store, QObject* parent) : QObject(parent), store_(store) {
  connect(&watcher_, &QFutureWatcher<QString>::finished, this, [this] {
    if (!running_) return; // wait() reported it already
    running_ = false;
    emit finished(watcher_.result());
  });
}

Autosaver::~Autosaver() {
  watcher_.disconnect(this);
  watcher_.waitForFinished();
}

bool Autosaver::start(std::shared_ptr<const core::Scene> snapshot, const QString& originalPath) {
  if (running_ || !snapshot) return false;
  running_ = true;
  RecoveryStore* store = &store_;
  watcher_.setFuture(QtConcurrent::run([store, snapshot = std::move(snapshot), originalPath] {
    try {
      store->save(*snapshot, originalPath);
      return QString();
    } catch (const std::exception& e) {
      return QString::fromUtf8(e.what());
    }
  }));
  return true;
}

void Autosaver::wait() {
  watcher_.waitForFinished();
  if (!running_) return;
  running_ = false;
  emit finished(watcher_.result());
}

} // namespace octaclay::app
