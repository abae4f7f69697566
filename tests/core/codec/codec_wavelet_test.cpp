#include "octaclay/core/codec/wavelet_codec.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace octaclay::core;

namespace {

FloatImage toFloatImage(const GeometryImage& image) {
  FloatImage out{image.size(), 3, {}};
  for (const Vec4f& t : image.texels())
    out.texels.insert(out.texels.end(), {t.x, t.y, t.z});
  return out;
}

GeometryImage toGeometryImage(const FloatImage& image) {
  GeometryImage out(image.n);
  auto texels = out.texels();
  for (std::size_t k = 0; k < texels.size(); ++k)
    texels[k] = {image.texels[3 * k], image.texels[3 * k + 1], image.texels[3 * k + 2], 0.0f};
  return out;
}

// Per channel: RMS over the vertices (canonical samples) of a − b.
std::vector<double> channelRms(const FloatImage& a, const FloatImage& b) {
  std::vector<double> sums(static_cast<std::size_t>(a.channels), 0.0);
  std::size_t count = 0;
  const int n = a.n;
  forEachCanonicalRun(n, [&](int j, int begin, int end) {
    for (int i = begin; i < end; ++i)
      for (int c = 0; c < a.channels; ++c) {
        const std::size_t k = (static_cast<std::size_t>(j) * (n + 1) + i) * a.channels + c;
        const double d = double(a.texels[k]) - double(b.texels[k]);
        sums[static_cast<std::size_t>(c)] += d * d;
      }
    count += static_cast<std::size_t>(end - begin);
  });
  for (double& s : sums)
    s = std::sqrt(s / double(count));
  return sums;
}

double maxRms(const FloatImage& a, const FloatImage& b) {
  const auto rms = channelRms(a, b);
  return *std::max_element(rms.begin(), rms.end());
}

// Diagonal of the bounding box of the first min(3, channels) channels.
double diagonal(const FloatImage& image) {
  double sum = 0;
  for (int c = 0; c < std::min(image.channels, 3); ++c) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (std::size_t k = static_cast<std::size_t>(c); k < image.texels.size();
         k += static_cast<std::size_t>(image.channels)) {
      lo = std::min(lo, image.texels[k]);
      hi = std::max(hi, image.texels[k]);
    }
    sum += double(hi - lo) * double(hi - lo);
  }
  return std::sqrt(sum);
}

// The image's first `channels` channels, a 4th one (saliency-like, a function of the position,
// so seamed too) made up from xyz when asked for.
FloatImage withChannels(const FloatImage& image, int channels) {
  FloatImage out{image.n, channels, {}};
  const std::size_t samples = image.texels.size() / static_cast<std::size_t>(image.channels);
  for (std::size_t k = 0; k < samples; ++k)
    for (int c = 0; c < channels; ++c)
      out.texels.push_back(c < image.channels
                               ? image.texels[k * static_cast<std::size_t>(image.channels) +
                                              static_cast<std::size_t>(c)]
                               : 0.5f + 0.4f * std::sin(3.0f * image.texels[k * 3]) *
                                            std::cos(2.0f * image.texels[k * 3 + 1]));
  return out;
}

// RMS over the vertices of the position error along the original's vertex normals, and of the
// length of its tangential part.
std::pair<double, double> positionErrors(const FloatImage& original, const FloatImage& decoded) {
  const GeometryImage image = toGeometryImage(original);
  const std::vector<Vec3f> normals = computeNormals(image);
  const GeometryImage result = toGeometryImage(decoded);
  double normal = 0, tangent = 0;
  std::size_t count = 0;
  const int n = original.n;
  forEachCanonicalRun(n, [&](int j, int begin, int end) {
    for (int i = begin; i < end; ++i) {
      const Vec3f d = result.at(i, j).xyz() - image.at(i, j).xyz();
      const double along = dot(d, normals[static_cast<std::size_t>(j) * (n + 1) + i]);
      normal += along * along;
      tangent += std::max(0.0, double(dot(d, d)) - along * along);
    }
    count += static_cast<std::size_t>(end - begin);
  });
  return {std::sqrt(normal / double(count)), std::sqrt(tangent / double(count))};
}

