// Strokes on the GPU: a stroke over seams and the corner pole leaves a closed genus-0 surface
// with no crack, symmetric strokes give mirror-equal results, and undo/redo over 100 random
// strokes of every brush restores each state bit-exactly on the CPU mirror and the textures.
// StrokeSession names every texel it changed for redrawing, and its undo record restores the
// start bit-exactly. (That a viewport's stroke and a script's are the same stroke is tested at
// the one door they share: tests/gui/stroke_door_test.cpp.)

#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/stroke.h"
#include "octaclay/gpu/stroke_rules.h"

#include <QtTest>

#include <cstring>
#include <limits>
#include <optional>
#include <random>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

constexpr core::EditLayer kLayers[] = {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                       core::EditLayer::Feature, core::EditLayer::Mask};

// The same, read back from the GPU textures (feature is RGBA there, RGB in the mirror).
std::vector<std::vector<float>> textureSnapshot(GpuDocument& document) {
  const int side = document.size() + 1;
  std::vector<std::vector<float>> layers;
  for (core::EditLayer layer : kLayers) {
    std::vector<float> texels = document.texture(layer).read({0, 0, side, side});
    if (layer == core::EditLayer::Feature) {
      std::vector<float> rgb;
      for (std::size_t t = 0; t < texels.size(); t += 4)
        rgb.insert(rgb.end(), {texels[t], texels[t + 1], texels[t + 2]});
      texels = std::move(rgb);
    }
    layers.push_back(std::move(texels));
  }
  return layers;
}

PathStroke strokeOf(const std::string& brush, std::vector<std::array<float, 2>> path, float radius,
                    float strength) {
  PathStroke s;
  s.brush = brush;
  s.path = std::move(path);
  s.radius = radius;
  s.strength = strength;
  return s;
}

// Texels of any layer that differ between two snapshots, as (i, j) samples.
std::vector<core::Sample> changedTexels(const std::vector<std::vector<float>>& before,
                                        const std::vector<std::vector<float>>& after, int side) {
  std::vector<core::Sample> changed;
  for (std::size_t k = 0; k < before.size(); ++k) {
    const std::size_t channels = before[k].size() / std::size_t(side * side);
    for (int j = 0; j < side; ++j)
      for (int i = 0; i < side; ++i) {
        const std::size_t at = (std::size_t(j) * std::size_t(side) + std::size_t(i)) * channels;
        if (std::memcmp(&before[k][at], &after[k][at], channels * sizeof(float)) != 0)
          changed.push_back({i, j});
      }
  }
  return changed;
}

bool inside(core::Sample s, const std::vector<core::TexelRect>& rects) {
  for (const core::TexelRect& r : rects)
    if (s.i >= r.x && s.i < r.x + r.width && s.j >= r.y && s.j < r.y + r.height) return true;
  return false;
}

} // namespace

class StrokesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void strokeOverSeamsAndPoleLeavesAClosedSphere_data();
  void strokeOverSeamsAndPoleLeavesAClosedSphere();
  void symmetricStrokesAreMirrorEqual_data();
  void symmetricStrokesAreMirrorEqual();
  void undoRedoIsBitExactOverRandomStrokes_data();
  void undoRedoIsBitExactOverRandomStrokes();
  void sessionTouchedRectsCoverEveryChange();
  void sessionUndoRestoresTheStartBitExactly();
  void sessionRefusesSamplesOutsideTheImage();
  void gpuTileBoundsEqualTheMirrors();
  void areaSumOnTheGpuEqualsTheCpus();
  void deferredPositionsGiveTheSameStrokes();
  void finiteCheckOnTheGpuFindsEachBadValue();

private:
  const BrushManifest& manifest(const std::string& id) const { return manifests_.at(id); }
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

void StrokesTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    loadBuiltIns(*engine_);
    for (const char* id : {"snake-hook", "grab"}) { // a drag, an anchored stroke
      const BrushManifest extra = builtInManifest(id);
      engine_->load(extra, readFile(extra.shaderPath()));
    }
    for (const char* id : {"push", "inflate", "smooth", "flatten", "sphere-add", "sphere-subtract",
                           "mask", "paint", "snake-hook", "grab"})
      manifests_.emplace(id, builtInManifest(id));
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

void StrokesTest::strokeOverSeamsAndPoleLeavesAClosedSphere_data() {
  QTest::addColumn<QString>("brush");
  for (const char* b : {"push", "inflate", "smooth", "flatten", "sphere-add", "sphere-subtract"})
    QTest::newRow(b) << b;
}

void StrokesTest::strokeOverSeamsAndPoleLeavesAClosedSphere() {
  QFETCH(QString, brush);
  const int n = 128;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  // Across the left seam, along the bottom seam, into the corner pole and out over the top.
  const PathStroke stroke =
      strokeOf(brush.toStdString(),
               {{0.1f, 0.3f}, {0.0f, 0.3f}, {0.0f, 0.0f}, {0.3f, 0.0f}, {0.7f, 1.0f}}, 0.25f, 0.3f);
  const StrokeResult result =
      strokeAlongPath(*engine_, document, manifest(brush.toStdString()), stroke);
  QVERIFY(result.dabs > 10);
  const core::GeometryImage& after = document.document().positions;
  QCOMPARE(core::maxSeamGap(after), 0.0f);
  const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
  QVERIFY(topology.closed());
  QVERIFY(topology.manifold());
  QCOMPARE(topology.euler, 2LL);
}

void StrokesTest::symmetricStrokesAreMirrorEqual_data() {
  QTest::addColumn<QString>("brush");
  QTest::addColumn<unsigned>("axis");
  QTest::addColumn<float>("u");
  QTest::addColumn<float>("v");
  QTest::addColumn<float>("strength");
  // Paths far enough from the mirror plane that a dab and its mirror image do not overlap.
  // sphere-subtract's dabs do not add up (each cuts strength × share of half the radius deep),
  // so it needs the whole strength to move as many samples as the others.
  QTest::newRow("push x") << "push" << unsigned(kSymmetryX) << 0.85f << 0.6f << 0.4f;
  QTest::newRow("inflate y") << "inflate" << unsigned(kSymmetryY) << 0.6f << 0.85f << 0.4f;
  QTest::newRow("sphere-subtract z")
      << "sphere-subtract" << unsigned(kSymmetryZ) << 0.45f << 0.5f << 1.0f;
  QTest::newRow("smooth x") << "smooth" << unsigned(kSymmetryX) << 0.85f << 0.4f << 0.4f;
}

void StrokesTest::symmetricStrokesAreMirrorEqual() {
  QFETCH(QString, brush);
  QFETCH(unsigned, axis);
  QFETCH(float, u);
  QFETCH(float, v);
  QFETCH(float, strength);
  const int n = 128;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  const auto mirror = [axis](core::Vec3f p) {
    if (axis == kSymmetryX) p.x = -p.x;
    if (axis == kSymmetryY) p.y = -p.y;
    if (axis == kSymmetryZ) p.z = -p.z;
    return p;
  };
  // Pair every sample with the sample at its mirrored position (the sphere's sampling is
  // mirror-symmetric, which the pairing checks: every sample finds its partner).
  const auto key = [](core::Vec3f p) {
    return std::array<long, 3>{std::lround(p.x * 1e5f), std::lround(p.y * 1e5f),
                               std::lround(p.z * 1e5f)};
  };
  std::map<std::array<long, 3>, core::Sample> byPosition;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      byPosition[key(sphere.at(i, j).xyz())] = {i, j};

  GpuDocument document(core::makeDocument(sphere));
  PathStroke stroke =
      strokeOf(brush.toStdString(), {{u, v}, {u + 0.05f, v + 0.05f}}, 0.3f, strength);
  stroke.symmetry = axis;
  const StrokeResult result =
      strokeAlongPath(*engine_, document, manifest(brush.toStdString()), stroke);
  QVERIFY(result.dabs >= 4);
  QCOMPARE(result.dabs % 2, 0);
  const core::GeometryImage& after = document.document().positions;
  int moved = 0;
  float worst = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto partner = byPosition.find(key(mirror(sphere.at(i, j).xyz())));
      QVERIFY2(partner != byPosition.end(), qPrintable(QString("(%1,%2)").arg(i).arg(j)));
      const core::Vec3f here = after.at(i, j).xyz();
      worst = std::max(worst, core::length(after.at(partner->second).xyz() - mirror(here)));
      moved += !(here == sphere.at(i, j).xyz());
    }
  QVERIFY2(moved > 200, qPrintable(QString("%1 samples moved").arg(moved)));
  QVERIFY2(worst < 1e-5f, qPrintable(QString("mirror mismatch %1").arg(worst)));
}

