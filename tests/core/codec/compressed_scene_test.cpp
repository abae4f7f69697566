// The .ocz container of a scene (version 2): three objects (a ball, a torus of W ≠ H, a plane)
// round-trip exactly with an exact codec, metadata bit-exact; lossy positions within the codec's
// stated bound; a lossy codec refused for a torus by name; today's one-document files (version 1,
// written by compressDocument) read as one object; and the files that lie: an object count of
// 10^6, sizes against the object's document, an unknown topology, a NaN transform, a flag of 7,
// a repeated name, lengths that disagree, a checksum.

#include "../../file_test_support.h"
#include "codec_test_support.h"

#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/codec/wavelet_codec.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <QTemporaryDir>
#include <QtTest>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>

using namespace octaclay::core;
using namespace octaclay::core::testing;
using octaclay::testing::resealCrc;

namespace {

void paint(Document& doc, int seed) {
  const std::size_t count = doc.positions.texelCount();
  doc.diffuse.texels.resize(count * 4);
  for (std::size_t k = 0; k < count; ++k)
    for (int c = 0; c < 4; ++c)
      doc.diffuse.texels[k * 4 + c] = float((k * 7 + c * 31 + seed) % 97) / 96.0f;
}

// A painted ball with a mask, a painted 32 × 8 torus, hidden, and a locked disc sheet, each
// somewhere else, with transforms whose floats are not short decimals.
Scene threeObjects() {
  Scene scene;
  Document ball = makeDocument(makeBaseShape(BaseShape::Blob, 16));
  paint(ball, 1);
  ball.hasMask = true;
  ball.mask.fill = {0.25f, 0, 0, 0};
  scene.objects.push_back({"Body",
                           std::move(ball),
                           {{0.1f, -1.0f / 3, 1e-7f}, {12.5f, -0.001f, 359.9f}, {1, 1, 1}},
                           true,
                           false});
  Document ring = makeDocument(makeTorus(Torus{0.8f, 0.2f}, 32, 8));
  paint(ring, 2);
  scene.objects.push_back(
      {"Ring", std::move(ring), {{0, 1, 0}, {90, 0, -45}, {0.5f, 2.0f, 1.0f / 7}}, false, false});
  scene.objects.push_back({"Ground \xc3\xa4",
                           makeDocument(makeSheet(Sheet::Disc, 16)),
                           {{0, 0, -2}, {}, {-1.5f, 1.5f, 0.25f}},
                           true,
                           true});
  return scene;
}

bool sameBits(const void* a, const void* b, std::size_t bytes) {
  return std::memcmp(a, b, bytes) == 0;
}

void requireSameMetadata(const Scene& a, const Scene& b) {
  QCOMPARE(b.objects.size(), a.objects.size());
  for (std::size_t k = 0; k < a.objects.size(); ++k) {
    const SceneObject& x = a.objects[k];
    const SceneObject& y = b.objects[k];
    QCOMPARE(y.name, x.name);
    QVERIFY2(sameBits(&x.transform, &y.transform, sizeof x.transform), x.name.c_str());
    QCOMPARE(y.visible, x.visible);
    QCOMPARE(y.locked, x.locked);
    QCOMPARE(y.document.topology, x.document.topology);
    QCOMPARE(y.document.positions.topology(), x.document.positions.topology());
    QCOMPARE(y.document.positions.width(), x.document.positions.width());
    QCOMPARE(y.document.positions.height(), x.document.positions.height());
    QCOMPARE(y.document.hasMask, x.document.hasMask);
  }
}

std::vector<float> positionsOf(const Document& doc) {
  std::vector<float> xyz;
  for (const Vec4f& t : doc.positions.texels())
    xyz.insert(xyz.end(), {t.x, t.y, t.z});
  return xyz;
}

// Where object k's entry starts in a version-2 file (after magic, version and count).
std::size_t entryAt(const std::vector<std::uint8_t>& bytes, std::size_t k) {
  std::size_t at = 4 + 2 + 4;
  for (std::size_t i = 0; i < k; ++i)
    at += 1 + bytes[at] + 1 + 4 + 4 + 36 + 1 + 1 + 8;
  return at;
}

void putU32(std::vector<std::uint8_t>& bytes, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k)
    bytes[at + k] = std::uint8_t(v >> (8 * k));
}

