// A scene of several objects in the modeller (issue 33, item 3): File ▸ Open and Save keep every
// object, the active one is edited and switching it keeps the others' work. Drawn through the
// real VTK viewport (xcb under Xvfb, llvmpipe).
#include "history_list.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QStandardPaths>
#include <QStatusBar>
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
using app::testing::bitEqual;
using app::testing::positionsOf;

namespace {

bool samePositions(const core::Document& a, const core::Document& b) {
  const auto x = a.positions.texels(), y = b.positions.texels();
  return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size_bytes()) == 0;
}

// Three N = 64 objects: a sphere at the origin (the one sculpted), a cube to its right and a
// blob to its left, each with its own rotation and non-uniform scale.
core::Scene threeObjects() {
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)), "Body");
  scene.objects.push_back({"Box",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 64)),
                           {{3.0f, 0.25f, 0.0f}, {0.0f, 30.0f, 0.0f}, {0.5f, 0.75f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Lump",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 64)),
                           {{-3.0f, 0.0f, 0.5f}, {10.0f, 0.0f, -20.0f}, {0.4f, 0.4f, 0.8f}},
                           false,
                           true});
  return scene;
}

// The camera every placement test looks through: from (1, 0, 10) towards -z, +y up, 30°
// vertically (VTK's default angle), perspective.
constexpr double kEyeX = 1.0, kEyeZ = 10.0, kViewAngle = 30.0;

