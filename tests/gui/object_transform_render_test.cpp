// Moving, rotating and scaling objects on the canvas (issue 33, item 3) under real X input
// (XTEST): G / R / S with X / Y / Z and typed numbers kept exactly by Enter, the pointer
// followed, Esc and a right click putting the object back bit for bit, a locked object refused,
// the move gizmo's arrows on screen by their pixels and a drag on one moving along that axis
// alone. Drawn through the real VTK viewport (xcb under Xvfb, llvmpipe).
#include "camera_control.h"
#include "main_window.h"
#include "modeller.h"
#include "object_transform_mode.h"
#include "test_window.h"
#include "transform_gizmo.h"
#include "viewport_widget.h"
#include "x_input.h"

#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QAction>
#include <QGuiApplication>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <numbers>

using namespace octaclay;
using app::MainWindow;
using app::ObjectTransformMode;
using XTestInput = app::testing::FakeInput;

namespace {

core::Document ball() {
  return core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64));
}

// Body (a unit sphere at the origin, edited), Left (a half-size cube at x = -2.5) and Right (a
// half-size sphere at x = 2.5, off the axis a little in y and z so no value is a round one).
core::Scene threeObjects() {
  core::Scene scene = core::sceneOf(ball(), "Body");
  scene.objects.push_back({"Left",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 64)),
                           {{-2.5f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Right",
                           ball(),
                           {{2.5f, 0.125f, -0.25f}, {0.0f, 0.0f, 10.0f}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  return scene;
}

bool bitSame(const core::ObjectTransform& a, const core::ObjectTransform& b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

QString describe(const core::ObjectTransform& t) {
  return QString("t (%1, %2, %3) r (%4, %5, %6) s (%7, %8, %9)")
      .arg(double(t.translation.x), 0, 'g', 9)
      .arg(double(t.translation.y), 0, 'g', 9)
      .arg(double(t.translation.z), 0, 'g', 9)
      .arg(double(t.rotationDegrees.x), 0, 'g', 9)
      .arg(double(t.rotationDegrees.y), 0, 'g', 9)
      .arg(double(t.rotationDegrees.z), 0, 'g', 9)
      .arg(double(t.scale.x), 0, 'g', 9)
      .arg(double(t.scale.y), 0, 'g', 9)
      .arg(double(t.scale.z), 0, 'g', 9);
}

// Where world point p shows in the viewport (its pixels).
QPointF onView(app::ViewportWidget& view, core::Vec3f p) {
  return app::projectToView(*view.renderer()->GetActiveCamera(), view.modelRect(), p);
}

/// The viewport as the X server shows it (the root window's pixels, whatever draws them).
QImage onScreen(QWidget* view) {
  const QPoint at = view->mapToGlobal(QPoint(0, 0));
  return QGuiApplication::primaryScreen()
      ->grabWindow(0, at.x(), at.y(), view->width(), view->height())
      .toImage()
      .convertToFormat(QImage::Format_RGB32);
}

} // namespace

class ObjectTransformRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void typedAmountsAreKeptExactlyOnAnObjectPickedWithAltClick();
  void moveFollowsThePointerAndAClickKeepsIt();
  void rotateAndScaleFollowThePointer();
  void escAndRightClickPutTheObjectBackBitForBit();
  void lockedObjectIsRefusedWithAMessage();
  void brushKeysComeBackWhenABrushIsPicked();
  void aStrokeAfterAMoveSculptsTheObjectWhereItNowIs();
  void gizmoArrowsAreOnScreenAndADragMovesAlongOneAxis();

private:
  // The window with threeObjects(), the pointer over the viewport, the window active.
  bool openScene(XTestInput& input);
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void ObjectTransformRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("object_transform_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QSettings().clear();
}

// The real pointer parked in the screen's far corner, off every window the next test opens.
void ObjectTransformRenderTest::cleanup() {
  window_.reset();
  XTestInput input;
  if (input.ready()) input.moveTo(QGuiApplication::primaryScreen()->geometry().bottomRight());
}

bool ObjectTransformRenderTest::openScene(XTestInput& input) {
  if (QGuiApplication::platformName() != QString("xcb") || !input.ready()) return false;
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (!window_ || !window_->modeller()->setScene(threeObjects())) return false;
  app::ViewportWidget* view = window_->viewport();
  if (!app::testing::activate(*window_)) return false;
  view->setFocus();
  input.moveTo(view->mapToGlobal(QPoint(view->width() / 2, view->height() / 3)));
  return QTest::qWaitFor([&] { return view->glReady(); }, 5000);
}

void ObjectTransformRenderTest::typedAmountsAreKeptExactlyOnAnObjectPickedWithAltClick() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(mode);
  // Alt+click on Right (not the first object) makes it the edited one.
  const core::ObjectTransform right = modeller.objectAt(2).transform;
  input.moveTo(view->mapToGlobal(onView(*view, right.translation).toPoint()));
  input.key(XK_Alt_L, true);
  input.click(1);
  input.key(XK_Alt_L, false);
  QVERIFY(QTest::qWaitFor([&] { return modeller.activeObject() == 2; }, 3000));
  window_->action("actionObjectMode")->setChecked(true);

  // G X 0.5 Enter: exactly +0.5 in x, nothing else, one door call.
  QSignalSpy placed(&modeller, &app::Modeller::objectsChanged);
  input.press({XK_g});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::Move; }, 2000));
  input.press({XK_x});
  input.type("0.5");
  QVERIFY2(window_->statusBar()->currentMessage().startsWith("Move X: 0.5"),
           qPrintable(window_->statusBar()->currentMessage()));
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  core::ObjectTransform expected = right;
  expected.translation.x = right.translation.x + 0.5f;
  QVERIFY2(bitSame(modeller.objectAt(2).transform, expected),
           qPrintable(describe(modeller.objectAt(2).transform)));
  QCOMPARE(placed.count(), 1);
  QCOMPARE(modeller.objectAt(0).transform, core::ObjectTransform{});

  // R Z 90 Enter: 90 degrees more about Z. Then S 2 Enter: twice the size.
  input.press({XK_r});
  input.press({XK_z});
  input.type("90");
  QVERIFY2(window_->statusBar()->currentMessage().startsWith("Rotate Z: 90"),
           qPrintable(window_->statusBar()->currentMessage()));
  input.press({XK_Return});
  expected.rotationDegrees.z = right.rotationDegrees.z + 90.0f;
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  QVERIFY2(bitSame(modeller.objectAt(2).transform, expected),
           qPrintable(describe(modeller.objectAt(2).transform)));
  input.press({XK_s});
  input.type("2");
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  expected.scale = {1.0f, 1.0f, 1.0f};
  QVERIFY2(bitSame(modeller.objectAt(2).transform, expected),
           qPrintable(describe(modeller.objectAt(2).transform)));
  // A typed minus and Backspace: G Y -0.25, the 5 taken back: -0.2 kept.
  input.press({XK_g});
  input.press({XK_y});
  input.type("-0.25");
  input.press({XK_BackSpace});
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  expected.translation.y = float(double(expected.translation.y) + double(-0.2f));
  QVERIFY2(bitSame(modeller.objectAt(2).transform, expected),
           qPrintable(describe(modeller.objectAt(2).transform)));
  QCOMPARE(modeller.objectAt(1).transform, threeObjects().objects[1].transform);
}

