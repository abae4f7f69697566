// The level of detail of a torus or plane object (lod.h, detail::gridLod): every method gives a
// mesh of the object's topology (a torus closed with Euler characteristic 0, a plane with one
// boundary loop and Euler characteristic 1) whose corner coordinates tile the image once; a
// torus's wrap and a plane's outline survive resampling and collapse; the surface stays close;
// a bump across the wrap or on the boundary is kept by the salient and collapse methods.

#include "lod_checks.h"
#include "test_meshes.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/saliency.h"

#include <QtTest>

#include <cmath>
#include <string>
#include <tuple>

using namespace octaclay::core;
using testing::boundaryLoops;
using testing::checkCornerUv;

Q_DECLARE_METATYPE(octaclay::core::ResampleMethod)

namespace {

constexpr float kMajor = 0.7f, kMinor = 0.3f;

// A torus whose tube swells by `height` (× minor) in a bump centred at (u0, v0) of the image
// (fractions of W and H), measured the short way round: centred on 0, it straddles both wraps.
GeometryImage bumpedTorus(int w, int h, float u0, float v0, float height) {
  GeometryImage image(Topology::Torus, w, h);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) {
      const int ii = i % w, jj = j % h; // column W and row H repeat 0 exactly
      const float u = float(ii) / float(w), v = float(jj) / float(h);
      float du = std::abs(u - u0), dv = std::abs(v - v0);
      du = std::min(du, 1 - du);
      dv = std::min(dv, 1 - dv);
      const float r = kMinor * (1 + height * std::exp(-(du * du + dv * dv) / (0.06f * 0.06f)));
      const float a = 2 * float(M_PI) * u, b = 2 * float(M_PI) * v;
      image.at(i, j) = {(kMajor + r * std::cos(b)) * std::cos(a),
                        (kMajor + r * std::cos(b)) * std::sin(a), r * std::sin(b), 0};
    }
  return image;
}

// A W × H sheet over [-2, 2] × [-1, 1] (so W = 2H has square cells) with a bump of `height`
// centred at (x0, y0): on the boundary when x0 or y0 is ±.
GeometryImage bumpedSheet(int w, int h, float x0, float y0, float height) {
  GeometryImage image(Topology::Plane, w, h);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i) {
      const float x = 4 * float(i) / float(w) - 2, y = 2 * float(j) / float(h) - 1;
      const float d2 = (x - x0) * (x - x0) + (y - y0) * (y - y0);
      image.at(i, j) = {x, y, height * std::exp(-d2 / (0.15f * 0.15f)), 0};
    }
  return image;
}

void checkTorusMesh(const TriangleMesh& mesh) {
  const MeshTopology t = analyzeTopology(mesh);
  QVERIFY(t.closed());
  QVERIFY(t.manifold());
  QCOMPARE(t.euler, 0LL);
  QCOMPARE(t.unusedVertices, std::size_t(0));
  QCOMPARE(t.degenerateTriangles, std::size_t(0));
}

void checkSheetMesh(const TriangleMesh& mesh) {
  const MeshTopology t = analyzeTopology(mesh);
  QVERIFY(t.manifold());
  QCOMPARE(t.euler, 1LL);
  QCOMPARE(boundaryLoops(mesh), 1);
  QCOMPARE(t.unusedVertices, std::size_t(0));
  QCOMPARE(t.degenerateTriangles, std::size_t(0));
}

// The largest distance of a triangle's centroid or corner from the plain torus (no bump).
float farthestFromTorus(const TriangleMesh& mesh) {
  float worst = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    for (const Vec3f p : {a, (a + b + c) * (1.0f / 3)})
      worst = std::max(worst, std::abs(torusDistance(Torus{kMajor, kMinor}, p)));
  }
  return worst;
}

float highest(const TriangleMesh& mesh, int axis) {
  float top = -1e9f;
  for (const Vec3f& p : mesh.positions)
    top = std::max(top, axis == 2 ? p.z : length(Vec3f{p.x, p.y, 0}));
  return top;
}

constexpr std::array kAllMethods = {
    ResampleMethod::Point,        ResampleMethod::Average,  ResampleMethod::SalientAverage,
    ResampleMethod::SalientPoint, ResampleMethod::Adaptive, ResampleMethod::Collapse,
    ResampleMethod::Auto};

// Every method at each (W, H, triangle target; 0: none).
void addMethodRows(std::initializer_list<std::tuple<int, int, int>> sizes) {
  QTest::addColumn<ResampleMethod>("method");
  QTest::addColumn<int>("width");
  QTest::addColumn<int>("height");
  QTest::addColumn<int>("target");
  for (const ResampleMethod m : kAllMethods)
    for (const auto& [w, h, target] : sizes)
      QTest::addRow("%s %dx%d target %d", std::string(methodName(m)).c_str(), w, h, target)
          << m << w << h << target;
}

} // namespace

