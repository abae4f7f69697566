// The modeller core as the window uses it: a stroke made with the mouse reaches the renderer
// only through the document's change feed, and keep detail's relaxation runs beside the window.

#include "current_context.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_frames.h"

#include "octaclay/gpu/model_renderer.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>
#include <QUndoStack>
#include <QWheelEvent>

#include <cmath>

using namespace octaclay;
using app::MainWindow;

namespace {

// A stroke made with the mouse from the view's centre, 45 % of the view's width to the right in
// 20 moves, released: a snake hook pulls a limb (relaxed as it goes and at its end), a push
// raises a ridge (relaxed at its end alone).
void pullWithTheMouse(MainWindow& w, const QString& brush = "snake_hook") {
  w.brushState()->selectBrush(brush);
  w.brushState()->setRadius(0.08f);
  w.brushState()->setStrength(1.0f);
  w.brushState()->setKeepDetail(true);
  QWidget* view = w.viewport();
  const QPoint from(view->width() / 2, view->height() / 2);
  const QPoint to = from + QPoint(int(view->width() * 0.45), -view->height() / 10);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int k = 1; k <= 20; ++k) {
    QTest::mouseMove(view, from + (to - from) * k / 20);
    QCoreApplication::processEvents(); // the moves run as they arrive, as with a real mouse
  }
  QTest::mouseRelease(view, Qt::LeftButton, {}, to);
}

std::vector<float> readMap(const gpu::Texture& map, int side) {
  return map.read({0, 0, side, side});
}

std::size_t differing(const std::vector<float>& a, const std::vector<float>& b) {
  std::size_t count = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    count += a[k] != b[k];
  return count;
}

} // namespace

class ModellerCoreRenderTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void aRelaxedStrokeLeavesNormalsAndStretchAsAFullRecomputation();
  void theWindowAnswersWhileAStrokeRelaxes();

private:
  QTemporaryDir dir_;
};

void ModellerCoreRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
}

void ModellerCoreRenderTest::aRelaxedStrokeLeavesNormalsAndStretchAsAFullRecomputation() {
  auto window = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  constexpr int n = 256;
  QVERIFY(window->newDocument(core::BaseShape::Sphere, n, true));
  app::ViewportWidget* view = window->viewport();
  app::Modeller& modeller = *window->modeller();
  view->setPreview(gpu::ModelView::Preview::Stretch);
  view->grabFramebuffer(); // the stretch map as the sphere has it
  pullWithTheMouse(*window);
  QTRY_VERIFY_WITH_TIMEOUT(!view->stroking(), 30000);
  // Not a test of anything unless keep detail moved samples beyond the dabs.
  QVERIFY2(!modeller.session().lastRelaxation().tiles.empty(), "keep detail relaxed nothing");
  QCOMPARE(window->undoStack()->count(), 1);
  view->grabFramebuffer(); // the stretch preview brings its map up to date as it draws

  const int side = n + 1;
  app::CurrentContext current(*view);
  const gpu::ModelRenderer& shown = *view->frames().modelRenderer();
  const std::vector<float> normals = readMap(shown.normalMap(), side);
  const std::vector<float> stretch = readMap(shown.stretchMap(), side);
  // A renderer that computes everything anew from the document as it is.
  gpu::GpuDocument& document = modeller.session().gpuDocument();
  gpu::ModelRenderer fresh;
  fresh.setLevel(n, view->levelDivisor());
  fresh.refreshAllNormals(document);
  gpu::ModelView stretchView;
  stretchView.preview = gpu::ModelView::Preview::Stretch;
  fresh.draw(document, stretchView); // computes its stretch map first
  const std::size_t staleNormals = differing(normals, readMap(fresh.normalMap(), side));
  const std::size_t staleStretch = differing(stretch, readMap(fresh.stretchMap(), side));
  qInfo("relaxation: %zu tiles; normal map values differing from a full recomputation: %zu, "
        "stretch map: %zu",
        modeller.session().lastRelaxation().tiles.size(), staleNormals, staleStretch);
  QCOMPARE(staleNormals, std::size_t(0));
  QCOMPARE(staleStretch, std::size_t(0));
}

void ModellerCoreRenderTest::theWindowAnswersWhileAStrokeRelaxes() {
  auto window = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 1024, true));
  app::ViewportWidget* view = window->viewport();
  const std::vector<float> before = app::testing::positionsOf(*window);
  QSignalSpy swapped(view, &app::ViewportWidget::frameSwapped);
  pullWithTheMouse(*window, "push");
  // The release handed the relaxation to a worker: the stroke is not recorded yet.
  QVERIFY2(window->modeller()->strokes().relaxing(), "the relaxation did not run beside the GUI");
  QCOMPARE(window->undoStack()->count(), 0);
  // The wait shows: a busy cursor over the view and the status bar saying why.
  QCOMPARE(view->cursor().shape(), Qt::BusyCursor);
  QVERIFY(window->statusBar()->currentMessage().startsWith("Keeping detail"));
  // An input event now (a wheel turn zooms): a frame answers it before the relaxation is in.
  swapped.clear();
  QElapsedTimer sinceInput;
  const QPointF at(view->width() / 4.0, view->height() / 4.0);
  QWheelEvent wheel(at, view->mapToGlobal(at), {}, {0, 120}, Qt::NoButton, {}, Qt::NoScrollPhase,
                    false);
  sinceInput.start();
  QApplication::sendEvent(view, &wheel);
  QVERIFY(QTest::qWaitFor([&] { return !swapped.isEmpty(); }, 5000));
  const qint64 answeredMs = sinceInput.elapsed();
  const bool stillRelaxing = window->modeller()->strokes().relaxing();
  qInfo("a frame %lld ms after the wheel event, the relaxation %s", answeredMs,
        stillRelaxing ? "still running" : "already in");
  QVERIFY2(stillRelaxing, "the relaxation ended before the frame: nothing measured");
  // The bound for a window that answers (a GUI thread held by the relaxation answers
  // after it, 0.4 s and more at N = 1024 here).
  QVERIFY2(answeredMs <= 100, qPrintable(QString("%1 ms").arg(answeredMs)));
  // Then the step arrives, whole: one undo step that gives the sphere back bit for bit.
  QTRY_COMPARE_WITH_TIMEOUT(window->undoStack()->count(), 1, 30000);
  QCOMPARE(view->cursor().shape(), Qt::ArrowCursor);
  QVERIFY(window->statusBar()->currentMessage().isEmpty());
  QVERIFY(!app::testing::bitEqual(app::testing::positionsOf(*window), before));
  window->undoStack()->undo();
  QVERIFY(app::testing::bitEqual(app::testing::positionsOf(*window), before));
}

QTEST_MAIN(ModellerCoreRenderTest)
#include "modeller_core_render_test.moc"
