// core::OutputSet, the atomic writer behind every output (atomic_output.h): nothing is visible
// before the commit, a failed stage or a dropped set leaves the previous files and no temporary,
// non-regular targets are refused, a replaced file keeps its permissions, and errors name the
// target with the reason.

#include "../../file_test_support.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest>
#include <sys/stat.h>

#include <fstream>
#include <string>

namespace core = octaclay::core;

using octaclay::testing::temporaries;

namespace {

std::string contents(const QString& path) {
  std::ifstream in(path.toStdString(), std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void put(const QString& path, const std::string& text) {
  std::ofstream(path.toStdString(), std::ios::binary) << text;
}

} // namespace

class OutputRuleTest : public QObject {
  Q_OBJECT

private slots:
  void init() { QVERIFY(dir_.isValid()); }
  void nothingIsVisibleBeforeTheCommit();
  void aFailedStageKeepsThePreviousSet();
  void aDroppedSetLeavesNoTemporary();
  void nonRegularTargetsAreRefused();
  void replacedFileKeepsItsPermissions();
  void errorsNameTheTargetAndTheReason();
  void emptyTargetIsAnArgumentError();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
};

void OutputRuleTest::nothingIsVisibleBeforeTheCommit() {
  put(file("a.txt"), "old a");
  core::OutputSet set;
  set.stageText(file("a.txt").toStdString(), "new a");
  set.stageText(file("b.txt").toStdString(), "new b");
  QCOMPARE(contents(file("a.txt")), std::string("old a"));
  QVERIFY(!QFileInfo::exists(file("b.txt")));
  QCOMPARE(temporaries(dir_.path()).size(), 2);
  set.commit();
  QCOMPARE(contents(file("a.txt")), std::string("new a"));
  QCOMPARE(contents(file("b.txt")), std::string("new b"));
  QVERIFY(temporaries(dir_.path()).isEmpty());
  QCOMPARE(set.targets().size(), std::size_t{2});
}

void OutputRuleTest::aFailedStageKeepsThePreviousSet() {
  put(file("m.obj"), "old obj");
  put(file("m.mtl"), "old mtl");
  try {
    core::OutputSet set;
    set.stageText(file("m.mtl").toStdString(), "new mtl");
    set.stage(file("m.obj").toStdString(), [](core::ByteSink&) {
      throw core::Error(core::ErrorKind::Io, "cannot write m.obj: disk full");
    });
    set.commit();
    QFAIL("the stage did not fail");
  } catch (const core::Error& e) {
    QCOMPARE(e.kind(), core::ErrorKind::Io);
  }
  QCOMPARE(contents(file("m.obj")), std::string("old obj"));
  QCOMPARE(contents(file("m.mtl")), std::string("old mtl"));
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void OutputRuleTest::aDroppedSetLeavesNoTemporary() {
  {
    core::OutputSet set;
    set.stageText(file("dropped.txt").toStdString(), "never committed");
  }
  QVERIFY(!QFileInfo::exists(file("dropped.txt")));
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void OutputRuleTest::nonRegularTargetsAreRefused() {
  const QString fifo = file("pipe.txt");
  QVERIFY(::mkfifo(fifo.toUtf8().constData(), 0644) == 0);
  QVERIFY(QDir().mkpath(file("folder.txt")));
  for (const QString& target : {fifo, file("folder.txt")}) {
    try {
      core::writeBytesAtomically(target.toStdString(), {});
      QFAIL("a non-regular target was accepted");
    } catch (const core::Error& e) {
      QCOMPARE(e.kind(), core::ErrorKind::Io);
      QVERIFY2(QString(e.what()).contains(target), e.what());
    }
  }
  struct stat st {};
  QVERIFY(::lstat(fifo.toUtf8().constData(), &st) == 0 && S_ISFIFO(st.st_mode));
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void OutputRuleTest::replacedFileKeepsItsPermissions() {
  put(file("p.txt"), "old");
  QVERIFY(::chmod(file("p.txt").toUtf8().constData(), 0640) == 0);
  core::writeBytesAtomically(file("p.txt").toStdString(), {});
  struct stat st {};
  QVERIFY(::stat(file("p.txt").toUtf8().constData(), &st) == 0);
  QCOMPARE(st.st_mode & 0777, 0640u);
  QCOMPARE(st.st_size, 0);
}

void OutputRuleTest::errorsNameTheTargetAndTheReason() {
  const QString folder = file("locked");
  QVERIFY(QDir().mkpath(folder));
  QVERIFY(::chmod(folder.toUtf8().constData(), 0500) == 0);
  const bool root = ::geteuid() == 0;
  try {
    core::writeBytesAtomically((folder + "/x.txt").toStdString(), {});
    QVERIFY2(root, "a read-only folder took a file");
  } catch (const core::Error& e) {
    const QString message = e.what();
    QVERIFY2(message.contains(folder + "/x.txt"), e.what());
    QVERIFY2(message.contains("Permission denied"), e.what());
    QVERIFY2(!message.contains(".tmp-"), e.what());
  }
  ::chmod(folder.toUtf8().constData(), 0700);
  try {
    core::writeBytesAtomically(file("missing/x.txt").toStdString(), {});
    QFAIL("a missing folder was accepted");
  } catch (const core::Error& e) {
    QVERIFY2(QString(e.what()).contains("does not exist"), e.what());
  }
}

void OutputRuleTest::emptyTargetIsAnArgumentError() {
  try {
    core::writeBytesAtomically("", {});
    QFAIL("an empty target was accepted");
  } catch (const core::Error& e) {
    QCOMPARE(e.kind(), core::ErrorKind::InvalidArgument);
  }
}

QTEST_GUILESS_MAIN(OutputRuleTest)
#include "output_rule_test.moc"
