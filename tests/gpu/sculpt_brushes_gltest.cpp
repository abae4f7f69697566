// The sculptor's brush set (brush API 3), each brush's numeric effect on a sphere: grab moves the
// sample under the drag's start to its end and nothing beyond the radius, and does not cross
// itself when dragged by its radius; snake hook's tip follows an L-shaped path out of the sphere;
// pinch draws samples together along the surface; crease leaves a valley deeper than its rims;
// layer reaches the same height over the stroke-start surface after one pass and after five;
// twist keeps every sample's distance from its axis; scrape cuts down to its plane and never
// raises. Strokes of each over seams and the corner pole keep the surface closed (Euler
// characteristic 2) and the seams exact, and undo and redo are bit-exact.

#include "../mesh_self_intersections.h"
#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/grid_point.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/stroke.h"
#include "octaclay/gpu/stroke_rules.h"

#include <QtTest>

#include <cmath>
#include <map>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;
using octaclay::testing::selfIntersectionsAfter;

namespace {

constexpr const char* kNewBrushes[] = {"grab",  "snake-hook",  "pinch",  "crease",
                                       "layer", "clay-strips", "scrape", "twist"};

PathStroke strokeOf(const std::string& brush, std::vector<std::array<float, 2>> path, float radius,
                    float strength) {
  PathStroke s;
  s.brush = brush;
  s.path = std::move(path);
  s.radius = radius;
  s.strength = strength;
  return s;
}

// The surface point of image at image coordinates uv (each in [0, 1]): where a stroke's path
// point lies on the surface as it was.
core::Vec3f surfaceAt(const core::GeometryImage& image, std::array<float, 2> uv) {
  const int n = image.size();
  return core::interpolatePosition(image, surfacePointAt(n, double(uv[0]) * n, double(uv[1]) * n));
}

bool sameTexel(const core::Vec4f& a, const core::Vec4f& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

// Distance of p from the line through c along unit axis.
float axisDistance(core::Vec3f p, core::Vec3f c, core::Vec3f axis) {
  const core::Vec3f d = p - c;
  return core::length(d - axis * core::dot(d, axis));
}

} // namespace

class SculptBrushesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void grabMovesTheDragStartToItsEnd_data();
  void grabMovesTheDragStartToItsEnd();
  void grabDraggedByItsRadiusDoesNotCrossItself_data();
  void grabDraggedByItsRadiusDoesNotCrossItself();
  void snakeHookFollowsAnLShapedPath();
  void draggingBrushesFollowThePointersRay();
  void pinchDrawsSamplesTogether();
  void creaseLeavesAValleyDeeperThanItsRims();
  void layerHeightIsTheSameAfterOneAndFivePasses();
  void twistKeepsDistancesFromTheAxis();
  void scrapeCutsDownToThePlaneAndNeverRaises();
  void clayStripsAddUpToThePlane();
  void strokesOverSeamsAndPoleStayClosedAndUndo_data();
  void strokesOverSeamsAndPoleStayClosedAndUndo();

private:
  StrokeResult stroke(GpuDocument& document, const PathStroke& settings) {
    return strokeAlongPath(*engine_, document, manifests_.at(settings.brush), settings);
  }
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

void SculptBrushesTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    for (const char* id : kNewBrushes) {
      manifests_.emplace(id, builtInManifest(id));
      engine_->load(manifests_.at(id), readFile(manifests_.at(id).shaderPath()));
    }
    BrushManifest linear = builtInManifest("grab"); // as a user sets it: falloff linear
    linear.id = "grab-linear";
    linear.falloff = Falloff::Linear;
    engine_->load(linear, readFile(linear.shaderPath()));
    manifests_.emplace(linear.id, linear);
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

void SculptBrushesTest::grabMovesTheDragStartToItsEnd_data() {
  QTest::addColumn<bool>("view");
  QTest::newRow("along the path") << false;
  QTest::newRow("in the view plane") << true;
}

void SculptBrushesTest::grabMovesTheDragStartToItsEnd() {
  QFETCH(bool, view);
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  // From the +z pole (sample (64, 64)) over a third of the way to the point the drag ends at.
  PathStroke settings = strokeOf("grab", {{0.5f, 0.5f}, {0.53f, 0.52f}, {0.56f, 0.5f}}, 0.3f, 1.0f);
  const core::Vec3f start = surfaceAt(sphere, settings.path.front());
  core::Vec3f drag = surfaceAt(sphere, settings.path.back()) - start;
  if (view) {
    settings.viewEye = core::Vec3f{0.0f, 0.0f, 6.0f}; // looking down -z: the drag plane is z = 1
    drag.z = 0;
  }
  const StrokeResult result = stroke(document, settings);
  QCOMPARE(result.dabs, 3); // one anchored dab, again at each move
  const core::GeometryImage& after = document.document().positions;
  const core::Sample centre{n / 2, n / 2};
  QVERIFY(
      sameTexel(core::Vec4f{start.x, start.y, start.z, sphere.at(centre).w}, sphere.at(centre)));
  const float miss = core::length(after.at(centre).xyz() - (start + drag));
  QVERIFY2(miss <= 0.05f * settings.radius,
           qPrintable(QString("missed the drag's end by %1 (drag %2)")
                          .arg(miss)
                          .arg(double(core::length(drag)))));
  QVERIFY2(core::length(drag) > 0.1f, qPrintable(QString::number(double(core::length(drag)))));
  int outside = 0, moved = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      if (core::length(sphere.at(i, j).xyz() - start) >= settings.radius) {
        ++outside;
        if (!sameTexel(sphere.at(i, j), after.at(i, j)))
          QFAIL(qPrintable(QString("(%1,%2) beyond the radius changed").arg(i).arg(j)));
      } else {
        moved += !sameTexel(sphere.at(i, j), after.at(i, j));
      }
    }
  QVERIFY(outside > 0);
  QVERIFY(moved > 50);
  QCOMPARE(core::maxSeamGap(after), 0.0f);
}