void ObjectTransformRenderTest::moveFollowsThePointerAndAClickKeepsIt() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(modeller.setActiveObject(1)); // Left
  window_->action("actionObjectMode")->setChecked(true);
  const core::ObjectTransform before = modeller.objectAt(1).transform;
  const QPoint start = onView(*view, before.translation).toPoint();
  input.moveTo(view->mapToGlobal(start));
  input.press({XK_g});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::Move; }, 2000));
  // The pointer goes 120 px right and 50 down in steps: the origin's place stays under it.
  const QPoint target = start + QPoint(120, 50);
  for (int k = 1; k <= 6; ++k)
    input.moveTo(view->mapToGlobal(start + (target - start) * k / 6));
  QVERIFY(QTest::qWaitFor(
      [&] {
        const QPointF at = onView(*view, modeller.objectAt(1).transform.translation);
        return std::hypot(at.x() - target.x(), at.y() - target.y()) < 2.0;
      },
      2000));
  const core::ObjectTransform shown = modeller.objectAt(1).transform;
  // In the view's plane: the front view's depth (z) kept.
  QCOMPARE(shown.translation.z, before.translation.z);
  QVERIFY(shown.translation.x > before.translation.x && shown.translation.y < before.translation.y);
  // Other keys are the gesture's too: Delete and Ctrl+Z do nothing under the preview.
  input.press({XK_Delete});
  input.press({XK_Control_L, XK_z});
  QCOMPARE(modeller.objectCount(), 3);
  QCOMPARE(mode->kind(), ObjectTransformMode::Kind::Move);
  QVERIFY(bitSame(modeller.objectAt(1).transform, shown));
  // A left click keeps it, and its release reaches nothing else (no stroke).
  input.click(1);
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  QVERIFY(bitSame(modeller.objectAt(1).transform, shown));
  // One step, the move; undo puts the object back bit for bit.
  QVERIFY2(window_->undoStack()->undoText().startsWith("Move "),
           qPrintable(window_->undoStack()->undoText()));
  QVERIFY(!view->stroking());
  const int steps = window_->undoStack()->count();
  window_->undoStack()->undo();
  QVERIFY(!bitSame(modeller.objectAt(1).transform, shown));
  window_->undoStack()->redo();
  QVERIFY(bitSame(modeller.objectAt(1).transform, shown));
  QCOMPARE(window_->undoStack()->count(), steps);
}

