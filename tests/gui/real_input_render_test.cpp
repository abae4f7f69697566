// The viewport under real X input (XTEST through the X server, as a mouse and keyboard give it),
// not events sent to the widget: its frames are a native GL window's, so the mouse, the keyboard
// focus and the shortcuts must still reach the widgets through it.
#include "brush_header.h"
#include "brush_panel.h"
#include "brush_state.h"
#include "camera_control.h"
#include "canvas_brush_adjust.h"
#include "history_dialog.h"
#include "main_window.h"
#include "modeller.h"
#include "radius_field.h"
#include "test_window.h"
#include "viewport_widget.h"
#include "x_input.h"

#include "octaclay/core/geometry/base_shapes.h"

#include <QAction>
#include <QApplication>
#include <QFontMetricsF>
#include <QGuiApplication>
#include <QLabel>
#include <QListView>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QStyle>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace octaclay;

using app::testing::activate;
using app::testing::FakeInput;

class RealInputRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void strokeUndoRedoShortcutAndWheelThroughTheGlWindow();
  void keypadViewsTurnTheCameraWithNumLockOnAndOff();
  void fAndShiftFAdjustOverTheModelOnScreen();
  void snakeHookAtItsDefaultPullsAlongTheDrag();
  void bracketWorksRightAfterDraggingTheStrengthSlider();
  void undoSaysWhenItsBudgetDropsSteps();
  void aSparseTipSaysWhyBeforeTheBrushActs();
  void aPressJustOffTheModelWithinTheRingSculpts();
  void preferencesSetTheUndoMemory();
  void aViewRadiusKeepsItsFootprintOnScreenWhenZoomedIn();

private:
  QTemporaryDir dir_;
};

void RealInputRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("real_input_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QSettings().clear();
}

// The real pointer parked in the screen's far corner, off every window the next test opens:
// a window appearing under it would get its motion.
void RealInputRenderTest::cleanup() {
  FakeInput input;
  if (!input.ready()) return;
  const QRect screen = QGuiApplication::primaryScreen()->geometry();
  input.moveTo(screen.bottomRight());
}

void RealInputRenderTest::strokeUndoRedoShortcutAndWheelThroughTheGlWindow() {
  QCOMPARE(QGuiApplication::platformName(), QString("xcb"));
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushState()->selectBrush("push"));
  QVERIFY(!view->modeller().canUndo());

  // A left drag across the model sculpts.
  const QPoint centre = view->mapToGlobal(view->project({0, 0, 0}).toPoint());
  input.moveTo(centre - QPoint(60, 0));
  input.button(1, true);
  for (int k = 1; k <= 12; ++k)
    input.moveTo(centre - QPoint(60, 0) + QPoint(10 * k, 3 * k));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().canUndo(); }, 3000));

  // Keys typed with the pointer over the frames reach the window's shortcuts.
  input.press({XK_Control_L, XK_z});
  QVERIFY(QTest::qWaitFor([&] { return !view->modeller().canUndo() && view->modeller().canRedo(); },
                          3000));
  input.press({XK_Control_L, XK_y});
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().canUndo(); }, 3000));
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor(
      [&] { return window->brushState()->currentBrushId() == QString("smooth"); }, 3000));

  // The wheel zooms.
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const double distance = camera->GetDistance();
  input.button(4, true);
  input.button(4, false);
  QVERIFY(QTest::qWaitFor([&] { return camera->GetDistance() < distance * 0.95; }, 3000));
}

namespace {

core::Vec3f towardEyeOf(vtkCamera& camera) {
  const double *p = camera.GetPosition(), *f = camera.GetFocalPoint();
  return core::normalize(core::Vec3f{float(p[0] - f[0]), float(p[1] - f[1]), float(p[2] - f[2])});
}

core::Vec3f upOf(vtkCamera& camera) {
  const double* u = camera.GetViewUp();
  return core::normalize(core::Vec3f{float(u[0]), float(u[1]), float(u[2])});
}

bool near(core::Vec3f a, core::Vec3f b) {
  return core::length(a - b) < 1e-3f;
}

QString text(core::Vec3f v) {
  return QString("(%1, %2, %3)").arg(v.x, 0, 'f', 3).arg(v.y, 0, 'f', 3).arg(v.z, 0, 'f', 3);
}

} // namespace