void StrokesTest::undoRedoIsBitExactOverRandomStrokes_data() {
  QTest::addColumn<bool>("deferred");
  QTest::newRow("positions read back at once") << false;
  QTest::newRow("positions deferred, bounds from the GPU") << true;
}

void StrokesTest::undoRedoIsBitExactOverRandomStrokes() {
  QFETCH(bool, deferred);
  const int n = 64;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  document.setPositionsDeferred(deferred);
  core::EditHistory history;
  std::vector<std::vector<std::vector<float>>> states{snapshot(document)};
  std::mt19937 random(11);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  const std::vector<std::string> brushes{"push",       "inflate",         "smooth", "flatten",
                                         "sphere-add", "sphere-subtract", "mask",   "paint"};
  int strokes = 0;
  while (strokes < 100) {
    PathStroke stroke;
    stroke.brush = brushes[random() % brushes.size()];
    const int points = 1 + int(random() % 3);
    for (int k = 0; k < points; ++k)
      stroke.path.push_back({unit(random), unit(random)});
    stroke.radius = 0.05f + 0.45f * unit(random);
    stroke.strength = -0.6f + 1.4f * unit(random);
    stroke.symmetry = random() % 4 == 0 ? unsigned(random() % 8) : 0u;
    if (stroke.brush == "paint")
      stroke.parameters["color"] = {unit(random), unit(random), unit(random), 1.0f};
    StrokeResult result = strokeAlongPath(*engine_, document, manifest(stroke.brush), stroke);
    const std::size_t before = history.undoCount();
    history.record(std::move(result.undo));
    if (history.undoCount() == before) { // nothing changed: nothing to undo
      QVERIFY(sameBits(snapshot(document), states.back()));
      continue;
    }
    states.push_back(snapshot(document));
    ++strokes;
  }
  QCOMPARE(history.undoCount(), std::size_t(100));
  const core::TileApplier apply = undoApplier(document);
  for (int k = 100; k > 0; --k) {
    QVERIFY(history.undo(apply));
    QVERIFY2(sameBits(snapshot(document), states[k - 1]), qPrintable(QString("undo %1").arg(k)));
    if (k % 25 == 1) QVERIFY(sameBits(textureSnapshot(document), states[k - 1]));
  }
  QVERIFY(!history.canUndo());
  for (int k = 1; k <= 100; ++k) {
    QVERIFY(history.redo(apply));
    QVERIFY2(sameBits(snapshot(document), states[k]), qPrintable(QString("redo %1").arg(k)));
  }
  QVERIFY(sameBits(textureSnapshot(document), states.back()));
  QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
}