FloatImage blob(int n) {
  return toFloatImage(makeBaseShape(BaseShape::Blob, n));
}

// A deterministic image with no symmetry: a wobbly ellipsoid.
FloatImage wobbly(int n) {
  GeometryImage image(n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f d = octahedralDirection(n, i, j);
      const float r = 1.0f + 0.1f * std::sin(3.0f * d.x + 2.0f * d.y) * std::cos(5.0f * d.z);
      image.at(i, j) = {1.5f * r * d.x, r * d.y, 0.7f * r * d.z, 0.0f};
    }
  return toFloatImage(image);
}

std::uint64_t fnv1a(const std::vector<std::uint8_t>& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::uint8_t b : bytes)
    h = (h ^ b) * 1099511628211ull;
  return h;
}

void expectInvalidInput(const std::function<void()>& f) {
  try {
    f();
    QFAIL("no error");
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidInput);
  }
}

} // namespace

class CodecWaveletTest : public QObject {
  Q_OBJECT

private slots:
  void errorStaysWithinTheBound_data();
  void errorStaysWithinTheBound();
  void seamsAreExact();
  void prefixesRefine();
  void goldenStream();
  void truncatedStreamsAreRefused();
  void damagedStreamsNeverCrash();
  void wrongShapeIsRefused();
  void badParametersAreRefused();
  void registryEntryCodes();
};

void CodecWaveletTest::errorStaysWithinTheBound_data() {
  QTest::addColumn<int>("n");
  QTest::addColumn<int>("channels");
  QTest::addColumn<double>("bound");
  for (double bound : {1e-5, 1e-4, 1e-3, 1e-2}) {
    QTest::addRow("N=64 xyz bound=%g", bound) << 64 << 3 << bound;
    QTest::addRow("N=16 xyz bound=%g", bound) << 16 << 3 << bound;
  }
  QTest::addRow("N=32 xyzw bound=1e-4") << 32 << 4 << 1e-4;
  QTest::addRow("N=32 x bound=1e-4") << 32 << 1 << 1e-4;
  QTest::addRow("N=32 xy bound=1e-3") << 32 << 2 << 1e-3;
}

void CodecWaveletTest::errorStaysWithinTheBound() {
  QFETCH(int, n);
  QFETCH(int, channels);
  QFETCH(double, bound);
  const FloatImage xyz = wobbly(n);
  const FloatImage image = withChannels(xyz, channels);
  const auto stream = encodeWavelet(image, bound);
  const FloatImage decoded = decodeWavelet(stream, n, channels);
  QCOMPARE(decoded.n, n);
  QCOMPARE(decoded.channels, channels);
  const double limit = bound * diagonal(image);
  double binding = 0; // the largest error as a fraction of its limit
  if (channels >= 3) {
    const auto [normal, tangent] = positionErrors(xyz, withChannels(decoded, 3));
    qInfo("N %d bound %g: %zu bytes, normal RMS %.3g, tangential %.3g, limit %.3g", n, bound,
          stream.size(), normal, tangent, limit);
    QVERIFY(normal <= limit);
    QVERIFY(tangent <= kWaveletTangentFactor * limit);
    binding = std::max(normal / limit, tangent / (kWaveletTangentFactor * limit));
  }
  const auto rms = channelRms(image, decoded);
  for (int c = channels >= 3 ? 3 : 0; c < channels; ++c) {
    qInfo("channel %d: RMS %.3g, limit %.3g", c, rms[static_cast<std::size_t>(c)], limit);
    QVERIFY(rms[static_cast<std::size_t>(c)] <= limit);
    binding = std::max(binding, rms[static_cast<std::size_t>(c)] / limit);
  }
  // The step is the largest that keeps the bound, so the error is not far below it.
  QVERIFY(binding > 0.3);
}