void RealInputRenderTest::keypadViewsTurnTheCameraWithNumLockOnAndOff() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(activate(*window));
  // A newcomer's first key reaches the model: the viewport has the keys from the start.
  QVERIFY2(QTest::qWaitFor([&] { return QApplication::focusWidget() == view; }, 3000),
           QApplication::focusWidget() ? QApplication::focusWidget()->metaObject()->className()
                                       : "no focus");
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  auto* ortho = window->findChild<QAction*>(QStringLiteral("actionOrthographic"));
  QVERIFY(ortho);
  input.moveTo(view->mapToGlobal(QPoint(view->width() / 2, view->height() / 2)));

  struct Case {
    KeySym key;
    bool ctrl;
    core::Vec3f towardEye, up;
  };
  const Case cases[] = {
      {XK_KP_1, false, {0, 0, 1}, {0, 1, 0}},  {XK_KP_1, true, {0, 0, -1}, {0, 1, 0}},
      {XK_KP_3, false, {1, 0, 0}, {0, 1, 0}},  {XK_KP_3, true, {-1, 0, 0}, {0, 1, 0}},
      {XK_KP_7, false, {0, 1, 0}, {0, 0, -1}}, {XK_KP_7, true, {0, -1, 0}, {0, 0, 1}},
  };
  const bool numLockWas = input.numLock();
  for (const bool numLock : {true, false}) {
    QVERIFY2(input.setNumLock(numLock), numLock ? "NumLock stays off" : "NumLock stays on");
    for (const Case& c : cases) {
      // From an oblique view at some distance: the key turns the camera and keeps the zoom.
      const double* f = camera->GetFocalPoint();
      const double d = 3.7;
      camera->SetPosition(f[0] + d * 0.48, f[1] + d * 0.6, f[2] + d * 0.64);
      camera->SetViewUp(0, 1, 0);
      camera->OrthogonalizeViewUp();
      view->update();
      const QString what = QString("%1keypad %2, NumLock %3")
                               .arg(c.ctrl ? "Ctrl+" : "")
                               .arg(XKeysymToString(c.key))
                               .arg(numLock ? "on" : "off");
      if (c.ctrl)
        input.press({XK_Control_L, c.key});
      else
        input.press({c.key});
      QVERIFY2(QTest::qWaitFor([&] { return near(towardEyeOf(*camera), c.towardEye); }, 2000),
               qPrintable(what + ": camera toward " + text(towardEyeOf(*camera))));
      QVERIFY2(near(upOf(*camera), c.up), qPrintable(what + ": up " + text(upOf(*camera))));
      QVERIFY2(std::abs(camera->GetDistance() - d) < 1e-6,
               qPrintable(what + QString(": distance %1").arg(camera->GetDistance())));
    }
    // Keypad 5 switches the projection and the menu's check mark, both ways.
    const bool parallel = camera->GetParallelProjection();
    input.press({XK_KP_5});
    QVERIFY2(
        QTest::qWaitFor([&] { return bool(camera->GetParallelProjection()) != parallel; }, 2000),
        numLock ? "keypad 5, NumLock on" : "keypad 5, NumLock off");
    QCOMPARE(ortho->isChecked(), !parallel);
    input.press({XK_KP_5});
    QVERIFY(
        QTest::qWaitFor([&] { return bool(camera->GetParallelProjection()) == parallel; }, 2000));
    QCOMPARE(ortho->isChecked(), parallel);
  }

  // The main keyboard's Home still frames the model from where the camera looks.
  app::setViewDirection(*camera, app::ViewDirection::Right);
  camera->Dolly(0.1); // ten times as far
  const double far = camera->GetDistance();
  input.press({XK_Home});
  QVERIFY2(QTest::qWaitFor([&] { return camera->GetDistance() < far * 0.5; }, 2000),
           qPrintable(QString("distance %1 after Home").arg(camera->GetDistance())));
  QVERIFY(near(towardEyeOf(*camera), {1, 0, 0}));
  input.setNumLock(numLockWas); // the display as it was, for the tests after this one
}

namespace {

/// The viewport as the X server shows it (the root window's pixels, whatever draws them).
QImage onScreen(QWidget* view) {
  const QPoint at = view->mapToGlobal(QPoint(0, 0));
  return QGuiApplication::primaryScreen()
      ->grabWindow(0, at.x(), at.y(), view->width(), view->height())
      .toImage()
      .convertToFormat(QImage::Format_RGB32);
}

int most(QRgb a, QRgb b) {
  return std::max({std::abs(qRed(a) - qRed(b)), std::abs(qGreen(a) - qGreen(b)),
                   std::abs(qBlue(a) - qBlue(b))});
}

} // namespace

