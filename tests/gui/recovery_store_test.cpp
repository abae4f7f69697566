// Autosave and crash recovery (app/gui/window/recovery_store.h). A crashed session and the one that
// restarts after it are simulated inside this one process by giving each store a PID of its
// own: one that no process has (crashed) or this process's real one (running).

#include "autosaver.h"
#include "recovery_store.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>
#include <signal.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <functional>
#include <memory>

using octaclay::app::RecoveryStore;
namespace core = octaclay::core;

namespace {

// Far above any pid_max Linux allows (2^22), so no process can have them.
constexpr qint64 kCrashedPid = 0x7ffffff0;
constexpr qint64 kRestartedPid = 0x7ffffff1;

core::Document makeTestDocument(core::BaseShape shape = core::BaseShape::Sphere) {
  return core::makeDocument(core::makeBaseShape(shape, 32));
}

bool positionsBitExact(const core::Document& a, const core::Document& b);

// A recovery of one object holds that object's document.
bool positionsBitExact(const core::Scene& a, const core::Document& b) {
  return a.objects.size() == 1 && positionsBitExact(a.objects.front().document, b);
}

bool positionsBitExact(const core::Document& a, const core::Document& b) {
  const auto ta = a.positions.texels();
  const auto tb = b.positions.texels();
  return a.size() == b.size() && ta.size() == tb.size() &&
         std::memcmp(ta.data(), tb.data(), ta.size_bytes()) == 0;
}

QStringList listFolder(const QString& folder) {
  return QDir(folder).entryList(
      QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot, QDir::Name);
}

void writeGarbage(const QString& path, const QByteArray& bytes) {
  QFile file(path);
  QVERIFY(file.open(QIODevice::WriteOnly | QIODevice::Truncate));
  QCOMPARE(file.write(bytes), bytes.size());
}

// Runs f, which must throw core::Error of kind. Returns what went wrong, empty on success.
QString expectError(const std::function<void()>& f, core::ErrorKind kind) {
  try {
    f();
  } catch (const core::Error& e) {
    if (e.kind() != kind)
      return QString("wrong ErrorKind %1 (expected %2): %3")
          .arg(int(e.kind()))
          .arg(int(kind))
          .arg(e.what());
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  }
  return "did not throw";
}

#define EXPECT_ERROR(call, kind)                                                                   \
  do {                                                                                             \
    const QString why_ = expectError([&] { call; }, kind);                                         \
    QVERIFY2(why_.isEmpty(), qPrintable(QString(#call ": ") + why_));                              \
  } while (false)

} // namespace

class RecoveryStoreTest : public QObject {
  Q_OBJECT

private slots:
  void init();
  void fakePidsAreDead();
  void emptyFolderHasNoPending();
  void crashLeavesRecovery();
  void cleanExitLeavesNothing();
  void liveInstanceHidesItsRecovery();
  void reusedOwnPidCountsAsCrashed();
  void corruptRecoveryThrows();
  void failedSaveKeepsPreviousRecovery();
  void autosaveRunsOnAWorkerAndEndsWhole();
  void sceneRecoveryKeepsEveryObject();

private:
  QString folder() const { return dir_->path() + "/recovery"; }
  std::unique_ptr<QTemporaryDir> dir_;
};

void RecoveryStoreTest::init() {
  dir_ = std::make_unique<QTemporaryDir>();
  QVERIFY(dir_->isValid());
}

void RecoveryStoreTest::fakePidsAreDead() {
  for (qint64 pid : {kCrashedPid, kRestartedPid}) {
    errno = 0;
    QCOMPARE(::kill(static_cast<pid_t>(pid), 0), -1);
    QCOMPARE(errno, ESRCH);
  }
}

void RecoveryStoreTest::emptyFolderHasNoPending() {
  // Neither a folder that does not exist yet nor an empty one.
  QVERIFY(!RecoveryStore(folder(), kRestartedPid).pending());
  QVERIFY(QDir().mkpath(folder()));
  QVERIFY(!RecoveryStore(folder(), kRestartedPid).pending());
  QVERIFY(!RecoveryStore(folder()).pending());
  // Metadata without its document is nothing to recover.
  writeGarbage(folder() + "/recovery.json", R"({"originalPath": "/x.exr"})");
  QVERIFY(!RecoveryStore(folder(), kRestartedPid).pending());
}

void RecoveryStoreTest::crashLeavesRecovery() {
  const core::Document doc = makeTestDocument(core::BaseShape::Blob);
  const QString original = dir_->path() + "/models/ünïcode head.exr";
  const QDateTime before = QDateTime::currentDateTimeUtc().addMSecs(-1);
  {
    RecoveryStore crashed(folder(), kCrashedPid);
    QVERIFY(!crashed.pending());
    QVERIFY(crashed.beginSession());
    crashed.save(core::sceneOf(makeTestDocument(core::BaseShape::Cube)),
                 original); // an older autosave
    crashed.save(core::sceneOf(doc), original);
    // A session's own autosave is not a recovery for itself.
    QVERIFY(!crashed.pending());
    // ... and the process dies here: no endSession().
  }
  const QDateTime after = QDateTime::currentDateTimeUtc().addMSecs(1);

  RecoveryStore restarted(folder(), kRestartedPid);
  const auto recovery = restarted.pending();
  QVERIFY(recovery);
  QCOMPARE(recovery->originalPath, original);
  QVERIFY(QFileInfo(recovery->recoveryFile).isAbsolute());
  QVERIFY2(recovery->savedAt >= before && recovery->savedAt <= after,
           qPrintable(recovery->savedAt.toString(Qt::ISODateWithMs)));
  core::Document loaded;
  try {
    loaded = restarted.load(*recovery).objects.at(0).document;
  } catch (const core::Error& e) {
    QFAIL(e.what());
  }
  QVERIFY(positionsBitExact(loaded, doc));

  // The user takes it: the new session claims the folder, after which the recovery is its own
  // autosave, not a pending one; discarding it leaves nothing for anyone.
  QVERIFY(restarted.beginSession());
  QVERIFY(!restarted.pending());
  restarted.discard();
  QVERIFY(!RecoveryStore(folder(), kCrashedPid).pending());

  // A damaged lock hides nothing: the recovery is offered.
  restarted.save(core::sceneOf(doc), QString());
  writeGarbage(folder() + "/session.lock", "not a pid");
  const auto untitled = RecoveryStore(folder(), kCrashedPid).pending();
  QVERIFY(untitled);
  QVERIFY(untitled->originalPath.isEmpty());
  // Damaged metadata only loses the path and time (savedAt falls back to the file's).
  writeGarbage(folder() + "/recovery.json", "{{{");
  const auto noMetadata = RecoveryStore(folder(), kCrashedPid).pending();
  QVERIFY(noMetadata);
  QVERIFY(noMetadata->originalPath.isEmpty());
  QVERIFY(noMetadata->savedAt.isValid());
}

void RecoveryStoreTest::cleanExitLeavesNothing() {
  RecoveryStore session(folder(), kCrashedPid);
  QVERIFY(session.beginSession());
  session.save(core::sceneOf(makeTestDocument()), "/tmp/a.exr");
  QVERIFY(QFile::exists(folder() + "/session.lock"));
  QVERIFY(QFile::exists(folder() + "/recovery.exr"));
  QVERIFY(QFile::exists(folder() + "/recovery.json"));
  // A temporary a crash left half-written is cleaned up with the rest.
  writeGarbage(folder() + "/.recovery.tmp-123-456.exr", "half");
  session.endSession();
  QVERIFY(!RecoveryStore(folder(), kRestartedPid).pending());
  QVERIFY2(listFolder(folder()).isEmpty(), qPrintable(listFolder(folder()).join(", ")));

  // discard() (the user saved the document) keeps the lock but nothing to recover.
  QVERIFY(session.beginSession());
  session.save(core::sceneOf(makeTestDocument()), "/tmp/a.exr");
  session.discard();
  QCOMPARE(listFolder(folder()), QStringList{"session.lock"});
  QVERIFY(!RecoveryStore(folder(), kRestartedPid).pending());
}

void RecoveryStoreTest::liveInstanceHidesItsRecovery() {
  // This process is the running instance; the store with a fake PID is a second instance.
  RecoveryStore running(folder());
  QVERIFY(running.beginSession());
  running.save(core::sceneOf(makeTestDocument()), "/tmp/live.exr");

  RecoveryStore second(folder(), kRestartedPid);
  QVERIFY(!second.pending());
  // It may not claim the folder either: both would write one recovery file.
  QVERIFY(!second.beginSession());
  QFile lock(folder() + "/session.lock");
  QVERIFY(lock.open(QIODevice::ReadOnly));
  QCOMPARE(lock.readAll().trimmed().toLongLong(), QCoreApplication::applicationPid());
  lock.close();
  // Its endSession() must not remove the running instance's lock.
  second.endSession();
  QVERIFY(QFile::exists(folder() + "/session.lock"));

  running.endSession();
  QVERIFY(!QFile::exists(folder() + "/session.lock"));
  QVERIFY(!second.pending());
  QVERIFY(second.beginSession());
}

void RecoveryStoreTest::reusedOwnPidCountsAsCrashed() {
  // A previous instance that had this very PID (reuse after a reboot, or PID 1 in a container)
  // crashed: its lock names a live process, ours, yet is stale.
  const core::Document doc = makeTestDocument();
  {
    RecoveryStore previous(folder());
    QVERIFY(previous.beginSession());
    previous.save(core::sceneOf(doc), "/tmp/reused.exr");
  }
  RecoveryStore now(folder());
  const auto recovery = now.pending();
  QVERIFY(recovery);
  QCOMPARE(recovery->originalPath, QString("/tmp/reused.exr"));
  QVERIFY(positionsBitExact(now.load(*recovery), doc));
  QVERIFY(now.beginSession());
  QVERIFY(!now.pending());
}

void RecoveryStoreTest::corruptRecoveryThrows() {
  {
    RecoveryStore crashed(folder(), kCrashedPid);
    QVERIFY(crashed.beginSession());
    crashed.save(core::sceneOf(makeTestDocument()), "/tmp/corrupt.exr");
  }
  const QString file = folder() + "/recovery.exr";
  QFile good(file);
  QVERIFY(good.open(QIODevice::ReadOnly));
  const QByteArray bytes = good.readAll();
  good.close();
  QVERIFY(bytes.size() > 1000);

  RecoveryStore restarted(folder(), kRestartedPid);
  for (const QByteArray& damaged :
       {QByteArray("garbage, not an EXR file at all"), QByteArray(), bytes.left(bytes.size() / 2),
        bytes.left(bytes.size() - 16), bytes.left(64)}) {
    writeGarbage(file, damaged);
    const auto recovery = restarted.pending();
    QVERIFY(recovery);
    try {
      restarted.load(*recovery);
      QFAIL(qPrintable(QString("a %1-byte recovery loaded").arg(damaged.size())));
    } catch (const core::Error& e) {
      // Says which file, so the user knows what to discard.
      QVERIFY2(QString(e.what()).contains("recovery.exr"), e.what());
    }
  }
  // And the user can still discard it.
  restarted.discard();
  QVERIFY(!restarted.pending());
}

void RecoveryStoreTest::failedSaveKeepsPreviousRecovery() {
  const core::Document first = makeTestDocument(core::BaseShape::Sphere);
  const core::Document second = makeTestDocument(core::BaseShape::Cylinder);

  // A folder that cannot be created (its path is a file).
  const QString blocked = dir_->path() + "/blocked";
  writeGarbage(blocked, "a file where the folder should be");
  EXPECT_ERROR(RecoveryStore(blocked, kCrashedPid).save(core::sceneOf(first), "/tmp/x.exr"),
               core::ErrorKind::Io);
  QVERIFY(QFileInfo(blocked).isFile());

  // How big the second document's file is, to fail its write just short of the end.
  const QString measure = dir_->path() + "/measure";
  RecoveryStore(measure, kCrashedPid).save(core::sceneOf(second), QString());
  const qint64 secondSize = QFileInfo(measure + "/recovery.exr").size();
  QVERIFY(secondSize > 1000);

  RecoveryStore session(folder(), kCrashedPid);
  QVERIFY(session.beginSession());
  session.save(core::sceneOf(first), "/tmp/first.exr");
  const QStringList before = listFolder(folder());

  auto checkFirstIsStillThere = [&](const char* when) {
    QVERIFY2(
        listFolder(folder()) == before,
        qPrintable(QString("%1: folder now holds %2").arg(when, listFolder(folder()).join(", "))));
    const auto recovery = RecoveryStore(folder(), kRestartedPid).pending();
    QVERIFY2(recovery, when);
    QCOMPARE(recovery->originalPath, QString("/tmp/first.exr"));
    QVERIFY2(positionsBitExact(RecoveryStore(folder(), kRestartedPid).load(*recovery), first),
             when);
  };

  // A read-only folder: root ignores permissions, so only where they apply.
  if (::geteuid() != 0) {
    QVERIFY(QFile::setPermissions(folder(), QFile::ReadOwner | QFile::ExeOwner));
    EXPECT_ERROR(session.save(core::sceneOf(second), "/tmp/second.exr"), core::ErrorKind::Io);
    QVERIFY(
        QFile::setPermissions(folder(), QFile::ReadOwner | QFile::WriteOwner | QFile::ExeOwner));
    checkFirstIsStillThere("read-only folder");
  }

  // A disk that fills up in the middle of the write, which works as root too: a file-size limit
  // makes write() fail with EFBIG, early and near the end of the file.
  rlimit old{};
  QCOMPARE(::getrlimit(RLIMIT_FSIZE, &old), 0);
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  for (rlim_t limit : {rlim_t(512), rlim_t(secondSize / 2), rlim_t(secondSize - 8)}) {
    rlimit lowered = old;
    lowered.rlim_cur = limit;
    QCOMPARE(::setrlimit(RLIMIT_FSIZE, &lowered), 0);
    const QString why = expectError([&] { session.save(core::sceneOf(second), "/tmp/second.exr"); },
                                    core::ErrorKind::Io);
    ::setrlimit(RLIMIT_FSIZE, &old);
    QVERIFY2(why.isEmpty(), qPrintable(QString("limit %1: %2").arg(limit).arg(why)));
    checkFirstIsStillThere("file-size limit");
  }
  std::signal(SIGXFSZ, oldHandler);

  // The recovery document's name taken by a folder: the rename fails, nothing is replaced.
  session.discard();
  QVERIFY(QDir().mkpath(folder() + "/recovery.exr"));
  EXPECT_ERROR(session.save(core::sceneOf(second), "/tmp/second.exr"), core::ErrorKind::Io);
  QVERIFY(QFileInfo(folder() + "/recovery.exr").isDir());
  QCOMPARE(listFolder(folder()), (QStringList{"recovery.exr", "session.lock"}));
  QVERIFY(QDir(folder() + "/recovery.exr").removeRecursively());

  // And once the disk is fine again, saving works.
  session.save(core::sceneOf(second), "/tmp/second.exr");
  const auto recovery = RecoveryStore(folder(), kRestartedPid).pending();
  QVERIFY(recovery);
  QCOMPARE(recovery->originalPath, QString("/tmp/second.exr"));
  QVERIFY(positionsBitExact(session.load(*recovery), second));
}

// No QApplication: the store is Qt Core only, and offscreen widgets would only slow this down.
// The modeller's autosave (Autosaver): start() hands a snapshot to a worker and returns; the GUI
// thread's event loop keeps turning while the file is encoded and written; a second start() is
// refused while one runs; the recovery it leaves is whole and bit-exact; and a save still in
// flight when the autosaver goes (the window quitting) finishes before it is gone, leaving no
// temporary beside it.
void RecoveryStoreTest::autosaveRunsOnAWorkerAndEndsWhole() {
  RecoveryStore store(folder(), kCrashedPid);
  QVERIFY(store.beginSession());
  // N = 2048 (about half a second to write here): long enough to see the loop turn meanwhile.
  const auto blob = std::make_shared<const core::Scene>(
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 2048))));
  const auto sphere = std::make_shared<const core::Scene>(
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 1024))));
  int finished = 0, ticksBeforeFinished = 0;
  QString error = "never finished";
  {
    octaclay::app::Autosaver saver(store);
    connect(&saver, &octaclay::app::Autosaver::finished, this, [&](const QString& e) {
      error = e;
      ++finished;
    });
    QTimer tick;
    connect(&tick, &QTimer::timeout, this, [&] { ticksBeforeFinished += finished == 0; });
    tick.start(5);
    QVERIFY(saver.start(blob, "/models/blob.exr"));
    QVERIFY(saver.busy());
    QVERIFY(!saver.start(sphere, "/models/sphere.exr")); // one at a time
    QTRY_COMPARE_WITH_TIMEOUT(finished, 1, 60000);
    QVERIFY2(error.isEmpty(), qPrintable(error));
    QVERIFY2(ticksBeforeFinished >= 2, qPrintable(QString::number(ticksBeforeFinished)));
    QVERIFY(!saver.busy());
    {
      RecoveryStore reader(folder(), kRestartedPid);
      const auto pending = reader.pending();
      QVERIFY(pending.has_value());
      QCOMPARE(pending->originalPath, QString("/models/blob.exr"));
      QVERIFY(positionsBitExact(reader.load(*pending), blob->objects.front().document));
    }
    // The second save is in flight as the autosaver goes.
    QVERIFY(saver.start(sphere, "/models/sphere.exr"));
  }
  RecoveryStore restarted(folder(), kRestartedPid);
  const auto pending = restarted.pending();
  QVERIFY(pending.has_value());
  QCOMPARE(pending->originalPath, QString("/models/sphere.exr"));
  QVERIFY(positionsBitExact(restarted.load(*pending), sphere->objects.front().document));
  for (const QString& name : listFolder(folder()))
    QVERIFY2(!name.contains("tmp"), qPrintable(name)); // no half-written file left
}

