// Even Out on a torus and a plane (relax.h's evenOut, detail::gridEvenOut): a pulled horn's
// stretched edges get shorter and its part more samples, the surface stays within the even-out's
// tolerance, a torus's wrap stays exact and closed, a sheet's outline stays on its rectangle and
// its corners in place, paint follows within its range; an evenly sampled torus comes back
// unchanged with the reason; damaged input is refused.

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/relax/relax.h"

#include <QtTest>

#include <cmath>
#include <cstring>

using namespace octaclay::core;

namespace {

// A W × H torus (0.7, 0.3) whose tube swells into a horn `height` long around (u0, v0), as wide
// as `spread` (its Gaussian's variance, in the image's units squared, stretched 4:1 along the
// ring).
GeometryImage hornedTorus(int w, int h, float u0, float v0, float height, float spread) {
  GeometryImage image(Topology::Torus, w, h);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) {
      const float u = float(i % w) / float(w), v = float(j % h) / float(h);
      float du = std::abs(u - u0), dv = std::abs(v - v0);
      du = std::min(du, 1 - du);
      dv = std::min(dv, 1 - dv);
      const float r = 0.3f + height * std::exp(-(du * du * 16 + dv * dv * 4) / spread);
      const float a = 2 * float(M_PI) * u, b = 2 * float(M_PI) * v;
      image.at(i, j) = {(0.7f + r * std::cos(b)) * std::cos(a),
                        (0.7f + r * std::cos(b)) * std::sin(a), r * std::sin(b), 0};
    }
  return image;
}

// A W × H sheet over [-2, 2] × [-1, 1] with a hill pulled up near its edge at (x0, y0).
GeometryImage pulledSheet(int w, int h, float x0, float y0, float height, float spread) {
  GeometryImage image(Topology::Plane, w, h);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) {
      const float x = 4 * float(i) / float(w) - 2, y = 2 * float(j) / float(h) - 1;
      const float d2 = (x - x0) * (x - x0) + (y - y0) * (y - y0);
      image.at(i, j) = {x, y, height * std::exp(-d2 / spread), 0};
    }
  return image;
}

Document painted(GeometryImage image) {
  Document doc = makeDocument(std::move(image));
  const int w = doc.positions.width(), h = doc.positions.height();
  doc.diffuse.texels.resize(doc.positions.texelCount() * 4);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) {
      const float red = (i % w) < w / 2 ? 0.9f : 0.2f;
      const std::size_t t = static_cast<std::size_t>(j) * static_cast<std::size_t>(w + 1) + i;
      doc.diffuse.texels[t * 4] = red;
      doc.diffuse.texels[t * 4 + 1] = doc.diffuse.texels[t * 4 + 2] = 0.3f;
      doc.diffuse.texels[t * 4 + 3] = 1;
    }
  return doc;
}