// A modeller redraws only what takeTouched() names, so every texel a move changed (on any
// layer, seams included) must lie in its rectangles.
void StrokesTest::sessionTouchedRectsCoverEveryChange() {
  const int n = 64, side = n + 1;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  PathStroke settings = strokeOf("inflate", {}, 0.15f, 0.4f);
  settings.symmetry = kSymmetryY;
  StrokeSession session(*engine_, document, manifest("inflate"), settings);
  // Ends across the left seam so a seamed dab is among them.
  const std::vector<core::Sample> moves{{20, 30}, {26, 34}, {26, 34}, {40, 10}, {3, 20}, {0, 24}};
  int changedTotal = 0;
  for (core::Sample move : moves) {
    const auto before = snapshot(document);
    const int dabs = session.moveTo(move, 0.15f, 0.4f, 0.8f);
    const auto after = snapshot(document);
    const std::vector<core::TexelRect> touched = session.takeTouched();
    const std::vector<core::Sample> changed = changedTexels(before, after, side);
    if (dabs == 0) {
      QVERIFY(touched.empty());
      QVERIFY(changed.empty());
    }
    for (core::Sample s : changed)
      QVERIFY2(inside(s, touched),
               qPrintable(QString("(%1,%2) changed outside the rects").arg(s.i).arg(s.j)));
    QVERIFY(session.takeTouched().empty()); // taken: forgotten
    changedTotal += int(changed.size());
  }
  QVERIFY(changedTotal > 100);
  QVERIFY(session.dabs() > 4);
}

void StrokesTest::sessionUndoRestoresTheStartBitExactly() {
  const int n = 64;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  const auto start = snapshot(document);
  PathStroke settings = strokeOf("push", {}, 0.2f, 0.5f);
  settings.symmetry = kSymmetryX;
  StrokeSession session(*engine_, document, manifest("push"), settings);
  // Pressure and radius vary along the stroke as a pen's would.
  const std::vector<core::Sample> moves{{32, 0}, {10, 5}, {0, 30}, {20, 60}, {64, 64}};
  for (std::size_t k = 0; k < moves.size(); ++k)
    session.moveTo(moves[k], 0.1f + 0.05f * float(k), 0.5f, 1.0f - 0.15f * float(k));
  const auto end = snapshot(document);
  QVERIFY(!sameBits(end, start));
  core::EditHistory history;
  history.record(session.finish("push stroke"));
  QCOMPARE(history.undoCount(), std::size_t(1));
  const core::TileApplier apply = undoApplier(document);
  QVERIFY(history.undo(apply));
  QVERIFY(sameBits(snapshot(document), start));
  QVERIFY(sameBits(textureSnapshot(document), start));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(snapshot(document), end));
  QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
}

// The tile bounds after dabs come from a reduction on the GPU: every tile's box must equal the
// one core::TileBounds computes from the mirror's positions, at two sizes (the last tile of a row
// holds sample N too: 33 samples wide), with dabs across the seams.
void StrokesTest::gpuTileBoundsEqualTheMirrors() {
  for (int n : {64, 128}) {
    GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
    document.setPositionsDeferred(true); // the bounds come from the GPU's reduction
    for (const char* brush : {"inflate", "push"}) {
      PathStroke stroke = strokeOf(brush, {{0.1f, 0.5f}, {0.5f, 0.9f}, {0.98f, 0.02f}}, 0.3f, 0.6f);
      strokeAlongPath(*engine_, document, manifest(brush), stroke);
    }
    const core::TileBounds fresh(document.document().positions);
    const core::TileBounds& kept = document.bounds();
    QCOMPARE(kept.tilesPerSide(), fresh.tilesPerSide());
    int differing = 0;
    for (int t = 0; t < fresh.tilesPerSide() * fresh.tilesPerSide(); ++t) {
      const core::BoundingBox a = kept.box(t), b = fresh.box(t);
      differing += !(a.min == b.min && a.max == b.max);
    }
    QCOMPARE(differing, 0);
    QCOMPARE(kept.diagonal(), fresh.diagonal());
    QVERIFY(fresh.diagonal() !=
            core::TileBounds(core::makeBaseShape(core::BaseShape::Blob, n)).diagonal());
  }
}

