// Strokes follow one set of rules (gpu/stroke_rules.h) whatever the image's resolution and
// whoever feeds them: the same stroke on a sphere at N = 128 … 1024 makes the same dabs and the
// same shape; StrokeSession fed the points a viewport picks along the way dabs where it dabs
// fed only the path's two ends; a dab falls every spacing × radius of the surface as it was
// when the stroke began, the remainder carried across moves.

#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/stroke.h"
#include "octaclay/gpu/stroke_rules.h"

#include <QtTest>

#include <algorithm>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

// The stroke: across the sphere's +z pole, radius 0.1 of the diagonal, strength 0.5.
constexpr std::array<float, 2> kFrom{0.35f, 0.5f}, kTo{0.65f, 0.5f};
constexpr float kRadiusFraction = 0.1f, kStrength = 0.5f;

// Distances from the origin to the surface along fixed directions around the stroke: the same
// directions at every N, so two resolutions' shapes can be compared point by point.
std::vector<float> radialProfile(const GpuDocument& document) {
  const core::GeometryImage& image = document.document().positions;
  std::vector<float> distances;
  // Directions of the upper octahedral half: u in [0.25, 0.75], v in [0.4, 0.6], on a grid
  // offset so that no ray passes exactly through a sample of any N (pickRay can miss those).
  for (int j = 0; j <= 26; ++j)
    for (int i = 0; i <= 64; ++i) {
      const float x = -0.5f + float(i) / 64.0f + 1e-3f, y = -0.2f + float(j) / 64.0f + 1e-3f;
      const core::Ray ray{{0, 0, 0}, core::normalize({x, y, 1.0f - std::abs(x) - std::abs(y)})};
      const std::optional<core::PickHit> hit = core::pickRay(image, document.bounds(), ray);
      distances.push_back(hit ? hit->distance : 0.0f);
    }
  return distances;
}

struct Shape {
  int dabs = 0;
  float radius = 0;      ///< object units
  float sampleMove = 0;  ///< largest |after − before| over the samples
  float profileMove = 0; ///< largest change of radialProfile
  std::vector<float> profile;
  bool missed = false; ///< a direction of radialProfile missed the surface
};

} // namespace

class StrokeIndependenceTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void sameStrokeAtEveryN();
  void viewportPointsDabWhereThePathDabs();
  void dabsFallEverySpacingOfTheStartSurface();
  void onePointIsOneDabAtTheSpacingShare();

private:
  Shape strokeSphere(int n, float spacing = 0);
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

void StrokeIndependenceTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    loadBuiltIns(*engine_);
    for (const char* id : {"push", "paint"})
      manifests_.emplace(id, builtInManifest(id));
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

Shape StrokeIndependenceTest::strokeSphere(int n, float spacing) {
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
  const core::GeometryImage before = document.document().positions;
  Shape shape;
  const std::vector<float> profileBefore = radialProfile(document);
  PathStroke stroke;
  stroke.brush = "push";
  stroke.path = {kFrom, kTo};
  shape.radius = stroke.radius = kRadiusFraction * document.bounds().diagonal();
  stroke.strength = kStrength;
  stroke.spacing = spacing;
  shape.dabs = strokeAlongPath(*engine_, document, manifests_.at("push"), stroke).dabs;
  const core::GeometryImage& after = document.document().positions;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      shape.sampleMove =
          std::max(shape.sampleMove, core::length(after.at(i, j).xyz() - before.at(i, j).xyz()));
  shape.profile = radialProfile(document);
  for (std::size_t k = 0; k < shape.profile.size(); ++k) {
    if (!(shape.profile[k] > 0 && profileBefore[k] > 0)) shape.missed = true;
    shape.profileMove = std::max(shape.profileMove, shape.profile[k] - profileBefore[k]);
  }
  return shape;
}

// Before the shared rules the issue measured 20/22/38/27 dabs and largest sample moves of
// 0.98/0.60/0.87/1.02 for this stroke (CLI, full strength per dab).
void StrokeIndependenceTest::sameStrokeAtEveryN() {
  std::vector<Shape> shapes;
  for (int n : {128, 256, 512, 1024}) {
    shapes.push_back(strokeSphere(n));
    const Shape& s = shapes.back();
    QVERIFY2(!s.missed, "a direction missed the surface");
    qInfo("N = %4d: %d dabs, largest sample move %.4f, largest radial move %.4f (radius %.4f)", n,
          s.dabs, double(s.sampleMove), double(s.profileMove), double(s.radius));
  }
  const auto [fewest, most] = std::minmax_element(
      shapes.begin(), shapes.end(), [](const Shape& a, const Shape& b) { return a.dabs < b.dabs; });
  QVERIFY2(most->dabs <= fewest->dabs * 1.05, "dab counts differ by more than 5 %");
  const float radius = shapes[0].radius; // the same sphere, so the same radius, at every N
  for (const Shape& s : shapes) {
    QVERIFY(std::abs(s.radius - radius) < 1e-3f * radius);
    QVERIFY2(s.profileMove > 0.2f * radius, "the stroke barely moved the surface");
    // 2 % of the radius: the shapes agree far closer than the stroke's own height (about half
    // the radius) and than the finest sample spacing here.
    QVERIFY2(std::abs(s.profileMove - shapes[0].profileMove) < 0.02f * radius,
             qPrintable(QString("largest radial move %1 vs %2 at N = 128")
                            .arg(s.profileMove)
                            .arg(shapes[0].profileMove)));
    QVERIFY2(std::abs(s.sampleMove - shapes[0].sampleMove) < 0.02f * radius,
             qPrintable(QString("largest sample move %1 vs %2 at N = 128")
                            .arg(s.sampleMove)
                            .arg(shapes[0].sampleMove)));
    float worst = 0; // direction by direction: the same shape, not only the same peak
    for (std::size_t k = 0; k < s.profile.size(); ++k)
      worst = std::max(worst, std::abs(s.profile[k] - shapes.back().profile[k]));
    QVERIFY2(worst < 0.02f * radius, qPrintable(QString("profiles differ by %1").arg(worst)));
  }
}

