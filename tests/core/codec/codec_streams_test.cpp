// Every codec in codecs(): unique ids and codes, worst-case sizes that hold, and decoders that
// never trust a stream: every truncated length refused, every flipped bit refused or decoded
// to an image of the right shape, headers for another codec, version, N or channel count
// refused.

#include "codec_test_support.h"

#include <QtTest>

#include <random>
#include <set>

using namespace octaclay::core;
using namespace octaclay::core::testing;

namespace {

CodecParams typicalParams(const Codec& codec) {
  if (codec.info.id == "exr") return {0, "piz"};
  return {}; // the codec's default
}

// A data row's settings: its exr mode, else the codec's typical ones.
CodecParams rowParams(const Codec& codec, const QString& mode) {
  return mode.isEmpty() ? typicalParams(codec) : CodecParams{0, mode.toStdString()};
}

} // namespace

class CodecStreamsTest : public QObject {
  Q_OBJECT

private slots:
  void registryIsConsistent() {
    std::set<std::string_view> ids;
    std::set<int> codes;
    for (const Codec& c : codecs()) {
      QVERIFY(ids.insert(c.info.id).second);
      QVERIFY(codes.insert(c.info.code).second);
      QVERIFY(c.info.version >= 1);
      QVERIFY(!c.info.quality.empty());
      QCOMPARE(findCodec(c.info.id), &c);
      QCOMPARE(findCodec(c.info.code), &c);
      QVERIFY(c.encode && c.decode && c.maxEncodedSize);
    }
    for (const char* id : {"bytepack", "dct", "exr", "lossless"})
      QVERIFY2(findCodec(id), id);
    QVERIFY(!findCodec("jpeg"));
    QVERIFY(!findCodec(std::uint8_t(0)));
  }

  void worstCaseSizesHold() {
    // Noise is the worst case for every codec: nothing to predict, every bit significant.
    for (const Codec& c : codecs())
      for (int channels : {1, 3, 4}) {
        FloatImage image = bumpyImage(16, channels);
        std::mt19937 random(11);
        std::uniform_real_distribution<float> noise(-1000.0f, 1000.0f);
        for (float& v : image.texels)
          v = noise(random);
        const CodecParams params = c.info.id == "exr" ? CodecParams{0, "zip"} : typicalParams(c);
        const auto stream = c.encode(image, params);
        QVERIFY2(stream.size() <= c.maxEncodedSize(16, channels, params), c.info.id.data());
      }
  }

  // One row per codec and, for exr, per mode: each mode writes a differently built stream.
  void damagedStreamsAreRefused_data() {
    QTest::addColumn<int>("index");
    QTest::addColumn<QString>("mode");
    for (int k = 0; k < int(codecs().size()); ++k) {
      const std::string id(codecs()[k].info.id);
      if (id == "exr") {
        for (const char* mode : {"zip", "piz", "pxr24", "half"})
          QTest::newRow((id + " " + mode).c_str()) << k << QString(mode);
      } else {
        QTest::newRow(id.c_str()) << k << QString();
      }
    }
  }

  void damagedStreamsAreRefused() {
    QFETCH(int, index);
    QFETCH(QString, mode);
    const Codec& codec = codecs()[index];
    const CodecParams params = rowParams(codec, mode);
    for (int channels : {1, 3}) {
      const FloatImage image = bumpyImage(8, channels);
      const auto stream = codec.encode(image, params);
      checkDamagedStreams(codec, stream, 8, channels);
    }
  }

  void foreignHeadersAreRefused_data() { damagedStreamsAreRefused_data(); }

  void foreignHeadersAreRefused() {
    QFETCH(int, index);
    QFETCH(QString, mode);
    const Codec& codec = codecs()[index];
    const CodecParams params = rowParams(codec, mode);
    const auto stream = codec.encode(bumpyImage(8), params);
    const auto refusedWith = [&](std::vector<std::uint8_t> bytes, int n, int channels,
                                 const char* needle) {
      try {
        codec.decode(bytes, n, channels);
        QFAIL(qPrintable(QString("accepted: %1").arg(needle)));
      } catch (const Error& e) {
        QCOMPARE(int(e.kind()), int(ErrorKind::InvalidInput));
        QVERIFY2(std::string(e.what()).find(needle) != std::string::npos, e.what());
      }
    };
    auto otherCode = stream;
    otherCode[0] ^= 0x40;
    refusedWith(otherCode, 8, 3, "codec code");
    auto newerVersion = stream;
    newerVersion[1] += 1;
    refusedWith(newerVersion, 8, 3, "version");
    refusedWith(stream, 16, 3, "N = 8");
    refusedWith(stream, 8, 4, "channels");
    refusedWith(stream, 12, 3, "N = 12");
    refusedWith(stream, 8, 0, "channels");
  }
};

QTEST_GUILESS_MAIN(CodecStreamsTest)
#include "codec_streams_test.moc"
