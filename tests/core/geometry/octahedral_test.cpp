// Octahedral topology of the geometry image (DESIGN.md, "The geometry image"): identification of
// border samples, wrap() over the tiled plane, and incident triangles against the welded mesh.

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/vertex_index.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <set>
#include <vector>

using namespace octaclay::core;

namespace {

using Tri = std::array<std::uint32_t, 3>;

// An oriented triangle rotated so that its smallest index comes first.
Tri canonicalTri(Tri t) {
  while (t[0] > t[1] || t[0] > t[2])
    t = {t[1], t[2], t[0]};
  return t;
}

bool inGrid(int n, Sample s) {
  return s.i >= 0 && s.j >= 0 && s.i <= n && s.j <= n;
}
bool onBorder(int n, Sample s) {
  return s.i == 0 || s.j == 0 || s.i == n || s.j == n;
}

// Independent oracle for the identification rule of DESIGN.md: each side folds at its midpoint,
// the four corners are one vertex.
std::set<std::pair<int, int>> expectedGroup(int n, Sample s) {
  std::set<std::pair<int, int>> g{{s.i, s.j}};
  const bool corner = (s.i == 0 || s.i == n) && (s.j == 0 || s.j == n);
  if (corner) return {{0, 0}, {0, n}, {n, 0}, {n, n}};
  if (s.i == 0 || s.i == n) g.insert({s.i, n - s.j});
  if (s.j == 0 || s.j == n) g.insert({n - s.i, s.j});
  return g;
}

std::set<std::pair<int, int>> actualGroup(int n, Sample s) {
  std::array<Sample, 4> out{};
  const int c = identifiedSamples(n, s, out);
  std::set<std::pair<int, int>> g;
  for (int k = 0; k < c; ++k)
    g.insert({out[k].i, out[k].j});
  return g;
}

// An image whose x coordinate is the VertexIndex of each sample, so the extracted mesh's
// positions name the vertices whatever numbering extractMesh uses internally.
GeometryImage idImage(int n, const VertexIndex& vi) {
  GeometryImage image(n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      image.at(i, j) = {static_cast<float>(vi.at(i, j)), 0, 0, 0};
  return image;
}

// The checks below run in lambdas, where QFAIL returns from the lambda only: stop the test
// function at the first failure.
#define CHECK_OR_RETURN(call)                                                                      \
  do {                                                                                             \
    call;                                                                                          \
    if (QTest::currentTestFailed()) return;                                                        \
  } while (false)

void sizeRows(int maxN) {
  QTest::addColumn<int>("n");
  for (int n = 2; n <= maxN; n *= 2)
    QTest::newRow(QByteArray::number(n).constData()) << n;
}

} // namespace

class OctahedralTest : public QObject {
  Q_OBJECT

private slots:
  void validSizes();
  void identification_data() { sizeRows(1024); }
  void identification();
  void wrapProperties_data() { sizeRows(1024); }
  void wrapProperties();
  void wrapNeighboursMatchMesh_data() { sizeRows(1024); }
  void wrapNeighboursMatchMesh();
  void cellTrianglesCoverGrid_data() { sizeRows(64); }
  void cellTrianglesCoverGrid();
};

void OctahedralTest::validSizes() {
  for (int n : {2, 4, 8, 16, 1024, 4096, 8192}) {
    QVERIFY2(isValidSize(n), qPrintable(QString::number(n)));
    requireValidSize(n); // must not throw
  }
  for (int n : {0, 1, 3, 6, 12, 1000, 16384, -2, -4, -1024}) {
    QVERIFY2(!isValidSize(n), qPrintable(QString::number(n)));
    bool threw = false;
    try {
      requireValidSize(n);
    } catch (const Error& e) {
      threw = true;
      QCOMPARE(e.kind(), ErrorKind::InvalidArgument);
      QVERIFY2(QString::fromStdString(e.what()).contains(QString::number(n)), e.what());
    }
    QVERIFY2(threw, qPrintable(QString("requireValidSize(%1) did not throw").arg(n)));
  }
  QVERIFY_THROWS_EXCEPTION(Error, GeometryImage(3));
  QVERIFY_THROWS_EXCEPTION(Error, VertexIndex(64, 3));
  QVERIFY_THROWS_EXCEPTION(Error, VertexIndex(64, 64));
  QVERIFY_THROWS_EXCEPTION(Error, VertexIndex(6, 1));
}

void OctahedralTest::identification() {
  QFETCH(int, n);
  const VertexIndex vi(n);
  QCOMPARE(vi.size(), n);
  QCOMPARE(vi.step(), 1);
  const std::uint64_t expectedVertices = static_cast<std::uint64_t>(n) * n + 2;
  QCOMPARE(static_cast<std::uint64_t>(vi.vertexCount()), expectedVertices);

  std::vector<Sample> first(vi.vertexCount(), Sample{-1, -1});
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Sample s{i, j};
      const std::uint32_t id = vi.at(i, j);
      QVERIFY(id < vi.vertexCount());
      if (onBorder(n, s)) {
        const auto group = actualGroup(n, s);
        if (group != expectedGroup(n, s))
          QFAIL(qPrintable(QString("identifiedSamples(%1, (%2,%3)) has %4 samples, expected %5")
                               .arg(n)
                               .arg(i)
                               .arg(j)
                               .arg(group.size())
                               .arg(expectedGroup(n, s).size())));
        const Sample c = canonical(n, s);
        QVERIFY(group.count({c.i, c.j}) == 1);
        for (auto [gi, gj] : group) {
          QCOMPARE(vi.at(gi, gj), id);
          QCOMPARE(canonical(n, Sample{gi, gj}), c);
        }
      } else {
        if (actualGroup(n, s) != expectedGroup(n, s))
          QFAIL(
              qPrintable(QString("interior sample (%1,%2) identified with others").arg(i).arg(j)));
        QCOMPARE(canonical(n, s), s);
      }
      // Samples sharing an index must be identified with each other.
      if (first[id].i < 0) {
        first[id] = s;
      } else if (expectedGroup(n, s).count({first[id].i, first[id].j}) == 0) {
        QFAIL(qPrintable(QString("(%1,%2) and (%3,%4) share vertex %5 but are not identified")
                             .arg(i)
                             .arg(j)
                             .arg(first[id].i)
                             .arg(first[id].j)
                             .arg(id)));
      }
    }
  }
  // Every index is used.
  for (std::size_t id = 0; id < first.size(); ++id)
    if (first[id].i < 0) QFAIL(qPrintable(QString("vertex %1 has no sample").arg(id)));

  // canonicalSamples(): one per vertex, canonical, row-major.
  const auto canon = vi.canonicalSamples();
  QCOMPARE(static_cast<std::uint64_t>(canon.size()), expectedVertices);
  for (std::size_t id = 0; id < canon.size(); ++id) {
    QCOMPARE(static_cast<std::size_t>(vi.at(canon[id].i, canon[id].j)), id);
    QCOMPARE(canonical(n, canon[id]), canon[id]);
    if (id > 0) {
      const bool rowMajor =
          std::pair(canon[id - 1].j, canon[id - 1].i) < std::pair(canon[id].j, canon[id].i);
      QVERIFY2(rowMajor, "canonicalSamples() not in row-major order");
    }
  }
}