QTEST_GUILESS_MAIN(RecoveryStoreTest)
void RecoveryStoreTest::sceneRecoveryKeepsEveryObject() {
  // A modeller scene of three objects: the autosave holds each with its name, transform,
  // visibility and lock, positions bit for bit.
  core::Scene scene = core::sceneOf(makeTestDocument(core::BaseShape::Sphere), "Body");
  scene.objects.push_back({"Hat",
                           makeTestDocument(core::BaseShape::Cylinder),
                           {{0.25f, 1.5f, -0.125f}, {10.0f, 0.0f, 30.0f}, {0.5f, 0.75f, 0.5f}},
                           true,
                           true});
  scene.objects.push_back({"Nose",
                           makeTestDocument(core::BaseShape::Cube),
                           {{0.0f, 0.5f, 1.0f}, {}, {0.1f, 0.1f, 0.3f}},
                           false,
                           false});
  {
    RecoveryStore crashed(folder(), kCrashedPid);
    QVERIFY(crashed.beginSession());
    crashed.save(scene, "/models/snowman.exr");
  }
  RecoveryStore restarted(folder(), kRestartedPid);
  const auto recovery = restarted.pending();
  QVERIFY(recovery);
  const core::Scene loaded = restarted.load(*recovery);
  QCOMPARE(loaded.objects.size(), std::size_t(3));
  for (std::size_t k = 0; k < 3; ++k) {
    const core::SceneObject& a = loaded.objects[k];
    const core::SceneObject& b = scene.objects[k];
    QCOMPARE(a.name, b.name);
    QVERIFY(a.transform == b.transform);
    QCOMPARE(a.visible, b.visible);
    QCOMPARE(a.locked, b.locked);
    QVERIFY(positionsBitExact(a.document, b.document));
  }
}

#include "recovery_store_test.moc"