void placeCamera(app::ViewportWidget& view) {
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  camera->SetParallelProjection(false);
  camera->SetPosition(kEyeX, 0, kEyeZ);
  camera->SetFocalPoint(kEyeX, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(kViewAngle);
  view.renderer()->ResetCameraClippingRange();
  view.update();
}

// Where world point p appears in a width × height view through that camera, by hand (pixels, y
// down).
QPointF expectedPixel(double x, double y, double z, int width, int height) {
  const double half = (kEyeZ - z) * std::tan(kViewAngle / 2 * std::numbers::pi / 180);
  const double aspect = double(width) / height;
  return {((x - kEyeX) / (half * aspect) * 0.5 + 0.5) * width, (0.5 - y / half * 0.5) * height};
}

// The box of the pixels that differ from the background (the top-left corner's colour), within
// columns [fromX, toX).
QRect drawnBox(const QImage& image, int fromX = 0, int toX = -1) {
  const QRgb background = image.pixel(0, 0);
  if (toX < 0) toX = image.width();
  int x0 = image.width(), y0 = image.height(), x1 = -1, y1 = -1;
  for (int y = 0; y < image.height(); ++y)
    for (int x = std::max(0, fromX); x < std::min(toX, image.width()); ++x) {
      const QRgb c = image.pixel(x, y);
      if (std::max({std::abs(qRed(c) - qRed(background)), std::abs(qGreen(c) - qGreen(background)),
                    std::abs(qBlue(c) - qBlue(background))}) <= 8)
        continue;
      x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
  return x1 < 0 ? QRect() : QRect(QPoint(x0, y0), QPoint(x1, y1));
}

void hideBrushOutline(QWidget* view) {
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(view, &leave);
}

} // namespace

class SceneObjectsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void openSculptSaveKeepsEveryObject();
  void switchingTheActiveObjectKeepsEachOnesWork();
  void activeObjectIsDrawnAndSculptedUnderItsTransform();
  void otherVisibleObjectsAreDrawnUnderTheirTransforms();
  void altClickOnAnObjectMakesItTheEditedOne();

private:
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void SceneObjectsRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("scene_objects_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void SceneObjectsRenderTest::cleanup() {
  window_.reset();
}

void SceneObjectsRenderTest::openSculptSaveKeepsEveryObject() {
  const core::Scene original = threeObjects();
  const QString opened = dir_.filePath("three.exr"), saved = dir_.filePath("three-saved.exr");
  core::writeScene(original, opened.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window_);
  QVERIFY(window_->openDocument(opened));
  app::Modeller& modeller = window_->viewport()->modeller();
  QCOMPARE(modeller.objectCount(), 3);
  QCOMPARE(modeller.activeObject(), 0);
  QVERIFY(samePositions(modeller.document(), original.objects[0].document));

  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(window_->isModified());
  QVERIFY(!samePositions(modeller.document(), original.objects[0].document));
  const std::vector<float> sculpted = positionsOf(*window_);

  QVERIFY(window_->saveDocument(saved));
  const core::Scene back = core::readScene(saved.toStdString());
  QCOMPARE(back.objects.size(), std::size_t(3));
  for (std::size_t k = 0; k < 3; ++k) {
    QCOMPARE(back.objects[k].name, original.objects[k].name);
    QVERIFY(back.objects[k].transform == original.objects[k].transform);
    QCOMPARE(back.objects[k].visible, original.objects[k].visible);
    QCOMPARE(back.objects[k].locked, original.objects[k].locked);
  }
  // The sculpted object holds the stroke, the others their bits.
  QVERIFY(samePositions(back.objects[0].document, modeller.document()));
  QVERIFY(!samePositions(back.objects[0].document, original.objects[0].document));
  QVERIFY(samePositions(back.objects[1].document, original.objects[1].document));
  QVERIFY(samePositions(back.objects[2].document, original.objects[2].document));
  QVERIFY(bitEqual(positionsOf(*window_), sculpted));

  // Export Mesh writes every visible object: one OBJ group each (the lump is hidden).
  const QString obj = dir_.filePath("three.obj");
  QVERIFY(window_->exportMesh(obj, 1));
  QFile file(obj);
  QVERIFY(file.open(QIODevice::ReadOnly));
  QStringList groups;
  while (!file.atEnd()) {
    const QByteArray line = file.readLine().trimmed();
    if (line.startsWith("o ")) groups << QString::fromUtf8(line.mid(2));
  }
  QCOMPARE(groups, QStringList({"Body", "Box"}));
}

void SceneObjectsRenderTest::switchingTheActiveObjectKeepsEachOnesWork() {
  const core::Scene original = threeObjects();
  const QString opened = dir_.filePath("switch.exr");
  core::writeScene(original, opened.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window_);
  QVERIFY(window_->openDocument(opened));
  app::Modeller& modeller = window_->viewport()->modeller();
  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(modeller.canUndo());
  const std::vector<float> sculpted = positionsOf(*window_);

  // Switching: the edited body goes back into the scene, the box is uploaded; not a step, and
  // the one history keeps the body's stroke (the status bar names the box), still modified.
  QVERIFY(!modeller.setActiveObject(3));
  QVERIFY(!modeller.setActiveObject(-1));
  QVERIFY(modeller.setActiveObject(1));
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY(samePositions(modeller.document(), original.objects[1].document));
  QCOMPARE(modeller.history().undoCount(), std::size_t(1));
  QCOMPARE(window_->undoStack()->undoText(), QString("Stroke (push)"));
  QVERIFY(window_->isModified());
  QVERIFY2(window_->statusBar()->currentMessage().contains("Box"),
           qPrintable(window_->statusBar()->currentMessage()));
  core::Scene now = modeller.scene();
  QCOMPARE(now.objects.size(), std::size_t(3));
  QCOMPARE(now.objects[1].name, std::string("Box"));
  QVERIFY(now.objects[1].transform == original.objects[1].transform);
  QVERIFY(!samePositions(now.objects[0].document, original.objects[0].document));
  QVERIFY(samePositions(now.objects[2].document, original.objects[2].document));

  // Back to the body: its stroke is still there, bit for bit.
  QVERIFY(modeller.setActiveObject(0));
  QVERIFY(bitEqual(positionsOf(*window_), sculpted));
  QVERIFY(samePositions(modeller.scene().objects[1].document, original.objects[1].document));
  QVERIFY(window_->isModified());
}

void SceneObjectsRenderTest::activeObjectIsDrawnAndSculptedUnderItsTransform() {
  // The edited object: a unit sphere moved to (2, 0, 0) and halved; a hidden one at the origin.
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)), "Small");
  scene.objects[0].transform = {{2.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}};
  scene.objects.push_back({"Hidden",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)),
                           {},
                           false,
                           false});
  const QString path = dir_.filePath("placed.exr");
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window_);
  QVERIFY(window_->openDocument(path));
  app::ViewportWidget* view = window_->viewport();
  placeCamera(*view);
  hideBrushOutline(view);
  const QImage image = view->grabFramebuffer();
  QCOMPARE(image.size(), view->size()); // one device pixel a logical one under Xvfb
  const int w = image.width(), h = image.height();

  // Its pixels lie around (2, 0, 0)'s projection, as wide as a radius of 0.5 there. A sphere's
  // outline seen from 10 units is within 0.2 % of the projected radius; 3 pixels allow for the
  // rasterization of its edge and the displayed level's facets.
  const QRect box = drawnBox(image);
  QVERIFY(!box.isNull());
  const QPointF centre = expectedPixel(2, 0, 0, w, h);
  const double radius =
      (expectedPixel(2.5, 0, 0, w, h).x() - expectedPixel(1.5, 0, 0, w, h).x()) / 2;
  const QPointF drawnCentre = QRectF(box).center();
  const QString where = QString("drawn %1,%2 %3×%4; expected centre %5,%6 radius %7")
                            .arg(box.x())
                            .arg(box.y())
                            .arg(box.width())
                            .arg(box.height())
                            .arg(centre.x())
                            .arg(centre.y())
                            .arg(radius);
  QVERIFY2(std::abs(drawnCentre.x() - centre.x()) < 3 && std::abs(drawnCentre.y() - centre.y()) < 3,
           qPrintable(where));
  QVERIFY2(std::abs(box.width() / 2.0 - radius) < 3 && std::abs(box.height() / 2.0 - radius) < 3,
           qPrintable(where));

  // A stroke made with the mouse over its front, (2, 0, 0.5) in the world, changes the
  // document there: around (0, 0, 1) of the object's own space.
  const core::GeometryImage before = view->modeller().document().positions;
  QVERIFY(window_->brushState()->selectBrush("inflate"));
  window_->brushState()->setRadius(0.05f);
  window_->brushState()->setStrength(0.5f);
  const QPoint press = expectedPixel(2, 0, 0.5, w, h).toPoint();
  QTest::mousePress(view, Qt::LeftButton, {}, press);
  for (int k = 1; k <= 5; ++k)
    QTest::mouseMove(view, press + QPoint(2 * k, 0));
  QTest::mouseRelease(view, Qt::LeftButton, {}, press + QPoint(10, 0));
  QTRY_VERIFY_WITH_TIMEOUT(!view->stroking(), 20000);
  QVERIFY(view->modeller().canUndo());
  const core::GeometryImage& after = view->modeller().document().positions;
  int changed = 0;
  core::Vec3f sum{};
  for (int j = 0; j <= before.size(); ++j)
    for (int i = 0; i <= before.size(); ++i) {
      const core::Vec3f a = before.at(i, j).xyz(), b = after.at(i, j).xyz();
      if (a.x == b.x && a.y == b.y && a.z == b.z) continue;
      ++changed;
      sum = sum + a;
    }
  QVERIFY2(changed > 5, qPrintable(QString::number(changed)));
  // The pointer moved 10 pixels right, about 0.09 object units: the centre of the change lies
  // within 0.25 object units of the front point (the brush's radius is 0.17).
  const core::Vec3f mean = sum * (1.0f / float(changed));
  QVERIFY2(core::length(mean - core::Vec3f{0, 0, 1}) < 0.25f,
           qPrintable(QString("%1 samples changed around %2, %3, %4")
                          .arg(changed)
                          .arg(mean.x)
                          .arg(mean.y)
                          .arg(mean.z)));
}

