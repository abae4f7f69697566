// Mesh extraction from the geometry image: counts, closedness, orientation and LOD subsampling.

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/geometry/vertex_index.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <set>
#include <tuple>
#include <vector>

using namespace octaclay::core;

namespace {

using P = std::tuple<float, float, float>;
P key(Vec3f v) {
  return {v.x, v.y, v.z};
}

// A triangle as its three corner positions, rotated so the smallest comes first (keeps
// orientation).
std::array<P, 3> orientedTriangle(const TriangleMesh& m, const std::array<std::uint32_t, 3>& t) {
  std::array<P, 3> p{key(m.positions[t[0]]), key(m.positions[t[1]]), key(m.positions[t[2]])};
  while (p[0] > p[1] || p[0] > p[2])
    p = {p[1], p[2], p[0]};
  return p;
}

void checkClosedGenus0(const TriangleMesh& mesh, int m) {
  const std::size_t v = static_cast<std::size_t>(m) * m + 2;
  const std::size_t t = static_cast<std::size_t>(2) * m * m;
  QCOMPARE(mesh.positions.size(), v);
  QCOMPARE(mesh.triangles.size(), t);
  for (const auto& tri : mesh.triangles)
    for (auto idx : tri)
      QVERIFY(idx < mesh.positions.size());
  const MeshTopology topo = analyzeTopology(mesh);
  QCOMPARE(topo.vertices, v);
  QCOMPARE(topo.unusedVertices, std::size_t{0});
  QCOMPARE(topo.triangles, t);
  QCOMPARE(topo.edges, static_cast<std::size_t>(3) * m * m);
  QCOMPARE(topo.boundaryEdges, std::size_t{0});
  QCOMPARE(topo.nonManifoldEdges, std::size_t{0});
  QCOMPARE(topo.degenerateTriangles, std::size_t{0});
  QCOMPARE(topo.euler, 2LL);
  QVERIFY(topo.closed());
  QVERIFY(topo.manifold());
}

void sizeRows() {
  QTest::addColumn<int>("n");
  for (int n = 2; n <= 1024; n *= 2)
    QTest::newRow(QByteArray::number(n).constData()) << n;
}

} // namespace

class MeshExtractionTest : public QObject {
  Q_OBJECT

private slots:
  void sphere_data() { sizeRows(); }
  void sphere();
  void octahedronAtTwo();
  void lod_data();
  void lod();
  void invalidSteps();
};

void MeshExtractionTest::sphere() {
  QFETCH(int, n);
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  const TriangleMesh mesh = extractMesh(image);
  checkClosedGenus0(mesh, n);
  if (QTest::currentTestFailed()) return;
  // Inscribed polyhedron of the unit sphere: volume below 4π/3, approaching it as N grows.
  const double volume = signedVolume(mesh);
  const double sphereVolume = 4.0 * M_PI / 3.0;
  QVERIFY2(volume > 0, qPrintable(QString::number(volume)));
  QVERIFY2(volume <= sphereVolume * (1 + 1e-6), qPrintable(QString::number(volume)));
  if (n >= 64)
    QVERIFY2(std::abs(volume - sphereVolume) / sphereVolume < 4.0 / (n / 4.0 * n / 4.0),
             qPrintable(QString::number(volume)));
  // Every vertex is an image sample on the unit sphere.
  for (const Vec3f& p : mesh.positions)
    QVERIFY(std::abs(length(p) - 1.0f) < 1e-5f);
  // Outward orientation, triangle by triangle: each normal points away from the centre.
  for (const auto& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    if (dot(cross(b - a, c - a), a + b + c) <= 0) QFAIL("an inward-facing triangle");
  }
}

