#include "test_meshes.h"

#include "octaclay/core/error.h"
#include "octaclay/core/measure/surface_distance.h"

// The closest-point primitives are private to core; the test reaches them by path.
#include "../../../core/src/detail/aabb_tree.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <utility>

using namespace octaclay::core;
using detail::Vec3d;

namespace {

// testing::unitSphere scaled to `radius`: extreme vertices on the axes (bbox [-r, r]³).
TriangleMesh sphere(int levels, float radius) {
  TriangleMesh mesh = testing::unitSphere(levels);
  for (Vec3f& p : mesh.positions)
    p = p * radius;
  return mesh;
}

// The unit cube [0, 1]³ as 12 outward triangles, moved by `offset`.
TriangleMesh cube(Vec3f offset = {}) {
  TriangleMesh mesh;
  for (std::uint32_t i = 0; i < 8; ++i)
    mesh.positions.push_back(Vec3f{float(i & 1u), float((i >> 1) & 1u), float((i >> 2) & 1u)} +
                             offset);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}

double distanceSquared(Vec3d p, Vec3d q) {
  return dot(p - q, p - q);
}

// The squared distance from p to the nearest of mesh's triangles, each measured: what a tree's
// query must find.
double bruteForceDistanceSquared(const TriangleMesh& mesh, Vec3d p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& [a, b, c] : mesh.triangles) {
    const Vec3d q = detail::closestPointOnTriangle(
        p, Vec3d(mesh.positions[a]), Vec3d(mesh.positions[b]), Vec3d(mesh.positions[c]));
    nearest = std::min(nearest, distanceSquared(p, q));
  }
  return nearest;
}

} // namespace

class SurfaceDistanceTest : public QObject {
  Q_OBJECT

private slots:
  void closestPointRegions_data();
  void closestPointRegions();
  void closestPointDegenerate();
  void treeMatchesBruteForce();
  void treeIsTheSameOnEveryThreadCount();
  void aRefittedTreeMatchesBruteForce();
  void aTreeOverBlocksMatchesBruteForce_data();
  void aTreeOverBlocksMatchesBruteForce();
  void identicalMeshesAreZero();
  void concentricSpheres();
  void translatedCube();
  void seedStability();
  void emptyMeshThrows();
  void badIndexThrows();
  void aTangleIsBoundedFromAbove();
};

void SurfaceDistanceTest::closestPointRegions_data() {
  QTest::addColumn<Vec3d>("p");
  QTest::addColumn<Vec3d>("expected");
  // Triangle (0,0,0), (1,0,0), (0,1,0).
  QTest::newRow("vertex a") << Vec3d{-1, -1, 0.5} << Vec3d{0, 0, 0};
  QTest::newRow("vertex b") << Vec3d{2, -1, 0} << Vec3d{1, 0, 0};
  QTest::newRow("vertex c") << Vec3d{-1, 2, 3} << Vec3d{0, 1, 0};
  QTest::newRow("edge ab") << Vec3d{0.5, -1, 2} << Vec3d{0.5, 0, 0};
  QTest::newRow("edge bc") << Vec3d{1, 1, -1} << Vec3d{0.5, 0.5, 0};
  QTest::newRow("edge ca") << Vec3d{-1, 0.25, 0} << Vec3d{0, 0.25, 0};
  QTest::newRow("face above") << Vec3d{0.25, 0.25, 5} << Vec3d{0.25, 0.25, 0};
  QTest::newRow("face below") << Vec3d{0.125, 0.5, -2} << Vec3d{0.125, 0.5, 0};
  QTest::newRow("on the face") << Vec3d{0.25, 0.5, 0} << Vec3d{0.25, 0.5, 0};
}