double rmsDisplacement(const FloatImage& a, const FloatImage& b) {
  double sum = 0;
  for (std::size_t k = 0; k < a.texels.size(); ++k)
    sum += double(a.texels[k] - b.texels[k]) * double(a.texels[k] - b.texels[k]);
  return std::sqrt(sum / double(a.texels.size() / 3));
}

// The codec's stated largest error: its errorBound, or for wavelet (which states none there) its
// quality, a fraction of the bounding box's diagonal.
double boundOf(const std::string& codec, const FloatImage& image, const CodecParams& params) {
  if (const auto& bound = findCodec(codec)->errorBound) return bound(image, params);
  std::array<float, 3> lo{}, hi{};
  lo.fill(std::numeric_limits<float>::max());
  hi.fill(-std::numeric_limits<float>::max());
  for (std::size_t k = 0; k < image.texels.size(); ++k) {
    lo[k % 3] = std::min(lo[k % 3], image.texels[k]);
    hi[k % 3] = std::max(hi[k % 3], image.texels[k]);
  }
  const double diagonal = std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
  return (params.quality > 0 ? params.quality : kWaveletDefaultBound) * diagonal;
}

QString errorOf(const std::function<void()>& call, ErrorKind& kind) {
  try {
    call();
  } catch (const Error& e) {
    kind = e.kind();
    return QString::fromUtf8(e.what());
  } catch (const std::exception& e) {
    return QString("a non-core exception: ") + e.what();
  }
  return "no error";
}

} // namespace

class CompressedSceneTest : public QObject {
  Q_OBJECT
private slots:
  void threeObjectsRoundTripExactly() {
    const Scene scene = threeObjects();
    for (const CompressOptions& options :
         {CompressOptions{"lossless", {}, "lossless"}, CompressOptions{"exr", {0, "piz"}, "exr"}}) {
      const std::vector<std::uint8_t> bytes = compressScene(scene, options);
      const Scene back = decompressScene(bytes);
      requireSameMetadata(scene, back);
      for (std::size_t k = 0; k < scene.objects.size(); ++k) {
        const Document& a = scene.objects[k].document;
        const Document& b = back.objects[k].document;
        QVERIFY2(positionsOf(a) == positionsOf(b), scene.objects[k].name.c_str());
        QCOMPARE(b.diffuse.uniform(), a.diffuse.uniform());
        QVERIFY(b.diffuse.texels == a.diffuse.texels);
        QVERIFY(b.mask.fill == a.mask.fill);
      }
      // A torus stays periodic: its last column and row are its first, bit for bit.
      const GeometryImage& ring = back.objects[1].document.positions;
      for (int j = 0; j <= ring.height(); ++j)
        QVERIFY(sameBits(&ring.at(0, j), &ring.at(ring.width(), j), 12));
    }
  }

  void lossyPositionsWithinTheStatedBound() {
    Scene scene;
    for (const auto& [name, shape, n] :
         {std::tuple{"A", BaseShape::Blob, 32}, std::tuple{"B", BaseShape::Cube, 16},
          std::tuple{"C", BaseShape::Sphere, 64}}) {
      Document doc = makeDocument(makeBaseShape(shape, n));
      paint(doc, n);
      scene.objects.push_back(
          {name, std::move(doc), {{float(n), 0, 0}, {0, 30, 0}, {1, 2, 3}}, n != 16, n == 32});
    }
    for (const auto& [codec, params] :
         {std::pair{"wavelet", CodecParams{}}, std::pair{"dct", CodecParams{40, ""}},
          std::pair{"bytepack", CodecParams{8, ""}}}) {
      const Scene back = decompressScene(compressScene(scene, {codec, params, "lossless"}));
      requireSameMetadata(scene, back);
      for (std::size_t k = 0; k < scene.objects.size(); ++k) {
        const Document& a = scene.objects[k].document;
        const FloatImage original{a.size(), 3, positionsOf(a)};
        const FloatImage decoded{a.size(), 3, positionsOf(back.objects[k].document)};
        // The codec's stated error: its errorBound on every coordinate, or wavelet's RMS bound
        // (its quality times the diagonal across the surface, kWaveletTangentFactor times that
        // along it) on the samples' displacements.
        const double bound = boundOf(codec, original, params);
        const double error = codec == std::string("wavelet") ? rmsDisplacement(decoded, original)
                                                             : maxAbsError(decoded, original);
        const double limit = codec == std::string("wavelet")
                                 ? bound * std::hypot(1.0, kWaveletTangentFactor)
                                 : bound;
        QVERIFY2(
            error <= limit,
            qPrintable(QString("%1, object %2: %3 > %4").arg(codec).arg(k).arg(error).arg(limit)));
        QVERIFY(maxAbsError(decoded, original) > 0); // lossy indeed: the check can fail
        QVERIFY(back.objects[k].document.diffuse.texels == a.diffuse.texels);
      }
    }
  }