void CodecWaveletTest::seamsAreExact() {
  for (double bound : {1e-4, 3e-3}) {
    const FloatImage decoded = decodeWavelet(encodeWavelet(blob(128), bound), 128, 3);
    QCOMPARE(maxSeamGap(toGeometryImage(decoded)), 0.0f);
  }
  // An unseamed input (identified samples slightly apart) still decodes seamed.
  FloatImage image = wobbly(32);
  image.texels[3 * 5] += 0.01f; // sample (5, 0), identified with (27, 0)
  const FloatImage decoded = decodeWavelet(encodeWavelet(image, 1e-4), 32, 3);
  QCOMPARE(maxSeamGap(toGeometryImage(decoded)), 0.0f);
}

void CodecWaveletTest::prefixesRefine() {
  const int n = 64;
  const FloatImage image = wobbly(n);
  const auto stream = encodeWavelet(image, 1e-4);
  const auto ends = waveletBandEnds(stream, n, 3);
  QCOMPARE(ends.back(), stream.size());
  double previous = std::numeric_limits<double>::infinity();
  // Whole levels: each finer one lowers the error.
  for (std::size_t k = 2; k < ends.size(); k += 3) {
    const FloatImage coarse = decodeWaveletPrefix(stream, n, 3, ends[k]);
    QCOMPARE(maxSeamGap(toGeometryImage(coarse)), 0.0f);
    const double error = maxRms(image, coarse);
    qInfo("prefix %6zu bytes: RMS %.3g", ends[k], error);
    QVERIFY(error < previous);
    previous = error;
  }
  // A prefix ending inside a band decodes as the bands before it.
  const FloatImage partial = decodeWaveletPrefix(stream, n, 3, ends[5] + 3);
  QCOMPARE(partial.texels, decodeWaveletPrefix(stream, n, 3, ends[5]).texels);
  QCOMPARE(decodeWaveletPrefix(stream, n, 3, stream.size()).texels,
           decodeWavelet(stream, n, 3).texels);
  expectInvalidInput([&] { decodeWaveletPrefix(stream, n, 3, 5); });
}

void CodecWaveletTest::goldenStream() {
  // Version 3 of the stream for a fixed small image. A change of these bytes is a format
  // change: bump kWaveletVersion and update the expected values.
  const auto stream = encodeWavelet(wobbly(8), 1e-3);
  QCOMPARE(kWaveletVersion, std::uint16_t{3});
  QCOMPARE(stream[0], std::uint8_t{4}); // codec code
  QCOMPARE(stream[1], std::uint8_t{3}); // version, little-endian
  QCOMPARE(stream[2], std::uint8_t{0});
  QCOMPARE(stream[3], std::uint8_t{8}); // N
  qInfo("golden: %zu bytes, FNV-1a %016llx", stream.size(),
        static_cast<unsigned long long>(fnv1a(stream)));
  QCOMPARE(stream.size(), std::size_t{282});
  QCOMPARE(fnv1a(stream), std::uint64_t{0x21d0d87f518261bb});
}

void CodecWaveletTest::truncatedStreamsAreRefused() {
  const auto stream = encodeWavelet(wobbly(16), 1e-4);
  for (std::size_t length = 0; length < stream.size(); ++length)
    expectInvalidInput([&] { decodeWavelet(std::span(stream).first(length), 16, 3); });
  auto longer = stream;
  longer.push_back(0);
  expectInvalidInput([&] { decodeWavelet(longer, 16, 3); });
}

