// octaclay-cli compress / decompress of a scene (issue 33): three objects (a painted ball, a
// hidden 32 × 8 torus, a locked disc sheet) round-trip through one .ocz exactly with an exact
// codec, names, transforms, visibility and locks bit-exact; a lossy codec codes balls within the
// error it reports and is refused for a torus by name (exit 2, nothing written); a .ocz of
// today's one-document format decompresses to the plain document it was; a file that claims 10^6
// objects is refused (exit 3, nothing written).

#include "../file_test_support.h"
#include "cli_support.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <QJsonArray>
#include <QTemporaryDir>

#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>

using namespace octaclay;

namespace {

core::Scene threeObjects() {
  core::Scene scene;
  core::Document ball = core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 32));
  ball.diffuse.texels.assign(ball.positions.texelCount() * 4, 0.5f);
  for (std::size_t k = 0; k < ball.diffuse.texels.size(); k += 7)
    ball.diffuse.texels[k] = 0.125f;
  scene.objects.push_back(
      {"Body", std::move(ball), {{0.1f, -1.0f / 3, 0}, {12.5f, 0, 0}, {1, 1, 1}}, true, false});
  scene.objects.push_back({"Ring",
                           core::makeDocument(core::makeTorus(core::Torus{0.8f, 0.2f}, 32, 8)),
                           {{0, 1, 0}, {90, 0, -45}, {0.5f, 2.0f, 1.0f / 7}},
                           false,
                           false});
  scene.objects.push_back({"Ground",
                           core::makeDocument(core::makeSheet(core::Sheet::Disc, 16)),
                           {{0, 0, -2}, {}, {-1.5f, 1.5f, 0.25f}},
                           true,
                           true});
  return scene;
}

// The file's bytes with the value of the occurrence-th attribute called name (its header's, in
// part order) replaced by value (the same length): a scene whose part header lies.
std::string withAttribute(std::string bytes, const std::string& name, int occurrence,
                          const std::string& value) {
  std::size_t at = 0;
  for (int k = 0; k <= occurrence; ++k) {
    at = bytes.find(name + '\0', at == 0 ? 0 : at + 1);
    if (at == std::string::npos) return {};
  }
  at += name.size() + 1;             // past the name
  at = bytes.find('\0', at) + 1 + 4; // past the type name and the size
  bytes.replace(at, value.size(), value);
  return bytes;
}