void OctahedralTest::wrapProperties() {
  QFETCH(int, n);
  const VertexIndex vi(n);

  // Identity inside the grid.
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (wrap(n, Sample{i, j}) != Sample{i, j})
        QFAIL(qPrintable(QString("wrap(%1,%2) is not the identity").arg(i).arg(j)));

  // Symmetries of the octahedral tiling: half turns about the side midpoints and the
  // translations by (2N,0), (0,2N), (N,N), (N,-N) map a position to the same vertex.
  auto sameVertex = [&](Sample a, Sample b) {
    const Sample wa = wrap(n, a), wb = wrap(n, b);
    return vi.at(wa.i, wa.j) == vi.at(wb.i, wb.j);
  };
  auto check = [&](Sample p) {
    const Sample w = wrap(n, p);
    if (!inGrid(n, w))
      QFAIL(qPrintable(
          QString("wrap(%1,%2) = (%3,%4) outside the grid").arg(p.i).arg(p.j).arg(w.i).arg(w.j)));
    const Sample ww = wrap(n, w);
    if (ww != w) QFAIL(qPrintable(QString("wrap not idempotent at (%1,%2)").arg(p.i).arg(p.j)));
    const std::array<Sample, 8> images{Sample{-p.i, n - p.j},    Sample{2 * n - p.i, n - p.j},
                                       Sample{n - p.i, -p.j},    Sample{n - p.i, 2 * n - p.j},
                                       Sample{p.i + 2 * n, p.j}, Sample{p.i, p.j - 2 * n},
                                       Sample{p.i + n, p.j + n}, Sample{p.i - n, p.j + n}};
    for (const Sample& q : images)
      if (!sameVertex(p, q))
        QFAIL(qPrintable(QString("(%1,%2) and its image (%3,%4) wrap to different vertices")
                             .arg(p.i)
                             .arg(p.j)
                             .arg(q.i)
                             .arg(q.j)));
  };

  // Every position in a band of two periods around the grid.
  if (n <= 64)
    for (int j = -2 * n; j <= 3 * n; ++j)
      for (int i = -2 * n; i <= 3 * n; ++i)
        CHECK_OR_RETURN(check({i, j}));

  std::mt19937 rng(12345u + static_cast<unsigned>(n));
  std::uniform_int_distribution<int> near(-10 * n, 10 * n);
  std::uniform_int_distribution<int> far(-(1 << 20), 1 << 20);
  for (int k = 0; k < 4000; ++k)
    CHECK_OR_RETURN(check({near(rng), near(rng)}));
  for (int k = 0; k < 4000; ++k)
    CHECK_OR_RETURN(check({far(rng), far(rng)}));
  CHECK_OR_RETURN(check({1 << 20, -(1 << 20)}));
  CHECK_OR_RETURN(check({-(1 << 20), 1 << 20}));

  // The cell beyond a corner belongs to the diagonally opposite corner's cell.
  QVERIFY(sameVertex({-1, -1}, {n - 1, n - 1}));
  QVERIFY(sameVertex({n + 1, -1}, {1, n - 1}));
  // Just across the left side: (-1, j) is (1, N-j).
  for (int j = 0; j <= n; ++j)
    QVERIFY(sameVertex({-1, j}, {1, n - j}));
}