// The viewport feeds a StrokeSession the (u, v) it picks at every pointer move; those points
// lie on the path, so the dabs must be those of the path's two ends, whatever the points and
// their count.
void StrokeIndependenceTest::viewportPointsDabWhereThePathDabs() {
  const int n = 256;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument scripted(core::makeDocument(sphere)), interactive(core::makeDocument(sphere));
  PathStroke stroke;
  stroke.brush = "push";
  stroke.path = {kFrom, kTo};
  stroke.radius = kRadiusFraction * scripted.bounds().diagonal();
  stroke.strength = kStrength;
  const StrokeResult result = strokeAlongPath(*engine_, scripted, manifests_.at("push"), stroke);

  StrokeSession session(*engine_, interactive, manifests_.at("push"), stroke);
  int dabs = 0;
  const int moves = 53; // uneven steps, as a pointer's are
  for (int k = 0; k <= moves; ++k) {
    const float t = float(k * k) / float(moves * moves);
    dabs += session.moveToUv({kFrom[0] + t * (kTo[0] - kFrom[0]), kFrom[1]}, stroke.radius,
                             stroke.strength);
  }
  session.finish("interactive");
  QVERIFY(result.dabs > 10);
  QCOMPARE(dabs, result.dabs);
  float worst = 0;
  const core::GeometryImage &a = scripted.document().positions,
                            &b = interactive.document().positions;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      worst = std::max(worst, core::length(a.at(i, j).xyz() - b.at(i, j).xyz()));
  // Only the arc length's rounding differs (summed over other pieces).
  QVERIFY2(worst < 1e-4f * stroke.radius, qPrintable(QString("differ by %1").arg(worst)));
}

// Paint never moves the surface, so its dabs' places can be read off a CPU walk: a dab at arc
// length 0, s, 2s, … of the straight (u, v) path, the remainder carried across the moves.
void StrokeIndependenceTest::dabsFallEverySpacingOfTheStartSurface() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  const float radius = 0.05f * document.bounds().diagonal();
  const BrushManifest& paint = manifests_.at("paint");
  const float spacing = dabSpacing(paint, 0) * radius;
  // Arc length of the path, finely sampled on the interpolated surface.
  const std::vector<core::Vec2f> points{{0.3f, 0.3f}, {0.31f, 0.32f}, {0.5f, 0.4f}, {0.7f, 0.7f}};
  double length = 0;
  for (std::size_t k = 1; k < points.size(); ++k)
    for (int step = 0; step < 4000; ++step) {
      const auto at = [&](int s) {
        const float t = float(s) / 4000.0f;
        const float u = points[k - 1].x + t * (points[k].x - points[k - 1].x);
        const float v = points[k - 1].y + t * (points[k].y - points[k - 1].y);
        return core::interpolatePosition(sphere, surfacePointAt(n, double(u) * n, double(v) * n));
      };
      length += double(core::length(at(step + 1) - at(step)));
    }
  PathStroke settings;
  settings.brush = "paint";
  settings.parameters["color"] = {1, 0, 0, 1};
  StrokeSession session(*engine_, document, paint, settings);
  for (core::Vec2f p : points)
    session.moveToUv(p, radius, 1.0f);
  session.finish("paint");
  const int expected = 1 + int(std::floor(length / double(spacing)));
  qInfo("path %.4f long, spacing %.4f: %d dabs (a walk without carried remainders would make "
        "fewer)",
        length, double(spacing), session.dabs());
  QCOMPARE(session.dabs(), expected);
}

// A one-point path is one dab at the spacing's share: push at spacing 1 moves the centre by the
// whole strength × radius, at the brush's spacing by that share of it.
void StrokeIndependenceTest::onePointIsOneDabAtTheSpacingShare() {
  const int n = 128;
  const core::Sample pole{n / 2, n / 2};
  for (float spacing : {1.0f, 0.0f}) {
    GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
    const core::Vec3f start = document.document().positions.at(pole).xyz();
    PathStroke stroke;
    stroke.brush = "push";
    stroke.path = {{0.5f, 0.5f}, {0.5f, 0.5f}};
    stroke.radius = 0.3f;
    stroke.strength = 0.8f;
    stroke.spacing = spacing;
    QCOMPARE(strokeAlongPath(*engine_, document, manifests_.at("push"), stroke).dabs, 1);
    const float moved = core::length(document.document().positions.at(pole).xyz() - start);
    const float expected =
        stroke.strength * stroke.radius * dabShare(manifests_.at("push"), spacing);
    QVERIFY2(std::abs(moved - expected) < 1e-4f,
             qPrintable(QString("moved %1, expected %2").arg(moved).arg(expected)));
  }
  QCOMPARE(dabShare(manifests_.at("push"), 0), 0.15f);
  QCOMPARE(dabShare(manifests_.at("push"), 3), 1.0f);
  QCOMPARE(dabShare(manifests_.at("push"), 0.001f), kMinDabSpacing);
  QCOMPARE(dabShare(manifests_.at("paint"), 0.1f), 1.0f);
}

QTEST_APPLESS_MAIN(StrokeIndependenceTest)
#include "stroke_independence_gltest.moc"
