#pragma once

#include "recovery_store.h"

#include "octaclay/core/document/scene.h"

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <memory>

namespace octaclay::app {

/// The modeller's autosave off the GUI thread. The caller copies the scene on the GUI thread
/// (a snapshot: at N = 1024 about 20 MB an object, milliseconds); start() hands it to a worker that
/// encodes and writes it through RecoveryStore::save (atomic: the previous recovery stays whole
/// until the new one is complete), and the window goes on meanwhile. One save at a time: start()
/// refuses while one runs. finished() is emitted on the thread that owns this object (the GUI
/// thread). Destroying it (the window closing, or quitting) waits for a save in flight, so it
/// finishes whole; a process killed mid-save leaves the old recovery, never half a file.
/// RecoveryStore is not thread-safe: call wait() before any other use of the store.
class Autosaver : public QObject {
  Q_OBJECT

public:
  explicit Autosaver(RecoveryStore& store, QObject* parent = nullptr);
  ~Autosaver() override;

  /// Starts saving snapshot as the recovery of originalPath on a worker; false (nothing started)
  /// while a save runs. Returns at once.
  bool start(std::shared_ptr<const core::Scene> snapshot, const QString& originalPath);
  /// Whether a save is in flight.
  bool busy() const { return running_; }
  /// Blocks until no save is in flight; a save that ends here emits finished() before this
  /// returns.
  void wait();

signals:
  /// A save ended: error is empty when the recovery was written, else what went wrong.
  void finished(const QString& error);

private:
  RecoveryStore& store_;
  QFutureWatcher<QString> watcher_;
  bool running_ = false;
};

} // namespace octaclay::app
