// Native document I/O: bit-exact round trips, headers, and every way a file can be wrong
// (foreign EXR, truncated, missing channels, bad size, unwritable paths, failed overwrites).

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <QtTest>
#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <set>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& p, std::string_view bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::set<std::string> listDir(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.insert(e.path().filename().string());
  return names;
}

// Runs f, which must throw core::Error of `kind` whose message contains `needle`
// (case-insensitive). Returns a description of what went wrong, empty on success.
QString expectError(const std::function<void()>& f, ErrorKind kind, const QString& needle) {
  try {
    f();
  } catch (const Error& e) {
    const QString message = QString::fromStdString(e.what());
    if (e.kind() != kind)
      return QString("wrong ErrorKind %1 (expected %2): %3")
          .arg(int(e.kind()))
          .arg(int(kind))
          .arg(message);
    if (!message.contains(needle, Qt::CaseInsensitive))
      return QString("message does not mention '%1': %2").arg(needle, message);
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  } catch (...) {
    return "threw a non-std exception";
  }
  return "did not throw";
}

#define EXPECT_ERROR(call, kind, needle)                                                           \
  do {                                                                                             \
    const QString why_ = expectError([&] { call; }, kind, needle);                                 \
    QVERIFY2(why_.isEmpty(), qPrintable(why_));                                                    \
  } while (false)

// Writes an EXR with Imf directly: width × height, FLOAT channels `channels` filled with a smooth
// pattern, and the non-standard attributes of `templateFile` (empty: none, i.e. a foreign EXR).
void writeRawExr(const fs::path& path, int width, int height,
                 const std::vector<std::string>& channels, const fs::path& templateFile = {},
                 const std::function<void(Imf::Header&)>& edit = {}) {
  Imf::Header header(width, height);
  if (!templateFile.empty()) {
    Imf::InputFile in(templateFile.c_str());
    static const std::set<std::string> standard{
        "channels",  "compression",      "dataWindow",         "displayWindow",
        "lineOrder", "pixelAspectRatio", "screenWindowCenter", "screenWindowWidth"};
    for (auto it = in.header().begin(); it != in.header().end(); ++it)
      if (!standard.count(it.name())) header.insert(it.name(), it.attribute());
  }
  if (edit) edit(header);
  for (const auto& c : channels)
    header.channels().insert(c, Imf::Channel(Imf::FLOAT));
  std::vector<std::vector<float>> data(channels.size(),
                                       std::vector<float>(std::size_t(width) * height));
  Imf::FrameBuffer frame;
  for (std::size_t c = 0; c < channels.size(); ++c) {
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x)
        data[c][std::size_t(y) * width + x] =
            std::sin(0.1f * float(x) + float(c)) * std::cos(0.1f * float(y));
    frame.insert(channels[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(data[c].data()),
                                         sizeof(float), sizeof(float) * width));
  }
  Imf::OutputFile out(path.c_str(), header);
  out.setFrameBuffer(frame);
  out.writePixels(height);
}

