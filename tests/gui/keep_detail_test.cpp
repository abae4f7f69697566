// Keep detail through the sculpting session the modeller uses (app/session): clicks that pull a
// limb out of a sphere get their stretch relaxed, each click and its relaxation are one undo
// step, and undo / redo give back every layer bit for bit.
#include "../creature_layout.h"
#include "../gpu/brush_test_support.h"
#include "../keep_detail_clicks.h"
#include "sculpt_session.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/core/relax/relax.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  void aHookRelaxedAsItGoesIsOneUndoStep();
  void aCreaseOnOneLegLeavesTheRestAlone_data();
  void aCreaseOnOneLegLeavesTheRestAlone();

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
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 128)));
  app::StrokeStart start;
  start.brushId = start.settings.brushId = "push";
  start.settings.radius = 0.06f;
  start.settings.strength = 1.0f;
  start.settings.pressureTarget = app::PressureTarget::None;
  start.settings.keepDetail = keepDetail;
  start.eye = core::Vec3f{0, 0, 10};
  *relaxedClicks = 0;
  for (int i = 0; i < clicks; ++i) {
    const Snapshot before = snapshot(session.gpuDocument());
    session.beginStroke(start);
    session.queueMove(app::StrokeMove::toUv({0.5f, 0.5f}));
    const app::DabRun run = session.runQueuedMoves();
    if (!run.error.empty()) qFatal("dab failed: %s", run.error.c_str());
    session.finishStroke();
    if (session.lastRelaxation().tiles.empty()) continue;
    ++*relaxedClicks;
    if (const char* failed = testing::oneBitExactStep(session, before)) qFatal("%s", failed);
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
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 256)));
  double worstRms = 0, worstHausdorff = 0;
  int relaxed = 0;
  for (int i = 0; i < 15; ++i) {
    app::playStroke(session, testing::pushClick(0.5f, 0.5f));
    if (session.lastRelaxation().tiles.empty()) continue;
    ++relaxed;
    const core::SurfaceDistance d = testing::lastRelaxationMove(session).moved;
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
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, 256);
  session.setDocument(core::makeDocument(ball));
  app::StrokeScript stroke =
      testing::creatureStroke(testing::creatureParts(layout)[0], ball, hook.id, session.diagonal());
  stroke.start.settings.keepDetail = keepDetail;
  app::playStroke(session, stroke);
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
// without keep-detail. Issue 30 bounds each relaxation by the tolerance (0.1 % of the diagonal,
// Hausdorff). One relaxation after the stroke had to move the samples along the whole leg, over
// its coarse facets: 1/8 of that move fitted (0.097). Relaxing as the stroke goes (after its 4th
// dab, then each time its dab count doubles), holding the leg's tip where the full move cuts it,
// the leg takes its samples in steps that fit: 0.32 on either half. It never loses samples and
// its longest edge gets no longer. Its relaxation once took samples off it (-z: 0.080, longest
// edge 30x the median; +z: 0.073, 40x): the coarse levels moved the samples around the pinned
// start sample, which lies between theirs, refining tore the cells at the pin and the fold repair
// put half the offsets back to zero. On the -z half the relaxed rectangle also stopped at the
// image's border.
void KeepDetailTest::aSnakeHookLegGainsOnEitherHalf() {
  QFETCH(testing::CreatureLayout, layout);
  const auto [offShare, offLongest] = hookLeg(false, layout);
  const auto [onShare, onLongest] = hookLeg(true, layout);
  qInfo("snake-hook leg: fair share %.3f -> %.3f, longest edge %.1fx -> %.1fx the median", offShare,
        onShare, offLongest, onLongest);
  QVERIFY(offShare < 0.1);
  QVERIFY(onShare >= 0.25);
  QVERIFY(onLongest < offLongest);
}

