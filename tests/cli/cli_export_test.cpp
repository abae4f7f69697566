// octaclay-cli export to the textured formats (core/textured_export.h): .obj writes the OBJ, its
// MTL and the PNG maps and lists them in --json; .glb writes one binary glTF; a format nobody
// writes is a usage error (exit 2) with a message, and an unwritable place an I/O error (exit 4)
// that leaves nothing behind.

#include "cli_support.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <QtEndian>

class CliExportTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void texturedObjWithMaps();
  void texturedObjAtALevel();
  void glb();
  void humanOutputNamesTheFiles();
  void badExtensionIsAUsageError();
  void unwritablePlaceIsAnIoError();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString document_;
};

void CliExportTest::initTestCase() {
  QVERIFY(dir_.isValid());
  document_ = file("blob.exr");
  RUN_JSON(created, "new", "--shape", "blob", "--size", "16", "-o", document_, "--json");
  QVERIFY(QFileInfo::exists(document_));
}

void CliExportTest::texturedObjWithMaps() {
  const QString mesh = file("painted.obj");
  RUN_JSON(exported, "export", document_, "-o", mesh, "--json");
  QCOMPARE(exported["output"].toString(), mesh);
  QCOMPARE(exported["lod"].toInt(), 16);
  QCOMPARE(exported["vertices"].toDouble(), 16.0 * 16 + 2); // the surface's vertices
  QCOMPARE(exported["triangles"].toDouble(), 2.0 * 16 * 16);
  QCOMPARE(exported["file_vertices"].toDouble(), 16.0 * 16 + 2); // each position once

  const QJsonArray files = exported["files"].toArray();
  const QStringList expected{mesh,
                             file("painted.mtl"),
                             file("painted_diffuse.png"),
                             file("painted_specular.png"),
                             file("painted_reflectivity.png"),
                             file("painted_height.png")};
  QCOMPARE(files.size(), expected.size());
  for (int k = 0; k < expected.size(); ++k) {
    QCOMPARE(files[k].toString(), expected[k]);
    QVERIFY2(QFileInfo(expected[k]).size() > 0, qPrintable(expected[k]));
  }

  QFile obj(mesh);
  QVERIFY(obj.open(QIODevice::ReadOnly | QIODevice::Text));
  int v = 0, vt = 0, f = 0;
  bool mtllib = false;
  while (!obj.atEnd()) {
    const QByteArray line = obj.readLine();
    v += line.startsWith("v ");
    vt += line.startsWith("vt ");
    f += line.startsWith("f ");
    mtllib = mtllib || line.trimmed() == "mtllib painted.mtl";
  }
  QCOMPARE(v, 16 * 16 + 2); // each position once: the model arrives closed
  QCOMPARE(vt, 17 * 17);    // seams split only their texture coordinates
  QCOMPARE(f, 2 * 16 * 16);
  QVERIFY(mtllib);

  QFile mtl(file("painted.mtl"));
  QVERIFY(mtl.open(QIODevice::ReadOnly | QIODevice::Text));
  const QByteArray material = mtl.readAll();
  for (const char* map : {"map_Kd painted_diffuse.png", "map_Ks painted_specular.png",
                          "map_refl painted_reflectivity.png"})
    QVERIFY2(material.contains(map), material.constData());
}

void CliExportTest::texturedObjAtALevel() {
  const QString mesh = file("level4.obj");
  RUN_JSON(exported, "export", document_, "-o", mesh, "--lod", "4", "--json");
  QCOMPARE(exported["lod"].toInt(), 4);
  QCOMPARE(exported["vertices"].toDouble(), 18.0);
  QCOMPARE(exported["triangles"].toDouble(), 32.0);
  QCOMPARE(exported["file_vertices"].toDouble(), 18.0);
  QCOMPARE(exported["files"].toArray().size(), 6);
  QVERIFY(QFileInfo::exists(file("level4_diffuse.png")));
  // The maps keep the document's resolution: 17×17 whatever the level.
  const QByteArray png = [&] {
    QFile f(file("level4_diffuse.png"));
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
  }();
  QVERIFY(png.size() > 24);
  QCOMPARE(qFromBigEndian<quint32>(png.constData() + 16), 17u); // IHDR width
  QCOMPARE(qFromBigEndian<quint32>(png.constData() + 20), 17u); // IHDR height
}

