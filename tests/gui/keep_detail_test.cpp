// Keep detail through the sculpting session the modeller uses (app/session): clicks that pull a
// limb out of a sphere get their stretch relaxed, each click and its relaxation are one undo
// step, and undo / redo give back every layer bit for bit.
#include "../creature_layout.h"
#include "../gpu/brush_test_support.h"
#include "sculpt_session.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <QTest>

#include <optional>
#include <utility>
#include <vector>

using namespace octaclay;

using Snapshot = std::vector<std::vector<float>>;
using gpu::testing::sameBits;
using gpu::testing::snapshot;

class KeepDetailTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void clicksKeepTheirDetailAndUndoBitExactly();
  void offLeavesTheSamplesWhereTheBrushPutThem();
  void theIssuesLimbStaysWithinTolerance();
  void aSnakeHookLegGainsOnEitherHalf_data();
  void aSnakeHookLegGainsOnEitherHalf();
  void theAnimalKeepsItsShareInEveryPart();

private:
  // Pulls at the pole (the image centre) with `clicks` one-dab strokes; returns the limb's
  // longest edge ÷ median edge, and checks every relaxed click's undo and redo.
  double pull(bool keepDetail, int clicks, int* relaxedClicks);
  // The first leg of bench_creature's layout, alone: its (the surface beyond 1.15) fair share of
  // samples and the longest edge ÷ median.
  std::pair<double, double> hookLeg(bool keepDetail, testing::CreatureLayout layout);

  std::optional<gpu::GlContext> context_;
  gpu::BrushCatalog catalog_;
  std::optional<gpu::BrushEngine> engine_;
};

void KeepDetailTest::initTestCase() {
  context_.emplace(gpu::GlContext::createHeadless());
  engine_.emplace();
  catalog_.scan(gpu::BrushCatalog::defaultSearchPath(OCTACLAY_SOURCE_BRUSHES));
  QVERIFY(catalog_.find("push") != nullptr);
}

double KeepDetailTest::pull(bool keepDetail, int clicks, int* relaxedClicks) {
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(*catalog_.find("push"));
  session.setKeepDetail(keepDetail);
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
  app::BrushSettings settings;
  settings.brushId = "push";
  settings.radius = 0.06f;
  settings.strength = 1.0f;
  settings.pressureTarget = app::PressureTarget::None;
  *relaxedClicks = 0;
  for (int i = 0; i < clicks; ++i) {
    const Snapshot before = snapshot(session.gpuDocument());
    session.beginStroke("push", settings, core::EditLayer::Diffuse, 1.0f, {0, 0, 10});
    session.queueDab({0.5f, 0.5f}, 1.0f);
    const app::DabRun run = session.runQueuedDabs(settings);
    if (!run.error.empty()) qFatal("dab failed: %s", run.error.c_str());
    session.finishStroke();
    if (session.lastRelaxation().tiles.empty()) continue;
    ++*relaxedClicks;
    const Snapshot after = snapshot(session.gpuDocument());
    const std::size_t steps = session.history().undoCount();
    if (!session.undo()) qFatal("nothing to undo");
    if (!sameBits(snapshot(session.gpuDocument()), before)) qFatal("undo was not bit-exact");
    if (!session.redo()) qFatal("nothing to redo");
    if (!sameBits(snapshot(session.gpuDocument()), after)) qFatal("redo was not bit-exact");
    if (session.history().undoCount() != steps) qFatal("the click was more than one step");
  }
  return core::summarizeStretch(session.document().positions).longestOverMedian;
}

void KeepDetailTest::clicksKeepTheirDetailAndUndoBitExactly() {
  int relaxedOn = 0, relaxedOff = 0;
  const double on = pull(true, 40, &relaxedOn);
  const double off = pull(false, 40, &relaxedOff);
  qInfo("40 clicks: longest edge %.1fx the median with keep-detail, %.1fx without; %d clicks "
        "relaxed",
        on, off, relaxedOn);
  QVERIFY(relaxedOn > 0);
  QCOMPARE(relaxedOff, 0);
  QVERIFY(on < off / 2);
}

void KeepDetailTest::offLeavesTheSamplesWhereTheBrushPutThem() {
  int relaxed = 0;
  pull(false, 3, &relaxed);
  QCOMPARE(relaxed, 0);
}