void CodecWaveletTest::damagedStreamsNeverCrash() {
  const auto stream = encodeWavelet(wobbly(16), 1e-4);
  int refused = 0, decoded = 0;
  for (std::size_t at = 0; at < stream.size(); ++at)
    for (std::uint8_t flip : {std::uint8_t{0x01}, std::uint8_t{0x80}, std::uint8_t{0xFF}}) {
      auto damaged = stream;
      damaged[at] ^= flip;
      try {
        const FloatImage image = decodeWavelet(damaged, 16, 3);
        QCOMPARE(image.texels.size(), std::size_t{17 * 17 * 3});
        ++decoded;
      } catch (const Error& e) {
        QCOMPARE(e.kind(), ErrorKind::InvalidInput);
        ++refused;
      }
    }
  qInfo("damaged streams: %d refused, %d decoded", refused, decoded);
  QVERIFY(refused > 0);
}

void CodecWaveletTest::wrongShapeIsRefused() {
  const auto stream = encodeWavelet(wobbly(16), 1e-3);
  expectInvalidInput([&] { decodeWavelet(stream, 32, 3); });
  expectInvalidInput([&] { decodeWavelet(stream, 16, 4); });
  expectInvalidInput([&] { decodeWavelet(stream, 16, 1); });
  expectInvalidInput([&] { decodeWavelet(stream, 17, 3); });
  expectInvalidInput([&] { decodeWavelet(stream, 16, 0); });
  auto future = stream;
  future[1] = 4;
  expectInvalidInput([&] { decodeWavelet(future, 16, 3); });
  for (int version : {1, 2}) { // 1: one step for every level; 2: axis-aligned frames
    auto old = stream;
    old[1] = static_cast<std::uint8_t>(version);
    expectInvalidInput([&] { decodeWavelet(old, 16, 3); });
  }
  auto otherCodec = stream;
  otherCodec[0] = 5;
  expectInvalidInput([&] { decodeWavelet(otherCodec, 16, 3); });
}

void CodecWaveletTest::badParametersAreRefused() {
  const FloatImage image = wobbly(16);
  for (double bound : {0.0, 1e-8, 0.5, std::nan("")})
    QVERIFY_THROWS_EXCEPTION(Error, encodeWavelet(image, bound));
  FloatImage broken = image;
  broken.texels[7] = std::numeric_limits<float>::infinity();
  QVERIFY_THROWS_EXCEPTION(Error, encodeWavelet(broken, 1e-3));
  broken = image;
  broken.texels.pop_back();
  QVERIFY_THROWS_EXCEPTION(Error, encodeWavelet(broken, 1e-3));
}

void CodecWaveletTest::registryEntryCodes() {
  const Codec codec = makeWaveletCodec();
  QCOMPARE(codec.info.id, std::string_view("wavelet"));
  QCOMPARE(codec.info.version, kWaveletVersion);
  const FloatImage image = wobbly(32);
  CodecParams params;
  params.quality = 1e-4;
  const auto stream = codec.encode(image, params);
  QVERIFY(stream.size() <= codec.maxEncodedSize(32, 3, params));
  QVERIFY(positionErrors(image, codec.decode(stream, 32, 3)).first <= 1e-4 * diagonal(image));
  params.quality = 0; // the default bound
  QCOMPARE(codec.encode(image, params), encodeWavelet(image, kWaveletDefaultBound));
  QCOMPARE(codec.info.code, std::uint8_t{4});
  // Noise at the tightest bound, the costliest kind of image, stays within the size bound.
  FloatImage noise{16, 4, {}};
  std::uint32_t state = 12345;
  for (int k = 0; k < 17 * 17 * 4; ++k) {
    state = state * 1664525u + 1013904223u;
    noise.texels.push_back(static_cast<float>(state >> 8) / 16777216.0f);
  }
  params.quality = kWaveletMinBound;
  const auto noisy = codec.encode(noise, params);
  qInfo("noise: %zu bytes of at most %zu", noisy.size(), codec.maxEncodedSize(16, 4, params));
  QVERIFY(noisy.size() <= codec.maxEncodedSize(16, 4, params));
  QVERIFY_THROWS_EXCEPTION(Error, codec.maxEncodedSize(15, 3, params));
}

QTEST_GUILESS_MAIN(CodecWaveletTest)
#include "codec_wavelet_test.moc"
