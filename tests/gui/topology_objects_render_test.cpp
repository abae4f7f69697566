// Torus and plane objects in the modeller (issue 33, item 2): the Add menu makes them (a
// torus's W × H from its radii, W ≠ H), the GPU renderer draws the edited one, and a stroke made
// with the mouse sculpts it: across the torus's wrap its seams stay exact (column W is column 0,
// row H is row 0) and both sides of the wrap move; on a plane the samples up to its edge move.
// The pixels change where the stroke went and nowhere far from it. The LOD view shows a torus's
// and a plane's level of detail (a closed ring; a sheet with one boundary) at its target; Mesh ▸
// Resolution resamples a ring. Drawn
// through the real VTK viewport (xcb under Xvfb, llvmpipe).
#include "camera_control.h"
#include "lod_generator.h"
#include "lod_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <QAction>
#include <QComboBox>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>

using namespace octaclay;
using app::MainWindow;

namespace {

// The camera: from (0, 0, 5) towards -z, +y up, 30° vertically, perspective.
constexpr double kEyeZ = 5.0, kViewAngle = 30.0;

void placeCamera(app::ViewportWidget& view) {
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  camera->SetParallelProjection(false);
  camera->SetPosition(0, 0, kEyeZ);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(kViewAngle);
  view.renderer()->ResetCameraClippingRange();
  view.update();
}

// Where world point (x, y, z) appears in a width × height view through that camera (y down).
QPoint pixelOf(double x, double y, double z, int width, int height) {
  const double half = (kEyeZ - z) * std::tan(kViewAngle / 2 * std::numbers::pi / 180);
  const double aspect = double(width) / height;
  return QPointF((x / (half * aspect) * 0.5 + 0.5) * width, (0.5 - y / half * 0.5) * height)
      .toPoint();
}

void hideBrushOutline(QWidget* view) {
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(view, &leave);
}

QImage frame(app::ViewportWidget& view) {
  placeCamera(view);
  hideBrushOutline(&view);
  QCoreApplication::processEvents();
  return view.grabFramebuffer();
}

// Pixels differing by more than `least` 8-bit steps in a channel, inside `box` and outside it.
// A sculpted bump changes its own pixels by far more than that; nothing else may change (a
// stroke across the torus's wrap once walked back across the whole image: pointer_legs).
std::pair<int, int> changedPixels(const QImage& a, const QImage& b, const QRect& box,
                                  int least = 96) {
  int inside = 0, outside = 0;
  for (int y = 0; y < std::min(a.height(), b.height()); ++y)
    for (int x = 0; x < std::min(a.width(), b.width()); ++x) {
      const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
      const int most = std::max({std::abs(qRed(p) - qRed(q)), std::abs(qGreen(p) - qGreen(q)),
                                 std::abs(qBlue(p) - qBlue(q))});
      if (most <= least) continue;
      (box.contains(x, y) ? inside : outside) += 1;
    }
  return {inside, outside};
}

bool sameBits(const core::Vec4f& a, const core::Vec4f& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

} // namespace

class TopologyObjectsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void addMenuOffersEveryShape();
  void aTorusIsAddedDrawnAndSculptedAcrossItsWrap();
  void aPlaneIsAddedDrawnAndSculptedToItsEdge();
  void aStrokeAcrossTheBallsBorderStaysUnderThePointer();
  void theLodViewShowsATorusAndAPlane();

private:
  // Opens a scene of one sphere (N = 64) far to the side, the one the Add menu adds beside.
  bool openStart();
  // Adds the shape through its Add menu action, then shows it alone at the origin, unscaled.
  // Returns what went wrong, empty on success.
  QString addAlone(const char* action);
  // An inflate stroke with the mouse from world point a to b (on the surface), in 12 moves.
  void strokeWithTheMouse(const QPoint& from, const QPoint& to);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void TopologyObjectsRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("topology_objects_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void TopologyObjectsRenderTest::cleanup() {
  window_.reset();
}

bool TopologyObjectsRenderTest::openStart() {
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)), "Body");
  scene.objects[0].transform.translation = {5.0f, 0.0f, 0.0f};
  const QString path = dir_.filePath("start.exr");
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  return window_ && window_->openDocument(path);
}