bool sameBits(const Vec4f& a, const Vec4f& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

class GridEvenOutTest : public QObject {
  Q_OBJECT
private slots:
  void hornOnATorus_data();
  void hornOnATorus();
  void pulledSheetKeepsItsOutline();
  void anEvenTorusStaysAsItIs();
  void refusesDamagedInput();
};

void GridEvenOutTest::hornOnATorus_data() {
  QTest::addColumn<int>("width");
  QTest::addColumn<int>("height");
  QTest::addColumn<float>("u0");
  QTest::addColumn<float>("v0");
  QTest::addColumn<float>("horn");
  QTest::addColumn<float>("spread");
  QTest::newRow("256 x 128, off centre") << 256 << 128 << 0.37f << 0.2f << 0.5f << 0.05f;
  QTest::newRow("256 x 128, across both wraps") << 256 << 128 << 0.0f << 0.0f << 0.5f << 0.05f;
  QTest::newRow("256 x 128, across the ring's wrap")
      << 256 << 128 << 0.02f << 0.6f << 0.5f << 0.05f;
}

void GridEvenOutTest::hornOnATorus() {
  QFETCH(int, width);
  QFETCH(int, height);
  QFETCH(float, u0);
  QFETCH(float, v0);
  QFETCH(float, horn);
  QFETCH(float, spread);
  const Document doc = painted(hornedTorus(width, height, u0, v0, horn, spread));
  const EvenOutResult r = evenOut(doc);
  qInfo("%s: longest %.2f -> %.2f x the median, p99 %.2f -> %.2f, stretched samples %zu -> %zu, "
        "step %.3f, moved RMS %.4f %%, Hausdorff %.4f %%",
        QTest::currentDataTag(), r.before.longestOverMedian, r.after.longestOverMedian,
        r.before.p99OverMedian, r.after.p99OverMedian, r.stretchedBefore, r.stretchedAfter, r.step,
        100 * r.moved.rms, 100 * r.moved.hausdorff);
  QVERIFY2(r.changed, r.reason.c_str());
  QVERIFY(r.after.longestOverMedian < 0.85 * r.before.longestOverMedian);
  QVERIFY(r.stretchedAfter > r.stretchedBefore);
  QVERIFY(r.moved.rms <= 1e-4 && r.moved.hausdorff <= 1e-3);
  const GeometryImage& p = r.document.positions;
  QCOMPARE(p.width(), width);
  QCOMPARE(p.height(), height);
  for (int j = 0; j <= height; ++j)
    QVERIFY(sameBits(p.at(width, j), p.at(0, j)));
  for (int i = 0; i <= width; ++i)
    QVERIFY(sameBits(p.at(i, height), p.at(i, 0)));
  const MeshTopology t = analyzeTopology(extractMesh(p));
  QVERIFY(t.closed());
  QCOMPARE(t.euler, 0LL);
  QCOMPARE(t.degenerateTriangles, std::size_t(0));
  for (std::size_t k = 0; k < r.document.diffuse.texels.size(); k += 4)
    QVERIFY(r.document.diffuse.texels[k] >= 0.2f - 1e-6f &&
            r.document.diffuse.texels[k] <= 0.9f + 1e-6f);
}

void GridEvenOutTest::pulledSheetKeepsItsOutline() {
  const Document doc = painted(pulledSheet(128, 64, 1.6f, -0.7f, 0.5f, 0.08f));
  const EvenOutResult r = evenOut(doc);
  qInfo("sheet: longest %.2f -> %.2f x the median, stretched samples %zu -> %zu, step %.3f",
        r.before.longestOverMedian, r.after.longestOverMedian, r.stretchedBefore, r.stretchedAfter,
        r.step);
  QVERIFY2(r.changed, r.reason.c_str());
  QVERIFY(r.after.longestOverMedian < r.before.longestOverMedian);
  const GeometryImage& p = r.document.positions;
  const int w = p.width(), h = p.height();
  for (int j = 0; j <= h; ++j) {
    QVERIFY(std::abs(p.at(0, j).x + 2) < 1e-5f);
    QVERIFY(std::abs(p.at(w, j).x - 2) < 1e-5f);
  }
  for (int i = 0; i <= w; ++i) {
    QVERIFY(std::abs(p.at(i, 0).y + 1) < 1e-5f);
    QVERIFY(std::abs(p.at(i, h).y - 1) < 1e-5f);
  }
  for (const auto& [i, j] : {std::pair{0, 0}, {w, 0}, {0, h}, {w, h}})
    QVERIFY(sameBits(p.at(i, j), doc.positions.at(i, j)));
  const MeshTopology t = analyzeTopology(extractMesh(p));
  QCOMPARE(t.euler, 1LL);
  QCOMPARE(t.boundaryEdges, std::size_t(2 * (w + h)));
}

void GridEvenOutTest::anEvenTorusStaysAsItIs() {
  const Document doc = makeDocument(makeTorus(Torus{}, 128, 64));
  const EvenOutResult r = evenOut(doc);
  QVERIFY(!r.changed);
  QVERIFY2(r.reason.find("already as even") != std::string::npos, r.reason.c_str());
  QVERIFY(std::memcmp(r.document.positions.texels().data(), doc.positions.texels().data(),
                      doc.positions.byteSize()) == 0);
}

void GridEvenOutTest::refusesDamagedInput() {
  Document doc = makeDocument(makeTorus(Torus{}, 16, 8));
  doc.positions.at(3, 2).y = std::nanf("");
  try {
    evenOut(doc);
    QFAIL("a NaN position was evened out");
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidInput);
  }
}

QTEST_APPLESS_MAIN(GridEvenOutTest)
#include "grid_even_out_test.moc"
