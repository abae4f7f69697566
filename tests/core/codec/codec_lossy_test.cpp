// The lossy codecs (bytepack, dct, exr pxr24/half): error within each codec's stated bound,
// identified samples exactly equal after decoding, size falling with quality, bad parameters
// refused.

#include "codec_test_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/seaming.h"

#include <QtTest>

using namespace octaclay::core;
using namespace octaclay::core::testing;

namespace {

FloatImage blob(int n) {
  const GeometryImage g = makeBaseShape(BaseShape::Blob, n);
  FloatImage image{n, 3, {}};
  for (const Vec4f& t : g.texels())
    image.texels.insert(image.texels.end(), {t.x, t.y, t.z});
  return image;
}

struct Case {
  const char* codec;
  CodecParams params;
};

const Case kCases[] = {{"bytepack", {1, ""}},  {"bytepack", {4, ""}}, {"bytepack", {16, ""}},
                       {"bytepack", {64, ""}}, {"dct", {1, ""}},      {"dct", {25, ""}},
                       {"dct", {75, ""}},      {"dct", {100, ""}},    {"exr", {0, "pxr24"}},
                       {"exr", {0, "half"}}};

} // namespace

class CodecLossyTest : public QObject {
  Q_OBJECT

private slots:
  void errorWithinBoundAndSeamsExact_data() {
    QTest::addColumn<int>("index");
    for (int k = 0; k < int(std::size(kCases)); ++k)
      QTest::newRow(qPrintable(QString("%1 %2%3")
                                   .arg(kCases[k].codec)
                                   .arg(kCases[k].params.quality)
                                   .arg(QString::fromStdString(kCases[k].params.mode))))
          << k;
  }

  void errorWithinBoundAndSeamsExact() {
    QFETCH(int, index);
    const Case& c = kCases[index];
    const Codec& codec = *findCodec(c.codec);
    QVERIFY(codec.info.lossy);
    for (const FloatImage& image : {blob(64), bumpyImage(128, 4)}) {
      const auto stream = codec.encode(image, c.params);
      QVERIFY(stream.size() <= codec.maxEncodedSize(image.n, image.channels, c.params));
      const FloatImage decoded = codec.decode(stream, image.n, image.channels);
      const double error = maxAbsError(decoded, image), bound = codec.errorBound(image, c.params);
      QVERIFY2(error <= bound, qPrintable(QString("error %1 > bound %2").arg(error).arg(bound)));
      QCOMPARE(maxSeamGap(asGeometry(decoded)), 0.0f);
      QVERIFY(seamsBitExactForTest(decoded));
    }
  }

  void higherQualityCostsMoreAndErrsLess() {
    const FloatImage image = blob(64);
    for (const auto& [codec, qualities] :
         {std::pair{"bytepack", std::vector<double>{2, 8, 32}},
          std::pair{"dct", std::vector<double>{10, 50, 90, 100}}}) {
      std::size_t previousSize = 0;
      double previousError = 1e9;
      for (double q : qualities) {
        const Codec& c = *findCodec(codec);
        const auto stream = c.encode(image, {q, ""});
        const double error = maxAbsError(c.decode(stream, 64, 3), image);
        QVERIFY2(stream.size() > previousSize && error < previousError,
                 qPrintable(QString("%1 q=%2: %3 bytes, error %4")
                                .arg(codec)
                                .arg(q)
                                .arg(stream.size())
                                .arg(error)));
        previousSize = stream.size();
        previousError = error;
      }
    }
  }

  void flatThinAndNonFiniteChannels() {
    FloatImage image = bumpyImage(16);
    for (std::size_t k = 0; k < image.texels.size(); k += 3) {
      image.texels[k] = 2.5f;                         // flat
      image.texels[k + 1] = (k % 2) ? 1e-44f : 0.0f;  // denormal-thin
      image.texels[k + 2] = (k % 7) ? 3e38f : -3e38f; // range overflows float
    }
    for (const char* id : {"bytepack", "dct"})
      QVERIFY_THROWS_EXCEPTION(Error, findCodec(id)->encode(image, {}));
    for (std::size_t k = 2; k < image.texels.size(); k += 3)
      image.texels[k] = 1.0f;
    for (const char* id : {"bytepack", "dct"}) {
      const Codec& codec = *findCodec(id);
      const FloatImage decoded = codec.decode(codec.encode(image, {}), 16, 3);
      QVERIFY(maxAbsError(decoded, image) <= codec.errorBound(image, {}));
      QCOMPARE(decoded.texels[0], 2.5f);
    }
  }

  void badParametersAreRefused() {
    const FloatImage image = bumpyImage(8);
    for (const Case& c :
         {Case{"bytepack", {3, ""}}, Case{"bytepack", {16, ""}}, Case{"bytepack", {2.5, ""}},
          Case{"dct", {101, ""}}, Case{"dct", {7.5, ""}}, Case{"exr", {0, "b44"}}}) {
      try {
        findCodec(c.codec)->encode(image, c.params);
        QFAIL(qPrintable(QString("%1 accepted %2").arg(c.codec).arg(c.params.quality)));
      } catch (const Error& e) {
        QCOMPARE(int(e.kind()), int(ErrorKind::InvalidArgument));
      }
    }
    FloatImage huge = bumpyImage(8);
    huge.texels[4] = 1e6f;
    QVERIFY_THROWS_EXCEPTION(Error, findCodec("exr")->encode(huge, {0, "half"}));
  }
};

QTEST_GUILESS_MAIN(CodecLossyTest)
#include "codec_lossy_test.moc"
