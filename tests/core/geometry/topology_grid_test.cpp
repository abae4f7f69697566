// The torus and plane topologies: wrap, seams, normals, extraction (Euler 0 closed / Euler 1 with
// one boundary loop), tile bounds and picking, beside the octahedral ball.

#include "test_meshes.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <QtTest>

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <random>
#include <set>
#include <utility>

using namespace octaclay::core;
using testing::boundaryLoops;

namespace {

// Every sample moved by a random offset: the seams open until seam() closes them again.
void scramble(GeometryImage& image, unsigned seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> offset(-0.05f, 0.05f);
  for (Vec4f& t : image.texels())
    t = {t.x + offset(random), t.y + offset(random), t.z + offset(random), t.w};
}

} // namespace

class TopologyGridTest : public QObject {
  Q_OBJECT
private slots:
  void gridsAreValidatedPerTopology() {
    QVERIFY(isValidGrid({Topology::Torus, 256, 64}));
    QVERIFY(isValidGrid({Topology::Plane, 2, 8}));
    QVERIFY(!isValidGrid({Topology::Octahedral, 64, 32})); // the ball is square
    QVERIFY(!isValidGrid({Topology::Torus, 64, 2}));       // too thin to be a ring
    QVERIFY(!isValidGrid({Topology::Plane, 64, 48}));      // not a power of two
    QVERIFY_THROWS_EXCEPTION(Error, GeometryImage(Topology::Torus, 8, 2));
    const GeometryImage image(Topology::Torus, 16, 4);
    QCOMPARE(image.side(), 17);
    QCOMPARE(image.rows(), 5);
    QCOMPARE(image.texelCount(), std::size_t(17 * 5));
  }

  void torusWrapIsPeriodicAndPlaneWrapClamps() {
    const SampleGrid torus{Topology::Torus, 16, 8};
    QCOMPARE(wrap(torus, {-1, 3}), (Sample{15, 3}));
    QCOMPARE(wrap(torus, {16, 8}), (Sample{0, 0}));
    QCOMPARE(wrap(torus, {16 * 5 + 3, -8 * 7 - 2}), (Sample{3, 6}));
    const SampleGrid plane{Topology::Plane, 16, 8};
    QCOMPARE(wrap(plane, {-3, 4}), (Sample{0, 4}));
    QCOMPARE(wrap(plane, {20, 12}), (Sample{16, 8}));
    QCOMPARE(wrap(plane, {5, 6}), (Sample{5, 6}));
    // The octahedral grid still folds as octahedral.h's wrap.
    QCOMPARE(wrap(SampleGrid{Topology::Octahedral, 16, 16}, {-1, 3}), wrap(16, {-1, 3}));
  }