void CliExportTest::glb() {
  const QString mesh = file("painted.glb");
  RUN_JSON(exported, "export", document_, "-o", mesh, "--json");
  QCOMPARE(exported["vertices"].toDouble(), 258.0);
  QCOMPARE(exported["triangles"].toDouble(), 512.0);
  QCOMPARE(exported["file_vertices"].toDouble(), 289.0);
  const QJsonArray files = exported["files"].toArray();
  QCOMPARE(files.size(), 1);
  QCOMPARE(files[0].toString(), mesh);

  QFile f(mesh);
  QVERIFY(f.open(QIODevice::ReadOnly));
  const QByteArray bytes = f.readAll();
  QVERIFY(bytes.size() > 12);
  QVERIFY(bytes.startsWith("glTF"));
  QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 4), 2u); // version
  QCOMPARE(qFromLittleEndian<quint32>(bytes.constData() + 8), quint32(bytes.size()));
  // Textures are embedded in the binary chunk, not written beside it.
  QVERIFY(bytes.contains("\"image/png\""));
  QVERIFY(!bytes.contains("\"uri\""));
  QVERIFY(bytes.contains("baseColorTexture"));
  QVERIFY(bytes.contains("metallicRoughnessTexture"));
}

void CliExportTest::humanOutputNamesTheFiles() {
  const QString mesh = file("human.obj");
  const QStringList args{"export", document_, "-o", mesh};
  const Result r = runCli(args);
  QVERIFY2(r.exitCode == kOk, qPrintable(describe(args, r)));
  for (const char* name : {"human.obj", "human.mtl", "human_diffuse.png", "human_specular.png",
                           "human_reflectivity.png"})
    QVERIFY2(r.out.contains(name), qPrintable(describe(args, r)));
}

void CliExportTest::badExtensionIsAUsageError() {
  for (const char* name : {"mesh.gltf", "mesh.fbx", "mesh"}) {
    const QString mesh = file(name);
    EXPECT_FAILURE(kUsage, mesh, "export", document_, "-o", mesh);
    const Result r = runCli({"export", document_, "-o", mesh});
    QVERIFY2(r.err.contains(".glb") && r.err.contains(".obj"), r.err.constData());
  }
  // Checked before the document is read: a missing document is still a usage error here.
  EXPECT_FAILURE(kUsage, file("x.gltf"), "export", file("missing.exr"), "-o", file("x.gltf"));
  EXPECT_FAILURE(kUsage, file("bad-lod.glb"), "export", document_, "-o", file("bad-lod.glb"),
                 "--lod", "32");
}

void CliExportTest::unwritablePlaceIsAnIoError() {
  const QString missingDir = file("no-such-dir");
  EXPECT_FAILURE(kIo, missingDir, "export", document_, "-o", missingDir + "/mesh.obj");
  EXPECT_FAILURE(kIo, missingDir, "export", document_, "-o", missingDir + "/mesh.glb");
  // An OBJ path that is a folder: the maps written before it are taken back.
  QVERIFY(QDir(dir_.path()).mkdir("folder.obj"));
  EXPECT_FAILURE(kIo, "", "export", document_, "-o", file("folder.obj"));
  QVERIFY(!QFileInfo::exists(file("folder_diffuse.png")));
  QVERIFY(!QFileInfo::exists(file("folder.mtl")));
  EXPECT_FAILURE(kIo, file("missing.glb"), "export", file("missing.exr"), "-o",
                 file("missing.glb"));
}

QTEST_APPLESS_MAIN(CliExportTest)
#include "cli_export_test.moc"
