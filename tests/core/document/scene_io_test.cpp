// Scenes in files: a multi-part EXR round trip (positions, layers and transforms bit-exact), a
// one-object scene as a plain single-part document that today's reader opens, today's files as
// one-object scenes, and the files that lie: sizes, topology, transforms, flags, names, an object
// count of 10^6, a data window 2^30 high, truncation.

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputPart.h>
#include <ImfIntAttribute.h>
#include <ImfMultiPartInputFile.h>
#include <ImfMultiPartOutputFile.h>
#include <ImfOutputPart.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

bool bitExact(const GeometryImage& a, const GeometryImage& b) {
  return a.size() == b.size() &&
         std::memcmp(a.texels().data(), b.texels().data(), a.byteSize()) == 0;
}

bool bitExact(const ObjectTransform& a, const ObjectTransform& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Three objects of three sizes, with transforms whose floats are not short decimals, a painted
// layer (values exact in half), a mask, one hidden and one locked.
Scene threeObjects() {
  Scene scene;
  Document body = makeDocument(makeBaseShape(BaseShape::Blob, 32));
  body.hasMask = true;
  body.mask.fill = {0.25f, 0, 0, 0};
  scene.objects.push_back({"Body",
                           std::move(body),
                           {{0.1f, -1.0f / 3.0f, 1e-7f}, {12.5f, -0.001f, 359.9f}, {1, 1, 1}},
                           true,
                           false});
  Document leg = makeDocument(makeCapsule(16, Capsule{0.25f, 1.5f}));
  leg.diffuse.texels.assign(leg.positions.texelCount() * 4, 0.5f);
  for (std::size_t k = 0; k < leg.diffuse.texels.size(); k += 7)
    leg.diffuse.texels[k] = 0.125f;
  scene.objects.push_back({"Leg",
                           std::move(leg),
                           {{-0.7f, 0.3f, -1.2f}, {90, 0, -45}, {0.5f, 2.0f, 1.0f / 7}},
                           false,
                           true});
  scene.objects.push_back({"Hat \xc3\xa4",
                           makeDocument(makeBaseShape(BaseShape::Cylinder, 8)),
                           {{0, 0, 2}, {}, {-1.5f, 1.5f, 0.25f}},
                           true,
                           true});
  return scene;
}

std::uint32_t versionField(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char b[8] = {};
  in.read(reinterpret_cast<char*>(b), 8);
  return std::uint32_t(b[4]) | std::uint32_t(b[5]) << 8 | std::uint32_t(b[6]) << 16 |
         std::uint32_t(b[7]) << 24;
}

// Rewrites the multi-part file `from` into `to` with its headers edited (pixels copied as they
// are): a file whose header lies but whose pixels are whole.
void rewriteHeaders(const fs::path& from, const fs::path& to,
                    const std::function<void(std::vector<Imf::Header>&)>& edit) {
  Imf::MultiPartInputFile in(from.c_str());
  std::vector<Imf::Header> headers;
  for (int k = 0; k < in.parts(); ++k)
    headers.push_back(in.header(k));
  edit(headers);
  Imf::MultiPartOutputFile out(to.c_str(), headers.data(), int(headers.size()), true);
  for (int k = 0; k < in.parts(); ++k) {
    Imf::InputPart inPart(in, k);
    Imf::OutputPart outPart(out, k);
    outPart.copyPixels(inPart);
  }
}

void putU32(std::string& bytes, std::uint32_t v) {
  for (int k = 0; k < 4; ++k)
    bytes.push_back(char((v >> (8 * k)) & 0xff));
}

// One raw header attribute: name, type, size, value.
void putAttribute(std::string& bytes, const std::string& name, const std::string& type,
                  const std::string& value) {
  bytes += name;
  bytes.push_back('\0');
  bytes += type;
  bytes.push_back('\0');
  putU32(bytes, std::uint32_t(value.size()));
  bytes += value;
}

std::string box(int xMin, int yMin, int xMax, int yMax) {
  std::string v;
  for (int x : {xMin, yMin, xMax, yMax})
    putU32(v, std::uint32_t(x));
  return v;
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

class SceneIoTest : public QObject {
  Q_OBJECT
private slots:
  void init() { QVERIFY(dir_.isValid()); }
  void threeObjectsRoundTripBitExact();
  void everyCompressionReadsBack();
  void uncompressedPartsReadByOpenExr();
  void lyingRawChunksRefused();
  void headersWithoutPixels();
  void oneObjectIsAPlainDocument();
  void todaysFileIsOneObject();
  void lyingHeaders_data();
  void lyingHeaders();
  void millionObjectsRefusedFromTheHeaders();
  void hugeWindowRefusedFromTheHeaders();
  void truncatedMultiPart();
  void badSceneWritesNothing();

private:
  fs::path path(const std::string& name) const {
    return fs::path(dir_.path().toStdString()) / name;
  }
  QTemporaryDir dir_;
};

void SceneIoTest::threeObjectsRoundTripBitExact() {
  const Scene scene = threeObjects();
  const fs::path p = path("scene.exr");
  writeScene(scene, p);
  QVERIFY2(versionField(p) & 0x1000, "three objects are not a multi-part file");
  const Scene back = readScene(p);
  QCOMPARE(back.objects.size(), std::size_t{3});
  for (std::size_t k = 0; k < 3; ++k) {
    const SceneObject& a = scene.objects[k];
    const SceneObject& b = back.objects[k];
    QCOMPARE(b.name, a.name);
    QVERIFY2(bitExact(a.transform, b.transform), a.name.c_str());
    QCOMPARE(b.visible, a.visible);
    QCOMPARE(b.locked, a.locked);
    QVERIFY2(bitExact(a.document.positions, b.document.positions), a.name.c_str());
    QCOMPARE(b.document.hasMask, a.document.hasMask);
    QCOMPARE(b.document.topology, Topology::Octahedral);
    for (auto [w, r] : {std::pair{&a.document.diffuse, &b.document.diffuse},
                        std::pair{&a.document.feature, &b.document.feature}}) {
      QCOMPARE(r->uniform(), w->uniform());
      if (w->uniform()) // a fill is stored as half: 0.8 comes back as 0.7998
        for (int c = 0; c < w->channels; ++c)
          QVERIFY(std::abs(r->fill[c] - w->fill[c]) < 1e-3f);
      else
        QVERIFY(r->texels == w->texels); // chosen exact in half
    }
  }
  QCOMPARE(back.objects[0].document.mask.fill[0], 0.25f);
  // Written again, the file is the same bytes: nothing drifts through a round trip.
  writeScene(back, path("again.exr"));
  std::ifstream one(p, std::ios::binary), two(path("again.exr"), std::ios::binary);
  QVERIFY(std::string(std::istreambuf_iterator<char>(one), {}) ==
          std::string(std::istreambuf_iterator<char>(two), {}));
}

void SceneIoTest::everyCompressionReadsBack() {
  const Scene scene = threeObjects();
  for (const DocumentCompression c : {DocumentCompression::None, DocumentCompression::Rle,
                                      DocumentCompression::Zips, DocumentCompression::Zip}) {
    const fs::path p = path("compressed.exr");
    writeScene(scene, p, {c, 1});
    const Scene back = readScene(p);
    for (std::size_t k = 0; k < 3; ++k)
      QVERIFY(bitExact(scene.objects[k].document.positions, back.objects[k].document.positions));
  }
}

// Uncompressed parts are written and read line by line straight between file and documents
// (raw_exr_lines, every part in one pass): the file must be the multi-part file OpenEXR itself
// reads, every part's pixels bit-exact there and through readScene, for a ball, a torus of W ≠ H
// with a painted layer and a plane sheet.
void SceneIoTest::uncompressedPartsReadByOpenExr() {
  Scene scene = threeObjects();
  Document ring = makeDocument(makeTorus(Torus{0.8f, 0.2f}, 32, 8));
  ring.diffuse.texels.assign(ring.positions.texelCount() * 4, 0.75f);
  for (std::size_t k = 0; k < ring.diffuse.texels.size(); k += 3)
    ring.diffuse.texels[k] = 0.0625f;
  scene.objects.push_back(
      {"Ring", std::move(ring), {{0, 1, 0}, {0, 0, 30}, {1, 1, 1}}, true, false});
  scene.objects.push_back({"Ground", makeDocument(makeSheet(Sheet::Disc, 16)), {}, true, false});
  const fs::path p = path("raw.exr");
  writeScene(scene, p, {DocumentCompression::None, 1});
  QVERIFY(versionField(p) & 0x1000);

  Imf::MultiPartInputFile file(p.c_str());
  QCOMPARE(file.parts(), 5);
  for (int k = 0; k < file.parts(); ++k) {
    const Document& written = scene.objects[std::size_t(k)].document;
    QVERIFY(file.partComplete(k));
    Imf::InputPart part(file, k);
    const Imath::Box2i window = part.header().dataWindow();
    const int columns = window.max.x - window.min.x + 1, rows = window.max.y - window.min.y + 1;
    QCOMPARE(columns, written.positions.side());
    QCOMPARE(rows, written.positions.rows());
    std::vector<float> x(std::size_t(columns) * rows), z(x.size());
    std::vector<half> red(x.size());
    Imf::FrameBuffer frame;
    const auto base = [&](auto* data, std::size_t size) {
      return reinterpret_cast<char*>(data) -
             (std::ptrdiff_t(window.min.x) + std::ptrdiff_t(window.min.y) * columns) *
                 std::ptrdiff_t(size);
    };
    frame.insert("P.X", Imf::Slice(Imf::FLOAT, base(x.data(), 4), 4, 4 * std::size_t(columns)));
    frame.insert("P.Z", Imf::Slice(Imf::FLOAT, base(z.data(), 4), 4, 4 * std::size_t(columns)));
    frame.insert("diffuse.R",
                 Imf::Slice(Imf::HALF, base(red.data(), 2), 2, 2 * std::size_t(columns)));
    part.setFrameBuffer(frame);
    part.readPixels(window.min.y, window.max.y);
    for (std::size_t t = 0; t < x.size(); ++t) {
      const Vec4f& q = written.positions.texels()[t];
      QVERIFY2(std::memcmp(&x[t], &q.x, 4) == 0 && std::memcmp(&z[t], &q.z, 4) == 0,
               qPrintable(QString("part %1 texel %2").arg(k).arg(t)));
      const float r =
          written.diffuse.uniform() ? written.diffuse.fill[0] : written.diffuse.texels[t * 4];
      QCOMPARE(float(red[t]), float(half(r)));
    }
  }

  const Scene back = readScene(p);
  QCOMPARE(back.objects.size(), scene.objects.size());
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const Document& a = scene.objects[k].document;
    const Document& b = back.objects[k].document;
    QCOMPARE(b.topology, a.topology);
    QVERIFY2(bitExact(a.positions, b.positions), scene.objects[k].name.c_str());
    QCOMPARE(b.diffuse.uniform(), a.diffuse.uniform());
    if (!a.diffuse.uniform()) QVERIFY(a.diffuse.texels == b.diffuse.texels);
    QVERIFY(bitExact(scene.objects[k].transform, back.objects[k].transform));
  }
  // The same bytes again from what was read: the raw writer is deterministic.
  writeScene(back, path("again.exr"), {DocumentCompression::None, 1});
  std::ifstream one(p, std::ios::binary), two(path("again.exr"), std::ios::binary);
  QVERIFY(std::string(std::istreambuf_iterator<char>(one), {}) ==
          std::string(std::istreambuf_iterator<char>(two), {}));
}

// An uncompressed multi-part file whose chunk lies (its part number, its line) is refused by the
// raw reader naming the line, never read into the wrong object.
void SceneIoTest::lyingRawChunksRefused() {
  const fs::path good = path("raw.exr");
  writeScene(threeObjects(), good, {DocumentCompression::None, 1});
  Imf::MultiPartInputFile file(good.c_str());
  std::string bytes;
  {
    std::ifstream in(good, std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  // The lines of every part: the offset tables' length.
  std::uint64_t tables = 0;
  for (int k = 0; k < file.parts(); ++k)
    tables +=
        std::uint64_t(file.header(k).dataWindow().max.y - file.header(k).dataWindow().min.y + 1);
  std::uint64_t firstChunk = 0;
  // The first offset table starts right after the headers: its first entry is the smallest
  // offset in the file's tables and points just past them.
  for (std::size_t at = 8; at + 8 <= bytes.size(); ++at) {
    std::uint64_t v;
    std::memcpy(&v, bytes.data() + at, 8);
    if (v == at + 8 * tables) {
      firstChunk = at; // the table's start
      break;
    }
  }
  QVERIFY2(firstChunk > 0, "no offset table found");
  std::uint64_t second; // part 2's first line: the entry after part 1's (33 lines)
  std::memcpy(&second, bytes.data() + firstChunk + 8 * 33, 8);
  for (const auto& [offset, value, needle] :
       {std::tuple{std::uint64_t(0), std::int32_t(2), "of part 2"},
        std::tuple{std::uint64_t(4), std::int32_t(5), "holds line 5"}}) {
    std::string lying = bytes;
    std::memcpy(lying.data() + second + offset, &value, 4);
    const fs::path p = path("lying-chunk.exr");
    std::ofstream(p, std::ios::binary).write(lying.data(), std::streamsize(lying.size()));
    ErrorKind kind = ErrorKind::Io;
    const QString message = errorOf([&] { (void)readScene(p); }, kind);
    QCOMPARE(kind, ErrorKind::InvalidInput);
    QVERIFY2(message.contains(needle) && message.contains("line 0 of part 1"), qPrintable(message));
  }
}

void SceneIoTest::headersWithoutPixels() {
  writeScene(threeObjects(), path("scene.exr"));
  const auto headers = readSceneHeaders(path("scene.exr"));
  QCOMPARE(headers.size(), std::size_t{3});
  QCOMPARE(headers[1].name, std::string("Leg"));
  QCOMPARE(headers[1].width, 16); // cells
  QCOMPARE(headers[1].height, 16);
  QCOMPARE(headers[1].document.size, 16);
  QCOMPARE(headers[2].width, 8);
  QVERIFY(!headers[1].visible && headers[1].locked);
  QCOMPARE(headers[1].transform.scale.z, 1.0f / 7);
}

void SceneIoTest::oneObjectIsAPlainDocument() {
  Scene scene = threeObjects();
  scene.objects.erase(scene.objects.begin(), scene.objects.begin() + 1);
  scene.objects.pop_back();
  const fs::path p = path("leg.exr");
  writeScene(scene, p);
  QVERIFY2(!(versionField(p) & 0x1000), "a one-object scene is written as multi-part");
  // Today's reader opens it as it is.
  const Document plain = readDocument(p);
  QVERIFY(bitExact(plain.positions, scene.objects[0].document.positions));
  QVERIFY(plain.diffuse.texels == scene.objects[0].document.diffuse.texels);
  // And the scene reader gives the object back whole, with its name and transform.
  const Scene back = readScene(p);
  QCOMPARE(back.objects.size(), std::size_t{1});
  QCOMPARE(back.objects[0].name, std::string("Leg"));
  QVERIFY(bitExact(back.objects[0].transform, scene.objects[0].transform));
  QVERIFY(!back.objects[0].visible && back.objects[0].locked);
  // Past the raw-lines size (N > 2048 writes uncompressed lines): the same.
  scene.objects[0].document = makeDocument(makeBaseShape(BaseShape::Sphere, 8));
  writeScene(scene, p, {DocumentCompression::None, 1});
  QVERIFY(bitExact(readDocument(p).positions, scene.objects[0].document.positions));
  QVERIFY(bitExact(readScene(p).objects[0].transform, scene.objects[0].transform));
}

void SceneIoTest::todaysFileIsOneObject() {
  const Document doc = makeDocument(makeBaseShape(BaseShape::Cube, 16));
  const fs::path p = path("creature.exr");
  writeDocument(doc, p);
  const Scene scene = readScene(p);
  QCOMPARE(scene.objects.size(), std::size_t{1});
  QCOMPARE(scene.objects[0].name, std::string("creature")); // from the file's name
  QVERIFY(bitExact(scene.objects[0].transform, ObjectTransform{}));
  QVERIFY(scene.objects[0].visible && !scene.objects[0].locked);
  QVERIFY(bitExact(scene.objects[0].document.positions, doc.positions));
  // A stem that is no object name: "Model".
  const fs::path q = path("a,b.exr");
  writeDocument(doc, q);
  QCOMPARE(readScene(q).objects[0].name, std::string("Model"));
}

void SceneIoTest::lyingHeaders_data() {
  QTest::addColumn<int>("lie");
  QTest::addColumn<QString>("needle");
  QTest::newRow("width") << 0 << "octaclay.width = 99";
  QTest::newRow("height") << 1 << "octaclay.height = 5";
  QTest::newRow("unknown topology") << 2 << "unknown topology 'klein'";
  QTest::newRow("NaN translation") << 3 << "not a finite number";
  QTest::newRow("zero scale") << 4 << "scale z = 0";
  QTest::newRow("visible 7") << 5 << "octaclay.visible is 7";
  QTest::newRow("repeated name") << 6 << "both named 'Body'";
  QTest::newRow("comma in name") << 7 << "comma";
  QTest::newRow("newer format in one part") << 8 << "format version 2";
}

void SceneIoTest::lyingHeaders() {
  QFETCH(int, lie);
  QFETCH(QString, needle);
  writeScene(threeObjects(), path("good.exr"));
  const fs::path p = path("lying.exr");
  rewriteHeaders(path("good.exr"), p, [&](std::vector<Imf::Header>& h) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    switch (lie) {
    case 0:
      h[1].insert("octaclay.width", Imf::IntAttribute(99));
      break;
    case 1:
      h[2].insert("octaclay.height", Imf::IntAttribute(5));
      break;
    case 2:
      h[1].insert("octaclay.parameterization", Imf::StringAttribute("klein"));
      break;
    case 3:
      h[2].insert("octaclay.translation", Imf::V3fAttribute({0, nan, 0}));
      break;
    case 4:
      h[0].insert("octaclay.scale", Imf::V3fAttribute({1, 1, 0}));
      break;
    case 5:
      h[1].insert("octaclay.visible", Imf::IntAttribute(7));
      break;
    case 6:
      h[2].insert("octaclay.name", Imf::StringAttribute("Body"));
      break;
    case 7:
      h[2].insert("octaclay.name", Imf::StringAttribute("a,b"));
      break;
    case 8:
      h[1].insert("octaclay.format", Imf::IntAttribute(2));
      break;
    }
  });
  for (const bool headersOnly : {false, true}) {
    ErrorKind kind = ErrorKind::Io;
    const QString message =
        errorOf([&] { headersOnly ? (void)readSceneHeaders(p) : (void)readScene(p); }, kind);
    QCOMPARE(kind, ErrorKind::InvalidInput);
    QVERIFY2(message.contains(needle), qPrintable(message));
  }
}

void SceneIoTest::millionObjectsRefusedFromTheHeaders() {
  // A multi-part file declaring 10^6 parts, each a name and a small data window: refused after
  // reading 1025 of them, before OpenEXR sizes anything from the count.
  std::string bytes;
  putU32(bytes, 20000630);   // the magic number 76 2f 31 01
  putU32(bytes, 2 | 0x1000); // version 2, multi-part
  std::string header;
  putAttribute(header, "dataWindow", "box2i", box(0, 0, 2, 2));
  putAttribute(header, "name", "string", "x");
  header.push_back('\0');
  bytes.reserve(bytes.size() + header.size() * 1000000 + 1);
  for (int k = 0; k < 1000000; ++k)
    bytes += header;
  bytes.push_back('\0');
  const fs::path p = path("million.exr");
  std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
  for (const bool headersOnly : {false, true}) {
    ErrorKind kind = ErrorKind::Io;
    const QString message =
        errorOf([&] { headersOnly ? (void)readSceneHeaders(p) : (void)readScene(p); }, kind);
    QCOMPARE(kind, ErrorKind::InvalidInput);
    QVERIFY2(message.contains("more than 1024 objects"), qPrintable(message));
  }
}

void SceneIoTest::hugeWindowRefusedFromTheHeaders() {
  for (const bool multi : {true, false}) {
    std::string bytes;
    putU32(bytes, 20000630);
    putU32(bytes, multi ? (2 | 0x1000) : 2);
    putAttribute(bytes, "dataWindow", "box2i", box(0, 0, 2, (1 << 30)));
    putAttribute(bytes, "chunkCount", "int", std::string(4, '\x01'));
    bytes.push_back('\0');
    if (multi) bytes.push_back('\0');
    bytes += std::string(64, '\0');
    const fs::path p = path("tall.exr");
    std::ofstream(p, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size()));
    ErrorKind kind = ErrorKind::Io;
    const QString message = errorOf([&] { (void)readScene(p); }, kind);
    QCOMPARE(kind, ErrorKind::InvalidInput);
    QVERIFY2(message.contains("3x1073741825"), qPrintable(message));
  }
}

void SceneIoTest::truncatedMultiPart() {
  writeScene(threeObjects(), path("whole.exr"));
  std::ifstream in(path("whole.exr"), std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), {}};
  // Cut inside the headers, inside the offset tables, inside the pixels.
  for (const double share : {0.02, 0.1, 0.5, 0.9, 0.999}) {
    const fs::path p = path("cut.exr");
    std::ofstream(p, std::ios::binary | std::ios::trunc)
        .write(bytes.data(), std::streamsize(double(bytes.size()) * share));
    ErrorKind kind = ErrorKind::Io;
    const QString message = errorOf([&] { (void)readScene(p); }, kind);
    QVERIFY2(kind == ErrorKind::InvalidInput, qPrintable(QString::number(share) + ": " + message));
  }
}

void SceneIoTest::badSceneWritesNothing() {
  Scene scene = threeObjects();
  scene.objects[1].transform.rotationDegrees.y = std::numeric_limits<float>::infinity();
  const fs::path folder = path("empty");
  fs::create_directory(folder);
  const fs::path p = folder / "never.exr";
  ErrorKind kind = ErrorKind::Io;
  const QString message = errorOf([&] { writeScene(scene, p); }, kind);
  QCOMPARE(kind, ErrorKind::InvalidArgument);
  QVERIFY2(message.contains("'Leg'"), qPrintable(message));
  QVERIFY(!fs::exists(p));
  QCOMPARE(std::distance(fs::directory_iterator(folder), fs::directory_iterator{}),
           std::ptrdiff_t{0});
}

QTEST_APPLESS_MAIN(SceneIoTest)
#include "scene_io_test.moc"