void RealInputRenderTest::fAndShiftFAdjustOverTheModelOnScreen() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushState()->selectBrush("push"));
  QVERIFY(activate(*window));
  auto* adjust = window->findChild<app::CanvasBrushAdjust*>(QStringLiteral("canvasBrushAdjust"));
  QVERIFY(adjust);
  const QColor background = view->looks().backgroundTop;
  // The pointer on the model a little off its centre; the picture then, ring included.
  const QPoint origin = view->project({0, 0, 0}).toPoint() - QPoint(40, 30);
  input.moveTo(view->mapToGlobal(origin));
  QTest::qWait(300);
  const QImage before = onScreen(view);
  int model = 0;
  for (int y = 0; y < before.height(); ++y)
    for (int x = 0; x < before.width(); ++x)
      model += most(before.pixel(x, y), background.rgb()) > 12;
  QVERIFY2(model > before.width() * before.height() / 10,
           qPrintable(QString("%1 model pixels before").arg(model)));

  for (const bool strength : {false, true}) {
    const QString what = strength ? "Shift+F" : "F";
    if (strength)
      input.press({XK_Shift_L, XK_f});
    else
      input.press({XK_f});
    const auto mode =
        strength ? app::CanvasBrushAdjust::Mode::Strength : app::CanvasBrushAdjust::Mode::Radius;
    QVERIFY2(QTest::qWaitFor([&] { return adjust->mode() == mode; }, 2000), qPrintable(what));
    QCOMPARE(adjust->origin(), QPointF(origin));
    const double ring0 = adjust->marks().ringPixels;
    input.moveTo(view->mapToGlobal(origin + QPoint(25, 4)));
    QVERIFY(QTest::qWaitFor([&] { return adjust->marks().ringPixels != ring0 || strength; }, 2000));
    const app::CanvasBrushAdjust::Marks marks = adjust->marks();
    const QFontMetricsF metrics(QGuiApplication::font());
    const QRectF box(marks.centre + QPointF(14, 14),
                     QSizeF(metrics.horizontalAdvance(marks.text) + 12, metrics.height() + 6));
    const double ring = std::max(ring0, marks.ringPixels) + 8;

    // On the screen: the model's pixels away from the ring and the value's box are as before,
    // and the box is there, dark with white text.
    int kept = 0, modelAway = 0, inBox = 0, darker = 0, white = 0;
    QImage during;
    (void)QTest::qWaitFor( // the checks below say what was not as waited for
        [&] {
          during = onScreen(view);
          kept = modelAway = inBox = darker = white = 0;
          for (int y = 0; y < during.height(); ++y)
            for (int x = 0; x < during.width(); ++x) {
              const QPointF p(x + 0.5, y + 0.5);
              const QRgb was = before.pixel(x, y), now = during.pixel(x, y);
              if (box.adjusted(2, 2, -2, -2).contains(p)) {
                ++inBox;
                darker += qGray(now) < qGray(was) - 20;
                white += qGray(now) > 200;
                continue;
              }
              if (std::hypot(p.x() - origin.x(), p.y() - origin.y()) < ring) continue;
              if (most(was, background.rgb()) <= 12) continue;
              ++modelAway;
              kept += most(was, now) <= 2;
            }
          return kept > modelAway * 0.98 && darker > inBox / 2 && white > 10;
        },
        3000);
    QVERIFY2(modelAway > model / 2, qPrintable(QString("%1 of %2").arg(modelAway).arg(model)));
    QVERIFY2(kept > modelAway * 0.98,
             qPrintable(
                 QString("%1: %2 of %3 model pixels in sight").arg(what).arg(kept).arg(modelAway)));
    QVERIFY2(darker > inBox / 2 && white > 10,
             qPrintable(QString("%1: value box %2 px, %3 darker, %4 white")
                            .arg(what)
                            .arg(inBox)
                            .arg(darker)
                            .arg(white)));
    if (strength) {
      // The strength's disc inside the ring, brighter than the model was.
      const QPoint inside = origin + QPoint(0, -int(marks.ringPixels * marks.strength / 2));
      QVERIFY(qGray(during.pixel(inside)) > qGray(before.pixel(inside)));
    }
    input.press({XK_Escape});
    QVERIFY(QTest::qWaitFor([&] { return adjust->mode() == app::CanvasBrushAdjust::Mode::None; },
                            2000));
    input.moveTo(view->mapToGlobal(origin));
  }
  // Afterwards the marks are gone: the picture is the one before.
  QVERIFY(QTest::qWaitFor(
      [&] { return app::testing::comparePixels(before, onScreen(view)).differing < 50; }, 3000));
}

