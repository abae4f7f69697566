// octaclay-cli end to end (DESIGN.md, "octaclay-cli contract"): new → info → export → compare,
// JSON output, and the exit code, stderr message and absence of output for every bad input.

#include "cli_support.h"

#include <QByteArray>
#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

class CliTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void newAndInfo_data();
  void newAndInfo();
  void newCapsuleOfAGivenShape();
  void humanOutput();
  void exportAndCompare();
  void lodExports();
  void badArguments();
  void invalidInput();
  void ioFailure();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QString makeDoc(const QString& shape, int n);
  QTemporaryDir dir_;
};

void CliTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QVERIFY2(QFileInfo(OCTACLAY_CLI).isExecutable(), OCTACLAY_CLI);
}

QString CliTest::makeDoc(const QString& shape, int n) {
  const QString path = file(QString("%1-%2.exr").arg(shape).arg(n));
  if (!QFileInfo::exists(path)) {
    const QStringList args{"new", "--shape", shape, "--size", QString::number(n), "-o", path};
    const Result r = runCli(args);
    if (r.exitCode != kOk) qWarning("%s", qPrintable(describe(args, r)));
  }
  return path;
}

void CliTest::newAndInfo_data() {
  QTest::addColumn<QString>("shape");
  for (const char* s : {"sphere", "cube", "cylinder", "blob", "capsule"})
    QTest::newRow(s) << QString(s);
}

void CliTest::newAndInfo() {
  QFETCH(QString, shape);
  const QString doc = file(shape + "-new.exr");
  RUN_JSON(created, "new", "--shape", shape, "--size", "64", "-o", doc, "--json");
  QVERIFY(QFileInfo(doc).size() > 0);
  QVERIFY(!created.isEmpty());

  RUN_JSON(info, "info", doc, "--json");
  QCOMPARE(info["size"].toInt(), 64);
  QCOMPARE(info["vertices"].toDouble(), 4098.0);
  QCOMPARE(info["triangles"].toDouble(), 8192.0);
  QCOMPARE(info["euler"].toDouble(), 2.0);
  QCOMPARE(info["closed"].toBool(false), true);
  QCOMPARE(info["manifold"].toBool(false), true);
  QVERIFY2(info["seam_gap"].isDouble(), "seam_gap is not a number");
  QCOMPARE(info["seam_gap"].toDouble(-1), 0.0);

  const QJsonObject bbox = info["bbox"].toObject();
  const QJsonArray min = bbox["min"].toArray(), max = bbox["max"].toArray();
  QCOMPARE(min.size(), 3);
  QCOMPARE(max.size(), 3);
  double squared = 0;
  for (int k = 0; k < 3; ++k) {
    const double lo = min[k].toDouble(NAN), hi = max[k].toDouble(NAN);
    QVERIFY(lo >= -1.0001 && hi <= 1.0001 && lo < hi);
    // Analytic extent ±1 (the capsule's ±0.5 across, ±1 along z), reached by the axis samples.
    const double extent = shape == "capsule" && k < 2 ? 0.5 : 1.0;
    if (shape != "blob") {
      QVERIFY2(std::abs(lo + extent) < 1e-5 && std::abs(hi - extent) < 1e-5,
               qPrintable(QString::number(lo)));
    }
    squared += (hi - lo) * (hi - lo);
  }
  QVERIFY(std::abs(bbox["diagonal"].toDouble() - std::sqrt(squared)) < 1e-5);

  QStringList layers;
  for (const auto& v : info["layers"].toArray())
    layers << v.toString();
  for (const char* l : {"positions", "diffuse", "feature"})
    QVERIFY2(layers.contains(l), qPrintable(layers.join(',')));

  // Stretch (core::summarizeStretch): every key a finite number; the shapes are evenly sampled.
  const QJsonObject stretch = info["stretch"].toObject();
  for (const char* key : {"longest_over_median", "p99_over_median", "share_over_4x", "median_edge",
                          "longest_edge", "mean_spacing"})
    QVERIFY2(stretch[key].isDouble(), key);
  const double longest = stretch["longest_over_median"].toDouble();
  QVERIFY2(longest >= stretch["p99_over_median"].toDouble() &&
               stretch["p99_over_median"].toDouble() >= 1,
           qPrintable(QJsonDocument(stretch).toJson()));
  QCOMPARE(stretch["share_over_4x"].toDouble(-1), 0.0);
  QVERIFY(std::abs(stretch["longest_edge"].toDouble() / stretch["median_edge"].toDouble() -
                   longest) < 1e-9 * longest);
  if (shape == "sphere") {
    // The octahedral sphere: edges within 1.3× of the median (the issue measured 1.3), and
    // the mean spacing of area 4π over N² + 2 vertices.
    QVERIFY2(std::abs(longest - 1.3) < 0.1, qPrintable(QString::number(longest)));
    QVERIFY(std::abs(stretch["mean_spacing"].toDouble() - std::sqrt(4 * M_PI / 4098)) < 1e-3);
  }
}