// A dab's area normal: the GPU's reduction (where the driver is a real GPU) against the CPU's loop
// (a software rasterizer's), on a ball at two N and on a torus, each after strokes, around
// points off-centre, on the image's corners and on its seams, at two radii, and on a ball far
// smaller and far larger than a unit and away from the origin: the same triangles
// counted and the same sum up to float rounding (the GPU sums per quarter of a tile).
void StrokesTest::areaSumOnTheGpuEqualsTheCpus() {
  struct Case {
    const char* name;
    core::GeometryImage image;
    float scale = 1; ///< of the model, and so of the strokes' radius
  };
  std::vector<Case> cases;
  for (int n : {64, 256})
    cases.push_back({"ball", core::makeBaseShape(core::BaseShape::Blob, n)});
  const core::Torus torus;
  cases.push_back({"torus", core::makeTorus(torus, 128, core::torusHeight(torus, 128))});
  // A thousandth and a thousand times the size, three sizes away from the origin: the CPU sums a
  // tile well inside the sphere by its border, about the tile's first corner.
  for (const float scale : {1e-3f, 1e3f}) {
    core::GeometryImage image = core::makeBaseShape(core::BaseShape::Blob, 128);
    for (core::Vec4f& t : image.texels())
      t = {t.x * scale + 3 * scale, t.y * scale - 3 * scale, t.z * scale + 3 * scale, t.w};
    cases.push_back({"ball off the origin", std::move(image), scale});
  }
  int compared = 0;
  for (const Case& c : cases) {
    GpuDocument document(core::makeDocument(c.image));
    for (const char* brush : {"inflate", "push"})
      strokeAlongPath(
          *engine_, document, manifest(brush),
          strokeOf(brush, {{0.1f, 0.5f}, {0.5f, 0.9f}, {0.98f, 0.02f}}, 0.3f * c.scale, 0.6f));
    const core::GeometryImage& positions = document.document().positions;
    const core::TileBounds& bounds = document.bounds();
    const int w = positions.width(), h = positions.height();
    const float d = bounds.diagonal();
    for (const core::Sample s :
         {core::Sample{w / 2, h / 2}, core::Sample{0, 0}, core::Sample{w, h},
          core::Sample{w / 3, 0}, core::Sample{7, h - 3}, core::Sample{w - 1, h / 5}})
      for (const float radius : {0.04f * d, 0.2f * d}) {
        const core::Vec3f centre = positions.at(s).xyz();
        const std::vector<int> near = bounds.tilesNearSphere(centre, radius);
        const AreaSum gpu = document.areaSum(near, centre, radius);
        const AreaSum cpu = areaSumOnCpu(document, near, centre, radius);
        const QByteArray where = QString("%1 %2x%3 at (%4, %5), radius %6: %7 and %8 triangles")
                                     .arg(c.name)
                                     .arg(w)
                                     .arg(h)
                                     .arg(s.i)
                                     .arg(s.j)
                                     .arg(double(radius))
                                     .arg(gpu.triangles)
                                     .arg(cpu.triangles)
                                     .toUtf8();
        QVERIFY2(cpu.triangles > 32, where.constData());
        // A centroid on the sphere's rim may round to either side.
        QVERIFY2(std::abs(gpu.triangles - cpu.triangles) <= 2, where.constData());
        const float off = core::length(gpu.sum - cpu.sum), size = core::length(cpu.sum);
        QVERIFY2(off <= 1e-4f * size + 1e-7f * d * d,
                 (where + QByteArray(" sums off by ") + QByteArray::number(double(off)) + " of " +
                  QByteArray::number(double(size)))
                     .constData());
        ++compared;
      }
  }
  QCOMPARE(compared, 60);
}