void RealInputRenderTest::snakeHookAtItsDefaultPullsAlongTheDrag() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  QSettings().clear(); // no strength remembered from an earlier session
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  app::BrushState* brushes = window->brushState();
  const QPoint centre = view->project({0, 0, 0}).toPoint();
  input.moveTo(view->mapToGlobal(centre));
  QVERIFY(activate(*window));
  input.press({XK_k});
  QVERIFY(
      QTest::qWaitFor([&] { return brushes->currentBrushId() == QString("snake-hook"); }, 2000));
  QCOMPARE(brushes->strength(), 1.0f);

  // A 200 px drag from the front of the sphere pulls a hook most of that far.
  const auto hit = view->pickAt(centre);
  QVERIFY(hit);
  const std::vector<float> before = app::testing::positionsOf(*window);
  const QPoint from = centre;
  input.moveTo(view->mapToGlobal(from));
  input.button(1, true);
  for (int k = 1; k <= 20; ++k)
    input.moveTo(view->mapToGlobal(from + QPoint(10 * k, 0)));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().canUndo() && !view->stroking(); }, 5000));
  const std::vector<float> after = app::testing::positionsOf(*window);
  float pulled = 0;
  for (std::size_t k = 0; k + 3 < after.size(); k += 4)
    pulled = std::max(pulled,
                      core::length(core::Vec3f{after[k] - before[k], after[k + 1] - before[k + 1],
                                               after[k + 2] - before[k + 2]}));
  // Object units to pixels at the front of the sphere, sideways.
  const core::Vec3f front = hit->position;
  const float unit = 0.1f;
  const QPointF a = view->project(front), b = view->project(front + core::Vec3f{unit, 0, 0});
  const double pixels = pulled * std::hypot(b.x() - a.x(), b.y() - a.y()) / unit;
  qInfo("a 200 px drag pulled the surface %.0f px", pixels);
  QVERIFY2(pixels > 120, qPrintable(QString("a 200 px drag pulled %1 px").arg(pixels)));
}

void RealInputRenderTest::bracketWorksRightAfterDraggingTheStrengthSlider() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 64, true));
  QVERIFY(activate(*window));
  app::BrushState* brushes = window->brushState();
  QVERIFY(brushes->selectBrush("push"));
  auto* slider = window->findChild<QSlider*>(QStringLiteral("headerStrength"));
  QVERIFY(slider && slider->isVisible());
  const float strength = brushes->strength();

  // Press on the slider's handle and drag it 40 px to the right, as a hand on the mouse does.
  const int handle = slider->style()->pixelMetric(QStyle::PM_SliderLength, nullptr, slider);
  const double at =
      double(slider->value() - slider->minimum()) / double(slider->maximum() - slider->minimum());
  const QPoint grip(handle / 2 + int(at * (slider->width() - handle)), slider->height() / 2);
  const QPoint start = slider->mapToGlobal(grip);
  input.moveTo(start);
  input.button(1, true);
  for (int k = 1; k <= 8; ++k)
    input.moveTo(start + QPoint(5 * k, 0));
  input.button(1, false);
  QVERIFY2(QTest::qWaitFor([&] { return brushes->strength() > strength + 0.05f; }, 2000),
           qPrintable(QString("strength %1 -> %2").arg(strength).arg(brushes->strength())));

  // ] at once (no Esc, no click on the model) grows the radius by a tenth.
  const float radius = brushes->radius();
  input.press({XK_bracketright});
  QVERIFY2(
      QTest::qWaitFor([&] { return std::abs(brushes->radius() - radius * 1.1f) < 1e-5f; }, 2000),
      qPrintable(QString("radius %1 -> %2 (focus: %3)")
                     .arg(radius)
                     .arg(brushes->radius())
                     .arg(QApplication::focusWidget()
                              ? QApplication::focusWidget()->metaObject()->className()
                              : "none")));
  QCOMPARE(QApplication::focusWidget(), window->viewport());
  // Shift+[ steps the strength the slider set.
  const float set = brushes->strength();
  input.press({XK_Shift_L, XK_bracketleft});
  QVERIFY(
      QTest::qWaitFor([&] { return std::abs(brushes->strength() - set / 1.1f) < 1e-3f; }, 2000));
}