  // A lossy codec codes the torus and the disc too (each one sample in on a square twice its
  // longer side, off the ball's seamed border): sizes and placement kept, the torus's wrap and
  // the disc's outline exact in the sense of their topology (column W is column 0, row H row 0,
  // bit for bit), every sample within the codec's error of where it was, the layers within the
  // layer codec's. An image whose doubled square passes the largest N is refused by name.
  void lossyCodecsCodeATorusAndADisc() {
    const Scene scene = threeObjects();
    for (const CompressOptions& options :
         {CompressOptions{"wavelet", {}, "lossless"},
          CompressOptions{"exr", {0, "half"}, "lossless"}, CompressOptions{"dct", {}, "dct"}}) {
      const Scene back = decompressScene(compressScene(scene, options));
      QCOMPARE(back.objects.size(), scene.objects.size());
      for (std::size_t k = 1; k < 3; ++k) {
        const GeometryImage& a = scene.objects[k].document.positions;
        const GeometryImage& b = back.objects[k].document.positions;
        QCOMPARE(b.topology(), a.topology());
        QCOMPARE(b.width(), a.width());
        QCOMPARE(b.height(), a.height());
        QCOMPARE(back.objects[k].name, scene.objects[k].name);
        double error = 0;
        for (int j = 0; j <= a.height(); ++j)
          for (int i = 0; i <= a.width(); ++i)
            error = std::max(error, double(length(a.at(i, j).xyz() - b.at(i, j).xyz())));
        QVERIFY2(error > 0 && error < 0.02,
                 qPrintable(QString("%1, object %2: %3")
                                .arg(QString::fromStdString(options.codec))
                                .arg(k)
                                .arg(error)));
        if (a.topology() == Topology::Torus) {
          for (int j = 0; j <= a.height(); ++j)
            QVERIFY(sameBits(&b.at(a.width(), j), &b.at(0, j), sizeof(Vec4f)));
          for (int i = 0; i <= a.width(); ++i)
            QVERIFY(sameBits(&b.at(i, a.height()), &b.at(i, 0), sizeof(Vec4f)));
        }
        const Layer& paint = back.objects[k].document.diffuse;
        if (!scene.objects[k].document.diffuse.uniform())
          QCOMPARE(paint.texels.size(), scene.objects[k].document.diffuse.texels.size());
      }
    }
    Scene wide;
    wide.objects.push_back(
        {"Hoop", makeDocument(makeTorus(Torus{0.8f, 0.01f}, 8192, 4)), {}, true, false});
    ErrorKind kind = ErrorKind::Io;
    const QString message = errorOf(
        [&] {
          compressScene(wide, {"wavelet", {}, "lossless"});
        },
        kind);
    QCOMPARE(kind, ErrorKind::InvalidArgument);
    QVERIFY2(message.contains("object 'Hoop'") && message.contains("use an exact codec"),
             qPrintable(message));
    QCOMPARE(decompressScene(compressScene(wide, {"lossless", {}, "lossless"}))
                 .objects[0]
                 .document.positions.width(),
             8192);
  }

  void todaysOneDocumentFileIsOneObject() {
    // Written by today's (version 1) writer, compressDocument.
    Document doc = makeDocument(makeBaseShape(BaseShape::Cube, 16));
    paint(doc, 3);
    const std::vector<std::uint8_t> v1 = compressDocument(doc, {"lossless", {}, "lossless"});
    QCOMPARE(int(v1[4] | v1[5] << 8), 1);
    const Scene scene = decompressScene(v1);
    QCOMPARE(scene.objects.size(), std::size_t{1});
    QCOMPARE(scene.objects[0].name, std::string("Model"));
    QVERIFY(scene.objects[0].transform == ObjectTransform{});
    QVERIFY(scene.objects[0].visible && !scene.objects[0].locked);
    QVERIFY(positionsOf(scene.objects[0].document) == positionsOf(doc));
    QVERIFY(scene.objects[0].document.diffuse.texels == doc.diffuse.texels);
    // From a file: named by its stem.
    QTemporaryDir dir;
    const std::filesystem::path path = dir.filePath("snowman.ocz").toStdString();
    writeCompressedDocument(doc, {"lossless", {}, "lossless"}, path);
    QCOMPARE(readCompressedScene(path).objects[0].name, std::string("snowman"));
    // And a scene file through the same door.
    writeCompressedScene(threeObjects(), {"lossless", {}, "lossless"}, path);
    QCOMPARE(readCompressedScene(path).objects.size(), std::size_t{3});
  }

