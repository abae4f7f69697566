// The second hostile pass (issue 34): every case of the issue, tried as its reporter did, ends in
// a bounded run with the right result or a clear refusal, nothing changed and nothing left
// behind. Endless strokes, reports slower than the work, progress and Ctrl+C, inputs named as
// outputs, signals during a save, long names and the messages that name what the user typed.
#include "../file_test_support.h"
#include "cli_support.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QCryptographicHash>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QThread>
#include <fcntl.h>
#include <signal.h>
#include <stdlib.h>
#include <unistd.h>

#include <cmath>
#include <random>

using namespace octaclay;
using octaclay::testing::temporaries;

namespace {

QByteArray checksum(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return {};
  return QCryptographicHash::hash(file.readAll(), QCryptographicHash::Sha256);
}

// A sphere of size n times scale, written with core (no command's checks in the way).
void writeSphere(const QString& path, int n, float scale) {
  core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, n);
  for (core::Vec4f& t : image.texels())
    t = {t.x * scale, t.y * scale, t.z * scale, t.w};
  core::writeDocument(core::makeDocument(std::move(image)), path.toStdString());
}

} // namespace

class CliBoundedTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void endlessStrokesAreRefusedUpFront();
  void degenerateModelsBlameTheDocument();
  void aTangledDocumentStillReportsInSeconds();
  void progressShowsOnATerminalOnly();
  void ctrlCStopsCleanly();
  void inputsAreNeverOutputs();
  void outputsCarryTheirFormatsExtension();
  void signalsDuringASaveLeaveNoTemporary();
  void aLongLegalNameIsWritten();
  void messagesNameWhatWasTyped();

private:
  QString path(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString sphere_; ///< N = 256, as `new --size 256` makes it
  QString large_;  ///< N = 1024: a long stroke over it takes seconds
  // A zigzag over the image, twelve times: about 7600 smooth dabs of radius 0.05 at N = 1024,
  // about 4.6 s here: the progress line (after 1 s) and a Ctrl+C after 1.5 s both have time.
  QStringList longStroke(const QString& output) const {
    QStringList points;
    for (int k = 0; k < 12; ++k)
      points << "0.1,0.1"
             << "0.9,0.9"
             << "0.1,0.9"
             << "0.9,0.1";
    return {"stroke",         large_,     "--brush", "smooth", "--path",
            points.join(';'), "--radius", "0.05",    "-o",     output};
  }
};

void CliBoundedTest::initTestCase() {
  QVERIFY(dir_.isValid());
  sphere_ = path("sphere.exr");
  const Result made = runCli({"new", "--size", "256", "-o", sphere_});
  QVERIFY2(made.exitCode == kOk, made.err.constData());
  large_ = path("large.exr");
  const Result madeLarge = runCli({"new", "--size", "1024", "-o", large_});
  QVERIFY2(madeLarge.exitCode == kOk, madeLarge.err.constData());
}

namespace {
// Ignored signals stay ignored across exec (a shell's background job ignores SIGINT): the
// child starts with every default action, as from a terminal.
void defaultSignalActions() {
  for (const int s : {SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGINT, SIGTERM})
    ::signal(s, SIG_DFL);
}
} // namespace