void RealInputRenderTest::undoSaysWhenItsBudgetDropsSteps() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 64, true));
  QVERIFY(activate(*window));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushState()->selectBrush("push"));
  window->brushState()->setRadius(0.1f);
  const QPoint centre = view->mapToGlobal(view->project({0, 0, 0}).toPoint());
  int strokes = 0;
  const auto stroke = [&] {
    const QPoint from = centre + QPoint(-40, 25 * (strokes % 3 - 1));
    input.moveTo(from);
    input.button(1, true);
    for (int k = 1; k <= 8; ++k)
      input.moveTo(from + QPoint(10 * k, 0));
    input.button(1, false);
    ++strokes;
    return QTest::qWaitFor(
        [&] {
          app::HistoryList* h = window->undoStack();
          return h->count() + int(h->dropped()) == strokes;
        },
        5000);
  };
  QVERIFY(stroke());
  app::HistoryList* stack = window->undoStack();
  // A budget of about two such strokes.
  const std::size_t one = view->modeller().history().bytes();
  QVERIFY(one > 0);
  stack->undo();
  QVERIFY(!view->modeller().canUndo());
  view->modeller().history().clear();
  view->modeller().setHistoryBudget(one * 5 / 2);
  strokes = 0;

  QAction* historyAction = window->findChild<QAction*>(QStringLiteral("actionHistory"));
  QVERIFY(historyAction);
  historyAction->trigger();
  auto* history = window->findChild<app::HistoryDialog*>();
  QVERIFY(history);
  history->move(window->frameGeometry().right() + 10, 0); // beside the model, not over it
  const auto firstRow = [&] { return history->view()->model()->index(0, 0).data().toString(); };
  QVERIFY(stroke());
  QCOMPARE(firstRow(), QString("Model as opened or made"));
  QVERIFY(activate(*window));
  while (strokes < 6 && stack->dropped() == 0)
    QVERIFY(stroke());
  QVERIFY2(stack->dropped() > 0, "six strokes fit a budget of two and a half");
  // The status bar says so, the dropped step says so, the first row no longer promises the
  // model as it was made.
  QVERIFY2(window->statusBar()->toolTip().startsWith("Undo now keeps only the newest"),
           qPrintable(window->statusBar()->currentMessage()));
  // One history: the dropped steps are gone from it, the kept ones all named.
  QCOMPARE(std::size_t(stack->count()), view->modeller().history().undoCount());
  QCOMPARE(stack->count() + int(stack->dropped()), strokes);
  QCOMPARE(firstRow(), QString("Oldest kept step"));
  // Undoing everything stops at the oldest kept step, and the redo comes back.
  const std::vector<float> newest = app::testing::positionsOf(*window);
  while (stack->canUndo())
    stack->undo();
  QVERIFY(!view->modeller().canUndo());
  while (stack->canRedo())
    stack->redo();
  QVERIFY(app::testing::bitEqual(app::testing::positionsOf(*window), newest));
}