class GridLodTest : public QObject {
  Q_OBJECT
private slots:
  void torusEveryMethod_data();
  void torusEveryMethod();
  void sheetEveryMethod_data();
  void sheetEveryMethod();
  void discOutlineStaysOnTheCircle();
  void bumpAcrossTheWrapIsKept();
  void bumpOnTheBoundaryIsKept();
  void sizesAreCheckedAgainstTheSides();
};

void GridLodTest::torusEveryMethod_data() {
  addMethodRows({{128, 64, 0}, {256, 32, 2000}, {64, 256, 1500}});
}

// A thin and a tall ring with a bump off centre: the mesh is a closed torus whatever the method,
// its corners tile the image once, it meets the target and lies on the surface.
void GridLodTest::torusEveryMethod() {
  QFETCH(ResampleMethod, method);
  QFETCH(int, width);
  QFETCH(int, height);
  QFETCH(int, target);
  GeometryImage image = bumpedTorus(width, height, 0.37f, 0.81f, 0.1f);
  computeSaliency(image);
  LodOptions options;
  options.method = method;
  options.targetTriangles = std::size_t(target);
  const LodMesh lod = generateLod(image, options);
  checkTorusMesh(lod.mesh);
  checkCornerUv(lod);
  const std::size_t full = 2 * std::size_t(width) * std::size_t(height);
  if (target > 0) {
    QVERIFY2(lod.mesh.triangles.size() <= std::size_t(target) + 2,
             qPrintable(QString::number(lod.mesh.triangles.size())));
    QVERIFY(lod.mesh.triangles.size() >= std::size_t(target) / 2);
  } else {
    QVERIFY(lod.mesh.triangles.size() <= full / 4 + 2); // the half grid's count
    QVERIFY(lod.mesh.triangles.size() >= full / 8);
  }
  // The bump (0.03) aside, every corner and centroid within 1.5 % of the ring's size.
  QVERIFY2(farthestFromTorus(lod.mesh) < 0.03f + 0.015f,
           qPrintable(QString::number(farthestFromTorus(lod.mesh))));
  const bool collapses = method == ResampleMethod::Collapse || method == ResampleMethod::Adaptive ||
                         method == ResampleMethod::Auto;
  QCOMPARE(lod.methodUsed, collapses ? ResampleMethod::Collapse : method);
}

void GridLodTest::sheetEveryMethod_data() {
  addMethodRows({{128, 64, 0}, {64, 64, 600}, {256, 16, 900}});
}

// A sheet with a bump inside: one boundary loop whose vertices stay on the rectangle's outline.
void GridLodTest::sheetEveryMethod() {
  QFETCH(ResampleMethod, method);
  QFETCH(int, width);
  QFETCH(int, height);
  QFETCH(int, target);
  GeometryImage image = bumpedSheet(width, height, 0.6f, -0.3f, 0.4f);
  computeSaliency(image);
  LodOptions options;
  options.method = method;
  options.targetTriangles = std::size_t(target);
  const LodMesh lod = generateLod(image, options);
  checkSheetMesh(lod.mesh);
  checkCornerUv(lod);
  if (target > 0)
    QVERIFY2(lod.mesh.triangles.size() <= std::size_t(target) + 2,
             qPrintable(QString::number(lod.mesh.triangles.size())));
  // Vertices with a corner coordinate on the image's border lie on the outline (within the
  // refit's float noise: it moves them along normals that are nearly vertical there), and the
  // four corners of the sheet are kept.
  int corners = 0;
  for (std::size_t t = 0; t < lod.mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const Vec2f c = lod.cornerUv[t][k];
      const Vec3f p = lod.mesh.positions[lod.mesh.triangles[t][k]];
      if (c.x == 0 || c.x == 1)
        QVERIFY2(std::abs(std::abs(p.x) - 2) < 1e-4f, qPrintable(QString::number(p.x)));
      if (c.y == 0 || c.y == 1)
        QVERIFY2(std::abs(std::abs(p.y) - 1) < 1e-4f, qPrintable(QString::number(p.y, 'g', 9)));
      corners += (c.x == 0 || c.x == 1) && (c.y == 0 || c.y == 1);
    }
  QVERIFY(corners >= 4);
  // The bump's top (0.4) within 15 %: every method's grid reaches it at these sizes.
  QVERIFY2(highest(lod.mesh, 2) > 0.34f, qPrintable(QString::number(highest(lod.mesh, 2))));
}