void CliBoundedTest::endlessStrokesAreRefusedUpFront() {
  const QByteArray before = checksum(sphere_);
  const auto refused = [&](const QStringList& extra, const char* words) {
    QStringList args{"stroke", sphere_, "--path", "0.5,0.5", "-o", path("o.exr")};
    args << extra;
    QElapsedTimer clock;
    clock.start();
    const Result r = runCli(args);
    qInfo("%-60s exit %d in %.2f s", qPrintable(extra.join(' ')), r.exitCode,
          static_cast<double>(clock.elapsed()) / 1000.0);
    QVERIFY2(!r.crashed && r.exitCode == kUsage, qPrintable(describe(args, r)));
    QVERIFY2(r.err.contains(words), qPrintable(describe(args, r)));
    QVERIFY2(!QFileInfo::exists(path("o.exr")), qPrintable(describe(args, r)));
  };
  // The drag to 1e30 (keep-detail on and off), and a drag 3000 units away.
  refused({"--brush", "snake-hook", "--drag", "1e30,0,0"}, "diagonals from the model");
  refused({"--brush", "snake-hook", "--drag", "1e30,0,0", "--keep-detail", "off"},
          "diagonals from the model");
  refused({"--brush", "snake-hook", "--drag", "0,0,3000"}, "diagonals from the model");
  refused({"--brush", "grab", "--drag", "0,0,-3000"}, "diagonals from the model");
  // A drag within reach but so long at this radius that it passes the dab cap.
  refused({"--brush", "snake-hook", "--drag", "0,0,150", "--radius", "0.0005"}, "at most 100000");
  // A 5000-point random stroke: refused before its first dab, not after minutes.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> uv(0, 1);
  QStringList points;
  for (int k = 0; k < 5000; ++k)
    points << QString("%1,%2").arg(uv(random)).arg(uv(random));
  QStringList args{"stroke",         sphere_,    "--brush", "push", "--path",
                   points.join(';'), "--radius", "0.1",     "-o",   path("o.exr")};
  const Result r = runCli(args);
  QVERIFY2(r.exitCode == kUsage && r.err.contains("at most 100000"), r.err.constData());
  QVERIFY(!QFileInfo::exists(path("o.exr")));
  // A drag within reach still works.
  RUN_JSON(ok, "stroke", sphere_, "--brush", "snake-hook", "--path", "0.5,0.5", "--drag", "0,0,1.5",
           "-o", path("o.exr"), "--json");
  QVERIFY(ok["dabs"].toInt() > 1 && ok["dabs"].toInt() < 1000);
  QCOMPARE(checksum(sphere_), before);
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliBoundedTest::degenerateModelsBlameTheDocument() {
  // Every sample at one point; a sphere 1e-30 across; a sphere 1e-9 across at 1e6 (below float
  // precision there).
  core::GeometryImage point = core::makeBaseShape(core::BaseShape::Sphere, 16);
  for (core::Vec4f& t : point.texels())
    t = {0.5f, 0.5f, 0.5f, 0};
  core::writeDocument(core::makeDocument(point), path("point.exr").toStdString());
  writeSphere(path("tiny.exr"), 16, 1e-30f);
  core::GeometryImage far = core::makeBaseShape(core::BaseShape::Sphere, 16);
  for (core::Vec4f& t : far.texels())
    t = {1e6f + t.x * 1e-9f, t.y * 1e-9f, t.z * 1e-9f, 0};
  core::writeDocument(core::makeDocument(far), path("far.exr").toStdString());

  for (const auto& [file, words] :
       {std::pair{QString("point.exr"), "no size"}, std::pair{QString("tiny.exr"), "1e-12"},
        std::pair{QString("far.exr"), "collapsed"}}) {
    const QString doc = path(file);
    const QByteArray before = checksum(doc);
    const QList<QStringList> runs{
        {"stroke", doc, "--brush", "push", "--path", "0.5,0.5", "-o", path("d.exr")},
        {"stroke", doc, "--brush", "snake-hook", "--path", "0.5,0.5", "--drag", "0,0,3", "-o",
         path("d.exr")},
        {"lod", doc, "--size", "8", "-o", path("d.glb")},
        {"export", doc, "--triangles", "100", "-o", path("d.obj")},
        {"compress", doc, "--codec", "wavelet", "-o", path("d.ocz")},
        {"compress", doc, "--codec", "dct", "-o", path("d.ocz")}};
    for (const QStringList& args : runs) {
      const Result r = runCli(args);
      QVERIFY2(!r.crashed && r.exitCode == kInvalidInput, qPrintable(describe(args, r)));
      QVERIFY2(r.err.contains(words) && r.err.contains(file.toUtf8()),
               qPrintable(describe(args, r)));
      QVERIFY2(!r.err.contains("brush produced"), qPrintable(describe(args, r)));
      QVERIFY(!QFileInfo::exists(args.last()));
    }
    // info still describes it.
    const Result info = runCli({"info", doc});
    QCOMPARE(info.exitCode, kOk);
    QCOMPARE(checksum(doc), before);
  }
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliBoundedTest::aTangledDocumentStillReportsInSeconds() {
  // The self-intersecting document: positions replaced by standard-normal noise.
  core::GeometryImage noise = core::makeBaseShape(core::BaseShape::Sphere, 128);
  std::mt19937 random(3);
  std::normal_distribution<float> normal;
  for (core::Vec4f& t : noise.texels())
    t = {normal(random), normal(random), normal(random), 0};
  core::writeDocument(core::makeDocument(noise), path("noise.exr").toStdString());
  const QString doc = path("noise.exr");
  QElapsedTimer clock;
  clock.start();
  RUN_JSON(compared, "compare", doc, path("sphere.exr"), "--json", "--samples", "50000");
  const QJsonObject report = compared["report"].toObject();
  qInfo("compare of a tangle: %.1f s, %d of %d queries at their bound",
        static_cast<double>(clock.elapsed()) / 1000.0, report["bounded_queries"].toInt(),
        compared["samples"].toInt());
  QCOMPARE(report["method"].toString(), QString("sampled"));
  QVERIFY(report["bounded_queries"].toInt() > 0);
  QVERIFY(!report["exact"].toBool());
  QVERIFY(std::isfinite(compared["rms"].toDouble()) && compared["rms"].toDouble() > 0);

  clock.restart();
  RUN_JSON(lod, "lod", doc, "--size", "32", "-o", path("noise.glb"), "--json");
  qInfo("lod of a tangle: %.1f s, report %s", static_cast<double>(clock.elapsed()) / 1000.0,
        QJsonDocument(lod["report"].toObject()).toJson(QJsonDocument::Compact).constData());
  QVERIFY(lod["report"].isObject());
  RUN_JSON(skipped, "lod", doc, "--size", "32", "-o", path("noise2.glb"), "--json", "--no-report");
  QVERIFY(skipped["report"].isNull());
  QVERIFY(skipped["psnr"].isNull());
  RUN_JSON(packed, "compress", doc, "--codec", "dct", "-o", path("noise.ocz"), "--json",
           "--no-report");
  QVERIFY(packed["report"].isNull());
  QVERIFY(!packed.contains("psnr"));

  // A smooth surface's report is exact: the bound never bites there.
  writeSphere(path("sphere64.exr"), 64, 1.0f);
  RUN_JSON(smooth, "lod", path("sphere64.exr"), "--size", "16", "-o", path("s.glb"), "--json");
  QCOMPARE(smooth["report"].toObject()["bounded_queries"].toInt(), 0);
  QVERIFY(smooth["report"].toObject()["exact"].toBool());
}

void CliBoundedTest::progressShowsOnATerminalOnly() {
  // stderr on a real terminal (a pseudo-terminal the test reads); a stroke of ~1000 dabs.
  const int master = posix_openpt(O_RDWR | O_NOCTTY);
  QVERIFY(master >= 0);
  QVERIFY(grantpt(master) == 0 && unlockpt(master) == 0);
  const QString terminal = QString::fromLocal8Bit(ptsname(master));
  fcntl(master, F_SETFL, O_NONBLOCK);
  const auto runOnTerminal = [&](const QStringList& args) {
    QProcess process;
    process.setChildProcessModifier(defaultSignalActions);
    process.setStandardErrorFile(terminal, QIODevice::Append);
    process.start(QStringLiteral(OCTACLAY_CLI), args);
    QByteArray seen;
    char buffer[4096];
    while (!process.waitForFinished(100))
      for (ssize_t got; (got = read(master, buffer, sizeof buffer)) > 0;)
        seen.append(buffer, static_cast<int>(got));
    for (ssize_t got; (got = read(master, buffer, sizeof buffer)) > 0;)
      seen.append(buffer, static_cast<int>(got));
    return std::pair{process.exitCode(), seen};
  };
  const QStringList stroke = longStroke(path("p.exr"));
  const auto [code, shown] = runOnTerminal(stroke);
  QCOMPARE(code, kOk);
  QVERIFY2(shown.contains("stroke: dabs") && shown.contains("of about"), shown.constData());
  QVERIFY2(shown.contains("Ctrl+C"), shown.constData());
  const auto [jsonCode, silent] = runOnTerminal(QStringList(stroke) << "--json");
  QCOMPARE(jsonCode, kOk);
  QVERIFY2(!silent.contains("dabs"), silent.constData());
  // Not a terminal (a pipe, as in every other test here): nothing on stderr.
  const Result piped = runCli(stroke);
  QCOMPARE(piped.exitCode, kOk);
  QVERIFY2(piped.err.isEmpty(), piped.err.constData());
  close(master);
}

void CliBoundedTest::ctrlCStopsCleanly() {
  // A stroke of several seconds, interrupted after one: no output, no temporary, input intact.
  const QByteArray before = checksum(large_);
  QProcess process;
  process.setChildProcessModifier(defaultSignalActions);
  process.start(QStringLiteral(OCTACLAY_CLI), longStroke(path("interrupted.exr")));
  QVERIFY(process.waitForStarted());
  QThread::msleep(1500);
  QVERIFY2(process.state() == QProcess::Running, "the stroke ended before it could be stopped");
  kill(static_cast<pid_t>(process.processId()), SIGINT);
  QVERIFY(process.waitForFinished(10000));
  QCOMPARE(process.exitStatus(), QProcess::CrashExit); // died of the signal, as a shell expects
  QVERIFY(!QFileInfo::exists(path("interrupted.exr")));
  QVERIFY(temporaries(dir_.path()).isEmpty());
  QCOMPARE(checksum(large_), before);
}

void CliBoundedTest::inputsAreNeverOutputs() {
  const QString doc = path("doc.exr");
  QVERIFY(QFile::copy(sphere_, doc));
  const QByteArray before = checksum(doc);
  EXPECT_FAILURE(kUsage, "", "export", doc, "-o", path("x.glb"), "--normal-map", doc);
  EXPECT_FAILURE(kUsage, "", "lod", doc, "--size", "16", "-o", path("x.glb"), "--normal-map", doc);
  EXPECT_FAILURE(kUsage, "", "compress", doc, "--codec", "wavelet", "-o", doc);
  // The same file through a link is the same file.
  QVERIFY(QFile::link(doc, path("link.exr")));
  EXPECT_FAILURE(kUsage, "", "export", doc, "-o", path("y.obj"), "--normal-map", path("link.exr"));
  QCOMPARE(checksum(doc), before);
  QVERIFY(!QFileInfo::exists(path("x.glb")) && !QFileInfo::exists(path("y.obj")));
  // An OBJ named as its own import's output is refused by its extension, and kept.
  RUN_JSON(exported, "export", doc, "-o", path("cube.obj"), "--lod", "16", "--json");
  const QByteArray mesh = checksum(path("cube.obj"));
  EXPECT_FAILURE(kUsage, "", "import", path("cube.obj"), "-o", path("cube.obj"));
  QCOMPARE(checksum(path("cube.obj")), mesh);
  // Commands that promise to write in place still do.
  RUN_JSON(inPlace, "stroke", doc, "--brush", "push", "--path", "0.5,0.5", "-o", doc, "--json");
  QVERIFY(checksum(doc) != before);
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliBoundedTest::outputsCarryTheirFormatsExtension() {
  const auto refused = [&](const QStringList& args, const char* expected) {
    const Result r = runCli(args);
    QVERIFY2(!r.crashed && r.exitCode == kUsage, qPrintable(describe(args, r)));
    QVERIFY2(r.err.contains(expected), qPrintable(describe(args, r)));
    QVERIFY2(!QFileInfo::exists(args.last()), qPrintable(describe(args, r)));
  };
  refused({"new", "--size", "8", "-o", path("n.obj")}, ".exr");
  refused({"new", "--size", "8", "-o", path("n")}, ".exr");
  refused({"stroke", sphere_, "--brush", "push", "--path", "0.5,0.5", "-o", path("s.png")}, ".exr");
  refused({"import", path("cube.obj"), "-o", path("i.ply")}, ".exr");
  refused({"decompress", path("noise.ocz"), "-o", path("d.ocz")}, ".exr");
}

void CliBoundedTest::signalsDuringASaveLeaveNoTemporary() {
  // `new --size 2048` writes ~70 MB: long enough to catch its temporary and signal the save.
  QDir folder(path("signals"));
  QVERIFY(folder.mkpath("."));
  for (const int signal : {SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE, SIGINT, SIGTERM}) {
    const QString target = folder.filePath("big.exr");
    QProcess process;
    process.setChildProcessModifier(defaultSignalActions);
    process.start(QStringLiteral(OCTACLAY_CLI), {"new", "--size", "2048", "-o", target});
    QVERIFY(process.waitForStarted());
    QElapsedTimer clock;
    clock.start();
    while (temporaries(folder.path()).isEmpty() && process.state() == QProcess::Running &&
           clock.elapsed() < 30000)
      QThread::usleep(200);
    const bool caught = !temporaries(folder.path()).isEmpty();
    kill(static_cast<pid_t>(process.processId()), signal);
    QVERIFY(process.waitForFinished(30000));
    QVERIFY2(caught,
             qPrintable(QString("signal %1: the save ended before it was seen").arg(signal)));
    QVERIFY2(process.exitStatus() == QProcess::CrashExit,
             qPrintable(QString("signal %1: exit %2").arg(signal).arg(process.exitCode())));
    QVERIFY2(
        temporaries(folder.path()).isEmpty(),
        qPrintable(
            QString("signal %1 left %2").arg(signal).arg(temporaries(folder.path()).join(", "))));
    QVERIFY(!QFileInfo::exists(target));
  }
}

void CliBoundedTest::aLongLegalNameIsWritten() {
  // 245 + ".exr" = 249 bytes: legal, though ".name.tmp-PID-N.exr" would not be.
  const QString name = path(QString(245, 'a') + ".exr");
  const Result r = runCli({"new", "--size", "8", "-o", name});
  QVERIFY2(r.exitCode == kOk, r.err.constData());
  QVERIFY(QFileInfo::exists(name));
  const QString relaxedName = path(QString(245, 'b') + ".exr");
  RUN_JSON(stroked, "stroke", name, "--brush", "push", "--path", "0.5,0.5", "-o", relaxedName,
           "--json");
  QVERIFY(QFileInfo::exists(relaxedName));
  QVERIFY(temporaries(dir_.path()).isEmpty());
}

void CliBoundedTest::messagesNameWhatWasTyped() {
  const auto says = [&](const QStringList& args, int code, const char* words) {
    const Result r = runCli(args);
    QVERIFY2(!r.crashed && r.exitCode == code, qPrintable(describe(args, r)));
    QVERIFY2((code == kOk ? r.out : r.err).contains(words), qPrintable(describe(args, r)));
    if (code != kOk) QCOMPARE(r.err.trimmed().count('\n'), 0); // one line
  };
  const QStringList stroke{"stroke", sphere_,   "--brush", "push",
                           "--path", "0.5,0.5", "-o",      path("m.exr")};
  says(QStringList(stroke) << "--strength"
                           << "1e39",
       kUsage, "1e39");
  says(QStringList(stroke) << "--spacing"
                           << "0",
       kUsage, "--spacing 0 is outside 0.01 to 100");
  says(QStringList(stroke) << "--spacing"
                           << "-1",
       kUsage, "--spacing -1");
  says(QStringList(stroke) << "--spacing"
                           << "1e-9",
       kUsage, "--spacing 1e-9");
  says({"relax", "--frobnicate"}, kUsage, "--frobnicate");
  says({"lod", sphere_, "--frobnicate=3", "-o", path("f.glb")}, kUsage, "--frobnicate");
  says({"--version"}, kOk, "octaclay-cli 0.");
  says(QStringList(stroke) << "--view"
                           << "1e39,0,0",
       kUsage, "1e39");
  // N = 2 has 8 triangles: --triangles 5 names the document's size, not an "LOD size 1".
  const Result tiny = runCli({"new", "--size", "2", "-o", path("two.exr")});
  QCOMPARE(tiny.exitCode, kOk);
  says({"export", path("two.exr"), "--triangles", "5", "-o", path("t.obj")}, kUsage, "N = 2");
  QVERIFY(!QFileInfo::exists(path("m.exr")) && !QFileInfo::exists(path("t.obj")));
  // A NaN in the mask is the document's fault, named as such (not the brush's).
  core::Document masked = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 16));
  masked.hasMask = true;
  masked.mask.texels.assign(17 * 17, 1.0f);
  masked.mask.texels[40] = std::nanf("");
  core::writeDocument(masked, path("masked.exr").toStdString());
  says({"stroke", path("masked.exr"), "--brush", "push", "--path", "0.5,0.5", "-o", path("m.exr")},
       kInvalidInput, "layer mask holds a value that is not a finite number");
}

QTEST_GUILESS_MAIN(CliBoundedTest)
#include "cli_bounded_test.moc"