// Issue 30: a limb pulled out with the snake hook (a 200 px drag, keep-detail on as it is by
// default) leaves few samples at its tip. A press there with Inflate says, before the brush acts,
// why the result will be coarse: the status bar names Preview ▸ Stretch and shows a "Remesh…"
// button that triggers Mesh ▸ Remesh…. A press on the ball, where the samples are dense, says
// nothing.
void RealInputRenderTest::aSparseTipSaysWhyBeforeTheBrushActs() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  QSettings().clear();
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  app::BrushState* brushes = window->brushState();
  const QPoint centre = view->project({0, 0, 0}).toPoint();
  input.moveTo(view->mapToGlobal(centre));
  QVERIFY(activate(*window));
  QVERIFY(brushes->selectBrush("snake-hook"));
  input.moveTo(view->mapToGlobal(centre));
  input.button(1, true);
  for (int k = 1; k <= 20; ++k)
    input.moveTo(view->mapToGlobal(centre + QPoint(10 * k, 0)));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().canUndo() && !view->stroking(); }, 10000));

  auto* button = window->statusBar()->findChild<QPushButton*>("sparseSamplingRemesh");
  QVERIFY(button);
  QVERIFY(brushes->selectBrush("inflate"));
  // On the ball, away from the limb: dense samples, no hint.
  const QPoint body = view->project({-0.5f, 0.3f, 0.8f}).toPoint();
  QVERIFY(view->pickAt(body));
  window->statusBar()->clearMessage();
  input.moveTo(view->mapToGlobal(body));
  input.button(1, true);
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return !view->stroking(); }, 5000));
  QVERIFY2(!window->statusBar()->currentMessage().startsWith("Few samples"),
           qPrintable(window->statusBar()->currentMessage()));
  QVERIFY(!button->isVisible());

  // The limb's tip: its sample farthest to the right on screen that a pick finds.
  const std::vector<float> p = app::testing::positionsOf(*window);
  QPoint tip;
  double farthest = -1e9;
  for (std::size_t k = 0; k + 3 < p.size(); k += 4) {
    const QPointF s = view->project({p[k], p[k + 1], p[k + 2]});
    if (s.x() > farthest && view->pickAt(s - QPointF(2, 0))) farthest = s.x(), tip = s.toPoint();
  }
  tip -= QPoint(2, 0);
  window->statusBar()->clearMessage();
  input.moveTo(view->mapToGlobal(tip));
  input.button(1, true);
  const QString said = window->statusBar()->currentMessage();
  const bool shown = button->isVisible();
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return !view->stroking(); }, 5000));
  qInfo("the tip (%d, %d px): %s", tip.x(), tip.y(), qPrintable(said));
  QVERIFY2(said.startsWith("Few samples here"), qPrintable(said));
  QVERIFY(said.contains(QString::fromUtf8("Preview ▸ Stretch")));
  QVERIFY(shown);
  // The button runs Mesh ▸ Remesh… (its dialog, closed here at once).
  QAction* remesh = window->findChild<QAction*>(QStringLiteral("actionRemesh"));
  QVERIFY(remesh);
  // (Mesh ▸ Remesh… waits while a background task runs, as the menu does.)
  QVERIFY(QTest::qWaitFor([&] { return remesh->isEnabled(); }, 10000));
  QSignalSpy triggered(remesh, &QAction::triggered);
  QTimer::singleShot(300, [] {
    if (QWidget* dialog = QApplication::activeModalWidget()) dialog->close();
  });
  button->click();
  QCOMPARE(triggered.count(), 1);
}

// Issue 31: half the strokes begun just beside a thin neck orbited the camera. A real press
// beside the sphere's silhouette, off the model but within the brush ring's radius of it, sculpts
// (and leaves the camera where it was); a press farther out than the ring still orbits.
void RealInputRenderTest::aPressJustOffTheModelWithinTheRingSculpts() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushState()->selectBrush("push"));
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  // Pixels a side: the unit sphere's outline and the brush ring (radius × the diagonal, 2√3).
  const QPointF centre = view->project({0, 0, 0});
  const core::Vec3f up = upOf(*camera);
  const double sphere =
      std::hypot(view->project(up).x() - centre.x(), view->project(up).y() - centre.y());
  const float radius = window->brushState()->radius() * 2.0f * std::sqrt(3.0f);
  const double ring = std::hypot(view->project(up * radius).x() - centre.x(),
                                 view->project(up * radius).y() - centre.y());
  qInfo("outline %.0f px, ring %.0f px", sphere, ring);
  QVERIFY2(ring > 12, "the ring is too small on screen to press beside the outline");
  // Below the outline (screen down is -up): a few pixels off the model, inside the ring.
  const QPointF beside = centre + QPointF(0, sphere + std::min(6.0, ring / 3));
  QVERIFY2(!view->pickAt(beside), "the press point is on the model: nothing tested");
  const double cameraBefore[3] = {camera->GetPosition()[0], camera->GetPosition()[1],
                                  camera->GetPosition()[2]};
  const auto cameraMoved = [&] {
    const double* p = camera->GetPosition();
    return std::hypot(p[0] - cameraBefore[0], p[1] - cameraBefore[1], p[2] - cameraBefore[2]) >
           1e-6;
  };
  input.moveTo(view->mapToGlobal(beside.toPoint()));
  input.button(1, true);
  for (int k = 1; k <= 8; ++k)
    input.moveTo(view->mapToGlobal(beside.toPoint() + QPoint(4 * k, -2 * k)));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().canUndo() && !view->stroking(); }, 3000));
  QVERIFY2(!cameraMoved(), "the press beside the model orbited the camera");

  // Farther out than the ring: the same drag orbits.
  const QPointF far = centre + QPointF(0, sphere + ring * 1.5 + 4);
  QVERIFY(far.y() < view->height() - 2);
  input.moveTo(view->mapToGlobal(far.toPoint()));
  input.button(1, true);
  for (int k = 1; k <= 8; ++k)
    input.moveTo(view->mapToGlobal(far.toPoint() + QPoint(4 * k, -2 * k)));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor(cameraMoved, 3000));
}