// Core calls that must succeed: an escaping exception would abort the whole executable.
#define NO_THROW(call)                                                                             \
  do {                                                                                             \
    try {                                                                                          \
      call;                                                                                        \
    } catch (const std::exception& e_) {                                                           \
      QFAIL(qPrintable(QString(#call " threw: ") + e_.what()));                                    \
    }                                                                                              \
  } while (false)

const std::vector<std::string> kP{"P.X", "P.Y", "P.Z"};

// A blob with a mask and non-default, uniform layers.
Document makeTestDocument(int n) {
  Document doc = makeDocument(makeBaseShape(BaseShape::Blob, n));
  // Values exactly representable in half, so uniform fills must come back exactly.
  doc.feature.fill = {0.5f, 0.125f, 0.75f, 0.0f};
  doc.hasMask = true;
  doc.mask.fill = {0.25f, 0, 0, 0};
  return doc;
}

// The same with a painted (non-uniform) diffuse layer.
Document makePaintedDocument(int n) {
  Document doc = makeTestDocument(n);
  const std::size_t texels = std::size_t(n + 1) * (n + 1);
  doc.diffuse.texels.resize(texels * 4);
  for (std::size_t t = 0; t < texels; ++t)
    for (std::size_t c = 0; c < 4; ++c)
      doc.diffuse.texels[t * 4 + c] = 0.5f + 0.49f * std::sin(0.37f * float(t) + 1.3f * float(c));
  return doc;
}

// A layer read back equals the written one: uniform fills exactly, texels within half precision.
QString compareLayer(const Layer& written, const Layer& read, int n) {
  if (read.name != written.name || read.channels != written.channels)
    return QString::fromStdString("layer " + written.name + " has wrong name or channels");
  const std::size_t texels = std::size_t(n + 1) * (n + 1);
  const auto expected = [&](std::size_t t, int c) {
    return written.uniform() ? written.fill[c] : written.texels[t * written.channels + c];
  };
  // Layers are stored as half: values come back rounded to half (relative error <= 2^-11).
  const auto halfTolerance = [](float v) { return std::max(std::abs(v), 6.2e-5f) / 2047.0f; };
  if (read.uniform()) {
    if (!written.uniform()) return QString::fromStdString(written.name + " came back uniform");
    for (int c = 0; c < read.channels; ++c)
      if (std::abs(read.fill[c] - written.fill[c]) > halfTolerance(written.fill[c]))
        return QString("%1 fill[%2] %3, written %4")
            .arg(QString::fromStdString(written.name))
            .arg(c)
            .arg(read.fill[c])
            .arg(written.fill[c]);
    return {};
  }
  if (read.texels.size() != texels * read.channels)
    return QString::fromStdString(written.name + " has the wrong number of texels");
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < read.channels; ++c) {
      const float e = expected(t, c), a = read.texels[t * read.channels + c];
      if (std::abs(a - e) > halfTolerance(e))
        return QString("%1 texel %2 channel %3: %4, written %5")
            .arg(QString::fromStdString(written.name))
            .arg(t)
            .arg(c)
            .arg(a)
            .arg(e);
    }
  return {};
}

bool positionsBitExact(const GeometryImage& a, const GeometryImage& b) {
  if (a.size() != b.size() || a.texelCount() != b.texelCount()) return false;
  for (std::size_t t = 0; t < a.texelCount(); ++t)
    if (std::memcmp(&a.texels()[t], &b.texels()[t], 3 * sizeof(float)) != 0) return false;
  return true;
}

} // namespace

class DocumentIoTest : public QObject {
  Q_OBJECT

private slots:
  void init() { QVERIFY(dir_.isValid()); }
  void roundTrip();
  void roundTripPaintedLayer();
  void everyCompressionReadsBack();
  void rawLinesAreOpenExrsOwn();
  void header();
  void missingFile();
  void notExr();
  void foreignExr();
  void newerVersion();
  void truncated();
  void missingChannel();
  void badSize_data();
  void badSize();
  void nonFinitePositions();
  void unwritablePath();
  void failedOverwriteKeepsOldFile();

private:
  fs::path path(const char* name) const { return fs::path(dir_.filePath(name).toStdString()); }
  fs::path goodFile() {
    const fs::path p = path("good.exr");
    if (!fs::exists(p)) writeDocument(makeTestDocument(64), p); // roundTrip() checks this works
    return p;
  }
  QTemporaryDir dir_;
};

void DocumentIoTest::roundTrip() {
  const Document doc = makeTestDocument(64);
  const fs::path p = path("roundtrip.exr");
  NO_THROW(writeDocument(doc, p));
  QVERIFY(fs::exists(p));
  QCOMPARE(listDir(p.parent_path()).count("roundtrip.exr"), std::size_t{1});

  Document back;
  NO_THROW(back = readDocument(p));
  QCOMPARE(back.size(), 64);
  QVERIFY2(positionsBitExact(doc.positions, back.positions), "positions not bit-exact");
  QVERIFY(back.hasMask);
  for (auto [w, r] : {std::pair{&doc.diffuse, &back.diffuse},
                      std::pair{&doc.feature, &back.feature}, std::pair{&doc.mask, &back.mask}}) {
    const QString why = compareLayer(*w, *r, 64);
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }

  // Positions only: layers keep their defaults.
  Document positionsOnly;
  NO_THROW(positionsOnly = readDocument(p, DocumentReadOptions{false}));
  QVERIFY(positionsBitExact(doc.positions, positionsOnly.positions));
  const Document defaults = makeDocument(GeometryImage(64));
  QVERIFY(positionsOnly.diffuse.uniform());
  QVERIFY(positionsOnly.diffuse.fill == defaults.diffuse.fill);
  QVERIFY(positionsOnly.feature.fill == defaults.feature.fill);

  // Without a mask, and at other sizes, with other layer fills.
  for (int n : {2, 256}) {
    Document d = makeDocument(makeBaseShape(BaseShape::Cube, n));
    d.diffuse.fill = {0.25f, 0.5f, 1.0f, 0.75f};
    const fs::path q = path("other.exr");
    NO_THROW(writeDocument(d, q));
    Document e;
    NO_THROW(e = readDocument(q));
    QCOMPARE(e.size(), n);
    QVERIFY(!e.hasMask);
    QVERIFY(positionsBitExact(d.positions, e.positions));
    QString why = compareLayer(d.diffuse, e.diffuse, n);
    QVERIFY2(why.isEmpty(), qPrintable(why));
    why = compareLayer(d.feature, e.feature, n);
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }
}

void DocumentIoTest::roundTripPaintedLayer() {
  const Document doc = makePaintedDocument(64);
  const fs::path p = path("painted.exr");
  NO_THROW(writeDocument(doc, p));
  Document back;
  NO_THROW(back = readDocument(p));
  QVERIFY2(positionsBitExact(doc.positions, back.positions), "positions not bit-exact");
  QVERIFY(!back.diffuse.uniform());
  for (auto [w, r] : {std::pair{&doc.diffuse, &back.diffuse},
                      std::pair{&doc.feature, &back.feature}, std::pair{&doc.mask, &back.mask}}) {
    const QString why = compareLayer(*w, *r, 64);
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }
}

// Documents are read and written in bands of rows, uncompressed files without OpenEXR's own
// conversion: every compression comes back the same, with a layer that turns non-uniform only
// after the first band, one painted from the first row, and a uniform one.
void DocumentIoTest::everyCompressionReadsBack() {
  const int n = 512; // 513 rows: bands of 128 and a short last one
  Document doc = makeTestDocument(n);
  const std::size_t side = n + 1, texels = side * side;
  doc.diffuse.texels.assign(texels * 4, 0.0f);
  for (std::size_t t = 0; t < texels; ++t)
    for (std::size_t c = 0; c < 4; ++c)
      doc.diffuse.texels[t * 4 + c] = t / side < 300 ? doc.diffuse.fill[c] : 0.25f * float(c);
  doc.feature.texels.resize(texels * 3);
  for (std::size_t t = 0; t < texels * 3; ++t)
    doc.feature.texels[t] = float(t % 7) / 8.0f;
  for (const DocumentCompression compression :
       {DocumentCompression::Automatic, DocumentCompression::None, DocumentCompression::Rle,
        DocumentCompression::Zips, DocumentCompression::Zip}) {
    const fs::path p = path("compressed.exr");
    NO_THROW(writeDocument(doc, p, {compression, 1}));
    Document back;
    NO_THROW(back = readDocument(p));
    QVERIFY2(positionsBitExact(doc.positions, back.positions), "positions not bit-exact");
    QVERIFY(back.hasMask && back.mask.uniform() && !back.diffuse.uniform());
    for (auto [w, r] : {std::pair{&doc.diffuse, &back.diffuse},
                        std::pair{&doc.feature, &back.feature}, std::pair{&doc.mask, &back.mask}}) {
      const QString why = compareLayer(*w, *r, n);
      QVERIFY2(
          why.isEmpty(),
          qPrintable(QString("compression %1: %2").arg(static_cast<int>(compression)).arg(why)));
    }
    Document positionsOnly;
    NO_THROW(positionsOnly = readDocument(p, DocumentReadOptions{false}));
    QVERIFY(positionsBitExact(doc.positions, positionsOnly.positions));
    QVERIFY(positionsOnly.diffuse.uniform() && positionsOnly.feature.uniform());
  }

  // A truncated uncompressed file is refused, whatever its length.
  const fs::path p = path("raw.exr");
  NO_THROW(writeDocument(doc, p, {DocumentCompression::None, 1}));
  const std::string bytes = readBytes(p);
  const fs::path cut = path("raw-cut.exr");
  for (std::size_t k = 1; k < 20; ++k) {
    writeBytes(cut, std::string_view(bytes).substr(0, bytes.size() * k / 20));
    const QString why = expectError([&] { readDocument(cut); }, ErrorKind::InvalidInput, "");
    QVERIFY2(why.isEmpty(), qPrintable(QString("length %1/20: %2").arg(k).arg(why)));
  }
}

// Uncompressed documents are read and written line by line on every core, beside OpenEXR's frame
// buffers: the file must be the one OpenEXR writes itself from the same header and pixels, byte
// for byte, and a line that is not where the offset table says is refused.
void DocumentIoTest::rawLinesAreOpenExrsOwn() {
  const int n = 256;
  Document doc = makeTestDocument(n);
  const int side = n + 1;
  const std::size_t texels = std::size_t(side) * side;
  doc.feature.texels.resize(texels * 3);
  for (std::size_t t = 0; t < texels * 3; ++t)
    doc.feature.texels[t] = float(t % 11) / 16.0f;
  // RLE, coded by raw_exr_lines as OpenEXR's RleCompressor codes it: OpenEXR's own file of the
  // pixels it decodes from ours is the same bytes.
  {
    const fs::path rle = path("rle-ours.exr"), rleTheirs = path("rle-theirs.exr");
    NO_THROW(writeDocument(doc, rle, {DocumentCompression::Rle, 1}));
    Imf::InputFile in(rle.c_str());
    QCOMPARE(in.header().compression(), Imf::RLE_COMPRESSION);
    std::vector<std::vector<char>> planes;
    Imf::FrameBuffer frame;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
      const std::size_t size = it.channel().type == Imf::HALF ? 2 : 4;
      planes.emplace_back(texels * size);
      frame.insert(it.name(),
                   Imf::Slice(it.channel().type, planes.back().data(), size, size * side));
    }
    in.setFrameBuffer(frame);
    in.readPixels(0, n);
    {
      Imf::OutputFile out(rleTheirs.c_str(), in.header());
      out.setFrameBuffer(frame);
      out.writePixels(side);
    }
    const std::string a = readBytes(rle), b = readBytes(rleTheirs);
    QCOMPARE(a.size(), b.size());
    QVERIFY2(a == b, "the RLE document differs from OpenEXR's own file");
    QVERIFY(positionsBitExact(doc.positions, readDocument(rle).positions));
    // Decoded by raw_exr_lines too: OpenEXR's own file reads back, painted feature and all.
    Document back;
    NO_THROW(back = readDocument(rleTheirs));
    QVERIFY(positionsBitExact(doc.positions, back.positions));
    QVERIFY(!back.feature.uniform() && back.diffuse.uniform() && back.hasMask);
    const QString kept = compareLayer(doc.feature, back.feature, n);
    QVERIFY2(kept.isEmpty(), qPrintable(kept));

    // Line 100's code made to lie: its byte count one short (the code then ends inside a run or
    // expands short), its first code byte a run that overruns the line, and a count past the
    // line's size: each refused with the line named, nothing read past the chunk.
    std::size_t at = std::string::npos;
    std::int32_t coded = 0;
    for (std::size_t k = 0; k + 8 < a.size() && at == std::string::npos; ++k) {
      std::int32_t y, size, nextY;
      std::memcpy(&y, a.data() + k, 4);
      std::memcpy(&size, a.data() + k + 4, 4);
      if (y != 100 || size <= 0 || k + 8 + std::size_t(size) + 4 > a.size()) continue;
      std::memcpy(&nextY, a.data() + k + 8 + std::size_t(size), 4);
      if (nextY == 101) at = k, coded = size;
    }
    QVERIFY(at != std::string::npos);
    std::int32_t lineBytes = 0;
    for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it)
      lineBytes += side * (it.channel().type == Imf::HALF ? 2 : 4);
    QVERIFY(coded < lineBytes); // coded, not stored
    const auto refused = [&](const char* what, const std::function<void(std::string&)>& lie) {
      std::string bytes = a;
      lie(bytes);
      const fs::path bad = path("rle-lying.exr");
      writeBytes(bad, bytes);
      const QString why =
          expectError([&] { readDocument(bad); }, ErrorKind::InvalidInput, "line 100");
      QVERIFY2(why.isEmpty(), qPrintable(QString(what) + ": " + why));
    };
    refused("a byte short", [&](std::string& bytes) {
      const std::int32_t shorter = coded - 1;
      std::memcpy(bytes.data() + at + 4, &shorter, 4);
    });
    refused("a run past the line", [&](std::string& bytes) {
      for (std::size_t k = 0; k + 1 < std::size_t(coded); k += 2) { // every code a 128-byte run
        bytes[at + 8 + k] = char(127);
      }
    });
    refused("a count past the line", [&](std::string& bytes) {
      const std::int32_t longer = lineBytes + 1;
      std::memcpy(bytes.data() + at + 4, &longer, 4);
    });
  }

  const fs::path ours = path("raw-ours.exr");
  NO_THROW(writeDocument(doc, ours, {DocumentCompression::None, 1}));

  // OpenEXR's own decoding of our file, then its own encoding of those pixels under our header.
  Imf::InputFile in(ours.c_str());
  QCOMPARE(in.header().compression(), Imf::NO_COMPRESSION);
  std::vector<std::vector<char>> planes;
  Imf::FrameBuffer frame;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
    const std::size_t size = it.channel().type == Imf::HALF ? 2 : 4;
    planes.emplace_back(texels * size);
    frame.insert(it.name(), Imf::Slice(it.channel().type, planes.back().data(), size, size * side));
  }
  in.setFrameBuffer(frame);
  in.readPixels(0, n);
  for (int j = 0; j < side; j += 37) // P.X, P.Y, P.Z are the first three planes (alphabetical)
    for (int i = 0; i < side; i += 5)
      for (int c = 0; c < 3; ++c) {
        float v;
        std::memcpy(&v, planes[std::size_t(c)].data() + (std::size_t(j) * side + i) * 4, 4);
        const Vec4f& t = doc.positions.at(i, j);
        QCOMPARE(v, c == 0 ? t.x : c == 1 ? t.y : t.z);
      }
  const fs::path theirs = path("raw-theirs.exr");
  {
    Imf::OutputFile out(theirs.c_str(), in.header());
    out.setFrameBuffer(frame);
    out.writePixels(side);
  }
  const std::string a = readBytes(ours), b = readBytes(theirs);
  QCOMPARE(a.size(), b.size());
  QVERIFY2(a == b, "the uncompressed document differs from OpenEXR's own file");

  // And OpenEXR's file reads back as written: painted feature, uniform diffuse, the mask.
  Document back;
  NO_THROW(back = readDocument(theirs));
  QVERIFY(positionsBitExact(doc.positions, back.positions));
  QVERIFY(!back.feature.uniform() && back.diffuse.uniform() && back.hasMask);
  for (auto [w, r] : {std::pair{&doc.diffuse, &back.diffuse},
                      std::pair{&doc.feature, &back.feature}, std::pair{&doc.mask, &back.mask}}) {
    const QString why = compareLayer(*w, *r, n);
    QVERIFY2(why.isEmpty(), qPrintable(why));
  }

  // Line 100's chunk says it is line 101: refused with the line named, never read as pixels.
  std::string moved = a;
  std::size_t at = std::string::npos;
  for (std::size_t k = a.size() / 2; k-- > 0;) { // the chunk of line 100: y = 100, then its size
    std::int32_t y;
    std::memcpy(&y, a.data() + k, 4);
    if (y == 100 && k + 8 < a.size()) {
      std::int32_t next;
      std::memcpy(&next, a.data() + k + 4, 4);
      if (next > 0 && std::size_t(next) == (a.size() - k) / std::size_t(side - 100) - 8) {
        at = k;
        break;
      }
    }
  }
  QVERIFY(at != std::string::npos);
  const std::int32_t wrong = 101;
  std::memcpy(moved.data() + at, &wrong, 4);
  const fs::path bad = path("raw-moved-line.exr");
  writeBytes(bad, moved);
  const QString why = expectError([&] { readDocument(bad); }, ErrorKind::InvalidInput, "line 100");
  QVERIFY2(why.isEmpty(), qPrintable(why));
}