void SculptBrushesTest::grabDraggedByItsRadiusDoesNotCrossItself_data() {
  QTest::addColumn<QString>("brush");
  QTest::addColumn<int>("shape");
  QTest::addColumn<float>("dragOverRadius");
  QTest::newRow("linear on a sphere") << "grab-linear" << int(core::BaseShape::Sphere) << 0.95f;
  QTest::newRow("linear on the blob") << "grab-linear" << int(core::BaseShape::Blob) << 0.95f;
  QTest::newRow("linear on the cube") << "grab-linear" << int(core::BaseShape::Cube) << 0.8f;
  QTest::newRow("smooth on the blob") << "grab" << int(core::BaseShape::Blob) << 0.6f;
}

// As push is tested: with linear falloff the displacement changes by at most |drag| / radius per
// unit of distance, so a drag of up to the radius (here exactly) folds nothing.
void SculptBrushesTest::grabDraggedByItsRadiusDoesNotCrossItself() {
  QFETCH(QString, brush);
  QFETCH(int, shape);
  QFETCH(float, dragOverRadius);
  const int n = 64;
  const core::GeometryImage start = core::makeBaseShape(core::BaseShape(shape), n);
  GpuDocument document(core::makeDocument(start));
  for (const std::vector<std::array<float, 2>>& path :
       {std::vector<std::array<float, 2>>{{0.5f, 0.5f}, {0.6f, 0.45f}},
        {{0.25f, 0.25f}, {0.15f, 0.3f}},
        {{0.0f, 0.25f}, {0.08f, 0.2f}}}) {
    const core::GeometryImage before = document.document().positions;
    PathStroke settings = strokeOf(brush.toStdString(), path, 1.0f, 1.0f);
    settings.radius =
        core::length(surfaceAt(before, path.back()) - surfaceAt(before, path[0])) / dragOverRadius;
    QVERIFY(settings.radius > 0.05f);
    stroke(document, settings);
    QCOMPARE(selfIntersectionsAfter(before, document.document().positions), 0);
  }
  const core::MeshTopology topology =
      core::analyzeTopology(core::extractMesh(document.document().positions));
  QVERIFY(topology.closed());
  QCOMPARE(topology.euler, 2LL);
}

void SculptBrushesTest::snakeHookFollowsAnLShapedPath() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  // Out of the +z pole, seen from above: right, then up; the limb grows in the plane z = 1.
  PathStroke settings =
      strokeOf("snake-hook", {{0.5f, 0.5f}, {0.62f, 0.5f}, {0.62f, 0.62f}}, 0.15f, 1.0f);
  settings.viewEye = core::Vec3f{0.0f, 0.0f, 6.0f};
  const core::Vec3f start = surfaceAt(sphere, settings.path.front());
  core::Vec3f end = surfaceAt(sphere, settings.path.back());
  end.z = start.z; // projected into the view plane through the start
  const StrokeResult result = stroke(document, settings);
  QVERIFY(result.dabs > 30);
  const core::GeometryImage& after = document.document().positions;
  float farthest = 0;
  core::Vec3f tip;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const float moved = core::length(after.at(i, j).xyz() - sphere.at(i, j).xyz());
      if (moved > farthest) farthest = moved, tip = after.at(i, j).xyz();
    }
  const float miss = core::length(tip - end);
  qInfo("snake hook: the tip moved %.3f and ends %.3f (%.2f radii) from the path's end", farthest,
        miss, miss / settings.radius);
  QVERIFY2(miss <= settings.radius, qPrintable(QString::number(miss)));
  QVERIFY(core::length(tip) > 1.1f); // drawn out of the sphere, not along it
  QCOMPARE(core::maxSeamGap(after), 0.0f);
  const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
  QVERIFY(topology.closed());
  QCOMPARE(topology.euler, 2LL);
}

