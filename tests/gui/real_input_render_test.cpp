// The viewport under real X input (XTEST through the X server, as a mouse and keyboard give it),
// not events sent to the widget: its frames are a native GL window's, so the mouse, the keyboard
// focus and the shortcuts must still reach the widgets through it.
#include "brush_panel.h"
#include "main_window.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/geometry/base_shapes.h"

#include <QGuiApplication>
#include <QTemporaryDir>
#include <QtTest>
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <memory>

using namespace octaclay;

namespace {

// An X connection of its own: XTEST input goes through the server to Qt's connection.
class FakeInput {
public:
  FakeInput() : display_(XOpenDisplay(nullptr)) {}
  ~FakeInput() {
    if (display_) XCloseDisplay(display_);
  }
  FakeInput(const FakeInput&) = delete;
  FakeInput& operator=(const FakeInput&) = delete;

  bool ready() const {
    int event = 0, error = 0, major = 0, minor = 0;
    return display_ && XTestQueryExtension(display_, &event, &error, &major, &minor);
  }
  void moveTo(QPoint global) {
    XTestFakeMotionEvent(display_, -1, global.x(), global.y(), CurrentTime);
    settle();
  }
  void button(unsigned int button, bool down) {
    XTestFakeButtonEvent(display_, button, down, CurrentTime);
    settle();
  }
  void key(KeySym symbol, bool down) {
    XTestFakeKeyEvent(display_, XKeysymToKeycode(display_, symbol), down, CurrentTime);
    settle();
  }
  void press(std::initializer_list<KeySym> chord) {
    for (KeySym k : chord)
      key(k, true);
    for (auto k = std::rbegin(chord); k != std::rend(chord); ++k)
      key(*k, false);
  }

private:
  void settle() {
    XFlush(display_);
    QTest::qWait(30);
  }
  Display* display_;
};

} // namespace

class RealInputRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void strokeUndoRedoShortcutAndWheelThroughTheGlWindow();

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

void RealInputRenderTest::strokeUndoRedoShortcutAndWheelThroughTheGlWindow() {
  QCOMPARE(QGuiApplication::platformName(), QString("xcb"));
  FakeInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<app::MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushPanel()->selectBrush("push"));
  QVERIFY(!view->canUndo());

  // A left drag across the model sculpts.
  const QPoint centre = view->mapToGlobal(view->project({0, 0, 0}).toPoint());
  input.moveTo(centre - QPoint(60, 0));
  input.button(1, true);
  for (int k = 1; k <= 12; ++k)
    input.moveTo(centre - QPoint(60, 0) + QPoint(10 * k, 3 * k));
  input.button(1, false);
  QVERIFY(QTest::qWaitFor([&] { return view->canUndo(); }, 3000));

  // Keys typed with the pointer over the frames reach the window's shortcuts.
  input.press({XK_Control_L, XK_z});
  QVERIFY(QTest::qWaitFor([&] { return !view->canUndo() && view->canRedo(); }, 3000));
  input.press({XK_Control_L, XK_y});
  QVERIFY(QTest::qWaitFor([&] { return view->canUndo(); }, 3000));
  input.press({XK_s});
  QVERIFY(QTest::qWaitFor(
      [&] { return window->brushPanel()->currentBrushId() == QString("smooth"); }, 3000));

  // The wheel zooms.
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const double distance = camera->GetDistance();
  input.button(4, true);
  input.button(4, false);
  QVERIFY(QTest::qWaitFor([&] { return camera->GetDistance() < distance * 0.95; }, 3000));
}

QTEST_MAIN(RealInputRenderTest)
#include "real_input_render_test.moc"
