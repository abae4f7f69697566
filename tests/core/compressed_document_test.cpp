// The .ocz container: round trips of every layer kind, lossy positions within their codec's
// bound with exact seams, and every way a file can be wrong (magic, version, N, checksum,
// truncation, unknown codec, missing file).

#include "codec_test_support.h"
#include "octaclay/core/base_shapes.h"
#include "octaclay/core/compressed_document.h"
#include "octaclay/core/seaming.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>
#include <zlib.h>

using namespace octaclay::core;
using namespace octaclay::core::testing;

namespace {

// A blob with saliency set, painted diffuse and mask (half-like values), uniform feature.
Document paintedDocument(int n) {
  Document doc = makeDocument(makeBaseShape(BaseShape::Blob, n));
  for (Vec4f& t : doc.positions.texels())
    t.w = 0.5f;
  const std::size_t count = doc.positions.texelCount();
  doc.diffuse.texels.resize(count * 4);
  doc.mask.texels.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    for (int c = 0; c < 4; ++c)
      doc.diffuse.texels[k * 4 + c] = float((k * 7 + c * 31) % 97) / 96.0f;
    doc.mask.texels[k] = (k % 11) < 5 ? 1.0f : 0.25f;
  }
  doc.feature.fill = {0.125f, 0.5f, 0.75f, 0.0f};
  doc.hasMask = true;
  return doc;
}

std::vector<float> positionsOf(const Document& doc) {
  std::vector<float> xyz;
  for (const Vec4f& t : doc.positions.texels())
    xyz.insert(xyz.end(), {t.x, t.y, t.z});
  return xyz;
}

void resealCrc(std::vector<std::uint8_t>& bytes) {
  const std::size_t body = bytes.size() - 4;
  const auto crc = static_cast<std::uint32_t>(
      crc32(crc32(0L, Z_NULL, 0), bytes.data(), static_cast<uInt>(body)));
  for (int k = 0; k < 4; ++k)
    bytes[body + k] = std::uint8_t(crc >> (8 * k));
}

QString refusedWith(std::span<const std::uint8_t> bytes) {
  try {
    decompressDocument(bytes);
  } catch (const Error& e) {
    return e.kind() == ErrorKind::InvalidInput ? QString::fromUtf8(e.what())
                                               : QString("wrong kind: ") + e.what();
  }
  return "accepted";
}

} // namespace

class CompressedDocumentTest : public QObject {
  Q_OBJECT

private slots:
  void losslessRoundTripKeepsEveryLayer() {
    const Document doc = paintedDocument(32);
    const auto bytes = compressDocument(doc, {"lossless", {}, "lossless"});
    const Document back = decompressDocument(bytes);
    QCOMPARE(back.size(), 32);
    QVERIFY(positionsOf(back) == positionsOf(doc));
    for (const Vec4f& t : back.positions.texels())
      QCOMPARE(t.w, 0.0f); // saliency is derived: not stored, zero until recomputed
    QVERIFY(back.diffuse.texels == doc.diffuse.texels);
    QVERIFY(back.feature.uniform());
    QVERIFY(back.feature.fill == doc.feature.fill);
    QVERIFY(back.hasMask);
    QVERIFY(back.mask.texels == doc.mask.texels);
  }

