// The Objects menu's commands (issue 33, items 3 and 7) with the keys a user types, as real X
// key and mouse events (XTEST): Shift+D duplicates the edited object bit for bit, Mirror
// Duplicate mirrors it exactly, H / Shift+H / Alt+H hide and show, the keypad's "." frames the
// edited object, Merge unites touching objects (and refuses apart ones, and Cancel changes
// nothing), and a row dragged in the Objects dock reorders the scene. Drawn through the real VTK
// viewport (xcb under Xvfb, llvmpipe).
#include "background_task.h"
#include "main_window.h"
#include "modeller.h"
#include "object_merge.h"
#include "objects_panel.h"
#include "scene_step.h"
#include "test_window.h"
#include "viewport_widget.h"
#include "x_input.h" // last: X11's macros are undefined at its end

#include "octaclay/core/document/document_mirror.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QGuiApplication>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QScreen>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QToolButton>
#include <QTreeWidget>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

using namespace octaclay;
using app::MainWindow;
using app::ObjectsPanel;
using app::testing::FakeInput;

namespace {

bool samePositions(const core::Document& a, const core::Document& b) {
  const auto x = a.positions.texels(), y = b.positions.texels();
  return a.positions.width() == b.positions.width() &&
         a.positions.height() == b.positions.height() && x.size() == y.size() &&
         std::memcmp(x.data(), y.data(), x.size_bytes()) == 0;
}

core::Document shape(core::BaseShape s, int n) {
  return core::makeDocument(core::makeBaseShape(s, n));
}

// Body (a blob, off the origin, turned and stretched: a transform whose mirror changes three
// signs), Box at x = 3 and Lump at x = -3, halved; N = 64.
core::Scene threeObjects() {
  core::Scene scene = core::sceneOf(shape(core::BaseShape::Blob, 64), "Body");
  scene.objects[0].transform = {{0.5f, 0.25f, -0.125f}, {10.0f, 20.0f, 30.0f}, {1.0f, 0.75f, 0.5f}};
  scene.objects.push_back({"Box",
                           shape(core::BaseShape::Cube, 64),
                           {{3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Lump",
                           shape(core::BaseShape::Sphere, 64),
                           {{-3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  return scene;
}

// Two unit balls that overlap (centres 1.5 apart) and one far from both, N = n.
core::Scene ballsScene(int n) {
  core::Scene scene = core::sceneOf(shape(core::BaseShape::Sphere, n), "Left");
  scene.objects[0].transform.translation = {-0.75f, 0.0f, 0.0f};
  scene.objects.push_back({"Right",
                           shape(core::BaseShape::Sphere, n),
                           {{0.75f, 0.0f, 0.0f}, {}, {1, 1, 1}},
                           true,
                           false});
  scene.objects.push_back(
      {"Far", shape(core::BaseShape::Sphere, n), {{8.0f, 0.0f, 0.0f}, {}, {1, 1, 1}}, true, false});
  return scene;
}

// Eight balls of radius 0.5 on a circle of radius 1 about the z axis, each overlapping the next
// by 0.23: a ring, whose union has genus 1, N = 64.
core::Scene ringOfBalls() {
  core::Scene scene;
  for (int k = 0; k < 8; ++k) {
    const float a = float(k) * float(M_PI) / 4;
    scene.objects.push_back({k == 0 ? std::string("Bead") : "Bead." + std::to_string(k),
                             shape(core::BaseShape::Sphere, 64),
                             {{std::cos(a), std::sin(a), 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                             true,
                             false});
  }
  return scene;
}

QStringList rowNames(const QTreeWidget& list) {
  QStringList names;
  for (int k = 0; k < list.topLevelItemCount(); ++k)
    names << list.topLevelItem(k)->text(ObjectsPanel::Name);
  return names;
}

QStringList objectNames(const app::Modeller& modeller) {
  QStringList names;
  for (int k = 0; k < modeller.objectCount(); ++k)
    names << QString::fromStdString(modeller.objectAt(k).name);
  return names;
}

bool isBackground(const QImage& image, QPoint p) {
  const QRgb background = image.pixel(0, 0), c = image.pixel(p);
  return std::max({std::abs(qRed(c) - qRed(background)), std::abs(qGreen(c) - qGreen(background)),
                   std::abs(qBlue(c) - qBlue(background))}) <= 8;
}

// From (0, 0, 20) towards -z, +y up, 30° vertically: all three objects in view.
void lookFromFront(app::ViewportWidget& view, double distance = 20) {
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  camera->SetParallelProjection(false);
  camera->SetPosition(0, 0, distance);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  view.renderer()->ResetCameraClippingRange();
  view.update();
}

// Where world point (x, y, 0) appears through lookFromFront's camera (widget pixels).
QPoint frontPixel(const app::ViewportWidget& view, double x, double y) {
  const double half = 20 * std::tan(15 * M_PI / 180);
  const double aspect = double(view.width()) / view.height();
  return QPoint(qRound((x / (half * aspect) * 0.5 + 0.5) * view.width()),
                qRound((0.5 - y / half * 0.5) * view.height()));
}

} // namespace

class ObjectsCommandsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void shiftDDuplicatesTheEditedObjectBitForBit();
  void mirrorDuplicateIsExactOnEveryAxis();
  void hKeysHideAndShowWhatIsDrawnAndPicked();
  void keypadPeriodFramesTheEditedObject();
  void mergeUnitesTouchingBallsAndRefusesApartOnes();
  void mergeRefusesARingNamingItsGenus();
  void cancelledMergeChangesNothing();
  void draggingARowReordersTheScene();

private:
  // Opens scene in a new test window, active, with the Objects dock raised and the pointer over
  // the viewport; null on failure.
  app::ViewportWidget* open(const core::Scene& scene, const QString& name, FakeInput& input);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void ObjectsCommandsRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("objects_commands_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QCOMPARE(QGuiApplication::platformName(), QString("xcb"));
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
}

// The window goes, and the real pointer is parked in the screen's far corner, off every window
// the next test opens.
void ObjectsCommandsRenderTest::cleanup() {
  window_.reset();
  FakeInput input;
  if (input.ready()) input.moveTo(QGuiApplication::primaryScreen()->geometry().bottomRight());
}

app::ViewportWidget* ObjectsCommandsRenderTest::open(const core::Scene& scene, const QString& name,
                                                     FakeInput& input) {
  const QString path = dir_.filePath(name);
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (!window_ || !window_->openDocument(path)) return nullptr;
  window_->findChild<QDockWidget*>("ObjectsDock")->raise(); // a tab behind Layers at first
  QCoreApplication::processEvents();
  app::ViewportWidget* view = window_->viewport();
  if (!app::testing::activate(*window_)) return nullptr;
  view->setFocus();
  input.moveTo(view->mapToGlobal(QPoint(view->width() / 2, view->height() / 2)));
  return view;
}

void ObjectsCommandsRenderTest::shiftDDuplicatesTheEditedObjectBitForBit() {
  FakeInput input;
  app::ViewportWidget* view = open(threeObjects(), "dup.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  // Sculpted first: the copy is the document as edited, not as opened.
  const core::Document opened = modeller.document();
  QVERIFY(window_->brushState()->selectBrush("push"));
  window_->brushState()->setRadius(0.1f);
  const QPointF centre = view->project({0, 0, 0});
  view->beginStrokeAt(centre - QPointF(20, 0));
  for (int k = 1; k <= 8; ++k)
    view->continueStrokeTo(centre + QPointF(5 * k - 20, 2 * k));
  view->endStroke();
  QVERIFY(QTest::qWaitFor([&] { return !view->stroking() && modeller.canUndo(); }, 20000));
  QVERIFY(!samePositions(modeller.document(), opened));
  const core::Document edited = modeller.document();
  const core::ObjectTransform placed = modeller.objectAt(0).transform;

  input.press({XK_Shift_L, XK_d});
  QVERIFY2(QTest::qWaitFor([&] { return modeller.objectCount() == 4; }, 3000),
           qPrintable(objectNames(modeller).join(", ")));
  QCOMPARE(modeller.activeObject(), 3);
  QCOMPARE(modeller.objectAt(3).name, std::string("Body.001"));
  QVERIFY(samePositions(modeller.document(), edited));
  QVERIFY(modeller.objectAt(3).transform == placed);
  QVERIFY(modeller.objectAt(3).visible && !modeller.objectAt(3).locked);
  // The original kept its sculpted document.
  QVERIFY(samePositions(modeller.scene().objects[0].document, edited));

  // Again, from the copy: the next free name.
  input.press({XK_Shift_L, XK_d});
  QVERIFY(QTest::qWaitFor([&] { return modeller.objectCount() == 5; }, 3000));
  QCOMPARE(modeller.objectAt(4).name, std::string("Body.002"));
  QVERIFY(samePositions(modeller.document(), edited));
  QCOMPARE(rowNames(*window_->objectsPanel()->list()),
           QStringList({"Body", "Box", "Lump", "Body.001", "Body.002"}));
  QVERIFY(window_->isModified());
  const QString saved = dir_.filePath("dup-saved.exr");
  QVERIFY(window_->saveDocument(saved));
  const core::Scene back = core::readScene(saved.toStdString());
  QCOMPARE(back.objects.size(), std::size_t(5));
  QVERIFY(samePositions(back.objects[3].document, edited));
  QVERIFY(back.objects[4].transform == placed);
}

void ObjectsCommandsRenderTest::mirrorDuplicateIsExactOnEveryAxis() {
  FakeInput input;
  app::ViewportWidget* view = open(threeObjects(), "mirror.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  const core::Document body = modeller.document();
  const core::ObjectTransform placed = modeller.objectAt(0).transform;
  const char* names[] = {"actionMirrorDuplicateX", "actionMirrorDuplicateY",
                         "actionMirrorDuplicateZ"};
  for (int axis = 0; axis < 3; ++axis) {
    QVERIFY(modeller.setActiveObject(0));
    QAction* mirror = window_->action(names[axis]);
    QVERIFY(mirror && mirror->isEnabled());
    const int count = modeller.objectCount();
    mirror->trigger();
    QCOMPARE(modeller.objectCount(), count + 1);
    QCOMPARE(modeller.activeObject(), count);
    QVERIFY(samePositions(modeller.document(), core::mirrorDocument(body, axis)));
    const core::ObjectTransform& t = modeller.objectAt(count).transform;
    QVERIFY(t == core::mirroredTransform(placed, axis));
    // By hand: the axis's translation and the other two angles change sign, nothing else.
    for (int c = 0; c < 3; ++c) {
      const float sign = c == axis ? -1.0f : 1.0f;
      QCOMPARE((&t.translation.x)[c], sign * (&placed.translation.x)[c]);
      QCOMPARE((&t.rotationDegrees.x)[c], -sign * (&placed.rotationDegrees.x)[c]);
      QCOMPARE((&t.scale.x)[c], (&placed.scale.x)[c]);
    }
    // The mirror of a world point of the body is a world point of the copy, exactly mirrored.
    const core::Vec3f p = body.positions.at(5, 17).xyz();
    const core::Vec3f world = core::applyTransform(placed, p);
    core::Vec3f q = p;
    (&q.x)[axis] = -(&q.x)[axis];
    const core::Vec3f mirrored = core::applyTransform(t, q);
    for (int c = 0; c < 3; ++c)
      QVERIFY2(std::abs((&mirrored.x)[c] - (c == axis ? -1.0f : 1.0f) * (&world.x)[c]) < 1e-5f,
               qPrintable(QString("axis %1, component %2").arg(axis).arg(c)));
  }
  QCOMPARE(objectNames(modeller),
           QStringList({"Body", "Box", "Lump", "Body.001", "Body.002", "Body.003"}));
  // The tool bar's Mirror X button does the same, and says what it does.
  auto* button = window_->findChild<QToolButton*>("mirrorDuplicateButton");
  QVERIFY(button && button->isVisible());
  QCOMPARE(button->text(), QString("Mirror X"));
  QVERIFY(modeller.setActiveObject(0));
  button->click();
  QCOMPARE(modeller.objectCount(), 7);
  QVERIFY(samePositions(modeller.document(), core::mirrorDocument(body, 0)));
  QCOMPARE(button->text(), QString("Mirror X"));
}

void ObjectsCommandsRenderTest::hKeysHideAndShowWhatIsDrawnAndPicked() {
  FakeInput input;
  app::ViewportWidget* view = open(threeObjects(), "hide.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  QVERIFY(modeller.setActiveObject(1)); // Box, at x = 3
  lookFromFront(*view);
  input.moveTo(view->mapToGlobal(QPoint(view->width() / 2, 5))); // no brush ring on the objects
  const QPoint body = frontPixel(*view, 0.5, 0.25), box = frontPixel(*view, 3, 0),
               lump = frontPixel(*view, -3, 0);
  const auto drawn = [&] {
    const QImage image = view->grabFramebuffer();
    const double ratio = double(image.width()) / view->width();
    return std::array<bool, 3>{!isBackground(image, body * ratio),
                               !isBackground(image, box * ratio),
                               !isBackground(image, lump * ratio)};
  };
  QVERIFY(drawn() == (std::array<bool, 3>{true, true, true}));

  input.press({XK_h}); // H: the edited Box goes
  QVERIFY(QTest::qWaitFor([&] { return !modeller.objectAt(1).visible; }, 3000));
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY(drawn() == (std::array<bool, 3>{true, false, true}));
  QVERIFY(modeller.objectAt(0).visible && modeller.objectAt(2).visible);
  // Not picked: Alt+click where it was, with Body edited, leaves Body edited.
  QVERIFY(modeller.setActiveObject(0));
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, box);
  QCOMPARE(modeller.activeObject(), 0);

  input.press({XK_Alt_L, XK_h}); // Alt+H: every object back
  QVERIFY(QTest::qWaitFor([&] { return modeller.objectAt(1).visible; }, 3000));
  QVERIFY(drawn() == (std::array<bool, 3>{true, true, true}));
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, box);
  QCOMPARE(modeller.activeObject(), 1);

  input.press({XK_Shift_L, XK_h}); // Shift+H: all but the edited Box go
  QVERIFY(QTest::qWaitFor([&] { return !modeller.objectAt(0).visible; }, 3000));
  QVERIFY(!modeller.objectAt(2).visible && modeller.objectAt(1).visible);
  QVERIFY(drawn() == (std::array<bool, 3>{false, true, false}));
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, lump);
  QCOMPARE(modeller.activeObject(), 1);
  // The dock's eyes follow.
  QTreeWidget* list = window_->objectsPanel()->list();
  QCOMPARE(list->topLevelItem(0)->checkState(ObjectsPanel::Visible), Qt::Unchecked);
  QCOMPARE(list->topLevelItem(1)->checkState(ObjectsPanel::Visible), Qt::Checked);

  const std::size_t steps = modeller.history().undoCount();
  input.press({XK_Alt_L, XK_h});
  QVERIFY(QTest::qWaitFor(
      [&] { return modeller.objectAt(0).visible && modeller.objectAt(2).visible; }, 3000));
  QVERIFY(drawn() == (std::array<bool, 3>{true, true, true}));
  // Show All was one step, as Hide Others was: one undo hides both again.
  QCOMPARE(modeller.history().undoCount(), steps + 1);
  const app::SceneHistory::Entry* shown = modeller.history().nextUndoEntry();
  QVERIFY(shown && shown->scene);
  QCOMPARE(shown->scene->label, std::string("Show All"));
  QCOMPARE(shown->scene->changes.size(), std::size_t{2});
  QVERIFY(modeller.undoStroke());
  QVERIFY(!modeller.objectAt(0).visible && !modeller.objectAt(2).visible);
  QVERIFY(modeller.objectAt(1).visible);
  const app::SceneHistory::Entry* hidden = modeller.history().nextUndoEntry();
  QVERIFY(hidden && hidden->scene);
  QCOMPARE(hidden->scene->label, std::string("Hide Others"));
  QVERIFY(modeller.redoStroke());
  QVERIFY(modeller.objectAt(0).visible && modeller.objectAt(2).visible);
  // Alt+H was taken by the viewport, not by the Help menu's mnemonic.
  QVERIFY(!QApplication::activePopupWidget());
}

void ObjectsCommandsRenderTest::keypadPeriodFramesTheEditedObject() {
  FakeInput input;
  app::ViewportWidget* view = open(threeObjects(), "frame.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  QVERIFY(modeller.setActiveObject(1)); // Box: x = 3, a side of 1 in the world
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const bool numLockWas = input.numLock();
  for (const bool numLock : {true, false}) {
    QVERIFY2(input.setNumLock(numLock), numLock ? "NumLock stays off" : "NumLock stays on");
    lookFromFront(*view, 40); // the box small, right of the centre
    const auto boxOnScreen = [&] {
      // The local box's eight corners as they appear.
      const core::BoundingBox local = core::boundingBox(modeller.document().positions);
      double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
      for (int c = 0; c < 8; ++c) {
        const QPointF p =
            view->project({c & 1 ? local.max.x : local.min.x, c & 2 ? local.max.y : local.min.y,
                           c & 4 ? local.max.z : local.min.z});
        x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
      }
      return QRectF(QPointF(x0, y0), QPointF(x1, y1));
    };
    const QRectF before = boxOnScreen();
    QVERIFY2(before.height() < 0.15 * view->height(), qPrintable(QString::number(before.height())));
    const int count = modeller.objectCount();
    input.press({XK_KP_Decimal});
    const QString what = numLock ? "keypad ., NumLock on" : "keypad Delete, NumLock off";
    QVERIFY2(
        QTest::qWaitFor([&] { return boxOnScreen().height() > 0.4 * view->height(); }, 2000),
        qPrintable(
            what +
            QString(": box %1 px high of %2").arg(boxOnScreen().height()).arg(view->height())));
    const QRectF after = boxOnScreen();
    // Centred, whole, and seen from where the camera looked (towards -z).
    QVERIFY2(
        std::abs(after.center().x() - view->width() / 2.0) < 0.02 * view->width() &&
            std::abs(after.center().y() - view->height() / 2.0) < 0.02 * view->height(),
        qPrintable(what +
                   QString(": centre (%1, %2)").arg(after.center().x()).arg(after.center().y())));
    QVERIFY(after.top() >= 0 && after.bottom() <= view->height());
    const double* f = camera->GetFocalPoint();
    QVERIFY(std::abs(f[0] - 3) < 1e-3 && std::abs(f[1]) < 1e-3 && std::abs(f[2]) < 1e-3);
    QVERIFY(camera->GetPosition()[2] > 0.5 && std::abs(camera->GetPosition()[0] - 3) < 1e-3);
    // KP_Delete is not the Delete key: the object stays.
    QCOMPARE(modeller.objectCount(), count);
  }
  input.setNumLock(numLockWas);
  // Also in View, named by its key.
  QAction* frame = window_->action("actionFrameSelected");
  QVERIFY(frame);
  QVERIFY(frame->shortcut().toString().contains("."));
}

void ObjectsCommandsRenderTest::mergeUnitesTouchingBallsAndRefusesApartOnes() {
  FakeInput input;
  app::ViewportWidget* view = open(ballsScene(64), "merge.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  QTreeWidget* list = window_->objectsPanel()->list();
  QAction* merge = window_->action("actionMergeObjects");
  QVERIFY(merge && merge->isEnabled());

  // Left and Far selected with a click and a Ctrl+click: they do not touch.
  const core::Scene before = modeller.scene();
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                    list->visualItemRect(list->topLevelItem(0)).center());
  QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::ControlModifier,
                    list->visualItemRect(list->topLevelItem(2)).center());
  QCOMPARE(window_->objectsPanel()->selectedObjects(), std::vector<int>({0, 2}));
  merge->trigger();
  auto* merger = window_->findChild<app::ObjectMerge*>("objectMerge");
  QVERIFY(merger);
  QVERIFY2(merger->lastRefusal().contains("do not touch"), qPrintable(merger->lastRefusal()));
  QVERIFY2(window_->statusBar()->currentMessage().contains("do not touch"),
           qPrintable(window_->statusBar()->currentMessage()));
  auto* box = window_->findChild<QMessageBox*>("mergeRefusal");
  QVERIFY(box && box->text().contains("do not touch"));
  box->close();
  // Nothing changed.
  const core::Scene after = modeller.scene();
  QCOMPARE(after.objects.size(), before.objects.size());
  for (std::size_t k = 0; k < after.objects.size(); ++k) {
    QCOMPARE(after.objects[k].name, before.objects[k].name);
    QVERIFY(samePositions(after.objects[k].document, before.objects[k].document));
    QVERIFY(after.objects[k].transform == before.objects[k].transform);
  }

  // Left and Right overlap: one object in their place, edited, their union.
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {},
                    list->visualItemRect(list->topLevelItem(0)).center());
  QTest::mouseClick(list->viewport(), Qt::LeftButton, Qt::ControlModifier,
                    list->visualItemRect(list->topLevelItem(1)).center());
  QCOMPARE(window_->objectsPanel()->selectedObjects(), std::vector<int>({0, 1}));
  merge->trigger();
  QVERIFY2(merger->lastRefusal().isEmpty(), qPrintable(merger->lastRefusal()));
  QCOMPARE(modeller.objectCount(), 2);
  QCOMPARE(modeller.objectAt(0).name, std::string("Far"));
  QCOMPARE(modeller.activeObject(), 1);
  QCOMPARE(modeller.objectAt(1).name, std::string("Left")); // the merged part keeps its name
  QVERIFY(modeller.objectAt(1).transform == core::ObjectTransform{});
  QCOMPARE(modeller.document().size(), 64);
  // The union of balls of radius 1 at x = ±0.75: x in [-1.75, 1.75], y and z in [-1, 1],
  // within a voxel of the level set (√(A / 64²) ≈ 0.07 here).
  const core::BoundingBox b = core::boundingBox(modeller.document().positions);
  const auto near = [](float a, float e) { return std::abs(a - e) < 0.1f; };
  QVERIFY2(near(b.min.x, -1.75f) && near(b.max.x, 1.75f) && near(b.min.y, -1) && near(b.max.y, 1) &&
               near(b.min.z, -1) && near(b.max.z, 1),
           qPrintable(QString("x %1 … %2, y %3 … %4, z %5 … %6")
                          .arg(b.min.x)
                          .arg(b.max.x)
                          .arg(b.min.y)
                          .arg(b.max.y)
                          .arg(b.min.z)
                          .arg(b.max.z)));
  // No sample inside either ball: the surface is the union's.
  for (const core::Vec4f& p : modeller.document().positions.texels()) {
    const float dl = core::length(p.xyz() - core::Vec3f{-0.75f, 0, 0}),
                dr = core::length(p.xyz() - core::Vec3f{0.75f, 0, 0});
    QVERIFY2(std::max(dl, dr) > 0.9f,
             qPrintable(QString("(%1, %2, %3) inside").arg(p.x).arg(p.y).arg(p.z)));
  }
  QCOMPARE(rowNames(*list), objectNames(modeller));
  QVERIFY(window_->isModified());
  QVERIFY(window_->statusBar()->currentMessage().startsWith("Merged 2 objects"));
}

void ObjectsCommandsRenderTest::mergeRefusesARingNamingItsGenus() {
  FakeInput input;
  app::ViewportWidget* view = open(ringOfBalls(), "ring.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  const core::Scene before = modeller.scene();
  // One row selected (the edited one): Merge takes every shown object, the whole ring.
  window_->action("actionMergeObjects")->trigger();
  auto* merger = window_->findChild<app::ObjectMerge*>("objectMerge");
  QVERIFY(merger);
  QVERIFY2(merger->lastRefusal().contains("genus 1"), qPrintable(merger->lastRefusal()));
  auto* box = window_->findChild<QMessageBox*>("mergeRefusal");
  QVERIFY(box && box->text().contains("genus 1"));
  QCOMPARE(modeller.objectCount(), 8);
  for (int k = 0; k < 8; ++k) {
    const core::Document& document =
        k == modeller.activeObject() ? modeller.document() : modeller.objectAt(k).document;
    QVERIFY(samePositions(document, before.objects[std::size_t(k)].document));
    QCOMPARE(modeller.objectAt(k).name, before.objects[std::size_t(k)].name);
  }
  QVERIFY(!window_->isModified());
}

void ObjectsCommandsRenderTest::cancelledMergeChangesNothing() {
  FakeInput input;
  app::ViewportWidget* view = open(ballsScene(128), "cancel.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  auto* merger = window_->findChild<app::ObjectMerge*>("objectMerge");
  QVERIFY(merger);
  const core::Scene before = modeller.scene();
  const auto unchanged = [&] {
    const core::Scene now = modeller.scene();
    if (now.objects.size() != before.objects.size() || modeller.activeObject() != 0) return false;
    for (std::size_t k = 0; k < now.objects.size(); ++k)
      if (now.objects[k].name != before.objects[k].name ||
          !samePositions(now.objects[k].document, before.objects[k].document))
        return false;
    return true;
  };

  // The progress dialog's Cancel, clicked once it shows: the merge stops, nothing changes.
  bool clicked = false;
  QTimer watch;
  QObject::connect(&watch, &QTimer::timeout, [&] {
    for (auto* dialog : window_->findChildren<QProgressDialog*>())
      if (dialog->isVisible() && !clicked)
        if (auto* cancel = dialog->findChild<QPushButton*>()) {
          cancel->click();
          clicked = true;
        }
  });
  watch.start(20);
  QVERIFY(!merger->merge({0, 1}));
  watch.stop();
  QVERIFY2(clicked, "the merge ended before its progress dialog showed");
  QVERIFY2(window_->statusBar()->currentMessage().contains("cancelled"),
           qPrintable(window_->statusBar()->currentMessage()));
  QVERIFY(unchanged());
  QVERIFY(!window_->isModified());

  // Cancelled from the start (a control already cancelled): the same.
  auto control = std::make_shared<app::TaskControl>();
  control->cancel = true;
  QVERIFY(!merger->merge({0, 1}, control));
  QVERIFY(unchanged());

  // With one row selected (the edited one), Merge takes every visible object: Far hidden, Left
  // and Right.
  QCOMPARE(window_->objectsPanel()->selectedObjects(), std::vector<int>({0}));
  QVERIFY(modeller.setObjectVisible(2, false));
  QCOMPARE(merger->chosenObjects(window_->objectsPanel()->selectedObjects()),
           std::vector<int>({0, 1}));
  QVERIFY(modeller.setObjectVisible(2, true));
  QCOMPARE(merger->chosenObjects({1}), std::vector<int>({0, 1, 2}));
  QCOMPARE(merger->chosenObjects({0, 2}), std::vector<int>({0, 2}));
  // A ground plane shown under them is not taken (a sheet encloses nothing); chosen by name
  // with another, the merge refuses it, naming it, and nothing changes.
  QVERIFY(modeller.addObject({"Ground",
                              core::makeDocument(core::makeSheet(core::Sheet::Square, 16)),
                              {{0, -1, 0}, {}, {3, 3, 3}},
                              true,
                              false}));
  QCOMPARE(modeller.objectCount(), 4);
  QCOMPARE(merger->chosenObjects({1}), std::vector<int>({0, 1, 2}));
  const auto objectsBefore = modeller.objectCount();
  QVERIFY(!merger->merge({0, 3}));
  QVERIFY2(merger->lastRefusal().contains("'Ground' is a plane"),
           qPrintable(merger->lastRefusal()));
  QCOMPARE(modeller.objectCount(), objectsBefore);
}

void ObjectsCommandsRenderTest::draggingARowReordersTheScene() {
  FakeInput input;
  app::ViewportWidget* view = open(threeObjects(), "drag.exr", input);
  QVERIFY(view);
  app::Modeller& modeller = *window_->modeller();
  QTreeWidget* list = window_->objectsPanel()->list();
  const core::Document box = modeller.scene().objects[1].document;

  // Body's row dragged with the real mouse below Lump's: last.
  const QPoint from =
      list->viewport()->mapToGlobal(list->visualItemRect(list->topLevelItem(0)).center());
  const QRect lumpRow = list->visualItemRect(list->topLevelItem(2));
  const QPoint to = list->viewport()->mapToGlobal(
      QPoint(lumpRow.center().x(), lumpRow.bottom() + lumpRow.height()));
  QVERIFY(app::testing::dragWithEventsRunning(from, to));
  QVERIFY2(QTest::qWaitFor([&] { return objectNames(modeller).front() == "Box"; }, 3000),
           qPrintable(objectNames(modeller).join(", ")));
  QCOMPARE(objectNames(modeller), QStringList({"Box", "Lump", "Body"}));
  QCOMPARE(rowNames(*list), objectNames(modeller));
  // The row pressed is the edited one, where it now is.
  QCOMPARE(modeller.activeObject(), 2);
  QCOMPARE(list->currentItem(), list->topLevelItem(2));
  QVERIFY(samePositions(modeller.scene().objects[0].document, box));

  // Lump's row dropped on Box's upper half goes first.
  const QPoint lump =
      list->viewport()->mapToGlobal(list->visualItemRect(list->topLevelItem(1)).center());
  const QRect boxRow = list->visualItemRect(list->topLevelItem(0));
  const QPoint top = list->viewport()->mapToGlobal(QPoint(boxRow.center().x(), boxRow.top() + 2));
  QVERIFY(app::testing::dragWithEventsRunning(lump, top));
  QVERIFY2(QTest::qWaitFor([&] { return objectNames(modeller).front() == "Lump"; }, 3000),
           qPrintable(objectNames(modeller).join(", ")));
  QCOMPARE(objectNames(modeller), QStringList({"Lump", "Box", "Body"}));
  // Pressing Lump's row edited it; it is still the edited one at its new place.
  QCOMPARE(QString::fromStdString(modeller.objectAt(modeller.activeObject()).name),
           QString("Lump"));
  // A move the dock asks for while another object is edited keeps that one edited.
  QVERIFY(modeller.setActiveObject(2)); // Body
  emit static_cast<app::ObjectList*>(list)->moveRequested(2, 1);
  QCOMPARE(objectNames(modeller), QStringList({"Lump", "Body", "Box"}));
  QCOMPARE(modeller.activeObject(), 1);
  QCOMPARE(list->currentItem(), list->topLevelItem(1));
  emit static_cast<app::ObjectList*>(list)->moveRequested(0, 2);
  QCOMPARE(objectNames(modeller), QStringList({"Body", "Box", "Lump"}));
  QCOMPARE(modeller.activeObject(), 0);
  QVERIFY(window_->isModified());
  const QString saved = dir_.filePath("drag-saved.exr");
  QVERIFY(window_->saveDocument(saved));
  QCOMPARE(core::readScene(saved.toStdString()).names(),
           std::vector<std::string>({"Body", "Box", "Lump"}));
}

QTEST_MAIN(ObjectsCommandsRenderTest)
#include "objects_commands_render_test.moc"