QString TopologyObjectsRenderTest::addAlone(const char* action) {
  app::Modeller& modeller = window_->viewport()->modeller();
  QAction* add = window_->findChild<QAction*>(action);
  if (!add) return QString("no action %1").arg(action);
  const int before = modeller.objectCount();
  add->trigger();
  if (modeller.objectCount() != before + 1)
    return QString("%1 added no object: %2").arg(action, modeller.error());
  const int k = modeller.objectCount() - 1;
  if (modeller.activeObject() != k) return "the added object is not the edited one";
  for (int o = 0; o < k; ++o)
    modeller.setObjectVisible(o, false);
  return modeller.setObjectTransform(k, core::ObjectTransform{});
}

void TopologyObjectsRenderTest::strokeWithTheMouse(const QPoint& from, const QPoint& to) {
  window_->brushState()->selectBrush("inflate");
  window_->brushState()->setRadius(0.04f);
  window_->brushState()->setStrength(0.6f);
  QWidget* view = window_->viewport();
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int k = 1; k <= 12; ++k)
    QTest::mouseMove(view, from + (to - from) * k / 12);
  QTest::mouseRelease(view, Qt::LeftButton, {}, to);
  QTRY_VERIFY_WITH_TIMEOUT(!window_->viewport()->stroking(), 20000);
}

void TopologyObjectsRenderTest::addMenuOffersEveryShape() {
  QVERIFY(openStart());
  for (const char* name : {"actionAddSphere", "actionAddCube", "actionAddCylinder", "actionAddBlob",
                           "actionAddCapsule", "actionAddTorus", "actionAddPlane", "actionAddDisc"})
    QVERIFY2(window_->findChild<QAction*>(name), name);
  app::Modeller& modeller = window_->viewport()->modeller();
  const int n = modeller.document().size();
  // The disc: a plane image of the scene's N, its boundary on the circle.
  const QString added = addAlone("actionAddDisc");
  QVERIFY2(added.isEmpty(), qPrintable(added));
  QCOMPARE(modeller.document().positions.topology(), core::Topology::Plane);
  QCOMPARE(modeller.document().positions.width(), n);
  const core::Vec3f rim = modeller.document().positions.at(n, n / 2).xyz();
  QVERIFY(std::abs(core::length(rim) - 1.0f) < 1e-5f);
}