// Issue 31: the undo budget could not be changed. Edit ▸ Preferences' "Undo memory", typed into
// as a user types, sets the history's budget, which the next document keeps and the next start
// reads back.
void RealInputRenderTest::preferencesSetTheUndoMemory() {
  QSettings().remove("undo/budgetMiB");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 64, true));
  app::ViewportWidget* view = window->viewport();
  QCOMPARE(view->modeller().history().budget(), std::size_t(256) << 20);
  QAction* preferences = window->findChild<QAction*>(QStringLiteral("actionPreferences"));
  QVERIFY(preferences);
  bool typed = false;
  QTimer::singleShot(300, window.get(), [&] {
    QWidget* dialog = QApplication::activeModalWidget();
    auto* memory = dialog ? dialog->findChild<QSpinBox*>(QStringLiteral("undoMemory")) : nullptr;
    if (!memory) {
      if (dialog) dialog->close();
      return;
    }
    memory->setFocus();
    memory->selectAll();
    QTest::keyClicks(memory, "64");
    typed = memory->value() == 64;
    QTest::keyClick(dialog, Qt::Key_Return); // the dialog's default button: OK
  });
  preferences->trigger(); // the dialog runs its own loop until the timer's Return
  QVERIFY2(typed, "no Undo memory box in Edit ▸ Preferences");
  QCOMPARE(window->undoBudgetMiB(), 64);
  QCOMPARE(view->modeller().history().budget(), std::size_t(64) << 20);
  QCOMPARE(QSettings().value("undo/budgetMiB").toInt(), 64);
  // The next document, and the next start, keep it.
  QVERIFY(window->newDocument(core::BaseShape::Cube, 64, true));
  QCOMPARE(view->modeller().history().budget(), std::size_t(64) << 20);
  const std::unique_ptr<app::MainWindow> next =
      app::testing::openTestWindow(dir_.filePath("recovery-next"));
  QVERIFY(next);
  QCOMPARE(next->undoBudgetMiB(), 64);
  QSettings().remove("undo/budgetMiB");
}