std::string fileBytes(const QString& path) {
  std::ifstream in(path.toStdString(), std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

std::string floatBytes(std::initializer_list<float> values) {
  std::string bytes;
  for (const float v : values)
    bytes.append(reinterpret_cast<const char*>(&v), 4);
  return bytes;
}

bool sameBits(const core::GeometryImage& a, const core::GeometryImage& b) {
  return a.grid() == b.grid() && a.texelCount() == b.texelCount() &&
         std::memcmp(a.texels().data(), b.texels().data(), a.byteSize()) == 0;
}

} // namespace

class CliCompressSceneTest : public QObject {
  Q_OBJECT

private slots:
  void init() { QVERIFY(dir_.isValid()); }

  void threeObjectsRoundTripExactly() {
    const core::Scene scene = threeObjects();
    core::writeScene(scene, file("scene.exr").toStdString());
    RUN_JSON(c, "compress", file("scene.exr"), "--codec", "lossless", "-o", file("scene.ocz"),
             "--json");
    QVERIFY(c["exact"].toBool());
    QCOMPARE(c["objects"].toArray().size(), 3);
    QCOMPARE(c["objects"].toArray()[1].toObject()["topology"].toString(), QString("torus"));
    QCOMPARE(c["objects"].toArray()[1].toObject()["height"].toInt(), 8);
    RUN_JSON(d, "decompress", file("scene.ocz"), "-o", file("back.exr"), "--json");
    QCOMPARE(d["objects"].toInt(), 3);
    const core::Scene back = core::readScene(file("back.exr").toStdString());
    QCOMPARE(back.objects.size(), scene.objects.size());
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      const core::SceneObject& a = scene.objects[k];
      const core::SceneObject& b = back.objects[k];
      QCOMPARE(b.name, a.name);
      QVERIFY2(std::memcmp(&a.transform, &b.transform, sizeof a.transform) == 0, a.name.c_str());
      QCOMPARE(b.visible, a.visible);
      QCOMPARE(b.locked, a.locked);
      QVERIFY2(sameBits(a.document.positions, b.document.positions), a.name.c_str());
      QVERIFY(b.document.diffuse.texels == a.document.diffuse.texels); // exact in half
    }
  }

  void lossyCodecWithinWhatItReports() {
    core::Scene scene = threeObjects();
    scene.objects.pop_back();
    scene.objects.pop_back();
    scene.objects.push_back({"Head",
                             core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 16)),
                             {{0, 0, 2}, {}, {0.5f, 0.5f, 0.5f}},
                             true,
                             false});
    core::writeScene(scene, file("balls.exr").toStdString());
    RUN_JSON(c, "compress", file("balls.exr"), "--codec", "wavelet", "-o", file("balls.ocz"),
             "--json");
    QVERIFY(!c["exact"].toBool());
    RUN_JSON(d, "decompress", file("balls.ocz"), "-o", file("balls-back.exr"), "--json");
    const core::Scene back = core::readScene(file("balls-back.exr").toStdString());
    for (std::size_t k = 0; k < scene.objects.size(); ++k) {
      const double reported = c["objects"].toArray()[int(k)].toObject()["max_error"].toDouble();
      QVERIFY(reported > 0 && reported < 1e-3); // wavelet's default: 1.5e-5 of the diagonal (RMS)
      const auto& a = scene.objects[k].document.positions.texels();
      const auto& b = back.objects[k].document.positions.texels();
      double error = 0;
      for (std::size_t t = 0; t < a.size(); ++t)
        error = std::max({error, double(std::abs(a[t].x - b[t].x)),
                          double(std::abs(a[t].y - b[t].y)), double(std::abs(a[t].z - b[t].z))});
      QCOMPARE(error, reported);
      QVERIFY(std::memcmp(&scene.objects[k].transform, &back.objects[k].transform,
                          sizeof(core::ObjectTransform)) == 0);
    }
  }

  // A lossy codec codes the scene's torus and disc as well: decompressed, each keeps its
  // topology and size, its wrap or outline exact (info: closed torus, seam gap 0), and lies
  // within the reported error of where it was.
  void lossyCodecCodesATorusAndADisc() {
    core::writeScene(threeObjects(), file("scene.exr").toStdString());
    RUN_JSON(c, "compress", file("scene.exr"), "--codec", "wavelet", "-o", file("lossy.ocz"),
             "--json");
    QVERIFY(!c["exact"].toBool());
    RUN_JSON(d, "decompress", file("lossy.ocz"), "-o", file("lossy.exr"), "--json");
    QCOMPARE(d["objects"].toInt(), 3);
    const core::Scene before = core::readScene(file("scene.exr").toStdString());
    const core::Scene back = core::readScene(file("lossy.exr").toStdString());
    for (std::size_t k = 0; k < 3; ++k) {
      const core::GeometryImage& a = before.objects[k].document.positions;
      const core::GeometryImage& b = back.objects[k].document.positions;
      QCOMPARE(b.topology(), a.topology());
      QCOMPARE(b.width(), a.width());
      QCOMPARE(b.height(), a.height());
      double error = 0;
      for (std::size_t t = 0; t < a.texels().size(); ++t)
        error = std::max(error, double(core::length(a.texels()[t].xyz() - b.texels()[t].xyz())));
      QVERIFY2(error > 0 && error < 1e-2, qPrintable(QString::number(error)));
      const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(b));
      QCOMPARE(topology.euler, a.topology() == core::Topology::Torus   ? 0LL
                               : a.topology() == core::Topology::Plane ? 1LL
                                                                       : 2LL);
    }
  }

  void todaysOneDocumentFileDecompressesAsBefore() {
    const core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 16));
    core::writeCompressedDocument(doc, {"lossless", {}, "lossless"},
                                  file("today.ocz").toStdString()); // version 1
    RUN_JSON(d, "decompress", file("today.ocz"), "-o", file("today.exr"), "--json");
    QCOMPARE(d["n"].toInt(), 16);
    QCOMPARE(d["objects"].toInt(), 1);
    // A plain document, as before scenes: no scene attributes, today's reader opens it.
    const core::Scene back = core::readScene(file("today.exr").toStdString());
    QCOMPARE(back.objects[0].name, std::string("today"));
    QVERIFY(sameBits(core::readDocument(file("today.exr").toStdString()).positions, doc.positions));
    // And a plain document compresses to today's format (version 1) still.
    RUN_JSON(c, "compress", file("today.exr"), "--codec", "lossless", "-o", file("again.ocz"),
             "--json");
    QCOMPARE(c["n"].toInt(), 16);
    QFile again(file("again.ocz"));
    QVERIFY(again.open(QIODevice::ReadOnly));
    QCOMPARE(again.read(6).right(2), QByteArray("\x01\x00", 2));
  }

  void millionObjectsRefused() {
    core::writeScene(threeObjects(), file("scene.exr").toStdString());
    RUN_JSON(c, "compress", file("scene.exr"), "--codec", "lossless", "-o", file("scene.ocz"),
             "--json");
    std::vector<std::uint8_t> bytes;
    {
      std::ifstream in(file("scene.ocz").toStdString(), std::ios::binary);
      bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::uint32_t million = 1000000;
    std::memcpy(&bytes[6], &million, 4);
    testing::resealCrc(bytes);
    {
      std::ofstream out(file("million.ocz").toStdString(), std::ios::binary);
      out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    }
    const Result r = runCli({"decompress", file("million.ocz"), "-o", file("million.exr")});
    QVERIFY2(r.exitCode == kInvalidInput, qPrintable(r.err));
    QVERIFY2(r.err.contains("declares 1000000 objects"), qPrintable(r.err));
    QVERIFY(!QFileInfo::exists(file("million.exr")));
  }

  // A scene file whose part header lies (sizes, an unknown topology, a NaN transform) or whose
  // parts disagree (two objects of one name): every command that reads it exits 3 naming the
  // problem, and writes nothing.
  void lyingSceneFilesExitThree_data() {
    QTest::addColumn<int>("lie");
    QTest::addColumn<QString>("needle");
    QTest::newRow("width") << 0 << "octaclay.width = 99";
    QTest::newRow("unknown topology") << 1 << "unknown topology 'octahedrax'";
    QTest::newRow("NaN translation") << 2 << "not a finite number";
    // (Format versions cannot disagree yet: a part of another version is refused on its own.)
    QTest::newRow("parts disagree: one name twice") << 3 << "both named 'Leg'";
  }

  void lyingSceneFilesExitThree() {
    QFETCH(int, lie);
    QFETCH(QString, needle);
    core::Scene scene = threeObjects();
    scene.objects[1] = {"Leg",
                        core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 16)),
                        {{0, 1, 0}, {}, {1, 1, 1}},
                        true,
                        false};
    scene.objects[2].document = core::makeDocument(core::makeTorus(core::Torus{0.8f, 0.2f}, 32, 8));
    scene.objects[2].name = "Lex";
    core::writeScene(scene, file("good.exr").toStdString());
    const std::string good = fileBytes(file("good.exr"));
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const std::string lying =
        lie == 0   ? withAttribute(good, "octaclay.width", 0, std::string("\x63\0\0\0", 4))
        : lie == 1 ? withAttribute(good, "octaclay.parameterization", 1, "octahedrax")
        : lie == 2 ? withAttribute(good, "octaclay.translation", 2, floatBytes({0, nan, 0}))
                   : withAttribute(good, "octaclay.name", 2, "Leg");
    QVERIFY(!lying.empty() && lying != good);
    std::ofstream(file("lying.exr").toStdString(), std::ios::binary)
        .write(lying.data(), std::streamsize(lying.size()));
    const QString out = file("never.ocz"), exr = file("never.exr");
    for (const QStringList& args :
         {QStringList{"objects", file("lying.exr")}, QStringList{"info", file("lying.exr")},
          QStringList{"compress", file("lying.exr"), "--codec", "lossless", "-o", out},
          QStringList{"transform", file("lying.exr"), "--object", "Body", "--scale", "2", "-o",
                      exr}}) {
      const Result r = runCli(args);
      QVERIFY2(r.exitCode == kInvalidInput && r.err.contains(needle.toUtf8()),
               qPrintable(describe(args, r)));
      QVERIFY(!QFileInfo::exists(out) && !QFileInfo::exists(exr));
    }
  }

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
};

QTEST_APPLESS_MAIN(CliCompressSceneTest)
#include "cli_compress_scene_test.moc"