void ObjectTransformRenderTest::rotateAndScaleFollowThePointer() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(modeller.setActiveObject(1)); // Left: no rotation
  window_->action("actionObjectMode")->setChecked(true);
  const core::ObjectTransform before = modeller.objectAt(1).transform;
  const QPointF c0 = onView(*view, before.translation);
  // R, then the pointer a quarter turn counter-clockwise round the origin's place on screen
  // (right of it to above it): a quarter turn about the axis toward the eye (+z from the front).
  input.moveTo(view->mapToGlobal((c0 + QPointF(80, 0)).toPoint()));
  input.press({XK_r});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::Rotate; }, 2000));
  for (int k = 1; k <= 9; ++k) {
    const double a = std::numbers::pi / 2 * k / 9;
    input.moveTo(view->mapToGlobal((c0 + QPointF(80 * std::cos(a), -80 * std::sin(a))).toPoint()));
  }
  QVERIFY2(window_->statusBar()->currentMessage().startsWith("Rotate: "),
           qPrintable(window_->statusBar()->currentMessage()));
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  const core::ObjectTransform turned = modeller.objectAt(1).transform;
  QVERIFY2(std::abs(turned.rotationDegrees.z - 90.0f) < 2.0f &&
               std::abs(turned.rotationDegrees.x) < 0.01f &&
               std::abs(turned.rotationDegrees.y) < 0.01f,
           qPrintable(describe(turned)));
  QCOMPARE(turned.translation, before.translation); // about its origin
  QCOMPARE(turned.scale, before.scale);
  // S, the pointer from 50 to 125 pixels from the origin's place: 2.5 times as large.
  input.moveTo(view->mapToGlobal((c0 + QPointF(0, 50)).toPoint()));
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::Scale; }, 2000));
  for (int k = 1; k <= 5; ++k)
    input.moveTo(view->mapToGlobal((c0 + QPointF(0, 50 + 15 * k)).toPoint()));
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  const core::ObjectTransform grown = modeller.objectAt(1).transform;
  QVERIFY2(std::abs(grown.scale.x / before.scale.x - 2.5f) < 0.08f, qPrintable(describe(grown)));
  QCOMPARE(grown.scale.y, grown.scale.x);
  QCOMPARE(grown.scale.z, grown.scale.x);
  QCOMPARE(grown.translation, before.translation);
}