// Issue 23's target: the animal of bench_creature (four legs from the ball's lower half, two of
// them from its -z half, and a neck, each one snake-hook stroke at N = 256): with keep-detail no
// part holds less than 0.3 of its fair share of samples (each 0.09-0.14 without). Issue 30's
// tolerance (each relaxation moves the surface by at most 0.1 % of the diagonal) bounds each
// step; relaxing as the stroke goes, every part holds at least 0.15 (measured: the legs
// 0.19-0.43, the neck 1.57; one relaxation after each stroke gave the legs 0.09-0.10).
void KeepDetailTest::theAnimalKeepsItsShareInEveryPart() {
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, 256);
  session.setDocument(core::makeDocument(ball));
  const std::vector<testing::CreaturePart> parts =
      testing::creatureParts(testing::CreatureLayout::Animal);
  for (const testing::CreaturePart& part : parts)
    app::playStroke(session, testing::creatureStroke(part, ball, hook.id, session.diagonal()));
  const std::vector<core::RegionSampling> sampling =
      testing::creatureSampling(session.document().positions, parts);
  // Without keep-detail: bench_creature's figures (0.088 each leg, 0.143 the neck).
  for (std::size_t k = 0; k < parts.size(); ++k) {
    qInfo("%s: fair share %.3f", parts[k].name, sampling[k].fairShare);
    QVERIFY2(sampling[k].fairShare >= 0.15, parts[k].name);
  }
}

// A snake hook pulled through the modeller's path (the start queued, then the pointer's rays,
// over several frames) on a painted ball: keep-detail relaxes as the stroke goes, and the
// relaxations (positions and the paint they resample) are part of the stroke: one undo step that
// gives back the ball bit for bit, and redo the result.
void KeepDetailTest::aHookRelaxedAsItGoesIsOneUndoStep() {
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  const int n = 128;
  core::Document ball = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
  ball.diffuse.texels.resize(std::size_t(n + 1) * std::size_t(n + 1) * 4);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      float* c = &ball.diffuse.texels[(std::size_t(j) * std::size_t(n + 1) + std::size_t(i)) * 4];
      c[0] = float(i) / float(n), c[1] = float(j) / float(n), c[2] = 0.5f, c[3] = 1.0f;
    }
  session.setDocument(ball);
  const Snapshot before = snapshot(session.gpuDocument());
  app::StrokeStart start;
  start.brushId = start.settings.brushId = hook.id;
  start.settings.radius = 0.06f;
  start.settings.strength = 1.0f;
  start.settings.pressureTarget = app::PressureTarget::None;
  start.settings.keepDetail = true;
  const core::Vec3f eye{0, 0, 10}, end{0.6f, 0.2f, 1.0f}; // on the view plane z = 1
  start.eye = eye;
  session.beginStroke(start);
  session.queueMove(app::StrokeMove::toUv({0.5f, 0.5f})); // the +z pole
  int made = 0;
  for (int frame = 1; frame <= 8; ++frame) {
    const core::Vec3f at =
        core::Vec3f{0, 0, 1} + (end - core::Vec3f{0, 0, 1}) * (float(frame) / 8.0f);
    session.queueMove(app::StrokeMove::alongRay(eye, core::normalize(at - eye)));
    const app::DabRun run = session.runQueuedMoves();
    QVERIFY2(run.error.empty(), run.error.c_str());
    made += run.made;
  }
  QCOMPARE(session.finishStroke().label, hook.id);
  const core::EditStep& relaxed = session.lastRelaxation();
  bool paint = false;
  for (const core::TileChange& t : relaxed.tiles)
    paint = paint || t.layer == core::EditLayer::Diffuse;
  qInfo("%d dabs; the relaxations changed %zu texels in %zu tiles (paint among them: %s)", made,
        relaxed.changedTexels, relaxed.tiles.size(), paint ? "yes" : "no");
  QVERIFY(made >= 8);
  QVERIFY2(!relaxed.tiles.empty(), "nothing relaxed: nothing tested");
  QVERIFY(paint);
  const Snapshot after = snapshot(session.gpuDocument());
  QCOMPARE(session.history().undoCount(), std::size_t(1));
  QVERIFY(session.undo());
  QVERIFY(sameBits(snapshot(session.gpuDocument()), before));
  QVERIFY(session.redo());
  QVERIFY(sameBits(snapshot(session.gpuDocument()), after));
}

