// octaclay-cli import: shared genus-0 meshes become documents with a quality report; every
// invalid shared mesh is refused with its own reason; broken files are errors, never crashes.

#include "cli_support.h"

#include <QTemporaryDir>

namespace {

QString mesh(const QString& name) {
  return QStringLiteral(OCTACLAY_SHARED_DATA) + "/meshes/" + name;
}

} // namespace

class CliImportTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void importsAMeshWithAQualityReport_data();
  void importsAMeshWithAQualityReport();
  void refusesEachInvalidMeshWithItsReason_data();
  void refusesEachInvalidMeshWithItsReason();
  void brokenFilesAreErrors();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
};

void CliImportTest::importsAMeshWithAQualityReport_data() {
  QTest::addColumn<QString>("name");
  // Small smooth meshes, with vt lines (spot) and low resolution (bunny_npm).
  for (const char* name : {"genus0/spot.obj", "genus0/bunny_npm.obj", "genus0/fandisk.obj"})
    QTest::newRow(name) << QString(name);
}

void CliImportTest::importsAMeshWithAQualityReport() {
  QFETCH(QString, name);
  const QString out = file(QFileInfo(name).baseName() + ".exr");
  RUN_JSON(report, "import", mesh(name), "--size", "256", "-o", out, "--json", "--quiet");
  QCOMPARE(report["flipped_triangles"].toInt(), 0);
  QCOMPARE(report["size"].toInt(), 256);
  QVERIFY2(report["rms"].toDouble() <= 0.002,
           qPrintable(QString::number(report["rms"].toDouble())));
  QVERIFY(report["hausdorff"].toDouble() >= report["rms"].toDouble());
  QVERIFY(report["stretch_l2"].toDouble() >= 1.0);
  QVERIFY(report["parameterize_ms"].toDouble() > 0);
  // The document is a closed genus-0 image.
  RUN_JSON(info, "info", out, "--json");
  QCOMPARE(info["euler"].toInt(), 2);
  QVERIFY(info["closed"].toBool());
}

void CliImportTest::refusesEachInvalidMeshWithItsReason_data() {
  QTest::addColumn<QString>("name");
  QTest::addColumn<QStringList>("reason");
  QTest::newRow("genus 1") << "invalid/bob_genus1.obj" << QStringList{"genus 1"};
  QTest::newRow("rocker arm") << "invalid/rocker_arm_genus1.obj" << QStringList{"genus 1"};
  QTest::newRow("genus 4") << "invalid/fertility_genus4.obj" << QStringList{"genus 4"};
  QTest::newRow("open") << "invalid/stanford_bunny_open.obj"
                        << QStringList{"5 holes", "223 boundary edges", "--fill-holes"};
  QTest::newRow("pinch") << "invalid/cow_pinch_vertex.obj" << QStringList{"pinch", "254"};
}

void CliImportTest::refusesEachInvalidMeshWithItsReason() {
  QFETCH(QString, name);
  QFETCH(QStringList, reason);
  const QString out = file("refused.exr");
  const Result r = runCli({"import", mesh(name), "-o", out, "--quiet"});
  QCOMPARE(r.exitCode, kInvalidInput);
  for (const QString& part : reason)
    QVERIFY2(r.err.contains(part.toUtf8()), r.err.constData());
  QVERIFY(!QFileInfo::exists(out));
}

void CliImportTest::brokenFilesAreErrors() {
  const QString out = file("never.exr");
  // Missing file: an I/O error.
  Result r = runCli({"import", file("missing.obj"), "-o", out});
  QCOMPARE(r.exitCode, kIo);
  // Truncated, NaN and out-of-range files: invalid input with a message, no crash.
  const QList<QPair<QString, QByteArray>> broken{
      {"truncated.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n"},
      {"nan.obj", "v nan 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n"},
      {"range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n"},
      {"empty.stl", ""},
  };
  for (const auto& [name, bytes] : broken) {
    QFile f(file(name));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
    f.close();
    r = runCli({"import", file(name), "-o", out, "--quiet"});
    QVERIFY2(!r.crashed && r.exitCode == kInvalidInput, qPrintable(describe({name}, r)));
    QVERIFY(!r.err.isEmpty());
  }
  // Sizes that are not a power of two are usage errors.
  r = runCli({"import", mesh("genus0/spot.obj"), "--size", "300", "-o", out});
  QCOMPARE(r.exitCode, kUsage);
  QVERIFY(!QFileInfo::exists(out));
}

QTEST_APPLESS_MAIN(CliImportTest)
#include "cli_import_test.moc"