  void lyingFiles_data() {
    QTest::addColumn<int>("lie");
    QTest::addColumn<QString>("needle");
    QTest::newRow("a million objects") << 0 << "declares 1000000 objects";
    QTest::newRow("no objects") << 1 << "declares 0 objects";
    QTest::newRow("width against its document")
        << 2 << "its document is N = 32 but its header says 16 x 8";
    QTest::newRow("width not a grid") << 3 << "is not a valid torus image";
    QTest::newRow("unknown topology") << 4 << "unknown topology code 7";
    QTest::newRow("NaN translation") << 5 << "not a finite number";
    QTest::newRow("visible 7") << 6 << "(0 or 1 expected)";
    QTest::newRow("repeated name") << 7 << "named 'Body' too";
    QTest::newRow("length beyond the file") << 8 << "longer than the file";
    QTest::newRow("lengths short of the file") << 9 << "the objects hold";
    QTest::newRow("checksum") << 10 << "checksum mismatch";
    QTest::newRow("version 3") << 11 << "format version 3";
  }

  void lyingFiles() {
    QFETCH(int, lie);
    QFETCH(QString, needle);
    std::vector<std::uint8_t> bytes = compressScene(threeObjects(), {"lossless", {}, "lossless"});
    const std::size_t body = entryAt(bytes, 0), ring = entryAt(bytes, 1);
    const std::size_t ringSizes = ring + 1 + bytes[ring] + 1; // width, height
    const std::size_t bodyTransform = body + 1 + bytes[body] + 1 + 8;
    bool reseal = true;
    switch (lie) {
    case 0:
      putU32(bytes, 6, 1000000);
      break;
    case 1:
      putU32(bytes, 6, 0);
      break;
    case 2:
      putU32(bytes, ringSizes, 16); // 16 × 8: a valid torus, but the document is 32 wide
      break;
    case 3:
      putU32(bytes, ringSizes, 33);
      break;
    case 4:
      bytes[ringSizes - 1] = 7;
      break;
    case 5: {
      const float nan = std::numeric_limits<float>::quiet_NaN();
      std::memcpy(&bytes[bodyTransform + 4], &nan, 4);
      break;
    }
    case 6:
      bytes[bodyTransform + 36] = 7;
      break;
    case 7:
      std::memcpy(&bytes[ring + 1], "Body", 4); // "Ring" → "Body"
      break;
    case 8:
      bytes[bodyTransform + 38 + 7] = 0x40; // object 1's length: 2^62
      break;
    case 9:
      bytes[bodyTransform + 38] -= 1;
      break;
    case 10:
      bytes[bodyTransform] ^= 1;
      reseal = false;
      break;
    case 11:
      bytes[4] = 3;
      break;
    }
    if (reseal) resealCrc(bytes);
    ErrorKind kind = ErrorKind::Io;
    const QString message = errorOf([&] { decompressScene(bytes); }, kind);
    QCOMPARE(kind, ErrorKind::InvalidInput);
    QVERIFY2(message.contains(needle), qPrintable(message));
  }

  void everyTruncationRefused() {
    const std::vector<std::uint8_t> bytes =
        compressScene(threeObjects(), {"lossless", {}, "lossless"});
    for (std::size_t length = 0; length < bytes.size(); length += 1 + length / 16) {
      ErrorKind kind = ErrorKind::Io;
      const QString message =
          errorOf([&] { decompressScene(std::span(bytes.data(), length)); }, kind);
      QVERIFY2(kind == ErrorKind::InvalidInput,
               qPrintable(QString::number(length) + ": " + message));
    }
  }
};

QTEST_APPLESS_MAIN(CompressedSceneTest)
#include "compressed_scene_test.moc"