void TopologyObjectsRenderTest::aTorusIsAddedDrawnAndSculptedAcrossItsWrap() {
  QVERIFY(openStart());
  app::Modeller& modeller = window_->viewport()->modeller();
  const int n = modeller.document().size();
  const QString added = addAlone("actionAddTorus");
  QVERIFY2(added.isEmpty(), qPrintable(added));
  const core::GeometryImage before = modeller.document().positions;
  // A ring (0.7, 0.3) of the scene's N around it and fewer cells around its tube.
  QCOMPARE(before.topology(), core::Topology::Torus);
  QCOMPARE(before.width(), n);
  QVERIFY2(before.height() < before.width(), qPrintable(QString::number(before.height())));
  const int w = before.width(), h = before.height();

  app::ViewportWidget* view = window_->viewport();
  const QImage shown = frame(*view);
  // Drawn: the top of the tube at (0.7, 0, 0.3) is the model's, the hole's centre the
  // background's.
  const QPoint top = pixelOf(0.7, 0, 0.3, shown.width(), shown.height());
  const QPoint hole = pixelOf(0, 0, 0, shown.width(), shown.height());
  QVERIFY(shown.pixel(top) != shown.pixel(hole));
  QCOMPARE(shown.pixel(hole), shown.pixel(0, 0));

  // Along the top of the tube across column 0 (= column W, the ring's angle 0 at y = 0).
  const QPoint from = pixelOf(0.7, -0.15, 0.3, shown.width(), shown.height());
  const QPoint to = pixelOf(0.7, 0.15, 0.3, shown.width(), shown.height());
  strokeWithTheMouse(from, to);
  QVERIFY(modeller.canUndo());
  const core::GeometryImage& after = modeller.document().positions;
  QCOMPARE(after.width(), w);
  QCOMPARE(after.height(), h);
  // Seams exact: column W is column 0 and row H is row 0, bit for bit.
  for (int j = 0; j <= h; ++j)
    QVERIFY2(sameBits(after.at(w, j), after.at(0, j)), qPrintable(QString("row %1").arg(j)));
  for (int i = 0; i <= w; ++i)
    QVERIFY2(sameBits(after.at(i, h), after.at(i, 0)), qPrintable(QString("column %1").arg(i)));
  // Both sides of the wrap moved: samples just past column 0 and just before column W.
  int early = 0, late = 0;
  for (int j = 0; j <= h; ++j)
    for (int i = 1; i < w; ++i) {
      if (sameBits(after.at(i, j), before.at(i, j))) continue;
      early += i < w / 8;
      late += i > w - w / 8;
    }
  QVERIFY2(early > 0 && late > 0, qPrintable(QString("%1 and %2").arg(early).arg(late)));
  const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
  QVERIFY(topology.closed());
  QCOMPARE(topology.euler, 0LL);

  // Nothing moved away from the stroke: its samples across the wrap, not a walk across the
  // image (pointer_legs); the half of the ring opposite the wrap kept bit for bit.
  for (int j = 0; j <= h; ++j)
    for (int i = w / 4; i < 3 * w / 4; ++i)
      QVERIFY2(sameBits(after.at(i, j), before.at(i, j)),
               qPrintable(QString("sample (%1, %2) moved").arg(i).arg(j)));
  // The pixels changed (more than 24 steps) around the stroke's path and nowhere else: within
  // the brush and keep detail's reach beyond it (its relaxation resamples the facets there).
  const QImage sculpted = frame(*view);
  const QRect around = QRect(from, to).normalized().adjusted(-80, -80, 80, 80);
  const auto [inside, outside] = changedPixels(shown, sculpted, around, 24);
  QVERIFY2(
      inside > 20 && outside == 0,
      qPrintable(
          QString("%1 pixels changed around the stroke, %2 elsewhere").arg(inside).arg(outside)));

  // The saliency preview reads the torus's own grid: normalised, the stroke's ridge across the
  // wrap standing out, column W equal to column 0.
  modeller.setSaliencyWanted(true);
  const auto peak = [&] {
    float most = 0;
    for (const core::Vec4f& t : modeller.document().positions.texels())
      most = std::max(most, t.w);
    return most;
  };
  QTRY_COMPARE_WITH_TIMEOUT(peak(), 1.0f, 20000);
  const core::GeometryImage& salient = modeller.document().positions;
  float stroked = 0, rest = 0;
  int restCount = 0;
  for (int j = 0; j <= h; ++j) {
    QCOMPARE(salient.at(w, j).w, salient.at(0, j).w);
    for (int i = 0; i <= w; ++i) {
      const bool nearWrap = i < w / 16 || i > w - w / 16;
      if (nearWrap) stroked = std::max(stroked, salient.at(i, j).w);
      if (i > w / 4 && i < 3 * w / 4) rest += salient.at(i, j).w, ++restCount;
    }
  }
  QVERIFY2(stroked > 10 * rest / float(restCount),
           qPrintable(QString("%1 near the stroke, %2 on average elsewhere")
                          .arg(double(stroked))
                          .arg(double(rest / float(restCount)))));
}

