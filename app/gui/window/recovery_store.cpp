#include "recovery_store.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <signal.h>

#include <cerrno>
#include <climits>
#include <filesystem>
#include <string>
#include <utility>

namespace octaclay::app {

namespace {

constexpr int kMetadataVersion = 1;

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(QFile::encodeName(path).toStdString());
}

// kill(pid, 0) sends nothing and only checks that the process exists; EPERM means it exists
// but belongs to another user. PIDs ≤ 0 would address process groups, so they are never alive.
bool processAlive(qint64 pid) {
  if (pid <= 0 || pid > INT_MAX) return false;
  return ::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM;
}

// Through the one output writer (core::OutputSet): a reader never sees half a file.
void writeFileAtomically(const QString& path, const QByteArray& bytes, const char* what) {
  try {
    core::writeBytesAtomically(toPath(path),
                               std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                         static_cast<std::size_t>(bytes.size())));
  } catch (const core::Error& e) {
    throw core::Error(core::ErrorKind::Io,
                      std::string("cannot write the ") + what + ": " + e.what());
  }
}

void makeFolder(const QString& folder) {
  if (!QDir().mkpath(folder))
    throw core::Error(core::ErrorKind::Io,
                      "cannot create the recovery folder " + folder.toStdString());
}

} // namespace

QString RecoveryStore::defaultFolder() {
  return QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + "/recovery";
}

RecoveryStore::RecoveryStore(QString folder, qint64 pid) : folder_(std::move(folder)), pid_(pid) {}

QString RecoveryStore::lockPath() const {
  return folder_ + "/session.lock";
}
QString RecoveryStore::documentPath() const {
  return folder_ + "/recovery.exr";
}
QString RecoveryStore::metadataPath() const {
  return folder_ + "/recovery.json";
}

std::optional<qint64> RecoveryStore::lockOwner() const {
  QFile file(lockPath());
  if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
  bool ok = false;
  const qint64 pid = file.readLine(64).trimmed().toLongLong(&ok);
  // An unreadable lock protects nothing: treat it like none, so a recovery is not hidden.
  return ok ? std::optional<qint64>(pid) : std::nullopt;
}

std::optional<RecoveryStore::Pending> RecoveryStore::pending() const {
  if (const auto owner = lockOwner()) {
    if (*owner == pid_) {
      if (sessionBegun_) return std::nullopt; // our own autosave, not something to recover
    } else if (processAlive(*owner)) {
      return std::nullopt; // another instance is running and owns this recovery
    }
  }
  const QFileInfo document(documentPath());
  if (!document.isFile()) return std::nullopt;

  Pending recovery{document.absoluteFilePath(), {}, document.lastModified().toUTC()};
  // The metadata is written after the document, so after a crash between the two it may be
  // missing or one save older; the document alone is still worth offering.
  QFile metadataFile(metadataPath());
  if (metadataFile.open(QIODevice::ReadOnly)) {
    const QJsonObject metadata = QJsonDocument::fromJson(metadataFile.readAll()).object();
    recovery.originalPath = metadata.value("originalPath").toString();
    const QDateTime savedAt =
        QDateTime::fromString(metadata.value("savedAt").toString(), Qt::ISODateWithMs);
    if (savedAt.isValid()) recovery.savedAt = savedAt.toUTC();
  }
  return recovery;
}

bool RecoveryStore::beginSession() {
  if (const auto owner = lockOwner(); owner && *owner != pid_ && processAlive(*owner)) return false;
  makeFolder(folder_);
  writeFileAtomically(lockPath(), QByteArray::number(pid_) + '\n', "session lock");
  sessionBegun_ = true;
  return true;
}

void RecoveryStore::save(const core::Scene& scene, const QString& originalPath) {
  makeFolder(folder_);
  try {
    core::writeScene(scene, toPath(documentPath()));
  } catch (const core::Error& e) {
    throw core::Error(e.kind(), std::string("cannot autosave: ") + e.what());
  }
  QJsonObject metadata;
  metadata["version"] = kMetadataVersion;
  metadata["originalPath"] = originalPath;
  metadata["savedAt"] = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
  metadata["pid"] = pid_;
  metadata["size"] = scene.objects.empty() ? 0 : scene.objects.front().document.size();
  metadata["objects"] = static_cast<qint64>(scene.objects.size());
  writeFileAtomically(metadataPath(), QJsonDocument(metadata).toJson(), "recovery metadata");
}

core::Scene RecoveryStore::load(const Pending& recovery) const {
  const std::string name = recovery.recoveryFile.toStdString();
  try {
    return core::readScene(toPath(recovery.recoveryFile));
  } catch (const core::Error& e) {
    throw core::Error(e.kind(), "the recovery file " + name +
                                    " cannot be loaded (discard it to go on): " + e.what());
  } catch (const std::exception& e) {
    throw core::Error(core::ErrorKind::InvalidInput,
                      "the recovery file " + name +
                          " is damaged (discard it to go on): " + e.what());
  }
}

void RecoveryStore::discard() {
  // Document first: metadata without a document is ignored, a document without metadata is
  // still offered, so this order never leaves a recovery that points at the wrong file.
  QFile::remove(documentPath());
  QFile::remove(metadataPath());
  // Temporaries a crash left in the middle of writeScene() (".recovery.tmp-<pid>-<n>.exr").
  const QDir dir(folder_);
  for (const QString& name :
       dir.entryList({".recovery.tmp-*"}, QDir::Files | QDir::Hidden | QDir::System))
    QFile::remove(dir.filePath(name));
}

void RecoveryStore::endSession() {
  discard();
  if (lockOwner() == pid_) QFile::remove(lockPath());
  sessionBegun_ = false;
}

} // namespace octaclay::app