// Issue 31: a crease folded into a curl on a short stroke zoomed in, because the radius was a
// fraction of the bounding box. With the radius in view pixels (a new user's unit) a short crease
// stroke, real presses and moves at the view's centre, covers the same span on screen at the
// default zoom and zoomed in ×4; with the scene radius the span grows with the zoom. The span:
// the texels the stroke moved (by more than 5 % of its largest move), projected through the
// stroke's camera, from top to bottom (across the stroke).
void RealInputRenderTest::aViewRadiusKeepsItsFootprintOnScreenWhenZoomedIn() {
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  QSettings().remove("brushes");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window->viewport();
  app::BrushState* brushes = window->brushState();
  // A new user's unit is the view's (openTestWindow chose the scene's for the older tests).
  QSettings().remove("brushes");
  QCOMPARE(app::BrushValueStore::loadRadiusUnit(), app::RadiusUnit::View);
  QCOMPARE(app::BrushState().radiusUnit(), app::RadiusUnit::View);
  brushes->setRadiusUnit(app::RadiusUnit::View);
  QVERIFY(brushes->selectBrush("crease"));
  brushes->setKeepDetail(false); // its relaxation would move samples beyond the brush
  brushes->setStabilizer(0);
  vtkCamera* camera = view->renderer()->GetActiveCamera();

  const auto strokeSpan = [&](double zoom) -> double {
    view->resetCamera();
    const QPointF centre(view->width() / 2.0, view->height() / 2.0);
    const std::optional<core::PickHit> hit = view->pickAt(centre);
    if (!hit) return -1;
    app::zoomCameraAt(*camera, hit->position, zoom);
    view->update();
    QTest::qWait(100);
    const std::vector<float> before = app::testing::positionsOf(*window);
    const QPoint at = view->mapToGlobal(centre.toPoint());
    input.moveTo(at - QPoint(12, 0));
    input.button(1, true);
    for (int k = 1; k <= 6; ++k)
      input.moveTo(at - QPoint(12, 0) + QPoint(4 * k, 0));
    input.button(1, false);
    if (!QTest::qWaitFor([&] { return view->modeller().canUndo() && !view->stroking(); }, 5000))
      return -1;
    const std::vector<float> after = app::testing::positionsOf(*window);
    float largest = 0;
    std::vector<float> moved(before.size() / 4);
    for (std::size_t k = 0; k < moved.size(); ++k) {
      moved[k] = std::hypot(after[4 * k] - before[4 * k], after[4 * k + 1] - before[4 * k + 1],
                            after[4 * k + 2] - before[4 * k + 2]);
      largest = std::max(largest, moved[k]);
    }
    double top = 1e9, bottom = -1e9;
    for (std::size_t k = 0; k < moved.size(); ++k)
      if (moved[k] > 0.05f * largest) {
        const double y = view->project({before[4 * k], before[4 * k + 1], before[4 * k + 2]}).y();
        top = std::min(top, y);
        bottom = std::max(bottom, y);
      }
    window->action("actionUndo")->trigger();
    return largest > 0 ? bottom - top : -1;
  };

  QCOMPARE(brushes->radiusPixels(), app::kDefaultRadiusPixels);
  const double view1 = strokeSpan(1), view4 = strokeSpan(4);
  brushes->setRadiusUnit(app::RadiusUnit::Scene);
  const double scene1 = strokeSpan(1), scene4 = strokeSpan(4);
  qInfo("crease span across the stroke on screen: view radius %.0f px: %.1f px at ×1, %.1f px at "
        "×4 (%.2f); scene radius %.1f %%: %.1f px at ×1, %.1f px at ×4 (%.2f)",
        double(brushes->radiusPixels()), view1, view4, view4 / view1,
        double(brushes->radius()) * 100, scene1, scene4, scene4 / scene1);
  QVERIFY(view1 > 0 && view4 > 0 && scene1 > 0 && scene4 > 0);
  // About the ring's diameter in the view unit, at both zooms (within 20 %).
  QVERIFY2(std::abs(view4 / view1 - 1) < 0.2, qPrintable(QString::number(view4 / view1)));
  QVERIFY2(view1 > 1.2 * app::kDefaultRadiusPixels && view1 < 2.2 * app::kDefaultRadiusPixels,
           qPrintable(QString::number(view1)));
  // The scene radius grows with the zoom (×4 give or take the sphere's curvature).
  QVERIFY2(scene4 / scene1 > 3.2 && scene4 / scene1 < 4.8,
           qPrintable(QString::number(scene4 / scene1)));

  // ] steps the view radius in pixels (the scene radius stays), and the header says pixels.
  brushes->setRadiusUnit(app::RadiusUnit::View);
  QVERIFY(activate(*window));
  input.moveTo(view->mapToGlobal(QPoint(view->width() / 2, view->height() / 2)));
  const float pixels = brushes->radiusPixels(), fraction = brushes->radius();
  input.press({XK_bracketright});
  QVERIFY2(QTest::qWaitFor(
               [&] { return std::abs(brushes->radiusPixels() - pixels * 1.1f) < 1e-3f; }, 2000),
           qPrintable(QString("%1 px -> %2 px").arg(pixels).arg(brushes->radiusPixels())));
  QCOMPARE(brushes->radius(), fraction);
  auto* header = window->findChild<app::BrushHeader*>(QStringLiteral("BrushHeader"));
  QVERIFY(header);
  QStringList labels;
  for (const QLabel* label : header->findChildren<QLabel*>())
    labels << label->text();
  QVERIFY2(labels.contains(app::radiusText(app::RadiusUnit::View, brushes->radiusPixels())),
           qPrintable(labels.join(" | ")));
  QVERIFY(labels.join(" ").contains(" px"));
}

QTEST_MAIN(RealInputRenderTest)
#include "real_input_render_test.moc"
