// brushSampling (issue 30, item 1): how many samples lie across a brush's radius where it lands,
// checked on a grid of known spacing, on one stretched along a "limb", on the unit sphere and
// across the image's corners, where the seams identify samples.

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/measure/brush_sampling.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace octaclay::core;

namespace {

// Positions (i·du, j·dv, 0): right edges du long, lower edges dv long (away from the borders).
GeometryImage grid(int n, float du, float dv) {
  GeometryImage image(n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      image.at(i, j) = {float(i) * du, float(j) * dv, 0.0f, 0.0f};
  return image;
}

} // namespace

class BrushSamplingTest : public QObject {
  Q_OBJECT
private slots:
  void countsTheSamplesAcrossTheRadius();
  void theSparsestDirectionCounts();
  void aStretchedPatchNearThePointCounts();
  void theSphereAtTheModellersSizes();
  void theCornersSeeTheSameSurfaceThroughTheSeams();
  void degenerateInput();
};

void BrushSamplingTest::countsTheSamplesAcrossTheRadius() {
  const GeometryImage image = grid(64, 0.01f, 0.01f);
  const BrushSampling five = brushSampling(image, {0.5f, 0.5f}, 0.05);
  QVERIFY(std::abs(five.longestEdge - 0.01) < 1e-6);
  QVERIFY(std::abs(five.samplesAcross - 5.0) < 1e-4);
  QVERIFY(!five.sparse());
  const BrushSampling two = brushSampling(image, {0.5f, 0.5f}, 0.02);
  QVERIFY(std::abs(two.samplesAcross - 2.0) < 1e-4);
  QVERIFY(two.sparse());
  // Just over 3 samples across are enough (the float grid's edges are 0.01 within rounding).
  QVERIFY(!brushSampling(image, {0.5f, 0.5f}, 0.0301).sparse());
  QVERIFY(brushSampling(image, {0.5f, 0.5f}, 0.0299).sparse());
}

void BrushSamplingTest::theSparsestDirectionCounts() {
  // Rows 0.1 apart, columns 0.01: a radius of 0.2 spans 20 columns but only 2 rows.
  const BrushSampling s = brushSampling(grid(64, 0.01f, 0.1f), {0.4f, 0.6f}, 0.2);
  QVERIFY(std::abs(s.longestEdge - 0.1) < 1e-6);
  QVERIFY(std::abs(s.samplesAcross - 2.0) < 1e-4);
  QVERIFY(s.sparse());
}

void BrushSamplingTest::aStretchedPatchNearThePointCounts() {
  // Columns 30..34 of a 0.01 grid pulled 0.25 apart (a limb's long edges), the rest as it was.
  const int n = 64;
  GeometryImage image = grid(n, 0.01f, 0.01f);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int pulled = std::clamp(i - 30, 0, 4);
      image.at(i, j).x = float(i) * 0.01f + float(pulled) * 0.24f;
    }
  // At column 32 (uv 0.5) the patch is under the brush: 0.1 / 0.25 = 0.4 samples across.
  const BrushSampling tip = brushSampling(image, {0.5f, 0.5f}, 0.1);
  QVERIFY(std::abs(tip.longestEdge - 0.25) < 1e-5);
  QVERIFY(std::abs(tip.samplesAcross - 0.4) < 1e-4);
  QVERIFY(tip.sparse());
  // Ten columns away the brush meets the even grid: 10 across.
  const BrushSampling body = brushSampling(image, {20.0f / float(n), 0.5f}, 0.1);
  QVERIFY(std::abs(body.samplesAcross - 10.0) < 1e-3);
  QVERIFY(!body.sparse());
}

void BrushSamplingTest::theSphereAtTheModellersSizes() {
  // The unit sphere's longest grid edge is about pi / N (a quarter circle spans N / 2 samples
  // along a side, longer near the octahedron's vertices): the modeller's default radius (0.1 of
  // the diagonal, 0.35) meets 9-20 samples at N = 128 and 77-177 at N = 1024 (measured); a radius
  // of 0.02 object units is sparse at N = 128 and not at N = 1024.
  for (const int n : {128, 1024}) {
    const GeometryImage ball = makeBaseShape(BaseShape::Sphere, n);
    for (const Vec2f uv : {Vec2f{0.5f, 0.5f}, Vec2f{0.3f, 0.7f}, Vec2f{0.02f, 0.5f}}) {
      const BrushSampling s = brushSampling(ball, uv, 0.35);
      qInfo("N = %d at (%.2f, %.2f): longest edge %.5f (pi / N = %.5f), %.1f samples across 0.35",
            n, double(uv.x), double(uv.y), s.longestEdge, M_PI / n, s.samplesAcross);
      QVERIFY(s.longestEdge > 0.5 * M_PI / n && s.longestEdge < 2.0 * M_PI / n);
      QVERIFY(!s.sparse());
      QCOMPARE(brushSampling(ball, uv, 0.02).sparse(), n == 128);
    }
  }
}

void BrushSamplingTest::theCornersSeeTheSameSurfaceThroughTheSeams() {
  // The four corners are one vertex: the same edges around it from each of them.
  const GeometryImage ball = makeBaseShape(BaseShape::Sphere, 64);
  const BrushSampling a = brushSampling(ball, {0.0f, 0.0f}, 0.2);
  for (const Vec2f corner : {Vec2f{1.0f, 0.0f}, Vec2f{0.0f, 1.0f}, Vec2f{1.0f, 1.0f}}) {
    const BrushSampling b = brushSampling(ball, corner, 0.2);
    QVERIFY(std::isfinite(b.samplesAcross));
    QVERIFY(std::abs(a.longestEdge - b.longestEdge) <= 1e-6);
  }
}

void BrushSamplingTest::degenerateInput() {
  const GeometryImage image = grid(16, 0.01f, 0.01f);
  // Outside [0, 1]: clamped to the border.
  QVERIFY(std::abs(brushSampling(image, {-3.0f, 2.0f}, 0.05).longestEdge -
                   brushSampling(image, {0.0f, 1.0f}, 0.05).longestEdge) < 1e-9);
  // A zero radius covers nothing; a point has no edges.
  QCOMPARE(brushSampling(image, {0.5f, 0.5f}, 0.0).samplesAcross, 0.0);
  GeometryImage point(16);
  const BrushSampling none = brushSampling(point, {0.5f, 0.5f}, 0.1);
  QCOMPARE(none.longestEdge, 0.0);
  QVERIFY(std::isinf(none.samplesAcross));
  QVERIFY(!none.sparse());
}

QTEST_GUILESS_MAIN(BrushSamplingTest)
#include "brush_sampling_test.moc"