void ObjectTransformRenderTest::escAndRightClickPutTheObjectBackBitForBit() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(modeller.setActiveObject(2));
  window_->action("actionObjectMode")->setChecked(true);
  const core::ObjectTransform before = modeller.objectAt(2).transform;
  const QPoint start = onView(*view, before.translation).toPoint() + QPoint(-60, -40);
  QSignalSpy placed(&modeller, &app::Modeller::objectsChanged);
  for (const KeySym key : {XK_g, XK_r, XK_s}) {
    for (const bool rightClick : {false, true}) {
      input.moveTo(view->mapToGlobal(start));
      input.press({key});
      QVERIFY(
          QTest::qWaitFor([&] { return mode->kind() != ObjectTransformMode::Kind::None; }, 2000));
      for (int k = 1; k <= 4; ++k)
        input.moveTo(view->mapToGlobal(start + QPoint(-15 * k, 25 * k)));
      QVERIFY2(!bitSame(modeller.objectAt(2).transform, before), "the preview shows no change");
      if (rightClick)
        input.click(3);
      else
        input.press({XK_Escape});
      QVERIFY(
          QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
      QVERIFY2(bitSame(modeller.objectAt(2).transform, before),
               qPrintable(describe(modeller.objectAt(2).transform)));
    }
  }
  QCOMPARE(placed.count(), 0); // nothing placed through the door
  QVERIFY(!view->stroking());
}

void ObjectTransformRenderTest::lockedObjectIsRefusedWithAMessage() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(modeller.setObjectLocked(0, true));
  window_->action("actionObjectMode")->setChecked(true);
  input.press({XK_g});
  QVERIFY(QTest::qWaitFor([&] { return window_->statusBar()->currentMessage().contains("locked"); },
                          2000));
  QCOMPARE(mode->kind(), ObjectTransformMode::Kind::None);
  QVERIFY(window_->statusBar()->currentMessage().contains("Body"));
  input.type("0.5");
  input.press({XK_Return});
  QCOMPARE(modeller.objectAt(0).transform, core::ObjectTransform{});
}

void ObjectTransformRenderTest::brushKeysComeBackWhenABrushIsPicked() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QAction* objectMode = window_->action("actionObjectMode");
  QVERIFY(window_->brushState()->selectBrush("push"));
  // Out of Object Mode S picks Smooth and starts nothing.
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor(
      [&] { return window_->brushState()->currentBrushId() == QString("smooth"); }, 2000));
  QCOMPARE(mode->kind(), ObjectTransformMode::Kind::None);
  // In it S scales (the brush stays); Esc.
  objectMode->setChecked(true);
  QVERIFY(window_->brushState()->selectBrush("push"));
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::Scale; }, 2000));
  input.press({XK_Escape});
  QCOMPARE(window_->brushState()->currentBrushId(), QString("push"));
  // A brush's key (C: Clay Strips) leaves Object Mode; S is Smooth's again.
  input.press({XK_c});
  QVERIFY(QTest::qWaitFor([&] { return !objectMode->isChecked(); }, 2000));
  QCOMPARE(window_->brushState()->currentBrushId(), QString("clay-strips"));
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor(
      [&] { return window_->brushState()->currentBrushId() == QString("smooth"); }, 2000));
  QCOMPARE(mode->kind(), ObjectTransformMode::Kind::None);
  QCOMPARE(modeller.objectAt(0).transform, core::ObjectTransform{});
}