void CliTest::newCapsuleOfAGivenShape() {
  // A limb: radius 0.2, a cylinder 2 long, so 2.4 along z and 0.4 across.
  const QString doc = file("limb.exr");
  RUN_JSON(created, "new", "--shape", "capsule", "--radius", "0.2", "--length", "2", "--size", "64",
           "-o", doc, "--json");
  RUN_JSON(info, "info", doc, "--json");
  QCOMPARE(info["euler"].toDouble(), 2.0);
  const QJsonObject bbox = info["bbox"].toObject();
  const QJsonArray min = bbox["min"].toArray(), max = bbox["max"].toArray();
  const double half[3] = {0.2, 0.2, 1.2};
  for (int k = 0; k < 3; ++k)
    QVERIFY2(std::abs(min[k].toDouble() + half[k]) < 1e-5 &&
                 std::abs(max[k].toDouble() - half[k]) < 1e-5,
             qPrintable(QJsonDocument(bbox).toJson()));
}

void CliTest::humanOutput() {
  const QString doc = makeDoc("sphere", 16);
  const QStringList args{"info", doc};
  const Result r = runCli(args);
  QVERIFY2(r.exitCode == kOk, qPrintable(describe(args, r)));
  QVERIFY2(r.out.contains("16") && r.out.contains("258"), qPrintable(describe(args, r)));
  QVERIFY2(r.out.contains("stretch    longest edge 1.") &&
               r.out.contains("% of samples over 4× median spacing"),
           qPrintable(describe(args, r)));
}

void CliTest::exportAndCompare() {
  const QString doc = makeDoc("blob", 64);
  for (const char* ext : {"obj", "ply", "stl", "off"}) {
    const QString mesh = file(QString("full.") + ext);
    RUN_JSON(exported, "export", doc, "-o", mesh, "--json");
    QVERIFY(QFileInfo(mesh).size() > 0);
    QCOMPARE(exported["vertices"].toDouble(), 4098.0);
    QCOMPARE(exported["triangles"].toDouble(), 8192.0);

    // The full-resolution export is the same surface, up to text precision.
    RUN_JSON(cmp, "compare", doc, mesh, "--json");
    const double rms = cmp["rms"].toDouble(-1), hausdorff = cmp["hausdorff"].toDouble(-1);
    QVERIFY2(rms >= 0 && rms < 1e-5, qPrintable(QString("%1: rms %2").arg(ext).arg(rms)));
    QVERIFY2(hausdorff >= rms && hausdorff < 1e-4,
             qPrintable(QString("%1: hausdorff %2").arg(ext).arg(hausdorff)));
    QVERIFY2(cmp["samples"].toDouble() >= 2 * 4098,
             qPrintable(QString::number(cmp["samples"].toDouble())));
    // PSNR = 20·log10(1/rms); an exact match has no finite PSNR.
    if (rms > 0)
      QVERIFY(std::abs(cmp["psnr"].toDouble() - 20 * std::log10(1 / rms)) <
              1e-3 * cmp["psnr"].toDouble());
  }
  // A document against itself: zero distance, and still one parseable JSON object.
  RUN_JSON(self, "compare", doc, doc, "--json");
  QCOMPARE(self["rms"].toDouble(-1), 0.0);
  QCOMPARE(self["hausdorff"].toDouble(-1), 0.0);
}

void CliTest::lodExports() {
  const QString doc = makeDoc("blob", 64);
  double previousRms = -1;
  for (int m : {64, 32, 16}) {
    const QString mesh = file(QString("lod%1.obj").arg(m));
    RUN_JSON(exported, "export", doc, "-o", mesh, "--lod", QString::number(m), "--json");
    QCOMPARE(exported["vertices"].toDouble(), double(m) * m + 2);
    QCOMPARE(exported["triangles"].toDouble(), 2.0 * m * m);
    RUN_JSON(cmp, "compare", doc, mesh, "--json");
    const double rms = cmp["rms"].toDouble(-1);
    QVERIFY2(rms > previousRms,
             qPrintable(QString("lod %1: rms %2, finer lod %3").arg(m).arg(rms).arg(previousRms)));
    if (m < 64) QVERIFY2(rms > 1e-5, qPrintable(QString::number(rms)));
    previousRms = rms;
  }
}