  void torusSeamsExactAtEverySize_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    for (auto [w, h] : {std::pair{4, 4}, {16, 4}, {64, 32}, {256, 64}, {128, 128}})
      QTest::addRow("%dx%d", w, h) << w << h;
  }
  void torusSeamsExactAtEverySize() {
    QFETCH(int, width);
    QFETCH(int, height);
    GeometryImage image = makeTorus(Torus{}, width, height);
    QCOMPARE(maxSeamGap(image), 0.0f); // the last column and row are the first, bit for bit
    scramble(image, unsigned(width * 7 + height));
    QVERIFY(maxSeamGap(image) > 0.01f);
    seam(image);
    QCOMPARE(maxSeamGap(image), 0.0f);
    for (int j = 0; j <= height; ++j)
      QCOMPARE(image.at(width, j).xyz(), image.at(0, j).xyz());
    for (int i = 0; i <= width; ++i)
      QCOMPARE(image.at(i, height).xyz(), image.at(i, 0).xyz());
  }

  void planeHasNoSeams() {
    GeometryImage image = makeSheet(Sheet::Square, 32);
    scramble(image, 5);
    const GeometryImage before = image;
    seam(image);
    QCOMPARE(maxSeamGap(image), 0.0f);
    QVERIFY(std::equal(before.texels().begin(), before.texels().end(), image.texels().begin(),
                       [](Vec4f a, Vec4f b) { return a.xyz() == b.xyz() && a.w == b.w; }));
  }

  void torusMeshIsClosedWithEulerZero_data() {
    QTest::addColumn<int>("width");
    QTest::addColumn<int>("height");
    QTest::addColumn<int>("step");
    for (auto [w, h, s] : {std::tuple{4, 4, 1}, {64, 16, 1}, {64, 16, 4}, {256, 128, 2}})
      QTest::addRow("%dx%d/%d", w, h, s) << w << h << s;
  }
  void torusMeshIsClosedWithEulerZero() {
    QFETCH(int, width);
    QFETCH(int, height);
    QFETCH(int, step);
    const Torus torus{0.7f, 0.3f};
    const TriangleMesh mesh = extractMesh(makeTorus(torus, width, height), step);
    const MeshTopology topology = analyzeTopology(mesh);
    const long long cells = (long long)(width / step) * (height / step);
    QCOMPARE((long long)topology.vertices, cells);
    QCOMPARE((long long)topology.triangles, 2 * cells);
    QVERIFY(topology.closed());
    QVERIFY(topology.manifold());
    QCOMPARE(topology.degenerateTriangles, std::size_t(0));
    QCOMPARE(topology.euler, 0LL);
    // Outward: the enclosed volume is positive, below 2π²Rr² (the polygon lies inside the torus)
    // and within 10 % of it once the tube has 16 sides.
    const double exact = 2 * std::numbers::pi * std::numbers::pi * 0.7 * 0.3 * 0.3;
    const double volume = signedVolume(mesh);
    const double least = height / step >= 16 ? 0.9 * exact : 0.3 * exact;
    QVERIFY2(volume > least && volume <= exact * 1.0001,
             qPrintable(QString("volume %1 of %2").arg(volume).arg(exact)));
    for (const Vec3f& p : mesh.positions)
      QVERIFY(std::abs(torusDistance(torus, p)) < 1e-5f);
  }

  void torusAspectFollowsTheRadii() {
    QCOMPARE(torusHeight(Torus{0.7f, 0.3f}, 256), 128); // 256 · 0.3/0.7 = 110
    QCOMPARE(torusHeight(Torus{0.9f, 0.1f}, 256), 32);  // 28.4
    QCOMPARE(torusHeight(Torus{0.9f, 0.1f}, 8), 4);     // never below 4
    QVERIFY_THROWS_EXCEPTION(Error, torusHeight(Torus{0.3f, 0.7f}, 64));
    // Cells about square on a thin ring: mean spacing around the ring and around the tube agree
    // within a factor √2.
    const Torus thin{0.9f, 0.1f};
    const int w = 256, h = torusHeight(thin, w);
    const double along = 2 * std::numbers::pi * thin.major / w;
    const double around = 2 * std::numbers::pi * thin.minor / h;
    QVERIFY(along / around < std::numbers::sqrt2 && around / along < std::numbers::sqrt2);
  }

  void planeMeshHasOneBoundaryLoopWithEulerOne_data() {
    QTest::addColumn<int>("sheet");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("step");
    for (int s : {0, 1})
      for (auto [n, step] : {std::pair{2, 1}, {32, 1}, {64, 8}})
        QTest::addRow("%s %d/%d", s ? "disc" : "square", n, step) << s << n << step;
  }
  void planeMeshHasOneBoundaryLoopWithEulerOne() {
    QFETCH(int, sheet);
    QFETCH(int, n);
    QFETCH(int, step);
    const GeometryImage image = makeSheet(sheet ? Sheet::Disc : Sheet::Square, n);
    const TriangleMesh mesh = extractMesh(image, step);
    const MeshTopology topology = analyzeTopology(mesh);
    const int m = n / step;
    QCOMPARE(topology.vertices, std::size_t((m + 1) * (m + 1)));
    QCOMPARE(topology.triangles, std::size_t(2 * m * m));
    QCOMPARE(topology.boundaryEdges, std::size_t(4 * m));
    QVERIFY(topology.manifold());
    QCOMPARE(topology.euler, 1LL);
    QCOMPARE(boundaryLoops(mesh), 1);
    if (sheet == 1) // the disc's boundary samples lie on the unit circle
      for (int k = 0; k <= n; ++k)
        QVERIFY(std::abs(length(image.at(k, 0).xyz()) - 1.0f) < 1e-6f);
  }

  void normalsFollowTheTopology() {
    const GeometryImage torus = makeTorus(Torus{0.7f, 0.3f}, 64, 32);
    // Sample (0, 0) is the outer equator at +x; its neighbours across both wraps count.
    for (const Vec3f n :
         {vertexNormal(torus, {0, 0}), gridNormal(torus, {0, 0}), vertexNormal(torus, {64, 32})})
      QVERIFY2(n.x > 0.999f, qPrintable(QString("%1 %2 %3").arg(n.x).arg(n.y).arg(n.z)));
    const Vec3f top = gridNormal(torus, {16, 8}); // θ = π/2, φ = π/2: the top of the tube
    QVERIFY(top.z > 0.999f);
    const GeometryImage plane = makeSheet(Sheet::Square, 16);
    for (const Sample s : {Sample{0, 0}, Sample{16, 16}, Sample{0, 7}, Sample{8, 8}}) {
      QVERIFY(vertexNormal(plane, s).z > 0.9999f);
      QVERIFY(gridNormal(plane, s).z > 0.9999f);
    }
    QCOMPARE(computeNormals(torus).size(), torus.texelCount());
  }

  void tileBoundsAndPickingCoverWideImages() {
    const GeometryImage torus = makeTorus(Torus{0.7f, 0.3f}, 256, 64);
    const TileBounds bounds(torus);
    QCOMPARE(bounds.tilesX(), 8);
    QCOMPARE(bounds.tilesY(), 2);
    const TexelRect last = bounds.tileRect(7, 1);
    QCOMPARE(last.x + last.width, 257);
    QCOMPARE(last.y + last.height, 65);
    // Straight down onto the top of the tube at θ = π: u = 0.5, v = 0.25, z = r.
    const auto hit = pickRay(torus, bounds, Ray{{-0.7f, 0.0f, 5.0f}, {0, 0, -1}});
    QVERIFY(hit);
    QVERIFY(std::abs(hit->position.z - 0.3f) < 1e-3f);
    QVERIFY(std::abs(hit->u - 0.5f) < 1e-3f);
    QVERIFY(std::abs(hit->v - 0.25f) < 1e-3f);
    QCOMPARE(hit->sample, (Sample{128, 16}));
    // Through the hole: no hit.
    QVERIFY(!pickRay(torus, bounds, Ray{{0.0f, 0.0f, 5.0f}, {0, 0, -1}}));
    // Across the wrap (θ = 0 is column 0 and column 256): a hit at +x.
    const auto seamHit = pickRay(torus, bounds, Ray{{0.7f, 0.0f, 5.0f}, {0, 0, -1}});
    QVERIFY(seamHit);
    QVERIFY(std::abs(seamHit->position.z - 0.3f) < 1e-3f);
    const GeometryImage plane = makeSheet(Sheet::Square, 64);
    const auto planeHit = pickRay(plane, TileBounds(plane), Ray{{0.5f, -0.5f, 3.0f}, {0, 0, -1}});
    QVERIFY(planeHit);
    QVERIFY(std::abs(planeHit->u - 0.75f) < 1e-5f && std::abs(planeHit->v - 0.25f) < 1e-5f);
  }
};

QTEST_APPLESS_MAIN(TopologyGridTest)
#include "topology_grid_test.moc"
