#include "octaclay/core/base_shapes.h"
#include "octaclay/core/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/mesh_extraction.h"
#include "octaclay/core/mesh_io.h"
#include "octaclay/core/mesh_validation.h"
#include "octaclay/core/octahedral.h"
#include "octaclay/core/octahedral_resampling.h"
#include "octaclay/core/seaming.h"
#include "octaclay/core/spherical_parameterization.h"
#include "octaclay/core/surface_distance.h"
#include "octaclay/core/wavelet_codec.h"

#include <QElapsedTimer>
#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
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

double diagonal(const FloatImage& image) {
  double sum = 0;
  for (int c = 0; c < 3; ++c) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (std::size_t k = static_cast<std::size_t>(c); k < image.texels.size(); k += 3) {
      lo = std::min(lo, image.texels[k]);
      hi = std::max(hi, image.texels[k]);
    }
    sum += double(hi - lo) * double(hi - lo);
  }
  return std::sqrt(sum);
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
  void rateAtPsnr();
};

void CodecWaveletTest::errorStaysWithinTheBound_data() {
  QTest::addColumn<int>("n");
  QTest::addColumn<double>("bound");
  for (double bound : {1e-5, 1e-4, 1e-3, 1e-2}) {
    QTest::addRow("N=64 bound=%g", bound) << 64 << bound;
    QTest::addRow("N=16 bound=%g", bound) << 16 << bound;
  }
}

void CodecWaveletTest::errorStaysWithinTheBound() {
  QFETCH(int, n);
  QFETCH(double, bound);
  const FloatImage image = wobbly(n);
  const auto stream = encodeWavelet(image, bound);
  const FloatImage decoded = decodeWavelet(stream, n, 3);
  QCOMPARE(decoded.n, n);
  QCOMPARE(decoded.channels, 3);
  const double limit = bound * diagonal(image);
  const double error = maxRms(image, decoded);
  qInfo("N %d bound %g: %zu bytes, RMS %.3g of the allowed %.3g", n, bound, stream.size(), error,
        limit);
  QVERIFY(error <= limit);
  // The step is the largest that keeps the bound, so the error is not far below it.
  QVERIFY(error > 0.3 * limit);
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
  // Version 1 of the stream for a fixed small image. A change of these bytes is a format
  // change: bump kWaveletVersion and update the expected values.
  const auto stream = encodeWavelet(wobbly(8), 1e-3);
  QCOMPARE(kWaveletVersion, std::uint16_t{1});
  QCOMPARE(stream[0], std::uint8_t{1});
  QCOMPARE(stream[1], std::uint8_t{0});
  QCOMPARE(stream[2], std::uint8_t{8});
  qInfo("golden: %zu bytes, FNV-1a %016llx", stream.size(),
        static_cast<unsigned long long>(fnv1a(stream)));
  QCOMPARE(stream.size(), std::size_t{0});
  QCOMPARE(fnv1a(stream), std::uint64_t{0});
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
  future[0] = 2;
  expectInvalidInput([&] { decodeWavelet(future, 16, 3); });
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
  QVERIFY(maxRms(image, codec.decode(stream, 32, 3)) <= 1e-4 * diagonal(image));
  params.quality = 0; // the default bound
  QCOMPARE(codec.encode(image, params), encodeWavelet(image, kWaveletDefaultBound));
}

// Measurement, not a check: OCTACLAY_WAVELET_RD=1 prints the bits per vertex at which each
// model reaches 95 dB (and the decode time at N = 1024). Imports are cached in
// /tmp/wavelet-cache.
void CodecWaveletTest::rateAtPsnr() {
  if (qEnvironmentVariableIsEmpty("OCTACLAY_WAVELET_RD")) QSKIP("set OCTACLAY_WAVELET_RD=1");
  const int n = 512;
  const auto load = [&](const QString& name) -> FloatImage {
    if (name == "blob") return blob(n);
    if (name == "sphere") return toFloatImage(makeBaseShape(BaseShape::Sphere, n));
    const std::filesystem::path cached = "/tmp/wavelet-cache/" + name.toStdString() + ".exr";
    if (std::filesystem::exists(cached)) return toFloatImage(readDocument(cached).positions);
    const QString path = QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/" + name;
    const TriangleMesh mesh = loadGenus0Mesh(path.toStdString()).mesh;
    const SphericalMap map = parameterizeOnSphere(mesh);
    const Document doc = makeDocument(resampleOctahedral(mesh, map, n));
    writeDocument(doc, cached);
    return toFloatImage(doc.positions);
  };
  SurfaceDistanceOptions options;
  options.samplesPerSurface = 300'000;
  QStringList names = {"sphere", "blob", "bunny_cgal.obj", "armadillo.obj", "igea.ply"};
  if (!qEnvironmentVariableIsEmpty("OCTACLAY_WAVELET_MODELS"))
    names = qEnvironmentVariable("OCTACLAY_WAVELET_MODELS").split(',');
  for (const QString& name : names) {
    const FloatImage image = load(name);
    const TriangleMesh reference = extractMesh(toGeometryImage(image));
    const std::filesystem::path obj = "/tmp/wavelet-cache/" + name.toStdString() + ".grid.obj";
    if (!std::filesystem::exists(obj)) writeMesh(reference, obj);
    const double vertices = double(n) * n + 2;
    const auto measure = [&](double bound) {
      const auto stream = encodeWavelet(image, bound);
      const FloatImage decoded = decodeWavelet(stream, n, 3);
      const double psnr =
          compareSurfaces(reference, extractMesh(toGeometryImage(decoded)), options).psnr;
      const double bpv = 8.0 * double(stream.size()) / vertices;
      qInfo("  %-14s bound %.3g: %.3f bpv, %.2f dB, seam gap %g", qPrintable(name), bound, bpv,
            psnr, double(maxSeamGap(toGeometryImage(decoded))));
      return std::pair{psnr, bpv};
    };
    if (!qEnvironmentVariableIsEmpty("OCTACLAY_WAVELET_BOUND")) {
      measure(qEnvironmentVariable("OCTACLAY_WAVELET_BOUND").toDouble());
      continue;
    }
    // Bisect log(bound) for 95 dB.
    double lo = 1e-6, hi = 1e-3; // lo reaches 95 dB, hi does not
    for (int k = 0; k < 7; ++k) {
      const double mid = std::sqrt(lo * hi);
      (measure(mid).first >= 95.0 ? lo : hi) = mid;
    }
    const auto [psnr, bpv] = measure(lo);
    qInfo("%-14s 95 dB: %.3f bpv (%.2f dB, bound %.3g)", qPrintable(name), bpv, psnr, lo);
  }
  if (!qEnvironmentVariableIsEmpty("OCTACLAY_WAVELET_NO_TIMING")) return;
  const FloatImage big = blob(1024);
  const auto stream = encodeWavelet(big, 2e-5);
  QElapsedTimer timer;
  double best = 1e9;
  for (int k = 0; k < 5; ++k) {
    timer.start();
    const FloatImage decoded = decodeWavelet(stream, 1024, 3);
    best = std::min(best, double(timer.nsecsElapsed()) / 1e6);
    QCOMPARE(decoded.n, 1024);
  }
  qInfo("decode N = 1024 (blob, bound 2e-5, %zu bytes): %.1f ms", stream.size(), best);
}

QTEST_GUILESS_MAIN(CodecWaveletTest)
#include "codec_wavelet_test.moc"