namespace {

// The samples within `margin` (Chebyshev, on the tiled plane: across the seams) of a marked one,
// every copy of a border sample with it: the region core::relaxChangedStep may move.
std::vector<std::uint8_t> grown(int n, const std::vector<std::uint8_t>& marked, int margin) {
  const auto index = [n](core::Sample s) {
    return static_cast<std::size_t>(s.j) * static_cast<std::size_t>(n + 1) +
           static_cast<std::size_t>(s.i);
  };
  std::vector<std::uint8_t> in(marked.size(), 0);
  std::vector<core::Sample> front;
  const auto reach = [&](core::Sample s, std::vector<core::Sample>& next) {
    std::array<core::Sample, 4> copies;
    const int k = core::identifiedSamples(n, core::wrap(n, s), copies);
    for (int c = 0; c < k; ++c)
      if (const core::Sample q = copies[std::size_t(c)]; !in[index(q)]) {
        in[index(q)] = 1;
        next.push_back(q);
      }
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (marked[index({i, j})]) reach({i, j}, front);
  for (int d = 0; d < margin; ++d) {
    std::vector<core::Sample> next;
    for (const core::Sample s : front)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          reach({s.i + di, s.j + dj}, next);
    front = std::move(next);
  }
  return in;
}

// The largest angle (degrees) between a sample's normal and its four grid neighbours' (through
// the wrap), over the marked samples.
std::vector<double> neighbourAngles(const core::GeometryImage& image,
                                    const std::vector<std::uint8_t>& marked) {
  const int n = image.size();
  const std::vector<core::Vec3f> normals = core::computeNormals(image);
  std::vector<double> out;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(n + 1) + std::size_t(i);
      if (!marked[k]) continue;
      double worst = 0;
      for (const core::Sample d : {core::Sample{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const core::Sample q = core::wrap(n, {i + d.i, j + d.j});
        const double c = std::clamp(
            double(core::dot(normals[k],
                             normals[std::size_t(q.j) * std::size_t(n + 1) + std::size_t(q.i)])),
            -1.0, 1.0);
        worst = std::max(worst, std::acos(c) * 180 / M_PI);
      }
      out.push_back(worst);
    }
  return out;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  const auto at = v.begin() + std::ptrdiff_t(p * double(v.size() - 1));
  std::nth_element(v.begin(), at, v.end());
  return *at;
}

} // namespace

void KeepDetailTest::aCreaseOnOneLegLeavesTheRestAlone_data() {
  QTest::addColumn<int>("leg");
  // creatureParts' order: back right, front right, back left, front left, neck.
  QTest::newRow("front left leg (+z half, off the image's centre)") << 3;
  QTest::newRow("back right leg (-z half: the image's corner triangles, across seams)") << 0;
}

// Issue 30: the animal of bench_creature at N = 256 (keep-detail on), then a crease stroke down
// one leg with keep-detail on. The relaxation after it moves samples only within
// core::keepDetailMargin of the texels the crease changed: every other sample of the image
// keeps its bits (so the other legs do, and the body beyond the margin), their normals too, and
// the relaxed surface stays within the issue's tolerance of what the crease left. The shading
// stays smooth where samples moved: the normal map refreshed where the viewport refreshes it is
// the one a full refresh computes, and no neighbouring normals there turn sharper than the
// crease left them (by more than a stated margin).
void KeepDetailTest::aCreaseOnOneLegLeavesTheRestAlone() {
  QFETCH(int, leg);
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  const gpu::BrushManifest& crease = *catalog_.find("crease");
  const int n = 256;
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, n);
  session.setDocument(core::makeDocument(ball));
  const std::vector<testing::CreaturePart> parts =
      testing::creatureParts(testing::CreatureLayout::Animal);
  for (const testing::CreaturePart& part : parts)
    app::playStroke(session, testing::creatureStroke(part, ball, hook.id, session.diagonal()));
  const core::Document made = session.document();

  // Down the leg's outer side, from near its tip to near the ball: the leg's samples nearest to
  // points beside its axis.
  const testing::CreaturePart& part = parts[std::size_t(leg)];
  const core::Vec3f tip = part.drag[1], side{part.start.x, 0, 0};
  app::StrokeScript s;
  s.start.brushId = s.start.settings.brushId = crease.id;
  for (const float t : {0.85f, 0.7f, 0.55f, 0.4f, 0.25f}) {
    const core::Vec3f beside = part.start + (tip - part.start) * t + side * 0.5f;
    float best = 1e30f;
    std::array<float, 2> uv{};
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const core::Vec3f p = made.positions.at(i, j).xyz();
        if (testing::creaturePartOf(parts, p) != leg) continue;
        if (const float d = core::length(p - beside); d < best)
          best = d, uv = {float(i) / float(n), float(j) / float(n)};
      }
    s.path.push_back(uv);
  }
  const float radius = 0.06f; // object units
  s.start.settings.radius = radius / session.diagonal();
  // A ridge (the crease's negative strength, Ctrl with the brush). A valley at 0.2-1.0 cuts
  // across the leg's coarse facets by 0.11-0.37 % of the diagonal (Hausdorff) even at 1/8 of the
  // move, so keep-detail leaves it unrelaxed and there would be nothing to check here.
  s.start.settings.strength = -0.5f;