// The disc's boundary samples lie on the unit circle; resampled, collapsed and refit (along the
// sheet's normal), the LOD's boundary loop still does.
void GridLodTest::discOutlineStaysOnTheCircle() {
  const GeometryImage disc = makeSheet(Sheet::Disc, 128);
  for (const ResampleMethod method :
       {ResampleMethod::Average, ResampleMethod::SalientPoint, ResampleMethod::Collapse}) {
    LodOptions options;
    options.method = method;
    options.targetTriangles = 500;
    const LodMesh lod = generateLod(disc, options);
    checkSheetMesh(lod.mesh);
    checkCornerUv(lod);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
    for (const auto& t : lod.mesh.triangles)
      for (int k = 0; k < 3; ++k)
        ++edges[std::minmax(t[k], t[(k + 1) % 3])];
    int onBoundary = 0;
    for (const auto& [e, count] : edges)
      if (count == 1) {
        // The outline stays round: no boundary edge cuts deeper than a 32-gon's (1 − cos π/32).
        const Vec3f mid = (lod.mesh.positions[e.first] + lod.mesh.positions[e.second]) * 0.5f;
        QVERIFY2(length(mid) > 0.995f, qPrintable(QString::number(length(mid))));
        for (const std::uint32_t v : {e.first, e.second}) {
          const Vec3f p = lod.mesh.positions[v];
          // The average's boundary samples are means of arcs: just inside the circle.
          const float tolerance = method == ResampleMethod::Average ? 2e-3f : 1e-5f;
          QVERIFY2(std::abs(length(p) - 1) < tolerance, qPrintable(QString::number(length(p))));
          ++onBoundary;
        }
      }
    QVERIFY(onBoundary >= 64);
  }
}

// A bump centred on the torus's corner (both wraps): the salient and collapse LODs keep its
// height (0.3 · minor above the tube) within a fifth, and the wrap stays closed.
void GridLodTest::bumpAcrossTheWrapIsKept() {
  GeometryImage image = bumpedTorus(256, 128, 0, 0, 0.3f);
  computeSaliency(image);
  const float top = kMajor + kMinor * 1.3f;
  for (const ResampleMethod method : {ResampleMethod::SalientPoint, ResampleMethod::Collapse}) {
    for (const std::size_t target : {std::size_t(1500), std::size_t(6000)}) {
      LodOptions options;
      options.method = method;
      options.targetTriangles = target;
      const LodMesh lod = generateLod(image, options);
      checkTorusMesh(lod.mesh);
      checkCornerUv(lod);
      const float reached = highest(lod.mesh, 0);
      QVERIFY2(reached - (kMajor + kMinor) > 0.8f * (top - kMajor - kMinor),
               qPrintable(QString("%1 reached %2 of %3")
                              .arg(QString::fromStdString(std::string(methodName(method))))
                              .arg(reached)
                              .arg(top)));
    }
  }
}

// A bump on the sheet's edge and one on its corner: kept, and the outline kept with them.
void GridLodTest::bumpOnTheBoundaryIsKept() {
  for (const auto& [x0, y0] : {std::pair{0.5f, -1.0f}, std::pair{2.0f, 1.0f}}) {
    GeometryImage image = bumpedSheet(128, 64, x0, y0, 0.5f);
    computeSaliency(image);
    LodOptions options;
    options.method = ResampleMethod::Collapse;
    options.targetTriangles = 800;
    const LodMesh lod = generateLod(image, options);
    checkSheetMesh(lod.mesh);
    checkCornerUv(lod);
    QVERIFY2(highest(lod.mesh, 2) > 0.45f, qPrintable(QString::number(highest(lod.mesh, 2))));
  }
}

void GridLodTest::sizesAreCheckedAgainstTheSides() {
  const GeometryImage ring = bumpedTorus(256, 16, 0.5f, 0.5f, 0);
  LodOptions options;
  options.method = ResampleMethod::Point;
  options.size = 128; // d = 2: 128 × 8
  const LodMesh ok = generateLod(ring, options);
  QCOMPARE(ok.resampledSize, 128);
  QCOMPARE(ok.mesh.triangles.size(), std::size_t(2 * 128 * 8));
  checkTorusMesh(ok.mesh);
  for (const int bad : {32, 256, 3, 0 - 2}) { // 32 leaves 2 cells around the tube
    options.size = bad;
    try {
      generateLod(ring, options);
      QFAIL(qPrintable(QString("size %1 accepted").arg(bad)));
    } catch (const Error& e) {
      QCOMPARE(e.kind(), ErrorKind::InvalidArgument);
      QVERIFY2(std::string(e.what()).find(std::to_string(bad)) != std::string::npos, e.what());
    }
  }
  // Too small for any LOD: a 4 × 4 torus and a 2 × 2 plane.
  QVERIFY_THROWS_EXCEPTION(Error, generateLod(bumpedTorus(4, 4, 0, 0, 0), LodOptions{}));
  QVERIFY_THROWS_EXCEPTION(Error, generateLod(bumpedSheet(2, 2, 0, 0, 0), LodOptions{}));
}

QTEST_APPLESS_MAIN(GridLodTest)
#include "grid_lod_test.moc"