void TopologyObjectsRenderTest::aPlaneIsAddedDrawnAndSculptedToItsEdge() {
  QVERIFY(openStart());
  app::Modeller& modeller = window_->viewport()->modeller();
  const QString added = addAlone("actionAddPlane");
  QVERIFY2(added.isEmpty(), qPrintable(added));
  const core::GeometryImage before = modeller.document().positions;
  QCOMPARE(before.topology(), core::Topology::Plane);
  const int w = before.width(), h = before.height();

  app::ViewportWidget* view = window_->viewport();
  const QImage shown = frame(*view);
  // Drawn over [-1, 1]² in z = 0, seen from either side.
  QVERIFY(shown.pixel(pixelOf(0.5, 0.5, 0, shown.width(), shown.height())) != shown.pixel(0, 0));
  QCOMPARE(shown.pixel(pixelOf(0, 1.2, 0, shown.width(), shown.height())), shown.pixel(0, 0));

  // From inside to the edge at x = 1 (column W).
  const QPoint from = pixelOf(0.6, 0.1, 0, shown.width(), shown.height());
  const QPoint to = pixelOf(0.98, 0.1, 0, shown.width(), shown.height());
  strokeWithTheMouse(from, to);
  QVERIFY(modeller.canUndo());
  const core::GeometryImage& after = modeller.document().positions;
  // The boundary moves like the samples inside it; the far edge (column 0) stays.
  int edge = 0;
  for (int j = 0; j <= h; ++j) {
    edge += !sameBits(after.at(w, j), before.at(w, j));
    QVERIFY(sameBits(after.at(0, j), before.at(0, j)));
  }
  QVERIFY2(edge > 0, "no sample of the edge moved");
  const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
  QCOMPARE(topology.euler, 1LL);
  QCOMPARE(topology.boundaryEdges, std::size_t(2 * (w + h)));

  const QImage sculpted = frame(*view);
  const QRect around = QRect(from, to).normalized().adjusted(-40, -40, 40, 40);
  const auto [inside, outside] = changedPixels(shown, sculpted, around);
  QVERIFY2(
      inside > 20 && outside == 0,
      qPrintable(
          QString("%1 pixels changed around the stroke, %2 elsewhere").arg(inside).arg(outside)));
}

// The ball's image border is a seam too: (i, 0) is (N − i, 0). A mouse stroke across it, seen
// from outside where it runs, changes the surface around the pointer and not the samples
// between the two sides in the image (walking that straight image segment moved them).
void TopologyObjectsRenderTest::aStrokeAcrossTheBallsBorderStaysUnderThePointer() {
  QVERIFY(openStart());
  app::Modeller& modeller = window_->viewport()->modeller();
  const QString added = addAlone("actionAddSphere");
  QVERIFY2(added.isEmpty(), qPrintable(added));
  const core::GeometryImage before = modeller.document().positions;
  const int n = before.size();
  const core::Sample a{n / 4, 2}, b{n - n / 4, 2}; // neighbours across the bottom edge
  const core::Vec3f pa = before.at(a).xyz(), pb = before.at(b).xyz();
  QVERIFY2(core::length(pa - pb) < 0.2f, "the two samples are neighbours on the surface");
  app::ViewportWidget* view = window_->viewport();
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const core::Vec3f mid = (pa + pb) * 0.5f, eye = core::normalize(mid) * 6.0f;
  camera->SetParallelProjection(false);
  camera->SetFocalPoint(mid.x, mid.y, mid.z);
  camera->SetPosition(eye.x, eye.y, eye.z);
  const core::Vec3f up =
      std::abs(core::normalize(mid).y) < 0.9f ? core::Vec3f{0, 1, 0} : core::Vec3f{1, 0, 0};
  camera->SetViewUp(up.x, up.y, up.z);
  view->renderer()->ResetCameraClippingRange();
  hideBrushOutline(view);
  QCoreApplication::processEvents();
  const QPoint from = app::projectToView(*camera, view->modelRect(), pa).toPoint();
  const QPoint to = app::projectToView(*camera, view->modelRect(), pb).toPoint();
  QVERIFY2((to - from).manhattanLength() > 8, "the stroke crosses the border on screen");
  strokeWithTheMouse(from, to);
  const core::GeometryImage& after = modeller.document().positions;
  // Changed around the pointer: some samples near a or b moved.
  int nearMoved = 0;
  for (int j = 0; j <= 6; ++j)
    for (const int i0 : {a.i, b.i})
      for (int i = i0 - 4; i <= i0 + 4; ++i)
        nearMoved += !sameBits(after.at(i, j), before.at(i, j));
  QVERIFY2(nearMoved > 0, "the stroke changed the surface under the pointer");
  // Not between them in the image: the border rows' middle, half the ball away from both (the
  // dabs reach some ten samples here: the scene's other, hidden ball makes its diagonal long).
  for (int j = 0; j <= 6; ++j)
    for (int i = n / 2 - 3; i <= n / 2 + 3; ++i)
      QVERIFY2(sameBits(after.at(i, j), before.at(i, j)),
               qPrintable(QString("sample (%1, %2) moved").arg(i).arg(j)));
}