// The modeller's drag: the first move says where the stroke starts, later ones give the pointer's
// ray, which meets the view plane through the start (here z = 1, seen from above).
void SculptBrushesTest::draggingBrushesFollowThePointersRay() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  const core::Vec3f eye{0.0f, 0.0f, 6.0f};
  const core::Vec3f pole = sphere.at(n / 2, n / 2).xyz(), end{0.35f, 0.2f, 1.0f};
  for (const char* brush : {"grab", "snake-hook"}) {
    GpuDocument document(core::makeDocument(sphere));
    PathStroke settings = strokeOf(brush, {}, 0.3f, 1.0f);
    settings.viewEye = eye;
    StrokeSession session(*engine_, document, manifests_.at(brush), settings);
    QVERIFY(session.drags());
    session.moveToUv({0.5f, 0.5f}, settings.radius, 1.0f);
    // Half way, then to the end: each ray from the eye through a point of the plane.
    const core::Vec3f half = (pole + end) * 0.5f;
    for (core::Vec3f at : {half, end})
      session.dragAlong(eye, core::normalize(at - eye), settings.radius, 1.0f);
    session.finish(brush);
    const core::Vec3f tip = document.document().positions.at(n / 2, n / 2).xyz();
    const float miss = core::length(tip - end);
    qInfo("%s: the pole ends %.4f (%.3f radii) from the pointer's point", brush, miss,
          miss / settings.radius);
    // Snake hook's last dab falls up to a spacing (0.1 radii) short of the pointer.
    QVERIFY2(miss <= (QString(brush) == "grab" ? 0.05f : 0.15f) * settings.radius,
             qPrintable(QString("%1: %2").arg(brush).arg(miss)));
    QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
  }
  GpuDocument document(core::makeDocument(sphere));
  StrokeSession pinch(*engine_, document, manifests_.at("pinch"), strokeOf("pinch", {}, 0.3f, 1));
  QVERIFY(!pinch.drags());
  pinch.moveToUv({0.5f, 0.5f}, 0.3f, 1.0f);
  QVERIFY_THROWS_EXCEPTION(core::Error, pinch.dragAlong(eye, {0, 0, -1}, 0.3f, 1.0f));
  pinch.finish("pinch");
}

void SculptBrushesTest::pinchDrawsSamplesTogether() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  const Dab dab = dabAt(sphere, {n / 2, n / 2}, 0.4f, 0.5f);
  engine_->dab(document, "pinch", dab);
  const core::GeometryImage& after = document.document().positions;
  int edges = 0;
  double before = 0, now = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const core::Vec3f p = sphere.at(i, j).xyz(), q = after.at(i, j).xyz();
      const float d = core::length(p - dab.centre) / dab.radius;
      if (d >= 1) {
        QVERIFY(sameTexel(sphere.at(i, j), after.at(i, j)));
        continue;
      }
      // Along the surface: no sample moves along the centre normal.
      QVERIFY(std::abs(core::dot(q - p, dab.centreNormal)) < 1e-5f);
      before += core::length(p - dab.centre), now += core::length(q - dab.centre);
      // Within 0.4 radii (where the falloff still falls slowly) every edge shrinks.
      for (const core::Sample o : {core::Sample{i + 1, j}, core::Sample{i, j + 1}}) {
        if (o.i > n || o.j > n ||
            core::length(sphere.at(o).xyz() - dab.centre) >= 0.4f * dab.radius)
          continue;
        if (d >= 0.4f) continue;
        const float was = core::length(sphere.at(o).xyz() - p);
        const float is = core::length(after.at(o).xyz() - q);
        QVERIFY2(is < was, qPrintable(QString("(%1,%2): %3 -> %4").arg(i).arg(j).arg(was).arg(is)));
        ++edges;
      }
    }
  QVERIFY(edges > 50);
  qInfo("pinch: summed distance to the centre inside the radius %.4f -> %.4f", before, now);
  QVERIFY(now < 0.9 * before);
}

