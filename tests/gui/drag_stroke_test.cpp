// Dragging brushes through the sculpting session the modeller uses (app/session): the viewport
// queues where the stroke starts, then the pointer's rays; grab lands the sample under the start
// on the point where the last ray meets the view plane, snake hook draws the pole out to it, and
// the stroke is one undo step that undo and redo give back bit for bit.
#include "../gpu/brush_test_support.h"
#include "sculpt_session.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <QTest>

#include <optional>

using namespace octaclay;

using gpu::testing::sameBits;
using gpu::testing::snapshot;

class DragStrokeTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void dragFollowsThePointersRays_data();
  void dragFollowsThePointersRays();

private:
  std::optional<gpu::GlContext> context_;
  gpu::BrushCatalog catalog_;
  std::optional<gpu::BrushEngine> engine_;
};

void DragStrokeTest::initTestCase() {
  context_.emplace(gpu::GlContext::createHeadless());
  engine_.emplace();
  catalog_.scan(gpu::BrushCatalog::defaultSearchPath(OCTACLAY_SOURCE_BRUSHES));
  QVERIFY(catalog_.find("grab") != nullptr);
  QVERIFY(catalog_.find("snake-hook") != nullptr);
}

void DragStrokeTest::dragFollowsThePointersRays_data() {
  QTest::addColumn<QString>("brush");
  QTest::addColumn<bool>("keepDetail");
  QTest::newRow("grab") << "grab" << false;
  QTest::newRow("snake-hook, keep-detail on") << "snake-hook" << true;
}

void DragStrokeTest::dragFollowsThePointersRays() {
  QFETCH(QString, brush);
  QFETCH(bool, keepDetail);
  const std::string id = brush.toStdString();
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(*catalog_.find(id));
  const int n = 128;
  session.setDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
  const auto before = snapshot(session.gpuDocument());
  app::StrokeStart start;
  start.brushId = start.settings.brushId = id;
  start.settings.radius = 0.08f; // of the diagonal: 0.28
  start.settings.strength = 1.0f;
  start.settings.pressureTarget = app::PressureTarget::None;
  start.settings.keepDetail = keepDetail;
  const core::Vec3f eye{0, 0, 10}, end{0.3f, 0.1f, 1.0f}; // on the view plane z = 1
  start.eye = eye;
  session.beginStroke(start);
  QVERIFY(session.strokeDrags());
  session.queueMove(app::StrokeMove::toUv({0.5f, 0.5f})); // the pole
  for (float t : {0.25f, 0.5f, 0.75f, 1.0f}) {
    const core::Vec3f at = core::Vec3f{0, 0, 1} + (end - core::Vec3f{0, 0, 1}) * t;
    session.queueMove(app::StrokeMove::alongRay(eye, core::normalize(at - eye)));
  }
  const app::DabRun run = session.runQueuedMoves();
  QVERIFY2(run.error.empty(), run.error.c_str());
  QVERIFY(run.made > 1);
  QCOMPARE(session.finishStroke().label, id);
  const core::GeometryImage& image = session.document().positions;
  // Some sample (the one under the start) reaches the point the last ray gives.
  float nearest = 1e9f;
  for (const core::Vec4f& t : image.texels())
    nearest = std::min(nearest, core::length(t.xyz() - end));
  QVERIFY2(nearest < 0.03f, qPrintable(QString::number(nearest)));
  const auto after = snapshot(session.gpuDocument());
  QCOMPARE(session.history().undoCount(), std::size_t(1));
  QVERIFY(session.undo());
  QVERIFY(sameBits(snapshot(session.gpuDocument()), before));
  QVERIFY(session.redo());
  QVERIFY(sameBits(snapshot(session.gpuDocument()), after));
}

QTEST_GUILESS_MAIN(DragStrokeTest)
#include "drag_stroke_test.moc"
