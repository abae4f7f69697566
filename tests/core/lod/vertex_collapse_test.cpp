// Vertex collapse (vertex_collapse.h): meets its triangle target within 1 %, keeps the mesh
// closed, manifold and genus 0, never turns a triangle's normal past the bound, honours the
// error bound and the caller's veto, and names bad arguments.

#include "test_meshes.h"

#include "octaclay/core/error.h"
#include "octaclay/core/lod/vertex_collapse.h"

#include <QtTest>

#include <cmath>
#include <string>

using namespace octaclay::core;

namespace {

// A sphere of 8192 triangles with a few bumps: curved enough that normals matter everywhere.
TriangleMesh bumpySphere() {
  TriangleMesh mesh = testing::unitSphere(5);
  for (Vec3f& p : mesh.positions) {
    const float bump = 0.15f * std::exp(-8 * (1 - p.z)) + 0.1f * std::exp(-12 * (1 - p.x)) -
                       0.08f * std::exp(-10 * (1 + p.y));
    p = p * (1 + bump);
  }
  return mesh;
}

Vec3f unitNormal(const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
  const Vec3f a = mesh.positions[t[0]];
  return normalize(cross(mesh.positions[t[1]] - a, mesh.positions[t[2]] - a));
}

void checkClosedGenus0(const TriangleMesh& mesh) {
  const MeshTopology t = analyzeTopology(mesh);
  QVERIFY(t.closed());
  QVERIFY(t.manifold());
  QCOMPARE(t.euler, 2LL);
  QCOMPARE(t.degenerateTriangles, std::size_t(0));
}

} // namespace

class VertexCollapseTest : public QObject {
  Q_OBJECT
private slots:
  void meetsTargetWithinOnePercent_data();
  void meetsTargetWithinOnePercent();
  void errorBoundStopsEarlier_data();
  void errorBoundStopsEarlier();
  void vetoKeepsVertices_data();
  void vetoKeepsVertices();
  void shapeBoundFollowsTheInput_data();
  void shapeBoundFollowsTheInput();
  void badArguments();
};

void VertexCollapseTest::meetsTargetWithinOnePercent_data() {
  QTest::addColumn<int>("target");
  QTest::addColumn<float>("degrees");
  QTest::addColumn<bool>("fast");
  for (const bool fast : {false, true}) {
    const char* engine = fast ? "fast" : "Decimater";
    QTest::addRow("%s, 4000, 60 degrees", engine) << 4000 << 60.0f << fast;
    QTest::addRow("%s, 1000, 30 degrees", engine) << 1000 << 30.0f << fast;
    QTest::addRow("%s, 301, 45 degrees", engine) << 301 << 45.0f << fast;
    QTest::addRow("%s, 2000, 5 degrees", engine) << 2000 << 5.0f << fast;
  }
}

void VertexCollapseTest::meetsTargetWithinOnePercent() {
  QFETCH(int, target);
  QFETCH(float, degrees);
  QFETCH(bool, fast);
  const TriangleMesh input = bumpySphere();
  VertexCollapseOptions options;
  options.engine = fast ? CollapseEngine::Fast : CollapseEngine::Decimater;
  options.targetTriangles = std::size_t(target);
  options.maxNormalTurnDegrees = degrees;
  const CollapsedMesh out = collapseVertices(input, options);
  // A 5° bound on this bumpy sphere allows all collapses down to 2000 (the test prints the
  // largest turn); the target is met within 1 % (two triangles per collapse).
  QVERIFY2(std::abs(double(out.mesh.triangles.size()) - target) <= 0.01 * target,
           qPrintable(QString::number(out.mesh.triangles.size())));
  checkClosedGenus0(out.mesh);
  QVERIFY(signedVolume(out.mesh) > 0);
  // Halfedge collapses move no vertex.
  QCOMPARE(out.inputVertex.size(), out.mesh.positions.size());
  for (std::size_t v = 0; v < out.inputVertex.size(); ++v)
    QCOMPARE(out.mesh.positions[v], input.positions[out.inputVertex[v]]);
  // Every result triangle stays within the bound of the input triangle it is.
  QCOMPARE(out.inputTriangle.size(), out.mesh.triangles.size());
  const float minCos = std::cos(degrees * float(M_PI) / 180);
  float worst = 1;
  for (std::size_t t = 0; t < out.mesh.triangles.size(); ++t)
    worst = std::min(worst, dot(unitNormal(out.mesh, out.mesh.triangles[t]),
                                unitNormal(input, input.triangles[out.inputTriangle[t]])));
  qInfo("largest normal turn %.1f degrees (bound %.0f)",
        double(std::acos(std::clamp(worst, -1.0f, 1.0f)) * 180 / float(M_PI)), double(degrees));
  QVERIFY(worst >= minCos - 1e-5f);
}

void VertexCollapseTest::errorBoundStopsEarlier_data() {
  QTest::addColumn<bool>("fast");
  QTest::newRow("Decimater") << false;
  QTest::newRow("fast") << true;
}