void SceneObjectsRenderTest::otherVisibleObjectsAreDrawnUnderTheirTransforms() {
  // The edited sphere at (2, 0, 0) halved, and a visible one at (0, 0.5, 0) scaled (0.5, 0.25,
  // 0.5): drawn in the same frame, flattened, where its transform puts it.
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)), "Small");
  scene.objects[0].transform = {{2.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}};
  scene.objects.push_back({"Flat",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)),
                           {{0.0f, 0.5f, 0.0f}, {}, {0.5f, 0.25f, 0.5f}},
                           true,
                           false});
  const QString path = dir_.filePath("two.exr");
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window_);
  QVERIFY(window_->openDocument(path));
  app::ViewportWidget* view = window_->viewport();
  app::Modeller& modeller = view->modeller();

  // Each object's pixels, left and right of the view's centre (world x = 1), against their
  // hand-computed projections: 3 pixels for the edge's rasterization and facets.
  auto check = [&](const char* when) {
    placeCamera(*view);
    hideBrushOutline(view);
    const QImage image = view->grabFramebuffer();
    const int w = image.width(), h = image.height();
    const int middle = qRound(expectedPixel(1, 0, 0, w, h).x());
    const QRect flat = drawnBox(image, 0, middle), small = drawnBox(image, middle);
    const QPointF flatLow = expectedPixel(-0.5, 0.25, 0, w, h),
                  flatHigh = expectedPixel(0.5, 0.75, 0, w, h);
    const QPointF smallLow = expectedPixel(1.5, -0.5, 0, w, h),
                  smallHigh = expectedPixel(2.5, 0.5, 0, w, h);
    auto near = [](const QRect& box, QPointF low, QPointF high) {
      return !box.isNull() && std::abs(box.left() - low.x()) < 3 &&
             std::abs(box.right() + 1 - high.x()) < 3 && std::abs(box.top() - high.y()) < 3 &&
             std::abs(box.bottom() + 1 - low.y()) < 3;
    };
    const QString where = QString("%1: flat drawn %2,%3 to %4,%5, expected %6,%7 to %8,%9; small "
                                  "drawn %10,%11 to %12,%13, expected %14,%15 to %16,%17")
                              .arg(when)
                              .arg(flat.left())
                              .arg(flat.top())
                              .arg(flat.right() + 1)
                              .arg(flat.bottom() + 1)
                              .arg(flatLow.x())
                              .arg(flatHigh.y())
                              .arg(flatHigh.x())
                              .arg(flatLow.y())
                              .arg(small.left())
                              .arg(small.top())
                              .arg(small.right() + 1)
                              .arg(small.bottom() + 1)
                              .arg(smallLow.x())
                              .arg(smallHigh.y())
                              .arg(smallHigh.x())
                              .arg(smallLow.y());
    qInfo().noquote() << where;
    if (qEnvironmentVariableIsSet("OCTACLAY_TEST_IMAGES"))
      image.save(qEnvironmentVariable("OCTACLAY_TEST_IMAGES") + "/" + when + ".png");
    QVERIFY2(near(flat, flatLow, flatHigh), qPrintable(where));
    QVERIFY2(near(small, smallLow, smallHigh), qPrintable(where));
  };
  check("Small edited");
  if (QTest::currentTestFailed()) return;
  // The other way round: the flat one edited (the GPU's), the small one a scene actor.
  QVERIFY(modeller.setActiveObject(1));
  check("Flat edited");
  if (QTest::currentTestFailed()) return;
  // A file whose first object is hidden opens with the first visible one edited.
  {
    core::Scene firstHidden = scene;
    firstHidden.objects[0].visible = false;
    const QString hiddenPath = dir_.filePath("first-hidden.exr");
    core::writeScene(firstHidden, hiddenPath.toStdString());
    QVERIFY(window_->openDocument(hiddenPath));
    QCOMPARE(modeller.activeObject(), 1);
    QCOMPARE(modeller.objectAt(1).name, std::string("Flat"));
  }
  // Hidden, it is not drawn: nothing right of the centre.
  core::Scene hidden = modeller.scene();
  hidden.objects[0].visible = false;
  QVERIFY(modeller.setScene(std::move(hidden), 1, true));
  placeCamera(*view);
  hideBrushOutline(view);
  const QImage image = view->grabFramebuffer();
  const int middle = qRound(expectedPixel(1, 0, 0, image.width(), image.height()).x());
  QVERIFY(drawnBox(image, middle).isNull());
  QVERIFY(!drawnBox(image, 0, middle).isNull());
}