void SculptBrushesTest::creaseLeavesAValleyDeeperThanItsRims() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  const float radius = 0.3f;
  stroke(document, strokeOf("crease", {{0.42f, 0.5f}, {0.58f, 0.5f}}, radius, 0.5f));
  const core::GeometryImage& after = document.document().positions;
  // Depth under the sphere, on the stroke's line (through the pole) and across it.
  const auto depth = [&](core::Sample s) { return 1.0f - core::length(after.at(s).xyz()); };
  const float valley = depth({n / 2, n / 2});
  float rims = -1;
  for (int j = 0; j <= n; ++j) // the samples across the line's middle, 0.6 to 1 radii from it
    for (int i = n / 2 - 1; i <= n / 2 + 1; ++i) {
      const float across = std::abs(sphere.at(i, j).y);
      if (across >= 0.6f * radius && across <= radius && sphere.at(i, j).z > 0)
        rims = std::max(rims, depth({i, j}));
    }
  qInfo("crease: valley %.4f deep, rims at most %.4f", valley, rims);
  QVERIFY(rims > -1);
  QVERIFY2(valley > 0.1f * radius, qPrintable(QString::number(valley)));
  QVERIFY2(valley > 2 * std::max(rims, 0.0f), qPrintable(QString("%1 %2").arg(valley).arg(rims)));
  QCOMPARE(core::maxSeamGap(after), 0.0f);
}

void SculptBrushesTest::layerHeightIsTheSameAfterOneAndFivePasses() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  const float radius = 0.3f;
  const auto heightAfter = [&](std::vector<std::array<float, 2>> path) {
    GpuDocument document(core::makeDocument(sphere));
    stroke(document, strokeOf("layer", std::move(path), radius, 1.0f));
    // Over the stroke-start surface at the pole, along its normal (+z).
    return document.document().positions.at(n / 2, n / 2).z - sphere.at(n / 2, n / 2).z;
  };
  const float a = 0.44f, b = 0.56f;
  const float once = heightAfter({{a, 0.5f}, {b, 0.5f}});
  const float five =
      heightAfter({{a, 0.5f}, {b, 0.5f}, {a, 0.5f}, {b, 0.5f}, {a, 0.5f}, {b, 0.5f}});
  qInfo("layer: height %.5f after one pass, %.5f after five (%.2f %%)", once, five,
        100.0 * (five - once) / once);
  const float wanted = 0.5f * radius; // the default height, 0.5 radii at strength 1
  QVERIFY2(once > 0.9f * wanted && once <= wanted * 1.0001f, qPrintable(QString::number(once)));
  QVERIFY2(std::abs(five - once) <= 0.02f * once, qPrintable(QString("%1 %2").arg(once).arg(five)));
}

void SculptBrushesTest::twistKeepsDistancesFromTheAxis() {
  const int n = 128;
  const core::GeometryImage blob = core::makeBaseShape(core::BaseShape::Blob, n);
  GpuDocument document(core::makeDocument(blob));
  Dab dab = dabAt(blob, {n / 3, n / 2}, 0.4f, 1.0f);
  dab.parameters["angle"] = {10.0f, 0, 0, 0};
  engine_->dab(document, "twist", dab);
  const core::GeometryImage& after = document.document().positions;
  float worst = 0, turned = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const core::Vec3f p = blob.at(i, j).xyz(), q = after.at(i, j).xyz();
      if (core::length(p - dab.centre) >= dab.radius) {
        QVERIFY(sameTexel(blob.at(i, j), after.at(i, j)));
        continue;
      }
      const float was = axisDistance(p, dab.centre, dab.centreNormal);
      const float is = axisDistance(q, dab.centre, dab.centreNormal);
      if (was < 1e-3f * dab.radius) continue;
      worst = std::max(worst, std::abs(is - was) / was);
      turned = std::max(turned, core::length(q - p) / was); // the chord of the angle turned
    }
  qInfo("twist: distance from the axis changed by at most %.2g; turned up to %.2f degrees", worst,
        2 * std::asin(turned / 2) * 180 / 3.14159265);
  QVERIFY2(worst <= 0.01f, qPrintable(QString::number(worst)));
  QVERIFY(turned > 2 * std::sin(9.0f / 2 * 3.14159265f / 180)); // near 10 degrees at the centre
  QCOMPARE(core::maxSeamGap(after), 0.0f);
}