void DocumentIoTest::header() {
  DocumentHeader h;
  NO_THROW(h = readDocumentHeader(goodFile()));
  QCOMPARE(h.size, 64);
  QCOMPARE(h.formatVersion, kDocumentFormatVersion);
  const std::set<std::string> channels(h.channels.begin(), h.channels.end());
  for (const char* c : {"P.X", "P.Y", "P.Z", "diffuse.R", "diffuse.G", "diffuse.B", "diffuse.A",
                        "feature.R", "feature.G", "feature.B", "mask.Y"})
    QVERIFY2(channels.count(c) == 1, c);
  QCOMPARE(channels.size(), std::size_t{11});

  Document noMask = makeDocument(makeBaseShape(BaseShape::Sphere, 8));
  DocumentHeader h2;
  NO_THROW(writeDocument(noMask, path("nomask.exr")));
  NO_THROW(h2 = readDocumentHeader(path("nomask.exr")));
  QCOMPARE(h2.size, 8);
  QCOMPARE(h2.channels.size(), std::size_t{10});
}

void DocumentIoTest::missingFile() {
  const fs::path p = path("does-not-exist.exr");
  EXPECT_ERROR(readDocument(p), ErrorKind::Io, "does-not-exist.exr");
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::Io, "does-not-exist.exr");
}

