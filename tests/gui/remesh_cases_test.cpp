// core::remeshDocument on issue 30's creature, made as a user makes it (four legs and a neck
// pulled out of a ball with the snake hook, keep-detail on, through the sculpting session) at
// N = 1024: every part keeps at least 0.7 of its fair share of samples, the surface stays within
// Remesh's tolerances, and the result is one closed genus-0 surface with exact seams.
#include "../creature_layout.h"
#include "sculpt_session.h"
#include "stroke_script.h"

#include "octaclay/core/document/document_info.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/import/remesh.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"

#include <QElapsedTimer>
#include <QTest>

#include <optional>
#include <vector>

using namespace octaclay;

class RemeshCasesTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void theCreatureKeepsEveryPartsShare();

private:
  std::optional<gpu::GlContext> context_;
  gpu::BrushCatalog catalog_;
  std::optional<gpu::BrushEngine> engine_;
};

void RemeshCasesTest::initTestCase() {
  context_.emplace(gpu::GlContext::createHeadless());
  engine_.emplace();
  catalog_.scan(gpu::BrushCatalog::defaultSearchPath(OCTACLAY_SOURCE_BRUSHES));
  QVERIFY(catalog_.find("snake-hook") != nullptr);
}

void RemeshCasesTest::theCreatureKeepsEveryPartsShare() {
  const gpu::BrushManifest& hook = *catalog_.find("snake-hook");
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(hook);
  const core::GeometryImage ball = core::makeBaseShape(core::BaseShape::Sphere, 1024);
  session.setDocument(core::makeDocument(ball));
  const std::vector<testing::CreaturePart> parts =
      testing::creatureParts(testing::CreatureLayout::Animal);
  for (const testing::CreaturePart& part : parts)
    app::playStroke(session, testing::creatureStroke(part, ball, hook.id, session.diagonal()));
  const core::Document creature = session.document();
  const std::vector<core::RegionSampling> before =
      testing::creatureSampling(creature.positions, parts);

  QElapsedTimer timer;
  timer.start();
  const core::RemeshResult r = core::remeshDocument(creature);
  const double ms = double(timer.nsecsElapsed()) / 1e6;
  QVERIFY2(r.changed, r.reason.c_str());
  const std::vector<core::RegionSampling> after =
      testing::creatureSampling(r.document.positions, parts);
  qInfo("creature N 1024: longest/median %.1f -> %.1f, moved RMS %.5f %%, Hausdorff %.4f %%, "
        "%d samples snapped, %.0f ms (parameterize %.0f, resample %.0f, measure %.0f)",
        r.before.longestOverMedian, r.after.longestOverMedian, 100 * r.moved.rms,
        100 * r.moved.hausdorff, r.snapped, ms, r.parameterizeMs, r.resampleMs, r.measureMs);
  // Measured: 0.89 to 1.14 of the fair share (the target: 0.7), RMS 0.0005 %, Hausdorff
  // 0.08 %, 17 s with the 2 cores shared at a load of 6 (about 8 s of CPU; the target:
  // 10 s). No timed assert: tests/bench/bench_remesh gives the figure.
  for (std::size_t k = 0; k < parts.size(); ++k) {
    qInfo("%s: fair share %.3f -> %.3f", parts[k].name, before[k].fairShare, after[k].fairShare);
    QVERIFY2(after[k].fairShare >= 0.7, parts[k].name);
  }
  QVERIFY(r.moved.rms <= 1e-4);
  QVERIFY(r.moved.hausdorff <= 2e-3);
  QCOMPARE(r.flipped, 0);
  const core::DocumentInfo info = core::describeDocument(r.document);
  QCOMPARE(info.euler, 2LL);
  QVERIFY(info.closed);
  QCOMPARE(info.seamGap, 0.0f);
}

QTEST_GUILESS_MAIN(RemeshCasesTest)
#include "remesh_cases_test.moc"
