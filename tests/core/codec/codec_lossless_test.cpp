// `lossless`: bit-exact for any floats (seamed or not, NaN, infinities, −0, denormals, half
// values), seams as copies, and at most 0.6× EXR ZIP's size on a smooth model.

#include "codec_test_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/seaming.h"

#include <QtTest>

#include <limits>
#include <random>

using namespace octaclay::core;
using namespace octaclay::core::testing;

namespace {

const Codec& lossless() {
  return *findCodec("lossless");
}

FloatImage fromGeometry(const GeometryImage& g) {
  FloatImage image{g.size(), 3, {}};
  for (const Vec4f& t : g.texels())
    image.texels.insert(image.texels.end(), {t.x, t.y, t.z});
  return image;
}

} // namespace

class CodecLosslessTest : public QObject {
  Q_OBJECT

private slots:
  void seamedImagesAreBitExact() {
    for (int channels : {1, 3, 4}) {
      const FloatImage image = bumpyImage(32, channels);
      const auto stream = lossless().encode(image, {});
      QVERIFY(stream.size() <= lossless().maxEncodedSize(32, channels, {}));
      QVERIFY(bitEqual(lossless().decode(stream, 32, channels), image));
    }
  }

  void unseamedAndSpecialFloatsAreBitExact() {
    FloatImage image = bumpyImage(16, 4);
    std::mt19937 random(7);
    for (float& v : image.texels)
      if (random() % 3 == 0) v = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
    const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity(),
                              -0.0f,
                              0.0f,
                              std::numeric_limits<float>::denorm_min(),
                              -1e-40f,
                              std::numeric_limits<float>::max()};
    for (std::size_t k = 0; k < std::size(specials); ++k)
      image.texels[k * 5] = specials[k];
    image.texels[0] = std::bit_cast<float>(0x7fc12345u); // NaN with a payload
    const auto stream = lossless().encode(image, {});
    QVERIFY(stream.size() <= lossless().maxEncodedSize(16, 4, {}));
    QVERIFY(bitEqual(lossless().decode(stream, 16, 4), image));
  }

  void halfValuedLayersCostFewerBits() {
    // Painted layers hold half floats: their 13 zero low bits must not be paid for.
    FloatImage full = bumpyImage(64, 4);
    FloatImage halves = full;
    for (float& v : halves.texels)
      v = std::bit_cast<float>(std::bit_cast<std::uint32_t>(v) & 0xffffe000u);
    const auto fullStream = lossless().encode(full, {});
    const auto halfStream = lossless().encode(halves, {});
    QVERIFY(bitEqual(lossless().decode(halfStream, 64, 4), halves));
    QVERIFY2(halfStream.size() * 2 < fullStream.size(),
             qPrintable(QString("%1 vs %2 bytes").arg(halfStream.size()).arg(fullStream.size())));
  }

  void identifiedSamplesAreNotStoredTwice() {
    // Breaking one seam forces every sample to be coded: the stream grows.
    const FloatImage seamed = bumpyImage(32);
    FloatImage broken = seamed;
    broken.texels[(0 * 33 + 31) * 3] += 0.25f; // (31, 0) is a copy of (1, 0)
    const auto a = lossless().encode(seamed, {});
    const auto b = lossless().encode(broken, {});
    QVERIFY(bitEqual(lossless().decode(b, 32, 3), broken));
    QVERIFY2(a.size() < b.size(), qPrintable(QString("%1 vs %2").arg(a.size()).arg(b.size())));
    QCOMPARE(maxSeamGap(asGeometry(lossless().decode(a, 32, 3))), 0.0f);
  }

  void beatsExrZipByFortyPercent() {
    const FloatImage image = fromGeometry(makeBaseShape(BaseShape::Blob, 128));
    const auto ours = lossless().encode(image, {});
    const auto exr = findCodec("exr")->encode(image, {0, "zip"});
    QVERIFY(bitEqual(lossless().decode(ours, 128, 3), image));
    const double ratio = double(ours.size()) / double(exr.size());
    qInfo("lossless %zu bytes, exr zip %zu bytes: %.3f", ours.size(), exr.size(), ratio);
    QVERIFY2(ratio <= 0.6, qPrintable(QString::number(ratio)));
  }
};

QTEST_GUILESS_MAIN(CodecLosslessTest)
#include "codec_lossless_test.moc"