void SceneObjectsRenderTest::altClickOnAnObjectMakesItTheEditedOne() {
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)), "Small");
  scene.objects[0].transform = {{2.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}};
  scene.objects.push_back({"Flat",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64)),
                           {{0.0f, 0.5f, 0.0f}, {}, {0.5f, 0.25f, 0.5f}},
                           true,
                           false});
  const QString path = dir_.filePath("alt.exr");
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window_);
  QVERIFY(window_->openDocument(path));
  app::ViewportWidget* view = window_->viewport();
  app::Modeller& modeller = view->modeller();
  placeCamera(*view);
  const int w = view->width(), h = view->height();
  const std::vector<float> small = positionsOf(*window_);

  // Alt+click on the flat one's front: it becomes the edited one, no stroke made.
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier,
                    expectedPixel(0, 0.5, 0.25, w, h).toPoint());
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY2(window_->statusBar()->currentMessage().contains("Flat"),
           qPrintable(window_->statusBar()->currentMessage()));
  QVERIFY(!modeller.canUndo());
  // On the background (between the two): nothing changes.
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, expectedPixel(1, 0, 0, w, h).toPoint());
  QCOMPARE(modeller.activeObject(), 1);
  // Back on the small one: edited again, with its samples as they were.
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier,
                    expectedPixel(2, 0, 0.5, w, h).toPoint());
  QCOMPARE(modeller.activeObject(), 0);
  QVERIFY(bitEqual(positionsOf(*window_), small));
  // An Alt+drag still orbits, and selects nothing.
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const QPoint from = expectedPixel(0, 0.5, 0.25, w, h).toPoint();
  QTest::mousePress(view, Qt::LeftButton, Qt::AltModifier, from);
  for (int k = 1; k <= 5; ++k)
    QTest::mouseMove(view, from + QPoint(8 * k, 0));
  QTest::mouseRelease(view, Qt::LeftButton, Qt::AltModifier, from + QPoint(40, 0));
  QCOMPARE(modeller.activeObject(), 0);
  QVERIFY2(std::abs(camera->GetPosition()[0] - kEyeX) > 0.5,
           qPrintable(QString::number(camera->GetPosition()[0])));
}

QTEST_MAIN(SceneObjectsRenderTest)
#include "scene_objects_render_test.moc"