// Where positions are deferred (a real GPU) the dabs read only the mirror's regions they sync:
// every stroke must come out bit for bit as where each dab's positions are read back at once,
// whatever the brush reads on the CPU (area normals, mirror images' nearest samples, a drag's
// tips, an anchored stroke), and the mirror must really lag during the stroke.
void StrokesTest::deferredPositionsGiveTheSameStrokes() {
  const int n = 64;
  GpuDocument atOnce(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  GpuDocument deferred(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  atOnce.setPositionsDeferred(false);
  deferred.setPositionsDeferred(true);
  std::vector<PathStroke> strokes;
  strokes.push_back(strokeOf("push", {{0.2f, 0.5f}, {0.8f, 0.4f}}, 0.2f, 0.5f));
  strokes.push_back(strokeOf("smooth", {{0.1f, 0.1f}, {0.0f, 0.6f}, {0.5f, 1.0f}}, 0.25f, 0.8f));
  strokes.push_back(strokeOf("inflate", {{0.3f, 0.3f}, {0.6f, 0.7f}}, 0.2f, 0.4f));
  strokes.back().symmetry = kSymmetryX | kSymmetryZ;
  strokes.push_back(strokeOf("paint", {{0.4f, 0.6f}, {0.9f, 0.9f}}, 0.2f, 1.0f));
  strokes.back().parameters["color"] = {0.9f, 0.2f, 0.1f, 1.0f};
  strokes.push_back(strokeOf("snake-hook", {{0.5f, 0.5f}}, 0.2f, 1.0f));
  strokes.push_back(strokeOf("grab", {{0.98f, 0.5f}}, 0.2f, 1.0f));
  const core::TileBounds& bounds = atOnce.bounds();
  const float d = bounds.diagonal();
  const core::Vec3f c = (bounds.box(0).min + bounds.box(0).max) * 0.5f;
  strokes[4].dragPoints = {c + core::Vec3f{0.1f * d, 0, 0}, c + core::Vec3f{0.3f * d, 0.1f * d, 0}};
  strokes[5].dragPoints = {c + core::Vec3f{0, 0.2f * d, 0}};
  for (PathStroke& stroke : strokes) {
    try {
      strokeAlongPath(*engine_, atOnce, manifest(stroke.brush), stroke);
      strokeAlongPath(*engine_, deferred, manifest(stroke.brush), stroke);
    } catch (const std::exception& e) {
      QFAIL((stroke.brush + ": " + e.what()).c_str());
    }
    QVERIFY2(sameBits(snapshot(deferred), snapshot(atOnce)), stroke.brush.c_str());
  }
  QVERIFY(!sameBits(snapshot(atOnce), snapshot(GpuDocument(core::makeDocument(
                                          core::makeBaseShape(core::BaseShape::Blob, n))))));
  // During a stroke the deferred document's positions wait for a reader; the bounds do not, and
  // the record so far (keep detail's between dabs) reads what it needs synced.
  StrokeSession session(*engine_, deferred, manifest("push"), strokeOf("push", {}, 0.2f, 0.5f));
  StrokeSession twin(*engine_, atOnce, manifest("push"), strokeOf("push", {}, 0.2f, 0.5f));
  for (StrokeSession* s : {&session, &twin}) {
    s->moveToUv({0.5f, 0.5f}, 0.2f * d, 0.5f);
    s->moveToUv({0.6f, 0.55f}, 0.2f * d, 0.5f);
  }
  QVERIFY(deferred.mirrorStale());
  const core::EditStep soFar = session.recordSoFar("push"), twinSoFar = twin.recordSoFar("push");
  QVERIFY(soFar.changedTexels > 100);
  QCOMPARE(soFar.changedTexels, twinSoFar.changedTexels);
  for (std::size_t k = 0; k < soFar.tiles.size(); ++k)
    QVERIFY(soFar.tiles[k].xorBits == twinSoFar.tiles[k].xorBits);
  twin.finish("push");
  session.moveToUv({0.7f, 0.5f}, 0.2f * d, 0.5f);
  QVERIFY(deferred.mirrorStale());
  const core::TileBounds fresh(deferred.document().positions); // synced by document()
  QVERIFY(!deferred.mirrorStale());
  int differing = 0;
  for (int t = 0; t < fresh.tilesPerSide() * fresh.tilesPerSide(); ++t)
    differing += !(fresh.box(t).min == deferred.bounds().box(t).min &&
                   fresh.box(t).max == deferred.bounds().box(t).max);
  QCOMPARE(differing, 0);
  session.finish("push");
}

// The stroke's finite check is a reduction on the GPU: it must flag a NaN or an infinity in any
// checked channel, a position beyond ±1e15 but not its saliency (w), and nothing elsewhere.
void StrokesTest::finiteCheckOnTheGpuFindsEachBadValue() {
  const int n = 64;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, n)));
  const core::TexelRect whole{0, 0, n + 1, n + 1}, at{40, 20, 1, 1}, away{0, 0, 30, 65};
  const std::vector<core::TexelRect> rects{{10, 10, 20, 5}, {33, 17, 12, 9}};
  QVERIFY(document.holdsOnlyFinite(core::EditLayer::Positions, std::span(&whole, 1)));
  QVERIFY(document.holdsOnlyFinite(core::EditLayer::Diffuse, std::span(&whole, 1)));
  const std::vector<float> good = document.mirrorTexels(core::EditLayer::Positions, at);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (int c = 0; c < 4; ++c)
    for (float bad : {nan, -inf, 2e15f}) {
      std::vector<float> texel = good;
      texel[c] = bad;
      document.restore(core::EditLayer::Positions, at, texel);
      const bool flagged = !(c == 3 && bad == 2e15f); // the saliency need only be finite
      QCOMPARE(document.holdsOnlyFinite(core::EditLayer::Positions, rects), !flagged);
      QVERIFY(document.holdsOnlyFinite(core::EditLayer::Positions, std::span(&away, 1)));
    }
  document.restore(core::EditLayer::Positions, at, good);
  QVERIFY(document.holdsOnlyFinite(core::EditLayer::Positions, rects));
  document.restore(core::EditLayer::Diffuse, at, std::vector<float>{0.5f, inf, 0.5f, 1.0f});
  QVERIFY(!document.holdsOnlyFinite(core::EditLayer::Diffuse, rects));
  document.restore(core::EditLayer::Mask, at, std::vector<float>{nan});
  QVERIFY(!document.holdsOnlyFinite(core::EditLayer::Mask, rects));
  QVERIFY(document.holdsOnlyFinite(core::EditLayer::Mask, std::span(&away, 1)));
}