void SculptBrushesTest::scrapeCutsDownToThePlaneAndNeverRaises() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  const Dab dab = dabAt(sphere, {n / 2, n / 2}, 0.4f, 1.0f);
  engine_->dab(document, "scrape", dab);
  const core::GeometryImage& after = document.document().positions;
  const float plane = 0.1f * dab.radius; // the default depth under the centre
  int cut = 0, core = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const core::Vec3f p = sphere.at(i, j).xyz(), q = after.at(i, j).xyz();
      const float was = core::dot(p - dab.centre, dab.centreNormal) + plane; // over the plane
      const float is = core::dot(q - dab.centre, dab.centreNormal) + plane;
      QVERIFY2(is <= was + 1e-6f, qPrintable(QString("(%1,%2) raised").arg(i).arg(j)));
      if (was <= 0) { // below the plane: left alone
        QVERIFY(sameTexel(sphere.at(i, j), after.at(i, j)));
        continue;
      }
      QVERIFY2(is >= -1e-6f, qPrintable(QString("(%1,%2) cut below the plane").arg(i).arg(j)));
      const float d = core::length(p - dab.centre) / dab.radius;
      if (d < 1) cut += is < was;
      if (d <= 0.4f) { // full weight: on the plane
        ++core;
        QVERIFY2(is <= 1e-6f,
                 qPrintable(QString("(%1,%2) %3 above the plane").arg(i).arg(j).arg(is)));
      }
    }
  QVERIFY(core > 50);
  QVERIFY(cut > core);
  QCOMPARE(core::maxSeamGap(after), 0.0f);
}

void SculptBrushesTest::clayStripsAddUpToThePlane() {
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(sphere));
  Dab dab = dabAt(sphere, {n / 2, n / 2}, 0.4f, 1.0f);
  engine_->dab(document, "clay-strips", dab);
  const core::GeometryImage& after = document.document().positions;
  const float plane = 0.25f * dab.radius; // the default height over the centre
  int raised = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const core::Vec3f p = sphere.at(i, j).xyz(), q = after.at(i, j).xyz();
      const float was = core::dot(p - dab.centre, dab.centreNormal) - plane;
      const float is = core::dot(q - dab.centre, dab.centreNormal) - plane;
      QVERIFY(is >= was - 1e-6f); // adds only
      QVERIFY(is <= 1e-6f);       // up to the plane
      raised += is > was + 1e-4f * dab.radius;
    }
  QCOMPARE(after.at(n / 2, n / 2).z, 1.0f + plane); // the centre reaches the plane
  QVERIFY(raised > 100);
}

void SculptBrushesTest::strokesOverSeamsAndPoleStayClosedAndUndo_data() {
  QTest::addColumn<QString>("brush");
  QTest::addColumn<float>("strength");
  QTest::addColumn<QString>("path");
  // Across the left seam, along the bottom seam, into the corner pole and out; grab drags from
  // the corner pole over the seams.
  const QString seams = "0.1,0.3;0,0.3;0,0;0.3,0;0.5,0.2";
  QTest::newRow("grab") << "grab" << 1.0f << "0,0;0.04,0.03;0.08,0.02";
  QTest::newRow("snake-hook") << "snake-hook" << 1.0f << "0.1,0.3;0,0.3;0,0;0.15,0";
  for (const char* b : {"pinch", "crease", "layer", "clay-strips", "scrape", "twist"})
    QTest::newRow(b) << b << 0.5f << seams;
}

void SculptBrushesTest::strokesOverSeamsAndPoleStayClosedAndUndo() {
  QFETCH(QString, brush);
  QFETCH(float, strength);
  QFETCH(QString, path);
  const int n = 64;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  PathStroke settings = strokeOf(brush.toStdString(), {}, 0.25f, strength);
  for (const QString& point : path.split(';'))
    settings.path.push_back({point.split(',')[0].toFloat(), point.split(',')[1].toFloat()});
  const auto start = snapshot(document);
  StrokeResult result = stroke(document, settings);
  const auto stroked = snapshot(document);
  QVERIFY(!sameBits(start, stroked));
  const core::GeometryImage& after = document.document().positions;
  QCOMPARE(core::maxSeamGap(after), 0.0f);
  const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
  QVERIFY(topology.closed());
  QVERIFY(topology.manifold());
  QCOMPARE(topology.euler, 2LL);

  core::EditHistory history;
  history.record(std::move(result.undo));
  const core::TileApplier apply = undoApplier(document);
  QVERIFY(history.undo(apply));
  QVERIFY(sameBits(snapshot(document), start));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(snapshot(document), stroked));
}

QTEST_GUILESS_MAIN(SculptBrushesTest)
#include "sculpt_brushes_gltest.moc"
