// octaclay-cli lod (DESIGN.md's CLI contract, issue 7): writes the LOD with its baked normal map
// as OBJ + MTL + PNG or as GLB, --json reports triangles, vertices, timings and RMS / Hausdorff /
// PSNR against the full-resolution surface; bad arguments are usage errors (exit 2) that name
// the problem and write nothing, a file that is not a document exit 3. Also export's
// --triangles and --normal-map, which go through the same pipeline.

#include "cli_support.h"

#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtEndian>

#include <cmath>

namespace {

// Width and height from a PNG's IHDR chunk.
QPair<int, int> pngSize(const QString& path) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {-1, -1};
  const QByteArray head = f.read(24);
  if (head.size() < 24 || !head.startsWith("\x89PNG")) return {-1, -1};
  return {int(qFromBigEndian<quint32>(head.constData() + 16)),
          int(qFromBigEndian<quint32>(head.constData() + 20))};
}

int countLines(const QString& path, const QByteArray& prefix) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return -1;
  int count = 0;
  while (!f.atEnd())
    count += f.readLine().startsWith(prefix);
  return count;
}

} // namespace

class CliLodTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void objWithMapAndFigures();
  void glbWithTriangleTargetAndTangentMap();
  void everyMethod_data();
  void everyMethod();
  void triangleTargetAlonePicksTheSize();
  void oversampledAdaptive();
  void humanOutputGivesTheFigures();
  void refusals_data();
  void refusals();
  void exportTrianglesAndNormalMap();
  void exportRefusals();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString document_;
};

void CliLodTest::initTestCase() {
  QVERIFY(dir_.isValid());
  document_ = file("blob.exr");
  RUN_JSON(created, "new", "--shape", "blob", "--size", "64", "-o", document_, "--json");
  QFile bad(file("bad.exr"));
  QVERIFY(bad.open(QIODevice::WriteOnly));
  bad.write("this is not an OpenEXR file\n");
}

void CliLodTest::objWithMapAndFigures() {
  const QString obj = file("lod.obj");
  RUN_JSON(lod, "lod", document_, "--size", "16", "--method", "salient-point", "-o", obj, "--json");
  QCOMPARE(lod["size"].toInt(), 16);
  QCOMPARE(lod["document_size"].toInt(), 64);
  QCOMPARE(lod["method"].toString(), QString("salient-point"));
  QCOMPARE(lod["method_used"].toString(), QString("salient-point"));
  QCOMPARE(lod["triangles"].toDouble(), 2.0 * 16 * 16);
  QCOMPARE(lod["vertices"].toDouble(), 16.0 * 16 + 2);
  QVERIFY(lod["file_vertices"].toDouble() > lod["vertices"].toDouble()); // seams split
  QCOMPARE(lod["normal_space"].toString(), QString("object"));
  QCOMPARE(lod["map_size"].toInt(), 64);
  QCOMPARE(lod["saliency_computed"].toBool(), true); // a new document has none
  for (const char* ms : {"ms", "bake_ms", "saliency_ms", "write_ms", "measure_ms"})
    QVERIFY2(lod[ms].toDouble() > 0, ms);
  QVERIFY(lod["total_ms"].toDouble() >=
          lod["ms"].toDouble() + lod["bake_ms"].toDouble() + lod["measure_ms"].toDouble());
  // A blob at M = 16 is close but not equal to its N = 64 surface.
  const double rms = lod["rms"].toDouble(), hausdorff = lod["hausdorff"].toDouble();
  QVERIFY2(rms > 1e-5 && rms < 0.02, qPrintable(QString::number(rms)));
  QVERIFY(hausdorff >= rms && hausdorff < 0.1);
  QVERIFY(std::abs(lod["psnr"].toDouble() - 20 * std::log10(1 / rms)) < 1e-6);

  const QJsonArray files = lod["files"].toArray();
  const QStringList expected{obj, file("lod.mtl"), file("lod_normal.png")};
  QCOMPARE(files.size(), expected.size());
  for (int k = 0; k < expected.size(); ++k) {
    QCOMPARE(files[k].toString(), expected[k]);
    QVERIFY2(QFileInfo(expected[k]).size() > 0, qPrintable(expected[k]));
  }
  QCOMPARE(countLines(obj, "v "), 16 * 16 + 2);
  QCOMPARE(countLines(obj, "f "), 2 * 16 * 16);
  QCOMPARE(countLines(obj, "vt "), int(lod["file_vertices"].toDouble()));
  QCOMPARE(countLines(obj, "mtllib lod.mtl"), 1);
  QCOMPARE(countLines(file("lod.mtl"), "norm lod_normal.png"), 1);
  QCOMPARE(pngSize(file("lod_normal.png")), qMakePair(64, 64));
}