void MeshExtractionTest::octahedronAtTwo() {
  const TriangleMesh mesh = extractMesh(makeBaseShape(BaseShape::Sphere, 2));
  QCOMPARE(mesh.positions.size(), std::size_t{6});
  QCOMPARE(mesh.triangles.size(), std::size_t{8});
  // The six vertices are ±x, ±y, ±z.
  std::array<int, 6> axisUsed{};
  std::vector<int> axisOf(6);
  for (std::size_t v = 0; v < 6; ++v) {
    const Vec3f p = mesh.positions[v];
    const std::array<float, 3> c{p.x, p.y, p.z};
    int axis = -1;
    for (int k = 0; k < 3; ++k) {
      if (std::abs(std::abs(c[k]) - 1.0f) < 1e-6f) {
        QCOMPARE(axis, -1);
        axis = 2 * k + (c[k] < 0 ? 1 : 0);
      } else {
        QVERIFY2(std::abs(c[k]) < 1e-6f, "octahedron vertex off an axis");
      }
    }
    QVERIFY(axis >= 0);
    ++axisUsed[axis];
    axisOf[v] = axis;
  }
  for (int a : axisUsed)
    QCOMPARE(a, 1);
  // Each face spans one octant: one vertex on each axis, and the 8 faces are the 8 octants.
  std::set<int> octants;
  for (const auto& t : mesh.triangles) {
    std::set<int> axes;
    int octant = 0;
    for (auto v : t) {
      axes.insert(axisOf[v] / 2);
      octant |= (axisOf[v] % 2) << (axisOf[v] / 2);
    }
    QCOMPARE(axes.size(), std::size_t{3});
    octants.insert(octant);
  }
  QCOMPARE(octants.size(), std::size_t{8});
  QVERIFY(std::abs(signedVolume(mesh) - 4.0 / 3.0) < 1e-6);
  checkClosedGenus0(mesh, 2);
}

void MeshExtractionTest::lod_data() {
  QTest::addColumn<int>("step");
  for (int step = 1; step <= 128; step *= 2)
    QTest::newRow(QByteArray::number(step).constData()) << step;
}

void MeshExtractionTest::lod() {
  QFETCH(int, step);
  const int n = 256, m = n / step;
  // The blob has no symmetry, so a wrong sample shows.
  const GeometryImage image = makeBaseShape(BaseShape::Blob, n);
  const TriangleMesh lod = extractMesh(image, step);
  checkClosedGenus0(lod, m);
  if (QTest::currentTestFailed()) return;
  QVERIFY2(signedVolume(lod) > 0, qPrintable(QString::number(signedVolume(lod))));

  // The LOD's vertices are exactly the full image's samples at (step·i, step·j).
  const VertexIndex vi(n, step);
  QCOMPARE(vi.size(), m);
  std::vector<P> expected, actual;
  for (const Sample& s : vi.canonicalSamples())
    expected.push_back(key(image.at(step * s.i, step * s.j).xyz()));
  for (const Vec3f& p : lod.positions)
    actual.push_back(key(p));
  std::sort(expected.begin(), expected.end());
  std::sort(actual.begin(), actual.end());
  QVERIFY2(std::adjacent_find(expected.begin(), expected.end()) == expected.end(),
           "blob samples are not distinct");
  QVERIFY2(expected == actual, "LOD vertices are not the subsampled image samples");

  // Its triangles are those of the image subsampled to M, extracted at full resolution.
  GeometryImage sub(m);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i)
      sub.at(i, j) = image.at(step * i, step * j);
  const TriangleMesh direct = extractMesh(sub);
  std::vector<std::array<P, 3>> a, b;
  for (const auto& t : lod.triangles)
    a.push_back(orientedTriangle(lod, t));
  for (const auto& t : direct.triangles)
    b.push_back(orientedTriangle(direct, t));
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  QVERIFY2(a == b, "LOD triangles differ from the subsampled image's mesh");
}

void MeshExtractionTest::invalidSteps() {
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, 64);
  for (int step : {3, 0, -2, 6, 64, 128}) {
    bool threw = false;
    try {
      (void)extractMesh(image, step);
    } catch (const Error& e) {
      threw = true;
      QCOMPARE(e.kind(), ErrorKind::InvalidArgument);
      QVERIFY(!QByteArray(e.what()).isEmpty());
    }
    QVERIFY2(threw, qPrintable(QString("step %1 accepted").arg(step)));
  }
  // The coarsest valid LOD (M = 2) is accepted.
  QCOMPARE(extractMesh(image, 32).triangles.size(), std::size_t{8});
}

QTEST_APPLESS_MAIN(MeshExtractionTest)
#include "mesh_extraction_test.moc"