void OctahedralTest::wrapNeighboursMatchMesh() {
  QFETCH(int, n);
  const VertexIndex vi(n);
  const TriangleMesh mesh = extractMesh(idImage(n, vi));
  const std::size_t vertexCount = vi.vertexCount();
  QCOMPARE(mesh.positions.size(), vertexCount);
  QCOMPARE(mesh.triangles.size(), static_cast<std::size_t>(2) * n * n);

  // Mesh vertex -> VertexIndex id.
  std::vector<std::uint32_t> idOf(mesh.positions.size());
  std::vector<char> seen(vertexCount, 0);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const float x = mesh.positions[v].x;
    QVERIFY(x >= 0 && x < static_cast<float>(vertexCount) && x == std::floor(x));
    idOf[v] = static_cast<std::uint32_t>(x);
    QVERIFY2(!seen[idOf[v]], "two mesh vertices carry the same sample");
    seen[idOf[v]] = 1;
  }

  // Incident triangles of every vertex in the mesh (CSR).
  std::vector<std::uint32_t> offset(vertexCount + 1, 0);
  for (const auto& t : mesh.triangles)
    for (auto v : t)
      ++offset[idOf[v] + 1];
  for (std::size_t v = 0; v < vertexCount; ++v)
    offset[v + 1] += offset[v];
  std::vector<Tri> incident(offset.back());
  {
    std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
    for (const auto& t : mesh.triangles) {
      const Tri ids{idOf[t[0]], idOf[t[1]], idOf[t[2]]};
      for (auto v : ids)
        incident[fill[v]++] = canonicalTri(ids);
    }
  }

  auto checkSample = [&](Sample s) {
    const std::uint32_t id = vi.at(s.i, s.j);
    std::array<std::array<Sample, 3>, 6> tris{};
    const int count = incidentTriangles(n, s, tris);
    if (count != 4 && count != 6)
      QFAIL(qPrintable(QString("incidentTriangles(%1,%2) = %3").arg(s.i).arg(s.j).arg(count)));
    std::set<Tri> fromWrap;
    std::set<std::uint32_t> neighboursWrap;
    for (int k = 0; k < count; ++k) {
      if (tris[k][0] != s)
        QFAIL(qPrintable(QString("incident triangle %1 of (%2,%3) does not start with it")
                             .arg(k)
                             .arg(s.i)
                             .arg(s.j)));
      Tri ids{};
      for (int c = 0; c < 3; ++c) {
        const Sample w = wrap(n, tris[k][c]);
        ids[c] = vi.at(w.i, w.j);
      }
      fromWrap.insert(canonicalTri(ids));
      neighboursWrap.insert(ids[1]);
      neighboursWrap.insert(ids[2]);
    }
    std::set<Tri> fromMesh(incident.begin() + offset[id], incident.begin() + offset[id + 1]);
    std::set<std::uint32_t> neighboursMesh;
    for (const Tri& t : fromMesh)
      for (auto v : t)
        if (v != id) neighboursMesh.insert(v);
    if (neighboursWrap != neighboursMesh)
      QFAIL(qPrintable(QString("(%1,%2): %3 neighbours through wrap, %4 in the welded mesh")
                           .arg(s.i)
                           .arg(s.j)
                           .arg(neighboursWrap.size())
                           .arg(neighboursMesh.size())));
    if (static_cast<int>(fromWrap.size()) != count)
      QFAIL(qPrintable(QString("(%1,%2): repeated incident triangles").arg(s.i).arg(s.j)));
    // Same triangles with the same orientation.
    if (fromWrap != fromMesh)
      QFAIL(qPrintable(
          QString("(%1,%2): incident triangles differ from the welded mesh's").arg(s.i).arg(s.j)));
  };

  if (n <= 64) {
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        CHECK_OR_RETURN(checkSample({i, j}));
  } else {
    for (int k = 0; k <= n; ++k) {
      CHECK_OR_RETURN(checkSample({k, 0}));
      CHECK_OR_RETURN(checkSample({k, n}));
      CHECK_OR_RETURN(checkSample({0, k}));
      CHECK_OR_RETURN(checkSample({n, k}));
    }
  }
  // Valence 4 exactly at the six octahedron vertices.
  std::array<std::array<Sample, 3>, 6> tris{};
  for (Sample s : {Sample{0, 0}, Sample{n / 2, n / 2}, Sample{0, n / 2}, Sample{n, n / 2},
                   Sample{n / 2, 0}, Sample{n / 2, n}})
    QCOMPARE(incidentTriangles(n, s, tris), 4);
  if (n >= 4) QCOMPARE(incidentTriangles(n, Sample{1, 0}, tris), 6);
}