void CliLodTest::glbWithTriangleTargetAndTangentMap() {
  const QString glb = file("lod.glb"), map = file("tangent.exr");
  RUN_JSON(lod, "lod", document_, "--size", "32", "--method", "salient-point", "--triangles", "300",
           "--normal-space", "tangent", "--normal-map", map, "--map-size", "128", "-o", glb,
           "--json");
  QCOMPARE(lod["size"].toInt(), 32);
  QVERIFY2(std::abs(lod["triangles"].toDouble() - 300) <= 3, // the target within 1 %
           qPrintable(QString::number(lod["triangles"].toDouble())));
  QCOMPARE(lod["vertices"].toDouble(), lod["triangles"].toDouble() / 2 + 2); // closed, genus 0
  QCOMPARE(lod["normal_space"].toString(), QString("tangent"));
  QCOMPARE(lod["map_size"].toInt(), 128);
  const QJsonArray files = lod["files"].toArray();
  QCOMPARE(files.size(), 2);
  QCOMPARE(files[0].toString(), glb);
  QCOMPARE(files[1].toString(), map);

  QFile f(glb);
  QVERIFY(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  QVERIFY(bytes.startsWith("glTF"));
  QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 4), quint32(2));
  QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 8), quint32(bytes.size()));
  const quint32 jsonLength = qFromLittleEndian<quint32>(bytes.constData() + 12);
  const QJsonObject gltf = QJsonDocument::fromJson(bytes.mid(20, int(jsonLength))).object();
  const QJsonObject primitive =
      gltf["meshes"].toArray()[0].toObject()["primitives"].toArray()[0].toObject();
  for (const char* attribute : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"})
    QVERIFY2(primitive["attributes"].toObject().contains(attribute), attribute);
  QCOMPARE(gltf["materials"].toArray()[0].toObject()["normalTexture"].toObject()["index"].toInt(-1),
           0);
  QFile exr(map);
  QVERIFY(exr.open(QIODevice::ReadOnly));
  QCOMPARE(qFromLittleEndian<quint32>(exr.read(4).constData()), quint32(20000630)); // EXR magic
}

void CliLodTest::everyMethod_data() {
  QTest::addColumn<QString>("method");
  QTest::addColumn<bool>("needsSaliency");
  QTest::newRow("point") << "point" << false;
  QTest::newRow("average") << "average" << false;
  QTest::newRow("salient-average") << "salient-average" << true;
  QTest::newRow("salient-point") << "salient-point" << true;
  QTest::newRow("adaptive") << "adaptive" << false; // --size 8: the 8-grid's 128 triangles
  QTest::newRow("collapse") << "collapse" << false; // the same count, from all 2N² triangles
  QTest::newRow("auto") << "auto" << false;         // adaptive or collapse: neither reads it
}

void CliLodTest::everyMethod() {
  QFETCH(QString, method);
  QFETCH(bool, needsSaliency);
  RUN_JSON(lod, "lod", document_, "--size", "8", "--method", method, "-o", file(method + ".glb"),
           "--json");
  QCOMPARE(lod["method"].toString(), method);
  if (method != "auto") QCOMPARE(lod["method_used"].toString(), method);
  QCOMPARE(lod["triangles"].toDouble(), 2.0 * 8 * 8);
  QCOMPARE(lod["vertices"].toDouble(), 8.0 * 8 + 2); // closed, genus 0
  QCOMPARE(lod["saliency_computed"].toBool(), needsSaliency);
  QVERIFY(lod["psnr"].toDouble() > 20);
  QVERIFY(QFileInfo(file(method + ".glb")).size() > 0);
}