void CliTest::badArguments() {
  const QString doc = makeDoc("sphere", 16);
  const QString out = file("bad-args.exr"), mesh = file("bad-args.obj");
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "klein", "--size", "16", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--size", "3", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--size", "0", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--size", "16384", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--size", "sixteen", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--size", "16");
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "sphere", "--radius", "0.2", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "capsule", "--radius", "0", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "capsule", "--radius", "nan", "-o", out);
  EXPECT_FAILURE(kUsage, out, "new", "--shape", "capsule", "--length", "-1", "-o", out);
  EXPECT_FAILURE(kUsage, mesh, "export", doc, "-o", mesh, "--lod", "12");
  EXPECT_FAILURE(kUsage, mesh, "export", doc, "-o", mesh, "--lod", "32");
  EXPECT_FAILURE(kUsage, mesh, "export", doc, "-o", mesh, "--lod", "1");
  EXPECT_FAILURE(kUsage, mesh, "export", doc, "-o", mesh, "--lod", "0");
  EXPECT_FAILURE(kUsage, file("bad-args.xyz"), "export", doc, "-o", file("bad-args.xyz"));
  EXPECT_FAILURE(kUsage, "", "frobnicate", doc);
  EXPECT_FAILURE(kUsage, "");
}

void CliTest::invalidInput() {
  const QString good = makeDoc("sphere", 16);
  QFile in(good);
  QVERIFY(in.open(QIODevice::ReadOnly));
  const QByteArray bytes = in.readAll();
  QVERIFY(bytes.size() > 1000);
  auto write = [&](const QString& name, const QByteArray& data) {
    QFile f(file(name));
    if (f.open(QIODevice::WriteOnly | QIODevice::Truncate)) f.write(data);
    return file(name);
  };
  const QString text = write("text.exr", "hello, I am not an image\n");
  const QString truncated = write("truncated.exr", bytes.left(bytes.size() / 2));
  // The channel list holds null-terminated names; renaming P.Z keeps the pixel layout (all
  // position channels are float and P.W sorts where P.Z did) but drops a required channel.
  QByteArray renamed = bytes;
  const qsizetype at = renamed.indexOf(QByteArray("P.Z\0", 4));
  QVERIFY(at > 0);
  renamed[at + 2] = 'W';
  const QString noPz = write("no-pz.exr", renamed);

  const QString mesh = file("invalid.obj"), out = file("invalid.exr");
  for (const QString& bad : {text, truncated, noPz}) {
    EXPECT_FAILURE(kInvalidInput, "", "info", bad);
    EXPECT_FAILURE(kInvalidInput, "", "info", bad, "--json");
    EXPECT_FAILURE(kInvalidInput, mesh, "export", bad, "-o", mesh);
    EXPECT_FAILURE(kInvalidInput, "", "compare", good, bad);
    EXPECT_FAILURE(kInvalidInput, "", "compare", bad, good);
  }
  const Result r = runCli({"info", noPz});
  QVERIFY2(r.err.contains("P.Z"), r.err.constData());
}

void CliTest::ioFailure() {
  const QString doc = makeDoc("sphere", 16);
  const QString missingDir = file("no-such-dir");
  EXPECT_FAILURE(kIo, "", "info", file("missing.exr"));
  EXPECT_FAILURE(kIo, "", "export", file("missing.exr"), "-o", file("missing.obj"));
  EXPECT_FAILURE(kIo, "", "compare", doc, file("missing.obj"));
  EXPECT_FAILURE(kIo, missingDir, "new", "--shape", "sphere", "--size", "16", "-o",
                 missingDir + "/doc.exr");
  for (const char* ext : {"obj", "ply", "stl", "off"})
    EXPECT_FAILURE(kIo, missingDir, "export", doc, "-o", missingDir + "/mesh." + ext);
  // An output path that is a directory.
  QVERIFY(QDir(dir_.path()).mkdir("folder.exr"));
  EXPECT_FAILURE(kIo, "", "new", "--shape", "sphere", "--size", "16", "-o", file("folder.exr"));
  QVERIFY(QFileInfo(file("folder.exr")).isDir());
  // Nothing but what the tests wrote on purpose.
  for (const QString& name : QDir(dir_.path()).entryList(QDir::Files | QDir::Hidden))
    QVERIFY2(!name.contains(".tmp"), qPrintable("temporary left behind: " + name));
}

QTEST_APPLESS_MAIN(CliTest)
#include "cli_test.moc"
