// The one output rule (DESIGN.md, "Rules every output follows") as octaclay-cli keeps it: a
// command writes all of its files or none. A file-size limit (the disk full) fails the command
// with a message and leaves the previous files and no temporary; SIGTERM during a save leaves
// the previous document; a stale temporary of a dead run goes with the next save; a FIFO or a
// device is refused (exit 4), never replaced; a failing LOD measure leaves no file.

#include "../file_test_support.h"
#include "cli_support.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QThread>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <map>

using octaclay::testing::temporaries;

namespace {

// Runs octaclay-cli in a forked child whose files may not grow past `limit` bytes
// (RLIMIT_FSIZE: what a nearly full disk looks like to the writer).
Result runWithFileSizeLimit(const QStringList& args, rlim_t limit, const QString& errorFile) {
  std::vector<QByteArray> storage{QByteArray(OCTACLAY_CLI)};
  for (const QString& a : args)
    storage.push_back(a.toUtf8());
  std::vector<char*> argv;
  for (QByteArray& s : storage)
    argv.push_back(s.data());
  argv.push_back(nullptr);
  const QByteArray errorPath = errorFile.toUtf8();
  Result r;
  const pid_t child = ::fork();
  if (child == 0) {
    const int err = ::open(errorPath.constData(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int null = ::open("/dev/null", O_WRONLY);
    if (err >= 0) ::dup2(err, STDERR_FILENO);
    if (null >= 0) ::dup2(null, STDOUT_FILENO);
    const rlimit fsize{limit, limit};
    ::setrlimit(RLIMIT_FSIZE, &fsize);
    ::execv(OCTACLAY_CLI, argv.data());
    ::_exit(127);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  r.crashed = !WIFEXITED(status);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  QFile err(errorFile);
  if (err.open(QIODevice::ReadOnly)) r.err = err.readAll();
  return r;
}

// Every file of a folder with its bytes, and the temporaries among them.
std::map<QString, QByteArray> snapshot(const QString& folder) {
  std::map<QString, QByteArray> files;
  for (const QFileInfo& info : QDir(folder).entryInfoList(QDir::Files | QDir::Hidden)) {
    QFile f(info.filePath());
    if (f.open(QIODevice::ReadOnly)) files[info.fileName()] = f.readAll();
  }
  return files;
}

} // namespace

class CliOutputRuleTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void diskFullFailsAndKeepsThePreviousFiles_data();
  void diskFullFailsAndKeepsThePreviousFiles();
  void failedObjExportKeepsThePreviousSet();
  void concurrentObjExportsNeverMix();
  void sigtermDuringALargeSaveKeepsTheDocument();
  void staleTemporaryOfADeadRunIsRemoved();
  void fifoTargetIsRefused();
  void deviceTargetIsRefused();
  void lodWhoseMeasureFailsLeavesNoFile();
  void sweepWhosePlotCannotBeWrittenKeepsThePreviousReport();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString blob_, cube_;
};

void CliOutputRuleTest::initTestCase() {
  QVERIFY(dir_.isValid());
  blob_ = file("blob.exr");
  cube_ = file("cube.exr");
  RUN_JSON(blob, "new", "--shape", "blob", "--size", "32", "-o", blob_, "--json");
  RUN_JSON(cube, "new", "--shape", "cube", "--size", "16", "-o", cube_, "--json");
}

void CliOutputRuleTest::diskFullFailsAndKeepsThePreviousFiles_data() {
  QTest::addColumn<QStringList>("previous"); // the run that writes the previous files
  QTest::addColumn<QStringList>("limited");  // the same output again, under the limit
  for (const char* ext : {"off", "ply", "stl", "obj"}) {
    const QString name = QString("full-%1").arg(ext);
    const QString out = QString("%1/out.%2").arg(name, ext);
    QTest::newRow(qPrintable("export ." + QString(ext)))
        << QStringList{"export", "CUBE", "-o", out} << QStringList{"export", "BLOB", "-o", out};
  }
  QTest::newRow("lod .obj") << QStringList{"lod", "CUBE", "--size", "8", "-o", "full-lod/l.obj"}
                            << QStringList{"lod", "BLOB", "--size", "16", "-o", "full-lod/l.obj"};
  QTest::newRow("save") << QStringList{"new", "--shape", "cube",           "--size",
                                       "16",  "-o",      "full-save/d.exr"}
                        << QStringList{"new", "--shape", "blob",           "--size",
                                       "64",  "-o",      "full-save/d.exr"};
}

void CliOutputRuleTest::diskFullFailsAndKeepsThePreviousFiles() {
  QFETCH(QStringList, previous);
  QFETCH(QStringList, limited);
  const auto resolve = [&](QStringList args) {
    for (QString& a : args) {
      if (a == "CUBE") a = cube_;
      if (a == "BLOB") a = blob_;
      if (a.contains('/') && !a.startsWith('/')) a = file(a);
    }
    return args;
  };
  previous = resolve(previous);
  limited = resolve(limited);
  const QString folder = QFileInfo(previous.last()).path();
  QVERIFY(QDir().mkpath(folder));
  const Result first = runCli(previous);
  QVERIFY2(first.exitCode == kOk, qPrintable(describe(previous, first)));
  const auto before = snapshot(folder);

  const Result r = runWithFileSizeLimit(limited, 2048, file("stderr.txt"));
  QVERIFY2(!r.crashed && r.exitCode == kIo, qPrintable(describe(limited, r)));
  QVERIFY2(!r.err.trimmed().isEmpty(), qPrintable(describe(limited, r)));
  // The message names the file that failed (the output or one of its set), not a temporary.
  QVERIFY2(r.err.contains(("cannot write " + folder + "/").toUtf8()) && !r.err.contains(".tmp-"),
           qPrintable("the message names the target: " + describe(limited, r)));
  QVERIFY2(temporaries(folder).isEmpty(), qPrintable(temporaries(folder).join(", ")));
  QVERIFY2(snapshot(folder) == before, "the previous files changed");
}

void CliOutputRuleTest::failedObjExportKeepsThePreviousSet() {
  const QString folder = file("set");
  QVERIFY(QDir().mkpath(folder));
  const QString obj = folder + "/x.obj";
  RUN_JSON(first, "export", cube_, "-o", obj, "--json");
  const auto before = snapshot(folder);
  QCOMPARE(before.size(), std::size_t{6}); // OBJ, MTL, four maps
  // The normal map's folder does not exist: the last file of the set fails after the others
  // were written to their temporaries.
  EXPECT_FAILURE(kIo, "", "export", blob_, "-o", obj, "--normal-map", file("missing/normals.png"));
  QVERIFY2(temporaries(folder).isEmpty(), qPrintable(temporaries(folder).join(", ")));
  QVERIFY2(snapshot(folder) == before, "the previous OBJ, MTL or maps changed");
}

void CliOutputRuleTest::concurrentObjExportsNeverMix() {
  // Each document's set exported alone, as the reference of what one writer leaves.
  std::vector<std::map<QString, QByteArray>> references;
  for (const QString& document : {cube_, blob_}) {
    const QString folder = file(QString("alone-%1").arg(references.size()));
    QVERIFY(QDir().mkpath(folder));
    RUN_JSON(alone, "export", document, "-o", folder + "/x.obj", "--json");
    references.push_back(snapshot(folder));
  }
  const QString folder = file("together");
  QVERIFY(QDir().mkpath(folder));
  for (int round = 0; round < 5; ++round) {
    QProcess first, second;
    first.start(QStringLiteral(OCTACLAY_CLI), {"export", cube_, "-o", folder + "/x.obj"});
    second.start(QStringLiteral(OCTACLAY_CLI), {"export", blob_, "-o", folder + "/x.obj"});
    QVERIFY(first.waitForFinished(60000) && second.waitForFinished(60000));
    QCOMPARE(first.exitCode(), kOk);
    QCOMPARE(second.exitCode(), kOk);
    const auto together = snapshot(folder);
    QVERIFY2(together == references[0] || together == references[1],
             "the OBJ, MTL and maps come from different exports");
  }
}

void CliOutputRuleTest::sigtermDuringALargeSaveKeepsTheDocument() {
  const QString folder = file("sigterm");
  QVERIFY(QDir().mkpath(folder));
  const QString document = folder + "/big.exr";
  QVERIFY(QFile::copy(cube_, document));
  const auto before = snapshot(folder);

  QProcess process;
  process.start(QStringLiteral(OCTACLAY_CLI),
                {"new", "--shape", "sphere", "--size", "4096", "-o", document});
  QVERIFY(process.waitForStarted(10000));
  // Killed once the save has begun (its temporary exists), or after a short delay.
  QElapsedTimer timer;
  timer.start();
  while (temporaries(folder).isEmpty() && timer.elapsed() < 60000 &&
         process.state() == QProcess::Running)
    QThread::msleep(5);
  QThread::msleep(50);
  process.terminate();
  QVERIFY(process.waitForFinished(60000));
  QVERIFY2(process.exitStatus() == QProcess::CrashExit || process.exitCode() != 0,
           "the save was not interrupted");
  QVERIFY2(temporaries(folder).isEmpty(), qPrintable(temporaries(folder).join(", ")));
  QVERIFY2(snapshot(folder) == before, "the previous document changed");
}

void CliOutputRuleTest::staleTemporaryOfADeadRunIsRemoved() {
  const QString folder = file("stale");
  QVERIFY(QDir().mkpath(folder));
  const pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const QString stale = QString("%1/.d.tmp-%2-7.exr").arg(folder).arg(dead);
  const QString live = QString("%1/.d.tmp-%2-7.exr").arg(folder).arg(::getpid());
  for (const QString& path : {stale, live}) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write("half a document");
  }
  RUN_JSON(saved, "new", "--shape", "cube", "--size", "16", "-o", folder + "/d.exr", "--json");
  QVERIFY2(!QFileInfo::exists(stale), "the dead run's temporary is still there");
  QVERIFY2(QFileInfo::exists(live), "a live process's temporary was removed");
  QFile::remove(live);
}

void CliOutputRuleTest::fifoTargetIsRefused() {
  const QString fifo = file("pipe.off"), documentFifo = file("pipe.exr");
  QVERIFY(::mkfifo(fifo.toUtf8().constData(), 0644) == 0);
  QVERIFY(::mkfifo(documentFifo.toUtf8().constData(), 0644) == 0);
  for (const QStringList& args :
       {QStringList{"export", cube_, "-o", fifo},
        QStringList{"new", "--shape", "cube", "--size", "16", "-o", documentFifo}}) {
    const Result r = runCli(args);
    QVERIFY2(!r.crashed && r.exitCode == kIo, qPrintable(describe(args, r)));
    QVERIFY2(r.err.contains("not a regular file"), qPrintable(describe(args, r)));
    struct stat st {};
    QVERIFY(::lstat(args.last().toUtf8().constData(), &st) == 0 && S_ISFIFO(st.st_mode));
  }
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliOutputRuleTest::deviceTargetIsRefused() {
  if (::geteuid() != 0) QSKIP("a copy of /dev/full needs mknod, which needs root");
  const QString device = file("full.stl");
  QVERIFY(::mknod(device.toUtf8().constData(), S_IFCHR | 0666, makedev(1, 7)) == 0);
  const QStringList args{"export", cube_, "-o", device};
  const Result r = runCli(args);
  QVERIFY2(!r.crashed && r.exitCode == kIo, qPrintable(describe(args, r)));
  QVERIFY2(r.err.contains("not a regular file"), qPrintable(describe(args, r)));
  struct stat st {};
  QVERIFY(::lstat(device.toUtf8().constData(), &st) == 0 && S_ISCHR(st.st_mode));
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliOutputRuleTest::lodWhoseMeasureFailsLeavesNoFile() {
  const QString folder = file("zero");
  QVERIFY(QDir().mkpath(folder));
  octaclay::core::Document doc = octaclay::core::makeDocument(
      octaclay::core::makeBaseShape(octaclay::core::BaseShape::Cube, 16));
  for (octaclay::core::Vec4f& t : doc.positions.texels())
    t = {0, 0, 0, 0};
  octaclay::core::writeDocument(doc, (folder + "/zero.exr").toStdString());
  const QStringList args{"lod", folder + "/zero.exr", "--size",       "8",
                         "-o",  folder + "/l.obj",    "--normal-map", folder + "/n.png"};
  const Result r = runCli(args);
  QVERIFY2(!r.crashed && r.exitCode != kOk && r.exitCode != 1, qPrintable(describe(args, r)));
  QVERIFY2(!r.err.trimmed().isEmpty(), qPrintable(describe(args, r)));
  const QStringList left = QDir(folder).entryList(QDir::Files | QDir::Hidden);
  QVERIFY2(left == QStringList{"zero.exr"}, qPrintable("left behind: " + left.join(", ")));
}

// compress --sweep writes rd.md, rd.csv and rd.png as one set: when the plot cannot be written
// (its name is taken by a folder) the previous report stays byte for byte and nothing is added.
void CliOutputRuleTest::sweepWhosePlotCannotBeWrittenKeepsThePreviousReport() {
  const QString folder = file("sweep");
  QVERIFY(QDir().mkpath(folder));
  const QStringList first{"compress", cube_, "--sweep", "-o", folder};
  const Result made = runCli(first);
  QVERIFY2(made.exitCode == kOk, qPrintable(describe(first, made)));
  QVERIFY(QFile::remove(folder + "/rd.png"));
  QVERIFY(QDir().mkpath(folder + "/rd.png"));
  const auto before = snapshot(folder);
  QCOMPARE(before.size(), std::size_t(2)); // rd.md and rd.csv
  const QStringList second{"compress", blob_, "--sweep", "-o", folder};
  const Result r = runCli(second);
  QVERIFY2(!r.crashed && r.exitCode == kIo, qPrintable(describe(second, r)));
  QVERIFY2(r.err.contains("rd.png"), qPrintable(describe(second, r)));
  QVERIFY(snapshot(folder) == before);
  QVERIFY(temporaries(folder).isEmpty());

  const QString fresh = file("sweep-fresh");
  QVERIFY(QDir().mkpath(fresh + "/rd.png"));
  const QStringList third{"compress", blob_, "--sweep", "-o", fresh};
  QCOMPARE(runCli(third).exitCode, kIo);
  QCOMPARE(QDir(fresh).entryList(QDir::Files | QDir::Hidden), QStringList());
}

QTEST_GUILESS_MAIN(CliOutputRuleTest)
#include "cli_output_rule_test.moc"