// Issue 21's scenario: 15 one-dab strokes at N = 256 (radius 0.06 of the diagonal, strength 1,
// as `octaclay-cli stroke --path "0.5,0.5;0.5,0.5"` makes them). Every relaxation stays within
// the issue's surface tolerance of what its stroke left, and the limb keeps its detail.
void KeepDetailTest::theIssuesLimbStaysWithinTolerance() {
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(*catalog_.find("push"));
  session.setKeepDetail(true);
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 256)));
  double worstRms = 0, worstHausdorff = 0;
  int relaxed = 0;
  for (int i = 0; i < 15; ++i) {
    gpu::StrokeSettings s;
    s.brush = "push";
    s.path = {{0.5f, 0.5f}, {0.5f, 0.5f}};
    s.radius = 0.06f * session.gpuDocument().bounds().diagonal();
    s.strength = 1.0f;
    s.spacing = 1.0f;
    session.strokeAlongPath(*catalog_.find("push"), s);
    if (session.lastRelaxation().tiles.empty()) continue;
    ++relaxed;
    core::Document stroked = session.document();
    const core::TileApplier apply = core::applierFor(stroked);
    for (const core::TileChange& t : session.lastRelaxation().tiles)
      t.apply(core::TileState::Before, apply);
    const core::SurfaceDistance d = core::compareSurfaces(
        core::extractMesh(stroked.positions), core::extractMesh(session.document().positions),
        {.samplesPerSurface = 200'000});
    worstRms = std::max(worstRms, d.rms);
    worstHausdorff = std::max(worstHausdorff, d.hausdorff);
  }
  const core::RegionSampling limb = core::regionSampling(
      session.document().positions, [](const core::Vec3f& p) { return core::length(p) > 1.5f; });
  const double longest = core::summarizeStretch(session.document().positions).longestOverMedian;
  qInfo("%d of 15 strokes relaxed; worst relaxation RMS %.4f %%, Hausdorff %.3f %% of the "
        "diagonal; limb fair share %.2f, spacing %.2fx the body's, longest edge %.1fx",
        relaxed, 100 * worstRms, 100 * worstHausdorff, limb.fairShare, limb.spacingRatio, longest);
  QVERIFY(relaxed > 0);
  QVERIFY(worstRms <= 1e-4);
  QVERIFY(worstHausdorff <= 1e-3);
  QVERIFY(limb.fairShare >= 0.3);
  QVERIFY(limb.spacingRatio <= 2.0);
  QVERIFY(longest <= 16.0);
}

std::pair<double, double> KeepDetailTest::hookLeg(bool keepDetail, testing::CreatureLayout layout) {
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  session.setKeepDetail(keepDetail);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, 256);
  session.setDocument(core::makeDocument(ball));
  session.strokeAlongPath(
      hook, testing::creatureStroke(testing::creatureParts(layout)[0], ball, hook.id));
  const core::RegionSampling leg = core::regionSampling(
      session.document().positions, [](const core::Vec3f& p) { return core::length(p) > 1.15f; });
  return {leg.fairShare, core::summarizeStretch(session.document().positions).longestOverMedian};
}

void KeepDetailTest::aSnakeHookLegGainsOnEitherHalf_data() {
  QTest::addColumn<testing::CreatureLayout>("layout");
  QTest::newRow("-z half (the image's corner triangles)") << testing::CreatureLayout::LegsMinusZ;
  QTest::newRow("+z half (the image's middle)") << testing::CreatureLayout::LegsPlusZ;
}

// bench_creature's back right leg alone, one snake-hook stroke at N = 256: 0.08 of its fair share
// without keep-detail. Its relaxation once took samples off it (-z: 0.080, longest edge 30x the
// median; +z: 0.073, 40x): the coarse levels moved the samples around the pinned start sample,
// which lies between theirs, refining tore the cells at the pin and the fold repair put half the
// offsets back to zero. On the -z half the relaxed rectangle also stopped at the image's border.
void KeepDetailTest::aSnakeHookLegGainsOnEitherHalf() {
  QFETCH(testing::CreatureLayout, layout);
  const auto [offShare, offLongest] = hookLeg(false, layout);
  const auto [onShare, onLongest] = hookLeg(true, layout);
  qInfo("snake-hook leg: fair share %.3f -> %.3f, longest edge %.1fx -> %.1fx the median", offShare,
        onShare, offLongest, onLongest);
  QVERIFY(offShare < 0.1);
  QVERIFY(onShare >= 0.5);
  QVERIFY(onLongest < offLongest / 2);
}

// Issue 23's target: the animal of bench_creature (four legs from the ball's lower half, two of
// them from its -z half, and a neck, each one snake-hook stroke at N = 256): with keep-detail no
// part holds less than 0.3 of its fair share of samples (each 0.09-0.14 without).
void KeepDetailTest::theAnimalKeepsItsShareInEveryPart() {
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  session.setKeepDetail(true);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, 256);
  session.setDocument(core::makeDocument(ball));
  const std::vector<testing::CreaturePart> parts =
      testing::creatureParts(testing::CreatureLayout::Animal);
  for (const testing::CreaturePart& part : parts)
    session.strokeAlongPath(hook, testing::creatureStroke(part, ball, hook.id));
  const std::vector<core::RegionSampling> sampling =
      testing::creatureSampling(session.document().positions, parts);
  for (std::size_t k = 0; k < parts.size(); ++k) {
    qInfo("%s: fair share %.3f", parts[k].name, sampling[k].fairShare);
    QVERIFY2(sampling[k].fairShare >= 0.3, parts[k].name);
  }
}

QTEST_GUILESS_MAIN(KeepDetailTest)
#include "keep_detail_test.moc"