  void absentMaskAndUniformLayersStayThat() {
    Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, 16));
    doc.diffuse.fill = {0.1f, 0.2f, 0.3f, 1.0f};
    const auto bytes = compressDocument(doc, {"lossless", {}, "lossless"});
    const auto positionsOnly = findCodec("lossless")->encode({16, 3, positionsOf(doc)}, {}).size();
    QVERIFY2(bytes.size() < positionsOnly + 100,
             qPrintable(QString("%1 vs %2").arg(bytes.size()).arg(positionsOnly)));
    const Document back = decompressDocument(bytes);
    QVERIFY(!back.hasMask);
    QVERIFY(back.diffuse.uniform() && back.feature.uniform() && back.mask.uniform());
    QVERIFY(back.diffuse.fill == doc.diffuse.fill);
  }

  void lossyPositionsStayWithinTheirBoundAndSeamed() {
    const Document doc = paintedDocument(64);
    const FloatImage original{64, 3, positionsOf(doc)};
    for (const auto& [codec, params] :
         {std::pair{"bytepack", CodecParams{8, ""}}, std::pair{"dct", CodecParams{40, ""}},
          std::pair{"exr", CodecParams{0, "half"}}, std::pair{"bytepack", CodecParams{}}}) {
      const Document back = decompressDocument(compressDocument(doc, {codec, params, "lossless"}));
      const FloatImage decoded{64, 3, positionsOf(back)};
      QVERIFY(maxAbsError(decoded, original) <= findCodec(codec)->errorBound(original, params));
      QCOMPARE(maxSeamGap(back.positions), 0.0f);
      QVERIFY(back.diffuse.texels == doc.diffuse.texels);
    }
    // Layers may use another codec too.
    const Document exrLayers = decompressDocument(compressDocument(doc, {"lossless", {}, "exr"}));
    QVERIFY(exrLayers.mask.texels == doc.mask.texels);
  }

  void defaultOptionsUseTheWaveletCodecSeamed() {
    const Document doc = paintedDocument(64);
    const auto bytes = compressDocument(doc, {});
    QCOMPARE(int(bytes[13]),
             int(findCodec("wavelet")->info.code)); // positions: storage, channels, code
    const Document back = decompressDocument(bytes);
    QCOMPARE(maxSeamGap(back.positions), 0.0f);
    const FloatImage original{64, 3, positionsOf(doc)};
    QVERIFY(maxAbsError({64, 3, positionsOf(back)}, original) < 0.01); // the blob spans ~2.3
    QVERIFY(back.diffuse.texels == doc.diffuse.texels);
  }

  void unknownCodecIsRefused() {
    const Document doc = paintedDocument(8);
    for (const CompressOptions& options :
         {CompressOptions{"jpeg2000", {}, "lossless"}, CompressOptions{"lossless", {}, "png"}}) {
      try {
        compressDocument(doc, options);
        QFAIL("accepted an unknown codec");
      } catch (const Error& e) {
        QCOMPARE(int(e.kind()), int(ErrorKind::InvalidArgument));
        QVERIFY2(std::string(e.what()).find("lossless") != std::string::npos, e.what());
      }
    }
  }

  void wrongMagicVersionAndSizeAreRefused() {
    const auto good = compressDocument(paintedDocument(8), {"lossless", {}, "lossless"});
    auto magic = good;
    magic[0] = 'P';
    QVERIFY2(refusedWith(magic).contains("magic"), qPrintable(refusedWith(magic)));
    auto version = good;
    version[4] = 2;
    QVERIFY2(refusedWith(version).contains("version 2"), qPrintable(refusedWith(version)));
    for (int n : {12, 0, 1}) {
      auto size = good;
      size[6] = std::uint8_t(n);
      resealCrc(size);
      QVERIFY2(refusedWith(size).contains(QString("N = %1").arg(n)), qPrintable(refusedWith(size)));
    }
    auto other = good; // a consistent file for N = 16 whose streams say N = 8
    other[6] = 16;
    resealCrc(other);
    QVERIFY2(refusedWith(other).contains("N = 8"), qPrintable(refusedWith(other)));
  }

  void everyTruncationAndFlipIsRefused() {
    const auto good = compressDocument(paintedDocument(8), {"dct", {}, "lossless"});
    for (std::size_t length = 0; length < good.size(); ++length) {
      const QString why = refusedWith(std::span(good).first(length));
      QVERIFY2(!why.startsWith("accepted") && !why.startsWith("wrong"),
               qPrintable(QString("%1 bytes: %2").arg(length).arg(why)));
    }
    auto damaged = good;
    for (std::size_t at = 0; at < good.size(); ++at) {
      damaged[at] ^= std::uint8_t(1u << (at % 8));
      const QString why = refusedWith(damaged);
      QVERIFY2(!why.startsWith("accepted") && !why.startsWith("wrong"),
               qPrintable(QString("flip at %1: %2").arg(at).arg(why)));
      damaged[at] = good[at];
    }
    QVERIFY(refusedWith(damaged) == "accepted");
  }

  void filesAreWrittenAndReadBack() {
    QTemporaryDir dir;
    const std::filesystem::path path = dir.filePath("model.ocz").toStdString();
    const Document doc = paintedDocument(16);
    writeCompressedDocument(doc, {"lossless", {}, "lossless"}, path);
    QVERIFY(positionsOf(readCompressedDocument(path)) == positionsOf(doc));
    QCOMPARE(std::distance(std::filesystem::directory_iterator(dir.path().toStdString()),
                           std::filesystem::directory_iterator()),
             1); // no temporary left beside it

    const auto kindOf = [](const std::filesystem::path& p) {
      try {
        readCompressedDocument(p);
      } catch (const Error& e) {
        return int(e.kind());
      }
      return -1;
    };
    QCOMPARE(kindOf(dir.filePath("missing.ocz").toStdString()), int(ErrorKind::Io));
    QCOMPARE(kindOf(dir.path().toStdString()), int(ErrorKind::Io));
    std::ofstream(dir.filePath("text.ocz").toStdString()) << "not a model";
    QCOMPARE(kindOf(dir.filePath("text.ocz").toStdString()), int(ErrorKind::InvalidInput));
    QVERIFY_THROWS_EXCEPTION(
        Error, writeCompressedDocument(doc, {"lossless", {}, "lossless"},
                                       dir.filePath("no/such/dir/x.ocz").toStdString()));
  }
};

QTEST_GUILESS_MAIN(CompressedDocumentTest)
#include "compressed_document_test.moc"