void CliLodTest::triangleTargetAlonePicksTheSize() {
  RUN_JSON(lod, "lod", document_, "--method", "salient-point", "--triangles", "200", "-o",
           file("target.glb"), "--json");
  QCOMPARE(lod["size"].toInt(), 16); // the smallest M with 2M² ≥ 200
  QVERIFY(std::abs(lod["triangles"].toDouble() - 200) <= 2);
  QCOMPARE(lod["normal_space"].toString(), QString("tangent")); // what glTF viewers read
}

// --oversample 2 with the adaptive method: cut at 4 x the triangles, collapsed to the target
// (under a looser shape bound).
void CliLodTest::oversampledAdaptive() {
  RUN_JSON(lod, "lod", document_, "--method", "adaptive", "--triangles", "300", "--oversample", "2",
           "--max-aspect", "25", "-o", file("oversampled.glb"), "--json");
  QCOMPARE(lod["oversample"].toInt(), 2);
  QVERIFY(std::abs(lod["triangles"].toDouble() - 300) <= 3);
  QVERIFY(lod["psnr"].toDouble() > 20);
}

void CliLodTest::humanOutputGivesTheFigures() {
  const QStringList args{"lod", document_, "--size", "16", "-o", file("human.obj")};
  const Result r = runCli(args);
  QVERIFY2(r.exitCode == kOk, qPrintable(describe(args, r)));
  for (const char* words : {"512 triangles", "PSNR", "Hausdorff", "object-space normal map",
                            "wrote ", "human.mtl", "human_normal.png"})
    QVERIFY2(r.out.contains(words), qPrintable(describe(args, r)));
}

void CliLodTest::refusals_data() {
  QTest::addColumn<QStringList>("args");
  QTest::addColumn<int>("code");
  QTest::addColumn<QString>("message");
  const QString out = "refused.obj";
  QTest::newRow("M = N") << QStringList{"--size", "64", "-o", out} << kUsage << "N = 64";
  QTest::newRow("M > N") << QStringList{"--size", "128", "-o", out} << kUsage << "N = 64";
  QTest::newRow("M not a power of two")
      << QStringList{"--size", "24", "-o", out} << kUsage << "power of two";
  QTest::newRow("M = 1") << QStringList{"--size", "1", "-o", out} << kUsage << "power of two";
  QTest::newRow("4 triangles") << QStringList{"--size", "16", "--triangles", "4", "-o", out}
                               << kUsage << "more than 4";
  QTest::newRow("unknown method") << QStringList{"--size", "16", "--method", "best", "-o", out}
                                  << kUsage << "salient-point";
  QTest::newRow("bad output") << QStringList{"--size", "16", "-o", "refused.ply"} << kUsage
                              << ".glb";
  QTest::newRow("bad space") << QStringList{"--size", "16", "--normal-space", "world", "-o", out}
                             << kUsage << "tangent";
  QTest::newRow("bad map") << QStringList{"--size", "16", "--normal-map", "m.tga", "-o", out}
                           << kUsage << ".exr";
  QTest::newRow("bad map size") << QStringList{"--size", "16", "--map-size", "1", "-o", out}
                                << kUsage << "--map-size";
  QTest::newRow("negative error") << QStringList{"--size", "16", "--max-error", "-1", "-o", out}
                                  << kUsage << "negative";
  QTest::newRow("no size, no target") << QStringList{"-o", out} << kUsage << "--size";
  QTest::newRow("aspect 1.5") << QStringList{"--triangles", "100", "--max-aspect", "1.5", "-o", out}
                              << kUsage << "--max-aspect";
  QTest::newRow("oversample 3") << QStringList{"--triangles", "100", "--oversample", "3", "-o", out}
                                << kUsage << "--oversample 3";
}