void ObjectTransformRenderTest::aStrokeAfterAMoveSculptsTheObjectWhereItNowIs() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* mode = window_->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  window_->action("actionObjectMode")->setChecked(true);
  // Body up by 1.5: its old place at the origin is empty now.
  input.press({XK_g});
  input.press({XK_y});
  input.type("1.5");
  input.press({XK_Return});
  QVERIFY(QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000));
  QCOMPARE(modeller.objectAt(0).transform.translation.y, 1.5f);
  QVERIFY(window_->brushState()->selectBrush("push"));
  window_->brushState()->setRadius(0.05f);
  const std::vector<float> before = app::testing::positionsOf(*window_);
  // A drag across the old place touches nothing; across the new one it sculpts there.
  const auto drag = [&](core::Vec3f world) {
    const QPoint at = view->mapToGlobal(onView(*view, world).toPoint());
    input.moveTo(at - QPoint(20, 0));
    input.button(1, true);
    for (int k = 1; k <= 8; ++k)
      input.moveTo(at + QPoint(-20 + 5 * k, 0));
    input.button(1, false);
    return QTest::qWaitFor([&] { return !view->stroking(); }, 20000);
  };
  QVERIFY(drag({0, 0, 0.0f}));
  QVERIFY(app::testing::bitEqual(app::testing::positionsOf(*window_), before));
  QVERIFY(drag({0, 1.5f, 0.0f}));
  QVERIFY(QTest::qWaitFor([&] { return modeller.canUndo(); }, 5000));
  const std::vector<float> after = app::testing::positionsOf(*window_);
  QVERIFY(!app::testing::bitEqual(after, before));
  // Where it sculpted: the moved samples sit about the front pole (object space: z = 1).
  double most = 0, zOfMost = 0;
  for (std::size_t k = 0; k < after.size(); k += 4) {
    const double d = std::hypot(after[k] - before[k], after[k + 1] - before[k + 1],
                                after[k + 2] - before[k + 2]);
    if (d > most) {
      most = d;
      zOfMost = before[k + 2];
    }
  }
  QVERIFY2(zOfMost > 0.9, qPrintable(QString("most moved sample at z = %1").arg(zOfMost)));
}