void OctahedralTest::cellTrianglesCoverGrid() {
  QFETCH(int, n);
  const VertexIndex vi(n);
  // The DESIGN.md split: lower-left quadrant along (i, j+1)-(i+1, j); the split mirrors in each
  // quadrant, i.e. it follows the octahedron edge crossing that quadrant.
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const bool left = i < n / 2, low = j < n / 2;
      const CellSplit expected = (left == low) ? CellSplit::AntiDiagonal : CellSplit::MainDiagonal;
      if (cellSplit(n, i, j) != expected)
        QFAIL(qPrintable(QString("cellSplit(%1, %2, %3) is wrong").arg(n).arg(i).arg(j)));
      const auto tris = cellTriangles(n, i, j);
      std::set<std::pair<int, int>> corners;
      for (const auto& t : tris) {
        // Counter-clockwise in (i, j).
        const long long area = static_cast<long long>(t[1].i - t[0].i) * (t[2].j - t[0].j) -
                               static_cast<long long>(t[1].j - t[0].j) * (t[2].i - t[0].i);
        QCOMPARE(area, 1LL);
        for (const Sample& s : t) {
          QVERIFY(s.i >= i && s.i <= i + 1 && s.j >= j && s.j <= j + 1);
          corners.insert({s.i, s.j});
        }
      }
      QCOMPARE(corners.size(), std::size_t{4});
      // The shared edge is the split diagonal.
      std::set<std::pair<int, int>> t0, t1;
      for (const Sample& s : tris[0])
        t0.insert({s.i, s.j});
      for (const Sample& s : tris[1])
        t1.insert({s.i, s.j});
      std::vector<std::pair<int, int>> shared;
      std::set_intersection(t0.begin(), t0.end(), t1.begin(), t1.end(), std::back_inserter(shared));
      QCOMPARE(shared.size(), std::size_t{2});
      const bool anti =
          shared[0].first != shared[1].first && shared[0].second != shared[1].second &&
          (shared[0].first - shared[1].first) == -(shared[0].second - shared[1].second);
      QCOMPARE(anti, expected == CellSplit::AntiDiagonal);
    }
  }
}

QTEST_APPLESS_MAIN(OctahedralTest)
#include "octahedral_test.moc"