void CliLodTest::refusals() {
  QFETCH(QStringList, args);
  QFETCH(int, code);
  QFETCH(QString, message);
  for (QString& a : args)
    if (a.startsWith("refused") || a == "m.tga") a = file(a);
  const QStringList all = QStringList{"lod", document_} + args;
  const Result r = runCli(all);
  QVERIFY2(!r.crashed && r.exitCode == code, qPrintable(describe(all, r)));
  QVERIFY2(r.err.contains(message.toUtf8()), qPrintable(describe(all, r)));
  QVERIFY(!QFileInfo::exists(file("refused.obj")));
  QVERIFY(!QFileInfo::exists(file("refused.mtl")));
  QVERIFY(!QFileInfo::exists(file("refused_normal.png")));
  QVERIFY(!QFileInfo::exists(file("refused.ply")));
  QVERIFY(!QFileInfo::exists(file("m.tga")));

  // Input files: not a document (3), missing (4); an unwritable place (4) leaves nothing.
  EXPECT_FAILURE(kInvalidInput, file("refused.obj"), "lod", file("bad.exr"), "--size", "16", "-o",
                 file("refused.obj"));
  EXPECT_FAILURE(kIo, file("refused.obj"), "lod", file("missing.exr"), "--size", "16", "-o",
                 file("refused.obj"));
  EXPECT_FAILURE(kIo, file("nowhere/lod.obj"), "lod", document_, "--size", "16", "--normal-map",
                 file("kept.png"), "-o", file("nowhere/lod.obj"));
  QVERIFY(!QFileInfo::exists(file("kept.png"))); // the separate map is taken back
}

void CliLodTest::exportTrianglesAndNormalMap() {
  const QString glb = file("exported.glb"), map = file("exported_map.png");
  RUN_JSON(exported, "export", document_, "--triangles", "300", "--normal-map", map, "-o", glb,
           "--json");
  QVERIFY(std::abs(exported["triangles"].toDouble() - 300) <= 3);
  QCOMPARE(exported["vertices"].toDouble(), exported["triangles"].toDouble() / 2 + 2);
  const QJsonArray files = exported["files"].toArray();
  QCOMPARE(files.size(), 2);
  QCOMPARE(files[0].toString(), glb);
  QCOMPARE(files[1].toString(), map);
  QCOMPARE(pngSize(map), qMakePair(64, 64));

  // Without --triangles the full-resolution export is unchanged, and the map comes along.
  const QString ply = file("full.ply"), fullMap = file("full_map.png");
  RUN_JSON(full, "export", document_, "--normal-map", fullMap, "-o", ply, "--json");
  QCOMPARE(full["triangles"].toDouble(), 2.0 * 64 * 64);
  QCOMPARE(full["files"].toArray().size(), 2);
  QCOMPARE(pngSize(fullMap), qMakePair(64, 64));

  // A plain format through --triangles: the collapsed geometry alone.
  RUN_JSON(plain, "export", document_, "--triangles", "120", "--lod", "16", "-o",
           file("collapsed.off"), "--json");
  QCOMPARE(plain["lod"].toInt(), 16);
  QVERIFY(std::abs(plain["triangles"].toDouble() - 120) <= 2);
  QCOMPARE(countLines(file("collapsed.off"), "3 "), int(plain["triangles"].toDouble()));
}

void CliLodTest::exportRefusals() {
  EXPECT_FAILURE(kUsage, file("no.glb"), "export", document_, "--triangles", "3", "-o",
                 file("no.glb"));
  EXPECT_FAILURE(kUsage, file("no.glb"), "export", document_, "--normal-map", file("no.bmp"), "-o",
                 file("no.glb"));
  EXPECT_FAILURE(kUsage, file("no.glb"), "export", document_, "--triangles", "100", "--lod", "64",
                 "-o", file("no.glb"));
  QVERIFY(!QFileInfo::exists(file("no.bmp")));
}

QTEST_GUILESS_MAIN(CliLodTest)
#include "cli_lod_test.moc"