void SurfaceDistanceTest::closestPointRegions() {
  QFETCH(Vec3d, p);
  QFETCH(Vec3d, expected);
  const Vec3d q = detail::closestPointOnTriangle(p, {0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  QVERIFY2(distanceSquared(q, expected) < 1e-24,
           qPrintable(QString("got %1 %2 %3").arg(q.x).arg(q.y).arg(q.z)));
}

void SurfaceDistanceTest::closestPointDegenerate() {
  // A point, a segment through three collinear corners, and a segment with a repeated corner.
  QCOMPARE(detail::closestPointOnTriangle({3, 4, 5}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}),
           (Vec3d{1, 1, 1}));
  QVERIFY(
      distanceSquared(detail::closestPointOnTriangle({1.5, 1, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}),
                      {1.5, 0, 0}) < 1e-24);
  QVERIFY(
      distanceSquared(detail::closestPointOnTriangle({1, 0.5, 0}, {0, 0, 0}, {0, 0, 0}, {0, 1, 0}),
                      {0, 0.5, 0}) < 1e-24);
}

void SurfaceDistanceTest::treeMatchesBruteForce() {
  // A bumpy sphere, so that many triangles are near-ties for queries around it.
  TriangleMesh mesh = sphere(4, 1);
  std::mt19937 random(7);
  std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
  for (Vec3f& p : mesh.positions)
    p = p * (1 + jitter(random));
  const detail::AabbTree tree(mesh);
  QCOMPARE(tree.triangles().size(), mesh.triangles.size());

  std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
  std::uint32_t hint = detail::AabbTree::noTriangle;
  for (int i = 0; i < 500; ++i) {
    const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
    const double expected = bruteForceDistanceSquared(mesh, p);
    const detail::AabbTree::Hit cold = tree.closest(p);
    const detail::AabbTree::Hit warm = tree.closest(p, hint);
    hint = warm.triangle;
    QVERIFY(std::abs(cold.distanceSquared - expected) <= 1e-12 * expected);
    QVERIFY(std::abs(warm.distanceSquared - expected) <= 1e-12 * expected);
  }
}

// A tree built on one surface and refitted onto the same triangles moved (a bulge pushed out
// on one side, the rest jittered): every query exact against the moved triangles, the same as a
// tree built on them; its triangles are the moved ones, in the same leaf order.
void SurfaceDistanceTest::aRefittedTreeMatchesBruteForce() {
  const TriangleMesh before = sphere(4, 1);
  TriangleMesh after = before;
  std::mt19937 random(11);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  for (Vec3f& p : after.positions)
    p = p * (1 + jitter(random) + (p.x > 0.5f ? 0.6f * (p.x - 0.5f) : 0.0f));
  detail::AabbTree tree(before);
  const std::vector<std::uint32_t> ids(tree.triangleIds().begin(), tree.triangleIds().end());
  tree.refit(after);
  QVERIFY(std::equal(ids.begin(), ids.end(), tree.triangleIds().begin()));
  for (std::size_t k = 0; k < ids.size(); ++k)
    QCOMPARE(tree.triangles()[k].a.x, after.positions[after.triangles[ids[k]][0]].x);
  const detail::AabbTree rebuilt(after);
  std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
  for (int i = 0; i < 500; ++i) {
    const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
    const double expected = bruteForceDistanceSquared(after, p);
    const detail::AabbTree::Hit hit = tree.closest(p);
    QVERIFY(std::abs(hit.distanceSquared - expected) <= 1e-12 * expected);
    QVERIFY(std::abs(rebuilt.closest(p).distanceSquared - expected) <= 1e-12 * expected);
  }
}

void SurfaceDistanceTest::aTreeOverBlocksMatchesBruteForce_data() {
  QTest::addColumn<int>("blockSize"); // 0: blocks of 1, 2, 3, … triangles in turn
  QTest::newRow("one triangle each") << 1;
  QTest::newRow("a leaf's worth") << 4;
  QTest::newRow("uneven sizes") << 0;
  QTest::newRow("128 triangles") << 128;
  QTest::newRow("one block") << 1'000'000;
}

// The tree over blocks of an order (keep detail's check: tiles of cells, each in Z order): every
// triangle once, every query exact against brute force, from a seed or cold, and again after a
// refit onto the moved triangles. The order is the mesh's own, shuffled in runs, so that some
// blocks are scattered over the sphere.
void SurfaceDistanceTest::aTreeOverBlocksMatchesBruteForce() {
  QFETCH(int, blockSize);
  TriangleMesh mesh = sphere(4, 1);
  std::mt19937 random(23);
  std::uniform_real_distribution<float> jitter(-0.05f, 0.05f);
  for (Vec3f& p : mesh.positions)
    p = p * (1 + jitter(random));
  std::vector<std::uint32_t> order(mesh.triangles.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = static_cast<std::uint32_t>(k);
  for (std::size_t k = 0; k + 64 <= order.size(); k += 256)
    std::shuffle(order.begin() + static_cast<std::ptrdiff_t>(k),
                 order.begin() + static_cast<std::ptrdiff_t>(k + 64), random);
  std::vector<std::uint32_t> starts;
  for (std::uint32_t at = 0, size = 1;
       at<order.size(); at += blockSize> 0 ? static_cast<std::uint32_t>(blockSize) : size++)
    starts.push_back(at);
  detail::AabbTree tree(mesh, order, starts);
  QCOMPARE(tree.triangles().size(), mesh.triangles.size());
  std::vector<std::uint32_t> ids(tree.triangleIds().begin(), tree.triangleIds().end());
  std::sort(ids.begin(), ids.end());
  for (std::size_t k = 0; k < ids.size(); ++k)
    QCOMPARE(ids[k], std::uint32_t(k));

  TriangleMesh moved = mesh;
  for (Vec3f& p : moved.positions)
    p = p * (1 + (p.y > 0.3f ? 0.8f * (p.y - 0.3f) : 0.0f));
  std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
  for (const TriangleMesh* surface : {&mesh, &moved}) {
    if (surface == &moved) tree.refit(moved);
    std::uint32_t hint = detail::AabbTree::noTriangle;
    for (int i = 0; i < 400; ++i) {
      const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
      const double expected = bruteForceDistanceSquared(*surface, p);
      const detail::AabbTree::Hit cold = tree.closest(p);
      const detail::AabbTree::Hit warm = tree.closest(p, hint);
      hint = warm.triangle;
      QVERIFY(std::abs(cold.distanceSquared - expected) <= 1e-12 * expected);
      QVERIFY(std::abs(warm.distanceSquared - expected) <= 1e-12 * expected);
      QVERIFY(!cold.bounded);
    }
  }
}

void SurfaceDistanceTest::treeIsTheSameOnEveryThreadCount() {
  // Enough triangles (over 100 000) that the first splits' subtrees are built on their own
  // threads; a bumpy sphere, so that the median splits meet many near-equal centres.
  TriangleMesh mesh = sphere(7, 1);
  std::mt19937 random(11);
  std::uniform_real_distribution<float> jitter(-0.02f, 0.02f);
  for (Vec3f& p : mesh.positions)
    p = p * (1 + jitter(random));
  QVERIFY(mesh.triangles.size() > 100'000);
  const detail::AabbTree one(mesh, 1);
  std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
  for (const unsigned threads : {2u, 3u, 8u}) {
    const detail::AabbTree many(mesh, threads);
    QVERIFY(std::ranges::equal(one.triangleIds(), many.triangleIds()));
    // The same nodes: a query within a small leaf budget visits the same leaves in the same
    // order, so it stops at the same triangle with the same count.
    for (int i = 0; i < 2000; ++i) {
      const Vec3d p{coordinate(random), coordinate(random), coordinate(random)};
      const detail::AabbTree::Hit a = one.closest(p, detail::AabbTree::noTriangle, 8);
      const detail::AabbTree::Hit b = many.closest(p, detail::AabbTree::noTriangle, 8);
      QCOMPARE(b.triangle, a.triangle);
      QCOMPARE(b.leaves, a.leaves);
      QCOMPARE(b.distanceSquared, a.distanceSquared);
    }
  }
}

void SurfaceDistanceTest::identicalMeshesAreZero() {
  const TriangleMesh mesh = sphere(3, 1);
  // Vertices alone land exactly on the other mesh's corners.
  const SurfaceDistance vertices = compareSurfaces(mesh, mesh, {.samplesPerSurface = 0});
  QCOMPARE(vertices.samples, 2 * mesh.positions.size());
  QCOMPARE(vertices.rms, 0.0);
  QCOMPARE(vertices.hausdorff, 0.0);
  QVERIFY(std::isinf(vertices.psnr) && vertices.psnr > 0);

  // Points inside triangles are off by rounding only.
  const SurfaceDistance sampled = compareSurfaces(mesh, mesh, {.samplesPerSurface = 10'000});
  QCOMPARE(sampled.samples, 2 * (mesh.positions.size() + 10'000));
  QVERIFY(sampled.rms < 1e-12);
  QVERIFY(sampled.hausdorff < 1e-12);
  QVERIFY(sampled.psnr > 200);
}

void SurfaceDistanceTest::concentricSpheres() {
  // Same tessellation scaled by 1.01: every point is 0.01·h from the other surface, h the
  // distance of its face's plane from the centre (≥ 0.999 at this level), and 0.01 at vertices.
  const TriangleMesh a = sphere(5, 1), b = sphere(5, 1.01f);
  const SurfaceDistance d = compareSurfaces(a, b, {.samplesPerSurface = 50'000});
  const double diagonal = 2 * std::sqrt(3.0);
  QVERIFY(std::abs(d.diagonal - diagonal) < 1e-6);
  const double expected = 0.01 / diagonal;
  QVERIFY2(std::abs(d.rms / expected - 1) < 0.02, qPrintable(QString::number(d.rms / expected)));
  QVERIFY2(std::abs(d.hausdorff / expected - 1) < 0.02,
           qPrintable(QString::number(d.hausdorff / expected)));
  QVERIFY(d.hausdorff >= d.rms);
  QVERIFY(std::abs(d.psnr - 20 * std::log10(1 / d.rms)) < 1e-9);
  QVERIFY(std::abs(d.psnr - 20 * std::log10(1 / expected)) < 0.2);
}

void SurfaceDistanceTest::translatedCube() {
  // Cube b is cube a moved by d = 0.01 along x. Per unit area a point of a is d from b on face
  // x = 0; min(d, distance to the face's border) on face x = 1; d − x on the strip x < d of the
  // four side faces, 0 elsewhere. Integrating the squares: 2d² − (4/3)d³ + 2d⁴ over area 6.
  // The other direction is the mirror image; the 16 corners barely move the mean.
  const double d = 0.01;
  const std::size_t n = 200'000;
  const SurfaceDistance result =
      compareSurfaces(cube(), cube({0.01f, 0, 0}), {.samplesPerSurface = n});
  QCOMPARE(result.samples, 2 * (8 + n));
  const double diagonal = std::sqrt(3.0);
  QVERIFY(std::abs(result.diagonal - diagonal) < 1e-6);
  const double expectedRms =
      std::sqrt((2 * d * d - 4.0 / 3 * d * d * d + 2 * d * d * d * d) / 6) / diagonal;
  QVERIFY2(std::abs(result.rms / expectedRms - 1) < 0.01,
           qPrintable(QString::number(result.rms / expectedRms)));
  // Float positions put b's face at 0.01f, not 0.01.
  QVERIFY(std::abs(result.hausdorff - d / diagonal) < 1e-6);
}

void SurfaceDistanceTest::seedStability() {
  const TriangleMesh a = cube(), b = cube({0.01f, 0, 0});
  const SurfaceDistance first = compareSurfaces(a, b, {.samplesPerSurface = 100'000, .seed = 1});
  const SurfaceDistance again = compareSurfaces(a, b, {.samplesPerSurface = 100'000, .seed = 1});
  const SurfaceDistance other = compareSurfaces(a, b, {.samplesPerSurface = 100'000, .seed = 2});
  QCOMPARE(again.rms, first.rms); // deterministic for a seed, whatever the thread count
  QCOMPARE(again.hausdorff, first.hausdorff);
  QVERIFY(first.rms != other.rms);
  QVERIFY2(std::abs(first.rms / other.rms - 1) < 0.01,
           qPrintable(QString("%1 vs %2").arg(first.rms).arg(other.rms)));
}

void SurfaceDistanceTest::emptyMeshThrows() {
  const TriangleMesh empty, pointsOnly{{{0, 0, 0}, {1, 0, 0}}, {}};
  for (const TriangleMesh* bad : {&empty, &pointsOnly}) {
    for (const bool first : {true, false}) {
      try {
        first ? compareSurfaces(*bad, cube()) : compareSurfaces(cube(), *bad);
        QFAIL("expected Error");
      } catch (const Error& e) {
        QCOMPARE(e.kind(), ErrorKind::InvalidInput);
      }
    }
  }
}

void SurfaceDistanceTest::badIndexThrows() {
  TriangleMesh broken = cube();
  broken.triangles.back()[2] = 8;
  try {
    compareSurfaces(cube(), broken);
    QFAIL("expected Error");
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidInput);
  }
}

// A self-intersecting tangle (vertices of a sphere moved to random points) makes every box
// overlap every query: with a small work bound the queries stop early, say so, and report
// distances that are never below the exact ones; on smooth surfaces the bound never bites.
void SurfaceDistanceTest::aTangleIsBoundedFromAbove() {
  TriangleMesh tangle = sphere(4, 1);
  std::mt19937 random(5);
  std::normal_distribution<float> normal;
  for (Vec3f& p : tangle.positions)
    p = {normal(random), normal(random), normal(random)};
  const TriangleMesh smooth = sphere(4, 1.01f);
  const SurfaceDistance exact =
      compareSurfaces(tangle, smooth, {.samplesPerSurface = 5000, .leavesPerQuery = 1u << 30});
  const SurfaceDistance bounded =
      compareSurfaces(tangle, smooth, {.samplesPerSurface = 5000, .leavesPerQuery = 4});
  QCOMPARE(exact.boundedQueries, std::size_t(0));
  QVERIFY(bounded.boundedQueries > 0);
  QVERIFY(bounded.rms >= exact.rms && bounded.hausdorff >= exact.hausdorff);
  const SurfaceDistance calm = compareSurfaces(sphere(5, 1), smooth, {.samplesPerSurface = 20'000});
  QCOMPARE(calm.boundedQueries, std::size_t(0));
}

QTEST_APPLESS_MAIN(SurfaceDistanceTest)
#include "surface_distance_test.moc"