void StrokesTest::sessionRefusesSamplesOutsideTheImage() {
  const int n = 32;
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
  const auto start = snapshot(document);
  StrokeSession session(*engine_, document, manifest("inflate"),
                        strokeOf("inflate", {}, 0.2f, 0.3f));
  for (core::Sample s :
       {core::Sample{-1, 0}, core::Sample{0, n + 1}, core::Sample{n + 1, 3}, core::Sample{4, -7}}) {
    try {
      session.moveTo(s, 0.2f, 0.3f);
      QFAIL(qPrintable(QString("(%1,%2) was accepted").arg(s.i).arg(s.j)));
    } catch (const core::Error& e) {
      QCOMPARE(e.kind(), core::ErrorKind::InvalidArgument);
    }
  }
  QCOMPARE(session.dabs(), 0);
  QVERIFY(sameBits(snapshot(document), start));
  QCOMPARE(session.moveTo({n, n}, 0.2f, 0.3f), 1); // the corner sample is inside

  BrushManifest unknown = manifest("inflate");
  unknown.id = "not-loaded";
  bool refused = false;
  try {
    StrokeSession never(*engine_, document, unknown, PathStroke{});
  } catch (const core::Error& e) {
    refused = e.kind() == core::ErrorKind::UnknownId;
  }
  QVERIFY(refused);
}

QTEST_APPLESS_MAIN(StrokesTest)
#include "strokes_gltest.moc"