// The LOD view on a torus, then on a plane (each alone): generated without an error, of the
// object's topology, at most the target's triangles, drawn where the model is and not in the
// torus's hole; after a stroke across the wrap, regenerated.
void TopologyObjectsRenderTest::theLodViewShowsATorusAndAPlane() {
  QVERIFY(openStart());
  const QString added = addAlone("actionAddTorus");
  QVERIFY2(added.isEmpty(), qPrintable(added));
  app::ViewportWidget* view = window_->viewport();
  // The Level list counts the ring's own W × H cells.
  const core::GeometryImage& made = window_->viewport()->modeller().document().positions;
  auto* levels = window_->lodPanel()->findChild<QComboBox*>(QStringLiteral("level"));
  QVERIFY(levels);
  QCOMPARE(levels->itemText(0), QString("Full (%1 × %2)").arg(made.width()).arg(made.height()));
  QSignalSpy generated(window_->lodGenerator(), &app::LodGenerator::generated);
  QSignalSpy failed(window_->lodGenerator(), &app::LodGenerator::failed);
  constexpr int kTarget = 3000;
  window_->lodPanel()->setTargetTriangles(kTarget);
  window_->lodPanel()->setDisplay(app::LodPanel::Display::Lod);
  const auto waitForLod = [&](int count) {
    return QTest::qWaitFor(
        [&] {
          return (generated.count() > count || failed.count() > 0) &&
                 !window_->lodGenerator()->busy() && view->lodTriangles() > 0;
        },
        30000);
  };
  QVERIFY(waitForLod(0));
  QVERIFY2(failed.isEmpty(), qPrintable(failed.isEmpty() ? "" : failed[0][0].toString()));
  const auto checkRing = [&] {
    const std::shared_ptr<const core::LodMesh> lod = window_->lodGenerator()->lod();
    QVERIFY(lod);
    QVERIFY2(lod->mesh.triangles.size() <= std::size_t(kTarget) + 2,
             qPrintable(QString::number(lod->mesh.triangles.size())));
    const core::MeshTopology topology = core::analyzeTopology(lod->mesh);
    QVERIFY(topology.closed());
    QCOMPARE(topology.euler, 0LL);
    QCOMPARE(view->lodTriangles(), static_cast<long long>(lod->mesh.triangles.size()));
  };
  checkRing();
  const QImage shown = frame(*view);
  if (qEnvironmentVariableIsSet("TOPOLOGY_TEST_SAVE")) shown.save("/tmp/torus_lod.png");
  const QPoint top = pixelOf(0.7, 0, 0.3, shown.width(), shown.height());
  const QPoint hole = pixelOf(0, 0, 0, shown.width(), shown.height());
  QVERIFY(shown.pixel(top) != shown.pixel(0, 0));
  QCOMPARE(shown.pixel(hole), shown.pixel(0, 0));
  // A stroke across the wrap: the LOD follows and is made again.
  const int before = int(generated.count());
  strokeWithTheMouse(pixelOf(0.7, -0.15, 0.3, shown.width(), shown.height()),
                     pixelOf(0.7, 0.15, 0.3, shown.width(), shown.height()));
  QVERIFY(waitForLod(before));
  QVERIFY(failed.isEmpty());
  checkRing();

  // Mesh ▸ Even Out Samples on the stroked ring: one undo step with the wrap exact, or (its own
  // check finding nothing to gain) the model unchanged and no step.
  const int steps = window_->undoStack()->count();
  const core::GeometryImage stroked = window_->viewport()->modeller().document().positions;
  const bool evened = window_->evenOutSamples();
  const core::GeometryImage& out = window_->viewport()->modeller().document().positions;
  QCOMPARE(window_->undoStack()->count(), steps + (evened ? 1 : 0));
  if (evened) {
    for (int j = 0; j <= out.height(); ++j)
      QVERIFY(sameBits(out.at(out.width(), j), out.at(0, j)));
    window_->undoStack()->undo();
  }
  QVERIFY(std::memcmp(window_->viewport()->modeller().document().positions.texels().data(),
                      stroked.texels().data(), stroked.byteSize()) == 0);
  // The stretch preview on the ring (W ≠ H): drawn, its mean spacing the ring's own.
  window_->lodPanel()->setDisplay(app::LodPanel::Display::FullResolution);
  view->setPreview(gpu::ModelView::Preview::Stretch);
  const QImage stretched = frame(*view);
  QVERIFY(stretched.pixel(top) != stretched.pixel(0, 0));
  QCOMPARE(stretched.pixel(hole), stretched.pixel(0, 0));
  view->setPreview(gpu::ModelView::Preview::Shaded);
  window_->lodPanel()->setDisplay(app::LodPanel::Display::Lod);
  // Mesh ▸ Resolution on the ring: twice the cells both ways, its wrap exact, drawn; one undo
  // brings the old image back bit for bit.
  const core::GeometryImage ring = window_->viewport()->modeller().document().positions;
  QVERIFY(window_->changeResolution(2 * ring.width()));
  const core::GeometryImage& finer = window_->viewport()->modeller().document().positions;
  QCOMPARE(finer.width(), 2 * ring.width());
  QCOMPARE(finer.height(), 2 * ring.height());
  for (int j = 0; j <= finer.height(); ++j)
    QVERIFY(sameBits(finer.at(finer.width(), j), finer.at(0, j)));
  const QImage resized = frame(*view);
  QVERIFY(resized.pixel(top) != resized.pixel(0, 0));
  QCOMPARE(resized.pixel(hole), resized.pixel(0, 0));
  window_->undoStack()->undo();
  const core::GeometryImage& undone = window_->viewport()->modeller().document().positions;
  QCOMPARE(undone.width(), ring.width());
  QVERIFY(std::memcmp(undone.texels().data(), ring.texels().data(), ring.byteSize()) == 0);

  const QString plane = addAlone("actionAddPlane");
  QVERIFY2(plane.isEmpty(), qPrintable(plane));
  const int planeBefore = int(generated.count());
  QVERIFY(waitForLod(planeBefore));
  QVERIFY(failed.isEmpty());
  const std::shared_ptr<const core::LodMesh> sheet = window_->lodGenerator()->lod();
  const core::MeshTopology topology = core::analyzeTopology(sheet->mesh);
  QCOMPARE(topology.euler, 1LL);
  QVERIFY(topology.boundaryEdges > 0);
  QVERIFY(sheet->mesh.triangles.size() <= std::size_t(kTarget) + 2);
  const QImage sheetShown = frame(*view);
  QVERIFY(sheetShown.pixel(pixelOf(0.5, 0.5, 0, sheetShown.width(), sheetShown.height())) !=
          sheetShown.pixel(0, 0));
}

QTEST_MAIN(TopologyObjectsRenderTest)
#include "topology_objects_render_test.moc"
