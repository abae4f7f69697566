// `exr`: ZIP and PIZ round trips are bit-exact, also for unseamed images; the stream is a
// plain OpenEXR file after the codec header; a stream of one mode is not read as another.

#include "codec_test_support.h"

#include <QtTest>

#include <random>

using namespace octaclay::core;
using namespace octaclay::core::testing;

class CodecExrTest : public QObject {
  Q_OBJECT

private slots:
  void losslessModesAreBitExact() {
    const Codec& exr = *findCodec("exr");
    for (const char* mode : {"zip", "piz", ""})
      for (int channels : {1, 3, 4}) {
        FloatImage image = bumpyImage(32, channels);
        std::mt19937 random(3);
        for (float& v : image.texels)
          if (random() % 4 == 0) v = std::bit_cast<float>(static_cast<std::uint32_t>(random()));
        const auto stream = exr.encode(image, {0, mode});
        QVERIFY(bitEqual(exr.decode(stream, 32, channels), image));
        QVERIFY(exr.errorBound(image, {0, mode}) == 0);
      }
  }

  void streamHoldsAnOpenExrFile() {
    const auto stream = findCodec("exr")->encode(bumpyImage(8), {0, "zip"});
    // codec header (8 bytes), mode byte, then OpenEXR's magic number 76 2f 31 01.
    QCOMPARE(int(stream[9]), 0x76);
    QCOMPARE(int(stream[10]), 0x2f);
    QCOMPARE(int(stream[11]), 0x31);
    QCOMPARE(int(stream[12]), 0x01);
  }

  void modeByteMustMatchTheFile() {
    auto stream = findCodec("exr")->encode(bumpyImage(8), {0, "zip"});
    stream[8] = 1; // claims PIZ
    QVERIFY_THROWS_EXCEPTION(Error, findCodec("exr")->decode(stream, 8, 3));
    stream[8] = 9;
    QVERIFY_THROWS_EXCEPTION(Error, findCodec("exr")->decode(stream, 8, 3));
  }
};

QTEST_GUILESS_MAIN(CodecExrTest)
#include "codec_exr_test.moc"