void DocumentIoTest::notExr() {
  const fs::path p = path("notes.exr");
  writeBytes(p, "these are not the pixels you are looking for\n");
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "OpenEXR");
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, "OpenEXR");
  writeBytes(p, "");
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "OpenEXR");
  // A compressed model given where a document goes: told how to open it.
  const fs::path ocz = path("model.ocz");
  writeBytes(ocz, std::string("OCZ1") + std::string(60, '\0'));
  EXPECT_ERROR(readDocument(ocz), ErrorKind::InvalidInput, "decompress it first");
  EXPECT_ERROR(readDocumentHeader(ocz), ErrorKind::InvalidInput, ".ocz");
}

void DocumentIoTest::foreignExr() {
  const fs::path p = path("foreign.exr");
  writeRawExr(p, 65, 65, kP);
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, "Octaclay");
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "Octaclay");
  // Sanity: the same writer with the document's attributes makes a readable document.
  const fs::path q = path("rewritten.exr");
  writeRawExr(q, 65, 65, kP, goodFile());
  Document d;
  NO_THROW(d = readDocument(q));
  QCOMPARE(d.size(), 64);
  QCOMPARE(d.positions.at(3, 0).y, std::sin(0.1f * 3 + 1) * std::cos(0.0f));
}

void DocumentIoTest::newerVersion() {
  const fs::path p = path("future.exr");
  writeRawExr(p, 65, 65, kP, goodFile(), [](Imf::Header& h) {
    for (auto it = h.begin(); it != h.end(); ++it)
      if (auto* a = dynamic_cast<Imf::IntAttribute*>(&it.attribute()))
        if (a->value() == kDocumentFormatVersion) a->value() = kDocumentFormatVersion + 1;
  });
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, "version");
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "version");
}

