#pragma once

#include "octaclay/core/document/scene.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QString>

#include <optional>

namespace octaclay::app {

/// Autosave and crash recovery. One folder holds, at most, one recovery:
///   session.lock   the PID of the running session that owns the folder (text, one line)
///   recovery.exr   the last autosaved scene (core's native format: every object, written
///   atomically) recovery.json  what it is: the document's original path and when it was saved
/// A session that ends cleanly removes all three (endSession()); one that crashes leaves its lock
/// behind with a PID that no longer runs, and the next session offers its recovery (pending()).
///
/// Lifecycle: construct, ask pending() and let the user load() or discard() it, beginSession(),
/// save() on a timer while the document has unsaved changes, discard() once the user saves the
/// document, endSession() on a clean exit. Not thread-safe: use it from one thread (save() does
/// file I/O, so an autosave may run it off the GUI thread, but not beside another call).
class RecoveryStore {
public:
  /// A recovery that a session which did not end cleanly left behind.
  struct Pending {
    QString recoveryFile; ///< the autosaved document, absolute path
    QString originalPath; ///< where the document came from; empty for a never-saved document
    QDateTime savedAt;    ///< when it was autosaved (UTC)
  };

  /// The folder a session uses unless told otherwise: AppLocalDataLocation + "/recovery".
  static QString defaultFolder();

  /// A store over folder (created on first save(), not here). pid identifies this session in
  /// the lock: the real process id, except in tests, which simulate a crashed session and its
  /// successor within one process by giving each store a different id.
  explicit RecoveryStore(QString folder = defaultFolder(),
                         qint64 pid = QCoreApplication::applicationPid());

  /// The folder this store uses.
  const QString& folder() const { return folder_; }

  /// The recovery a session that did not end cleanly left, or nullopt. A lock whose PID is this
  /// store's own counts as stale unless this store has begun its session (the PID was reused
  /// after a crash or reboot, common in containers); a lock whose PID is another running
  /// process means that instance is alive and owns the folder, so nullopt. Never throws:
  /// unreadable metadata only loses the original path and time, an unreadable document shows
  /// up when load() is called.
  std::optional<Pending> pending() const;

  /// Claims the folder for this session by writing the lock. Call after dealing with
  /// pending(): this session's first save() replaces any recovery still there. Returns false,
  /// writing nothing, when another running instance holds the lock; the caller should then not
  /// autosave, since both would share one recovery file. Throws core::Error(Io) when the
  /// folder or lock cannot be written.
  bool beginSession();

  /// Autosaves scene (every object: core::writeScene) as the recovery of the document at
  /// originalPath (empty for a never-saved one). The file is written atomically (a temporary
  /// file renamed over the old recovery), then the metadata the same way, so a crash or failure
  /// at any point leaves the previous recovery whole and no partial file. Throws
  /// core::Error(Io) on failure.
  void save(const core::Scene& scene, const QString& originalPath);

  /// Reads a pending recovery (core::readScene), positions and transforms bit-exact. Throws
  /// core::Error(InvalidInput) naming the recovery file when it is damaged, Error(Io) when it
  /// cannot be opened.
  core::Scene load(const Pending& recovery) const;

  /// Removes the recovery document and its metadata (the user declined the recovery, or saved
  /// the document). Keeps the lock. Missing files are not an error.
  void discard();

  /// A clean exit: discard() and remove the lock, if it is this session's.
  void endSession();

private:
  QString lockPath() const;
  QString documentPath() const;
  QString metadataPath() const;
  std::optional<qint64> lockOwner() const;

  QString folder_;
  qint64 pid_;
  bool sessionBegun_ = false;
};

} // namespace octaclay::app
