// Torus and plane documents in the .exr file: the topology and size attributes round-trip
// bit-exactly, and a header that lies about them is refused before anything is allocated.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <string>
#include <vector>

using namespace octaclay::core;

namespace {

bool sameTexels(const GeometryImage& a, const GeometryImage& b) {
  return a.grid() == b.grid() &&
         std::memcmp(a.texels().data(), b.texels().data(), a.byteSize()) == 0;
}

// An Octaclay-looking file of (columns × rows) samples with the given string and int attributes.
void writeFake(const std::string& path, int columns, int rows,
               const std::vector<std::pair<const char*, std::string>>& strings,
               const std::vector<std::pair<const char*, int>>& ints) {
  Imf::Header header(columns, rows);
  header.insert("octaclay.format", Imf::IntAttribute(kDocumentFormatVersion));
  for (const auto& [name, value] : strings)
    header.insert(name, Imf::StringAttribute(value));
  for (const auto& [name, value] : ints)
    header.insert(name, Imf::IntAttribute(value));
  std::vector<float> zeros(static_cast<std::size_t>(columns) * rows, 0.0f);
  Imf::FrameBuffer frame;
  for (const char* c : {"P.X", "P.Y", "P.Z"}) {
    header.channels().insert(c, Imf::Channel(Imf::FLOAT));
    frame.insert(c, Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(zeros.data()), sizeof(float),
                               sizeof(float) * columns));
  }
  Imf::OutputFile file(path.c_str(), header);
  file.setFrameBuffer(frame);
  file.writePixels(rows);
}

void requireRefused(const std::string& path, const char* words) {
  try {
    readDocument(path);
    QFAIL("the file was read");
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidInput);
    QVERIFY2(std::string(e.what()).find(words) != std::string::npos, e.what());
  }
}

} // namespace

class TopologyIoTest : public QObject {
  Q_OBJECT
private slots:
  void torusAndPlaneRoundTripBitExactly_data() {
    QTest::addColumn<int>("kind");
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addRow("torus 256x64") << 0 << 256 << 64;
    QTest::addRow("torus 8x8") << 0 << 8 << 8;
    QTest::addRow("plane 64") << 1 << 64 << 64;
    QTest::addRow("disc 2") << 2 << 2 << 2;
  }
  void torusAndPlaneRoundTripBitExactly() {
    QFETCH(int, kind);
    QFETCH(int, width);
    QFETCH(int, height);
    QTemporaryDir dir;
    const std::string path = dir.filePath("doc.exr").toStdString();
    Document document = makeDocument(kind == 0   ? makeTorus(Torus{}, width, height)
                                     : kind == 1 ? makeSheet(Sheet::Square, width)
                                                 : makeSheet(Sheet::Disc, width));
    document.diffuse.texels.assign(document.positions.texelCount() * 4, 0.5f);
    document.diffuse.texels[7] = 0.25f;
    writeDocument(document, path);
    const DocumentHeader header = readDocumentHeader(path);
    QCOMPARE(header.topology, document.positions.topology());
    QCOMPARE(header.width, width);
    QCOMPARE(header.height, height);
    const Document back = readDocument(path);
    QCOMPARE(back.topology, document.topology);
    QVERIFY(sameTexels(back.positions, document.positions));
    QCOMPARE(back.diffuse.texels, document.diffuse.texels);
  }

  void aBallsFileIsWrittenAsBefore() {
    QTemporaryDir dir;
    const std::string path = dir.filePath("ball.exr").toStdString();
    writeDocument(makeDocument(makeBaseShape(BaseShape::Sphere, 16)), path);
    Imf::InputFile file(path.c_str());
    QVERIFY(!file.header().findTypedAttribute<Imf::StringAttribute>("octaclay.topology"));
    QCOMPARE(file.header()
                 .findTypedAttribute<Imf::StringAttribute>("octaclay.parameterization")
                 ->value(),
             std::string("octahedral"));
    QCOMPARE(readDocument(path).topology, Topology::Octahedral);
  }

  void lyingHeadersAreRefused() {
    QTemporaryDir dir;
    const auto path = [&](const char* name) { return dir.filePath(name).toStdString(); };
    writeFake(path("klein.exr"), 17, 17, {{"octaclay.topology", "klein"}}, {});
    requireRefused(path("klein.exr"), "topology 'klein' is not supported");
    writeFake(path("mixed.exr"), 17, 5,
              {{"octaclay.topology", "torus"}, {"octaclay.parameterization", "octahedral"}},
              {{"octaclay.width", 16}, {"octaclay.height", 4}});
    requireRefused(path("mixed.exr"), "does not match the topology");
    writeFake(path("nosize.exr"), 17, 5, {{"octaclay.topology", "torus"}}, {});
    requireRefused(path("nosize.exr"), "needs octaclay.width and octaclay.height");
    // The attributes say 2^30 cells: refused before any allocation, whatever the data window.
    writeFake(path("huge.exr"), 17, 5, {{"octaclay.topology", "plane"}},
              {{"octaclay.width", 1 << 30}, {"octaclay.height", 4}});
    requireRefused(path("huge.exr"), "is not valid");
    writeFake(path("lie.exr"), 17, 5, {{"octaclay.topology", "torus"}},
              {{"octaclay.width", 32}, {"octaclay.height", 4}});
    requireRefused(path("lie.exr"), "header says 32x4 cells");
    writeFake(path("thin.exr"), 17, 3, {{"octaclay.topology", "torus"}},
              {{"octaclay.width", 16}, {"octaclay.height", 2}});
    requireRefused(path("thin.exr"), "at least 4");
    // A ball that is not square is refused as before.
    writeFake(path("oblong.exr"), 17, 9, {}, {});
    requireRefused(path("oblong.exr"), "is not (2^k+1)x(2^k+1)");
  }

  void writingAMismatchedDocumentIsRefused() {
    QTemporaryDir dir;
    Document document = makeDocument(makeTorus(Torus{}, 16, 8));
    document.topology = Topology::Octahedral;
    QVERIFY_THROWS_EXCEPTION(Error, writeDocument(document, dir.filePath("x.exr").toStdString()));
    QVERIFY(!QFile::exists(dir.filePath("x.exr")));
  }
};

QTEST_GUILESS_MAIN(TopologyIoTest)
#include "topology_io_test.moc"