void DocumentIoTest::truncated() {
  const std::string bytes = readBytes(goodFile());
  QVERIFY(bytes.size() > 1000);
  std::vector<std::size_t> lengths;
  for (std::size_t k = 0; k < 40; ++k)
    lengths.push_back(bytes.size() * k / 40);
  for (std::size_t len = 1; len < 400; len += 23)
    lengths.push_back(len);
  lengths.push_back(bytes.size() - 1);
  const fs::path p = path("truncated.exr");
  for (std::size_t len : lengths) {
    writeBytes(p, std::string_view(bytes).substr(0, len));
    const QString why = expectError([&] { readDocument(p); }, ErrorKind::InvalidInput, "");
    QVERIFY2(why.isEmpty(),
             qPrintable(QString("length %1 of %2: %3").arg(len).arg(bytes.size()).arg(why)));
  }
  // The message says what is wrong once the header is intact.
  writeBytes(p, std::string_view(bytes).substr(0, bytes.size() / 2));
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "truncated");
}

void DocumentIoTest::missingChannel() {
  const fs::path p = path("nopz.exr");
  writeRawExr(p, 65, 65, {"P.X", "P.Y"}, goodFile());
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, "P.Z");
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "P.Z");
}

void DocumentIoTest::badSize_data() {
  QTest::addColumn<int>("width");
  QTest::addColumn<int>("height");
  QTest::newRow("10x10") << 10 << 10;
  QTest::newRow("65x64") << 65 << 64;
  QTest::newRow("64x64") << 64 << 64;
  QTest::newRow("2x2") << 2 << 2;
  QTest::newRow("16385x1") << 16385 << 1;
}