void ObjectTransformRenderTest::gizmoArrowsAreOnScreenAndADragMovesAlongOneAxis() {
  XTestInput input;
  QVERIFY2(openScene(input), "no xcb window with XTEST input");
  app::Modeller& modeller = *window_->modeller();
  app::ViewportWidget* view = window_->viewport();
  auto* gizmo = window_->findChild<app::TransformGizmo*>(QStringLiteral("transformGizmo"));
  QVERIFY(gizmo);
  QVERIFY(modeller.setActiveObject(1));
  // From the front the Z arrow is seen end-on: an oblique view shows all three.
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  camera->Azimuth(35);
  camera->Elevation(25);
  camera->OrthogonalizeViewUp();
  view->frameModel();
  QVERIFY(!gizmo->arrows()); // off until Object Mode
  // Tab over the viewport turns Object Mode on, as the tool-bar toggle does.
  input.press({XK_Tab});
  QVERIFY(QTest::qWaitFor([&] { return window_->action("actionObjectMode")->isChecked(); }, 2000));
  QVERIFY(gizmo->arrows());
  input.moveTo(QGuiApplication::primaryScreen()->geometry().bottomRight());
  QTest::qWait(300);
  const QImage screen = onScreen(view);
  const auto arrows = *gizmo->arrows();
  for (int k = 0; k < 3; ++k) {
    const QPointF at = arrows[std::size_t(k)].from +
                       (arrows[std::size_t(k)].to - arrows[std::size_t(k)].from) * 0.6;
    const QColor c = screen.pixelColor(at.toPoint());
    const int own = k == 0 ? c.red() : k == 1 ? c.green() : c.blue();
    const int others = k == 0   ? std::max(c.green(), c.blue())
                       : k == 1 ? std::max(c.red(), c.blue())
                                : std::max(c.red(), c.green());
    QVERIFY2(own > 170 && others < own - 80,
             qPrintable(
                 QString("arrow %1 at (%2, %3): %4").arg(k).arg(at.x()).arg(at.y()).arg(c.name())));
  }

  // A real drag on the X arrow, 60 px along it on screen: only x changes, one step at the release.
  const core::ObjectTransform before = modeller.objectAt(1).transform;
  const QPointF from = arrows[0].from + (arrows[0].to - arrows[0].from) * 0.7;
  const QPointF along =
      (arrows[0].to - arrows[0].from) /
      std::hypot(arrows[0].to.x() - arrows[0].from.x(), arrows[0].to.y() - arrows[0].from.y());
  QSignalSpy placed(&modeller, &app::Modeller::objectsChanged);
  input.moveTo(view->mapToGlobal(from.toPoint()));
  input.button(1, true);
  for (int k = 1; k <= 6; ++k)
    input.moveTo(view->mapToGlobal((from + along * (10.0 * k) + QPointF(0, 3)).toPoint()));
  QCOMPARE(placed.count(), 0); // previewed while dragging
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return placed.count() == 1; }, 2000));
  const core::ObjectTransform after = modeller.objectAt(1).transform;
  QVERIFY2(after.translation.x > before.translation.x + 0.1f, qPrintable(describe(after)));
  QCOMPARE(after.translation.y, before.translation.y);
  QCOMPARE(after.translation.z, before.translation.z);
  QCOMPARE(after.rotationDegrees, before.rotationDegrees);
  QCOMPARE(after.scale, before.scale);
  QVERIFY(!view->stroking());
  // One step, the move (no stroke was made on the cube).
  QVERIFY2(window_->undoStack()->undoText().startsWith("Move "),
           qPrintable(window_->undoStack()->undoText()));
  // The arrow's tip followed: the origin moved about 60 px along the arrow on screen.
  const QPointF moved = onView(*view, after.translation) - onView(*view, before.translation);
  QVERIFY2(std::abs(QPointF::dotProduct(moved, along) - 60) < 4,
           qPrintable(QString("moved %1 px along").arg(QPointF::dotProduct(moved, along))));

  // The white ring: on screen where the gizmo says, gone with Object Mode off.
  input.moveTo(QGuiApplication::primaryScreen()->geometry().bottomRight());
  QTest::qWait(300);
  const QPointF c0 = (*gizmo->arrows())[0].from;
  const QPoint onRing =
      (c0 + QPointF(-1, -1) / std::sqrt(2.0) * app::TransformGizmo::kRingPixels).toPoint();
  const QColor ring = onScreen(view).pixelColor(onRing);
  QVERIFY2(std::min({ring.red(), ring.green(), ring.blue()}) > 200, qPrintable(ring.name()));
  window_->action("actionObjectMode")->setChecked(false);
  QVERIFY(!gizmo->arrows());
  QTest::qWait(300);
  const QColor without = onScreen(view).pixelColor(onRing);
  QVERIFY2(std::max({std::abs(without.red() - ring.red()), std::abs(without.green() - ring.green()),
                     std::abs(without.blue() - ring.blue())}) > 20,
           qPrintable(ring.name() + " " + without.name()));
  window_->action("actionObjectMode")->setChecked(true);

  // A real drag on the ring, outward: a uniform scale by the pointer's distance to the origin
  // against the ring's radius, placed at the release; nothing else changes.
  const QPoint grab = (c0 + QPointF(0, -app::TransformGizmo::kRingPixels)).toPoint();
  const QPoint release = grab + QPoint(0, -58);
  const double factor = std::hypot(release.x() - c0.x(), release.y() - c0.y()) /
                        std::hypot(grab.x() - c0.x(), grab.y() - c0.y());
  QCOMPARE(gizmo->arrowAt(grab), app::TransformGizmo::kRing);
  input.moveTo(view->mapToGlobal(grab));
  input.button(1, true);
  for (int k = 1; k <= 6; ++k)
    input.moveTo(view->mapToGlobal(grab + (release - grab) * k / 6));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return placed.count() == 2; }, 2000));
  const core::ObjectTransform grown = modeller.objectAt(1).transform;
  QVERIFY2(std::abs(grown.scale.x / after.scale.x / factor - 1) < 0.02,
           qPrintable(describe(grown)));
  QCOMPARE(grown.scale.y, grown.scale.x);
  QCOMPARE(grown.scale.z, grown.scale.x);
  QVERIFY(bitSame({grown.translation, grown.rotationDegrees, after.scale}, after));
  // The ring's drag is one step of its own; undoing it leaves the arrow's move.
  QVERIFY2(window_->undoStack()->undoText().startsWith("Scale "),
           qPrintable(window_->undoStack()->undoText()));
  window_->undoStack()->undo();
  QVERIFY(bitSame(modeller.objectAt(1).transform, after));
}

QTEST_MAIN(ObjectTransformRenderTest)
#include "object_transform_render_test.moc"