void VertexCollapseTest::errorBoundStopsEarlier() {
  QFETCH(bool, fast);
  const TriangleMesh input = bumpySphere();
  VertexCollapseOptions options;
  options.engine = fast ? CollapseEngine::Fast : CollapseEngine::Decimater;
  options.maxError = 0.0005;
  const std::size_t tight = collapseVertices(input, options).mesh.triangles.size();
  options.maxError = 0.005;
  const std::size_t loose = collapseVertices(input, options).mesh.triangles.size();
  qInfo("error bound 0.05 %%: %zu triangles, 0.5 %%: %zu", tight, loose);
  QVERIFY(tight < input.triangles.size());
  QVERIFY(loose < tight);
  // A target below what the bound allows: the bound wins.
  options.targetTriangles = 100;
  options.maxError = 0.0005;
  QVERIFY(collapseVertices(input, options).mesh.triangles.size() >= tight - tight / 20);
}

void VertexCollapseTest::vetoKeepsVertices_data() {
  errorBoundStopsEarlier_data();
}

void VertexCollapseTest::vetoKeepsVertices() {
  QFETCH(bool, fast);
  const TriangleMesh input = bumpySphere();
  VertexCollapseOptions options;
  options.engine = fast ? CollapseEngine::Fast : CollapseEngine::Decimater;
  options.targetTriangles = 500;
  // The octahedron's six vertices (indices 0 … 5 of unitSphere) may not be collapsed away.
  options.allowCollapse = [](std::uint32_t from, std::uint32_t) { return from >= 6; };
  const CollapsedMesh out = collapseVertices(input, options);
  for (std::uint32_t v = 0; v < 6; ++v)
    QVERIFY(std::find(out.inputVertex.begin(), out.inputVertex.end(), v) != out.inputVertex.end());
  checkClosedGenus0(out.mesh);
}

void VertexCollapseTest::shapeBoundFollowsTheInput_data() {
  errorBoundStopsEarlier_data();
}

// A sphere stretched 8 times along x: its input triangles are thin already. No triangle of the
// result is thinner (longest edge / height) than the bound 10 or twice its input triangle, and
// some use that room; with growth 0 the bound alone holds wherever the input was under it.
void VertexCollapseTest::shapeBoundFollowsTheInput() {
  QFETCH(bool, fast);
  TriangleMesh input = bumpySphere();
  for (Vec3f& p : input.positions)
    p.x *= 8;
  const auto aspect = [](const TriangleMesh& mesh, const std::array<std::uint32_t, 3>& t) {
    return aspectRatio(mesh.positions[t[0]], mesh.positions[t[1]], mesh.positions[t[2]]);
  };
  VertexCollapseOptions options;
  options.engine = fast ? CollapseEngine::Fast : CollapseEngine::Decimater;
  options.targetTriangles = 1000;
  const CollapsedMesh grown = collapseVertices(input, options);
  int aboveTen = 0;
  for (std::size_t t = 0; t < grown.mesh.triangles.size(); ++t) {
    const double was = aspect(input, input.triangles[grown.inputTriangle[t]]);
    const double now = aspect(grown.mesh, grown.mesh.triangles[t]);
    QVERIFY2(now <= std::max(10.0, 2 * was) * 1.0001,
             qPrintable(QString("aspect %1, input triangle %2").arg(now).arg(was)));
    aboveTen += now > 10;
  }
  QVERIFY(aboveTen > 0);
  options.maxAspectGrowth = 0;
  const CollapsedMesh bounded = collapseVertices(input, options);
  for (std::size_t t = 0; t < bounded.mesh.triangles.size(); ++t) {
    const double was = aspect(input, input.triangles[bounded.inputTriangle[t]]);
    if (was <= 10) QVERIFY(aspect(bounded.mesh, bounded.mesh.triangles[t]) <= 10 * 1.0001);
  }
  checkClosedGenus0(grown.mesh);
}

void VertexCollapseTest::badArguments() {
  const TriangleMesh input = testing::unitSphere(2);
  const auto expectError = [&](const TriangleMesh& mesh, const VertexCollapseOptions& options,
                               ErrorKind kind, const char* needle) {
    try {
      collapseVertices(mesh, options);
      QFAIL("no error");
    } catch (const Error& e) {
      QCOMPARE(e.kind(), kind);
      QVERIFY2(std::string(e.what()).find(needle) != std::string::npos, e.what());
    }
  };
  VertexCollapseOptions options;
  options.targetTriangles = 3;
  expectError(input, options, ErrorKind::InvalidArgument, "3");
  options.targetTriangles = 0;
  options.maxError = -2;
  expectError(input, options, ErrorKind::InvalidArgument, "-2");
  options.maxError = 0;
  options.maxNormalTurnDegrees = 0;
  expectError(input, options, ErrorKind::InvalidArgument, "0");
  options.maxNormalTurnDegrees = 60;
  options.maxAspectGrowth = -1;
  expectError(input, options, ErrorKind::InvalidArgument, "growth");
  options.maxAspectGrowth = 2;
  TriangleMesh open = input;
  open.triangles.pop_back();
  expectError(open, options, ErrorKind::InvalidInput, "boundary");
}

QTEST_APPLESS_MAIN(VertexCollapseTest)
#include "vertex_collapse_test.moc"