void DocumentIoTest::badSize() {
  QFETCH(int, width);
  QFETCH(int, height);
  const fs::path p = path("badsize.exr");
  writeRawExr(p, width, height, kP, goodFile());
  // The message names the size it found.
  EXPECT_ERROR(readDocumentHeader(p), ErrorKind::InvalidInput, QString::number(width));
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, QString::number(height));
}

void DocumentIoTest::nonFinitePositions() {
  Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, 16));
  doc.positions.at(3, 4).y = std::numeric_limits<float>::quiet_NaN();
  const fs::path p = path("nan.exr");
  try {
    writeDocument(doc, p); // refusing to write it is fine too
  } catch (const Error&) {
    QVERIFY(!fs::exists(p));
    return;
  }
  EXPECT_ERROR(readDocument(p), ErrorKind::InvalidInput, "finite");
}

void DocumentIoTest::unwritablePath() {
  const Document doc = makeTestDocument(16);
  const fs::path root(dir_.path().toStdString());
  const auto before = listDir(root);

  const fs::path inMissingDir = root / "no-such-dir" / "doc.exr";
  EXPECT_ERROR(writeDocument(doc, inMissingDir), ErrorKind::Io, "doc.exr");
  QVERIFY(!fs::exists(inMissingDir.parent_path()));

  const fs::path isDir = root / "a-directory.exr";
  fs::create_directory(isDir);
  EXPECT_ERROR(writeDocument(doc, isDir), ErrorKind::Io, "a-directory.exr");
  QVERIFY(fs::is_directory(isDir));
  QVERIFY(fs::is_empty(isDir));

  auto after = listDir(root);
  after.erase("a-directory.exr");
  QVERIFY2(after == before, "a failed write left a file behind");
}