  // The crease alone (keep-detail off), from the same document: what the stroke changed.
  app::SculptSession plain;
  plain.setBrushes(*engine_, catalog_);
  plain.loadBrush(crease);
  plain.setDocument(made);
  s.start.settings.keepDetail = false;
  app::playStroke(plain, s);
  s.start.settings.keepDetail = true;
  const core::Document creased = plain.document();

  session.loadBrush(crease);
  app::playStroke(session, s);
  QVERIFY2(!session.lastRelaxation().tiles.empty(), "the crease was not relaxed: nothing tested");
  const core::Document relaxed = session.document();

  const std::size_t count = made.positions.texels().size();
  std::vector<std::uint8_t> changed(count, 0);
  for (std::size_t k = 0; k < count; ++k)
    changed[k] = !(creased.positions.texels()[k] == made.positions.texels()[k]);
  const int margin = core::keepDetailMargin(creased.positions, radius);
  const std::vector<std::uint8_t> region = grown(n, changed, margin);
  const std::vector<std::uint8_t> normalRegion = grown(n, changed, margin + 1);
  const float diagonal = core::boundingBox(core::extractMesh(made.positions)).diagonal();
  const std::vector<core::Vec3f> normalsMade = core::computeNormals(made.positions);
  const std::vector<core::Vec3f> normalsRelaxed = core::computeNormals(relaxed.positions);
  std::size_t changedCount = 0, regionCount = 0, relaxedCount = 0, outside = 0, otherLegs = 0,
              bodyInRegion = 0, normalsOutside = 0, coloursOutside = 0;
  double farthest = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const core::Vec3f was = made.positions.texels()[k].xyz();
    const bool same = relaxed.positions.texels()[k] == made.positions.texels()[k];
    changedCount += changed[k];
    regionCount += region[k];
    relaxedCount += !(relaxed.positions.texels()[k] == creased.positions.texels()[k]);
    const int owner = testing::creaturePartOf(parts, was);
    if (!same && owner >= 0 && owner < 4 && owner != leg) ++otherLegs;
    if (!same && owner == -1 && region[k]) ++bodyInRegion;
    if (!region[k]) {
      outside += !same;
      farthest =
          std::max(farthest, double(core::length(relaxed.positions.texels()[k].xyz() - was)));
      if (!made.diffuse.uniform() || !relaxed.diffuse.uniform())
        for (std::size_t c = 0; c < 4; ++c)
          coloursOutside += made.diffuse.texels[4 * k + c] != relaxed.diffuse.texels[4 * k + c];
    }
    if (!normalRegion[k] && !(normalsMade[k] == normalsRelaxed[k])) ++normalsOutside;
  }
  const core::SurfaceDistance d =
      core::compareSurfaces(core::extractMesh(creased.positions),
                            core::extractMesh(relaxed.positions), {.samplesPerSurface = 200'000});
  qInfo("%s: the crease changed %zu samples; margin %d samples, region %zu; the relaxation moved "
        "%zu; changed outside the region: %zu (farthest %.2g of the diagonal), normals %zu, "
        "colours %zu; other legs' samples changed: %zu; body samples inside the region changed: "
        "%zu; relaxation RMS %.4f %%, Hausdorff %.3f %% of the diagonal",
        parts[std::size_t(leg)].name, changedCount, margin, regionCount, relaxedCount, outside,
        farthest / diagonal, normalsOutside, coloursOutside, otherLegs, bodyInRegion, 100 * d.rms,
        100 * d.hausdorff);
  QVERIFY(changedCount > 0);
  QVERIFY(relaxedCount > 0);
  QCOMPARE(outside, std::size_t(0));
  QVERIFY(farthest <= 1e-6 * diagonal);
  QCOMPARE(normalsOutside, std::size_t(0));
  QCOMPARE(coloursOutside, std::size_t(0));
  QCOMPARE(otherLegs, std::size_t(0));
  QVERIFY(d.rms <= 1e-4);
  QVERIFY(d.hausdorff <= 1e-3);

  // Smooth shading where samples moved: the angles between neighbouring normals over the relaxed
  // samples (and one ring around them) are no larger than the crease left them there: the 99th
  // percentile within kSharperP99 degrees, the largest (on the ridge's line, about 100 degrees)
  // within kSharperMax (measured: p99 49 -> 48, largest 100 -> 106).
  constexpr double kSharperP99 = 2.0, kSharperMax = 10.0;
  std::vector<std::uint8_t> moved(count, 0);
  for (std::size_t k = 0; k < count; ++k)
    moved[k] = !(relaxed.positions.texels()[k] == creased.positions.texels()[k]);
  const std::vector<std::uint8_t> around = grown(n, moved, 1);
  const std::vector<double> before = neighbourAngles(creased.positions, around);
  const std::vector<double> after = neighbourAngles(relaxed.positions, around);
  const double worstBefore = *std::max_element(before.begin(), before.end());
  const double worstAfter = *std::max_element(after.begin(), after.end());
  qInfo("  neighbouring normals over the %zu relaxed samples and their ring: p99 %.1f -> %.1f, "
        "largest %.1f -> %.1f degrees",
        before.size(), percentile(before, 0.99), percentile(after, 0.99), worstBefore, worstAfter);
  QVERIFY(worstAfter <= worstBefore + kSharperMax);
  QVERIFY(percentile(after, 0.99) <= percentile(before, 0.99) + kSharperP99);

  // The normal map the viewport keeps: refreshed over what the dabs touched and what the
  // relaxation changed (ViewportWidget::finishStroke), it is the map a full refresh computes.
  gpu::ModelRenderer renderer;
  renderer.refreshAllNormals(plain.gpuDocument()); // the map as the crease's dabs left it
  renderer.refreshNormals(
      session.gpuDocument(),
      app::normalRectsAround(app::changedRects(session.lastRelaxation()), n + 1));
  const std::vector<float> incremental = renderer.normalMap().read({0, 0, n + 1, n + 1});
  renderer.refreshAllNormals(session.gpuDocument());
  const std::vector<float> fresh = renderer.normalMap().read({0, 0, n + 1, n + 1});
  std::size_t stale = 0;
  for (std::size_t k = 0; k < fresh.size(); ++k)
    stale += incremental[k] != fresh[k];
  qInfo("  normal map texels that differ from a full refresh: %zu", stale / 4);
  QCOMPARE(stale, std::size_t(0));
}

QTEST_GUILESS_MAIN(KeepDetailTest)
#include "keep_detail_test.moc"
