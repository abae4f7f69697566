// The checks every reader shares (document_checks.h): documents whose bounding box overflows
// float and partial layers are refused by the full read, the positions-only read (`info`,
// `lod`) and the header read alike; .ocz files are refused on the same grounds, and one whose
// header claims a larger N than its streams hold is refused before anything of that size is
// allocated.

#include "../../file_test_support.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <QTemporaryDir>
#include <QtTest>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

using octaclay::testing::resealCrc;

namespace {

// Writes an Octaclay-looking EXR with Imf directly (the writer may refuse such documents):
// an N = 16 sphere whose sample (3, 4) has x = `x`, plus float channels `extra` (zero).
void writeExr(const fs::path& path, float x, const std::vector<std::string>& extra = {}) {
  const int n = 16, side = n + 1;
  const GeometryImage sphere = makeBaseShape(BaseShape::Sphere, n);
  Imf::Header header(side, side);
  header.insert("octaclay.format", Imf::IntAttribute(1));
  std::vector<std::vector<float>> planes(3 + extra.size(),
                                         std::vector<float>(std::size_t(side) * side, 0.0f));
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const Vec4f& t = sphere.at(i, j);
      const std::size_t k = std::size_t(j) * side + i;
      planes[0][k] = t.x;
      planes[1][k] = t.y;
      planes[2][k] = t.z;
    }
  planes[0][std::size_t(4) * side + 3] = x;
  std::vector<std::string> names{"P.X", "P.Y", "P.Z"};
  names.insert(names.end(), extra.begin(), extra.end());
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < names.size(); ++c) {
    header.channels().insert(names[c], Imf::Channel(Imf::FLOAT));
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(planes[c].data()),
                                      sizeof(float), sizeof(float) * side));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(side);
}

QString errorOf(const std::function<void()>& f, ErrorKind kind, const QString& needle) {
  try {
    f();
  } catch (const Error& e) {
    if (e.kind() != kind) return QString("wrong error kind: ") + e.what();
    if (!QString(e.what()).contains(needle))
      return QString("message lacks '%1': %2").arg(needle, e.what());
    return {};
  } catch (const std::exception& e) {
    return QString("not a core::Error: ") + e.what();
  }
  return "no error";
}

#define EXPECT_ERROR(call, kind, needle)                                                           \
  do {                                                                                             \
    const QString why_ = errorOf([&] { call; }, kind, needle);                                     \
    QVERIFY2(why_.isEmpty(), qPrintable(why_));                                                    \
  } while (false)

} // namespace

class DocumentChecksTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }

  void positionsProblemNamesTheCause() {
    GeometryImage image = makeBaseShape(BaseShape::Sphere, 8);
    QVERIFY(!positionsProblem(image));
    image.at(1, 2).z = 1e15f; // at the bound: still fine
    QVERIFY(!positionsProblem(image));
    image.at(1, 2).z = -3e19f;
    const auto huge = positionsProblem(image);
    QVERIFY(huge && huge->find("too large") != std::string::npos);
    image.at(1, 2).z = std::numeric_limits<float>::infinity();
    const auto inf = positionsProblem(image);
    QVERIFY(inf && inf->find("(1, 2)") != std::string::npos);
  }

  void sizeProblemNamesDegenerateModels() {
    GeometryImage image = makeBaseShape(BaseShape::Sphere, 8);
    QVERIFY(!sizeProblem(image));
    const auto scaled = [&](float scale, Vec3f offset) {
      GeometryImage copy = image;
      for (Vec4f& t : copy.texels())
        t = {t.x * scale + offset.x, t.y * scale + offset.y, t.z * scale + offset.z, t.w};
      return copy;
    };
    QVERIFY(!sizeProblem(scaled(1e-11f, {})));      // small, yet measurable
    QVERIFY(!sizeProblem(scaled(1e13f, {})));       // large, within the coordinate range
    QVERIFY(!sizeProblem(scaled(1, {1e5f, 0, 0}))); // off the origin, well resolved
    const auto point = sizeProblem(scaled(0, {2, 3, 4}));
    QVERIFY(point && point->find("no size") != std::string::npos);
    const auto tiny = sizeProblem(scaled(1e-20f, {}));
    QVERIFY(tiny && tiny->find("below the 1e-12") != std::string::npos);
    const auto collapsed = sizeProblem(scaled(1e-9f, {1e6f, 0, 0}));
    QVERIFY(collapsed && collapsed->find("collapsed") != std::string::npos);
    QVERIFY(sizeProblem(BoundingBox{}).has_value()); // no samples at all
  }

  void layerValuesProblemNamesTheSample() {
    Layer mask{"mask", 1, {1, 0, 0, 0}, {}};
    QVERIFY(!layerValuesProblem(mask, 8));
    mask.texels.assign(9 * 9, 1.0f);
    QVERIFY(!layerValuesProblem(mask, 8));
    mask.texels[9 * 2 + 3] = std::numeric_limits<float>::quiet_NaN();
    const auto nan = layerValuesProblem(mask, 8);
    QVERIFY(nan && nan->find("mask") != std::string::npos &&
            nan->find("(3, 2)") != std::string::npos);
  }

  void layerChannelsProblemNamesTheLayer() {
    QVERIFY(!layerChannelsProblem({"P.X", "P.Y", "P.Z"}));
    QVERIFY(!layerChannelsProblem({"P.X", "diffuse.R", "diffuse.G", "diffuse.B", "diffuse.A"}));
    const auto partial = layerChannelsProblem({"P.X", "diffuse.R", "diffuse.G"});
    QVERIFY(partial && partial->find("diffuse has 2 of its 4") != std::string::npos);
  }

  // Every read refuses what the others refuse: `info` and `lod` read positions only.
  void overflowingDocumentRefusedOnEveryRead() {
    const fs::path p = path("huge.exr");
    writeExr(p, 3e19f);
    for (bool layers : {true, false})
      EXPECT_ERROR(readDocument(p, {layers}), ErrorKind::InvalidInput, "too large");
    writeExr(p, 9e14f); // large, within the 1e15 every reader accepts
    QCOMPARE(readDocument(p, {false}).size(), 16);
  }

  void partialLayerRefusedOnEveryRead() {
    const fs::path p = path("partial.exr");
    writeExr(p, 0.5f, {"diffuse.R", "diffuse.G"});
    EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, "diffuse has 2 of its 4");
    for (bool layers : {true, false})
      EXPECT_ERROR(readDocument(p, {layers}), ErrorKind::InvalidInput, "diffuse has 2 of its 4");
  }

  void overflowingOczRefused() {
    Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, 16));
    doc.positions.at(5, 5).y = 1e30f;
    std::vector<std::uint8_t> bytes;
    try {
      bytes = compressDocument(doc, {"lossless", {}, "lossless"});
    } catch (const Error&) {
      return; // refusing to code it is fine too
    }
    EXPECT_ERROR(decompressDocument(bytes), ErrorKind::InvalidInput, "too large");
  }

  // N changed in the container only, checksum redone: the stream's own header disagrees, and
  // nothing of N = 8192's size (1 GB) may be allocated before that is found. Run in a child
  // whose address space may grow by only 512 MB, where such an allocation would fail.
  void oczClaimingLargerNRefusedWithoutAllocating() {
    const Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, 32));
    std::vector<std::uint8_t> bytes = compressDocument(doc, {"lossless", {}, "lossless"});
    const std::uint32_t n = 8192;
    for (int k = 0; k < 4; ++k)
      bytes[6 + k] = std::uint8_t(n >> (8 * k));
    resealCrc(bytes);
    EXPECT_ERROR(decompressDocument(bytes), ErrorKind::InvalidInput, "N = ");

    const pid_t child = fork();
    QVERIFY(child >= 0);
    if (child == 0) {
      unsigned long pages = 0;
      if (FILE* statm = std::fopen("/proc/self/statm", "r")) {
        if (std::fscanf(statm, "%lu", &pages) != 1) pages = 0;
        std::fclose(statm);
      }
      const rlim_t cap = rlim_t(pages) * rlim_t(sysconf(_SC_PAGESIZE)) + (512ull << 20);
      const rlimit limit{cap, cap};
      setrlimit(RLIMIT_AS, &limit);
      try {
        decompressDocument(bytes);
      } catch (const Error& e) {
        _exit(e.kind() == ErrorKind::InvalidInput ? 0 : 1);
      } catch (...) {
        _exit(2);
      }
      _exit(3);
    }
    int status = 0;
    waitpid(child, &status, 0);
    QVERIFY2(WIFEXITED(status) && WEXITSTATUS(status) == 0,
             qPrintable(QString("child status %1").arg(status)));
  }

private:
  fs::path path(const char* name) const { return fs::path(dir_.path().toStdString()) / name; }
  QTemporaryDir dir_;
};

QTEST_GUILESS_MAIN(DocumentChecksTest)
#include "document_checks_test.moc"