void DocumentIoTest::failedOverwriteKeepsOldFile() {
  const fs::path root(dir_.path().toStdString());
  const fs::path p = root / "overwrite.exr";
  fs::copy_file(goodFile(), p, fs::copy_options::overwrite_existing);
  const std::string good = readBytes(p);
  const auto before = listDir(root);

  // Another document, whose file size we measure first; written compressed (OpenEXR's frame
  // buffers) and raw (lines pwritten on every core, raw_exr_lines).
  const Document other = makeDocument(makeBaseShape(BaseShape::Sphere, 64));
  const auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
  for (const DocumentWriteOptions options :
       {DocumentWriteOptions{}, DocumentWriteOptions{DocumentCompression::None, 1}}) {
    NO_THROW(writeDocument(other, root / "measure.exr", options));
    const auto otherSize = fs::file_size(root / "measure.exr");
    fs::remove(root / "measure.exr");
    QVERIFY(otherSize > 2000);

    // Root ignores permissions, so make the write fail with a file-size limit (EFBIG): once early,
    // and once only a few bytes short of the full file.
    rlimit old{};
    QCOMPARE(getrlimit(RLIMIT_FSIZE, &old), 0);
    for (rlim_t limit : {rlim_t(1024), rlim_t(otherSize / 2), rlim_t(otherSize - 8)}) {
      rlimit lowered = old;
      lowered.rlim_cur = limit;
      QCOMPARE(setrlimit(RLIMIT_FSIZE, &lowered), 0);
      const QString why = expectError([&] { writeDocument(other, p, options); }, ErrorKind::Io, "");
      setrlimit(RLIMIT_FSIZE, &old);
      const std::string now = readBytes(p);
      QVERIFY2(why.isEmpty(),
               qPrintable(QString("limit %1 of %2 bytes: %3; %4 now holds %5 bytes%6")
                              .arg(limit)
                              .arg(otherSize)
                              .arg(why)
                              .arg(QString::fromStdString(p.filename().string()))
                              .arg(now.size())
                              .arg(now == good ? " (unchanged)" : " (replaced)")));
      QVERIFY2(now == good, qPrintable(QString("limit %1: old file changed").arg(limit)));
      QVERIFY2(listDir(root) == before, qPrintable(QString("limit %1: temporary left").arg(limit)));
    }
  }
  std::signal(SIGXFSZ, oldHandler);
  Document kept, replaced;
  NO_THROW(kept = readDocument(p));
  QVERIFY(positionsBitExact(kept.positions, makeTestDocument(64).positions));

  // And a successful overwrite replaces it.
  NO_THROW(writeDocument(other, p));
  NO_THROW(replaced = readDocument(p));
  QVERIFY(positionsBitExact(replaced.positions, other.positions));
  QVERIFY(listDir(root) == before);
}

QTEST_APPLESS_MAIN(DocumentIoTest)
#include "document_io_test.moc"
