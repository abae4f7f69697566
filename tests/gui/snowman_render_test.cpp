// Issue 33's newcomer target: a snowman (three balls, a cylinder hat, a capsule nose, two sphere
// eyes, a torus scarf) built with the Add menu and the canvas's G / S alone in under 20 actions,
// every one of them real X input (XTEST) as a newcomer's mouse and keyboard give it: menus
// opened and chosen with clicks (the menu bar's Add, or Shift+A at the pointer), the view panned
// with Shift+middle drag, objects moved by the pointer and scaled by typed amounts. Add stands
// a new object upright at the view's centre (the hat, the scarf lying flat), or with Shift+A on
// the surface under the pointer (the nose out of the face, the eyes on it). Drawn through the
// real VTK viewport (xcb, llvmpipe).
#include "camera_control.h"
#include "main_window.h"
#include "modeller.h"
#include "object_transform_mode.h"
#include "test_window.h"
#include "viewport_widget.h"
#include "x_input.h"

#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QAction>
#include <QGuiApplication>
#include <QMenu>
#include <QMenuBar>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <memory>

using namespace octaclay;
using app::MainWindow;
using app::ObjectTransformMode;
using XTestInput = app::testing::FakeInput;

namespace {

struct Box {
  core::Vec3f centre, half;
};

Box worldBox(const app::Modeller& modeller, int k) {
  const core::Scene scene = modeller.scene();
  const core::BoundingBox b = core::worldBounds(scene.objects.at(std::size_t(k)));
  return {(b.min + b.max) * 0.5f, (b.max - b.min) * 0.5f};
}

} // namespace

class SnowmanRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void aNewcomerBuildsASnowmanInUnderTwentyActions();

private:
  QTemporaryDir dir_;
};

void SnowmanRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("snowman_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QSettings().clear();
}

void SnowmanRenderTest::aNewcomerBuildsASnowmanInUnderTwentyActions() {
  QCOMPARE(QGuiApplication::platformName(), QString("xcb"));
  XTestInput input;
  QVERIFY2(input.ready(), "no X display with the XTEST extension");
  const std::unique_ptr<MainWindow> window =
      app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  // The modeller's first ball (a new document): the snowman's bottom.
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 64, true));
  QVERIFY(app::testing::activate(*window));
  app::ViewportWidget* view = window->viewport();
  view->setFocus();
  app::Modeller& modeller = *window->modeller();
  auto* mode = window->findChild<ObjectTransformMode*>(QStringLiteral("objectTransformMode"));
  QVERIFY(mode);
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  const auto screenOf = [&](core::Vec3f world) {
    return view->mapToGlobal(app::projectToView(*camera, view->modelRect(), world).toPoint());
  };
  const auto centreOf = [&](int k) { return modeller.objectAt(k).transform.translation; };
  int actions = 0;

  // Add ▸ <shape>, one action: the menu bar's Add clicked, or with Shift+A at the pointer over
  // `at` (the menu pops up there, the shape stands on the surface under `at`), then the shape.
  const auto addWith = [&](const char* actionName, std::optional<QPoint> at) {
    QMenuBar* bar = window->menuBar();
    auto* menu = window->findChild<QMenu*>(QStringLiteral("menuAdd"));
    QAction* item = window->action(actionName);
    if (!menu || !item) return false;
    const int before = modeller.objectCount();
    if (at) {
      input.moveTo(*at);
      input.press({XK_Shift_L, XK_a});
    } else {
      input.moveTo(bar->mapToGlobal(bar->actionGeometry(menu->menuAction()).center()));
      input.click(1);
    }
    if (!QTest::qWaitFor([&] { return menu->isVisible(); }, 3000)) return false;
    QTest::qWait(100);
    input.moveTo(menu->mapToGlobal(menu->actionGeometry(item).center()));
    input.click(1);
    ++actions;
    return QTest::qWaitFor([&] { return modeller.objectCount() == before + 1; }, 5000);
  };
  const auto add = [&](const char* actionName) { return addWith(actionName, std::nullopt); };
  const auto addAt = [&](QPoint at, const char* actionName) { return addWith(actionName, at); };
  // A key gesture: the pointer on the object, the key, then the pointer to `to` (when given),
  // then typed keys, then a click (pointer) or Enter (typed): one action.
  const auto gesture = [&](KeySym key, std::optional<QPoint> from, std::optional<QPoint> to,
                           std::initializer_list<KeySym> typed) {
    const int k = modeller.activeObject();
    input.moveTo(from ? *from : screenOf(centreOf(k)));
    input.press({key});
    if (!QTest::qWaitFor([&] { return mode->kind() != ObjectTransformMode::Kind::None; }, 2000))
      return false;
    if (to) {
      const QPoint start = from ? *from : screenOf(centreOf(k));
      for (int step = 1; step <= 5; ++step)
        input.moveTo(start + (*to - start) * step / 5);
    }
    for (const KeySym t : typed)
      input.press({t});
    if (to)
      input.click(1);
    else
      input.press({XK_Return});
    ++actions;
    return QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000);
  };
  const auto moveTo = [&](core::Vec3f world) {
    return gesture(XK_g, std::nullopt, screenOf(world), {});
  };

  // 1. The view panned up (Shift + middle drag) by one and a half times the bottom ball's
  //    radius: its upper half in sight, and the view's centre, where Add puts new objects,
  //    where the middle ball goes.
  const QPoint middle = screenOf({0, 0, 0});
  const QPoint lower = middle + (middle - screenOf({0, 1.5f, 0}));
  input.moveTo(middle);
  input.key(XK_Shift_L, true);
  input.button(2, true);
  for (int step = 1; step <= 5; ++step)
    input.moveTo(middle + (lower - middle) * step / 5);
  input.button(2, false);
  input.key(XK_Shift_L, false);
  ++actions;
  QVERIFY2(std::abs(camera->GetFocalPoint()[1] - 1.5) < 0.1,
           qPrintable(QString::number(camera->GetFocalPoint()[1])));

  // 2–3. The middle ball comes at the view's centre, on the bottom one: S makes it 2.6 times
  //      as large (the pointer from 40 to 104 pixels away from its centre).
  QVERIFY(add("actionAddSphere"));
  QVERIFY(window->action("actionObjectMode")->isChecked()); // a new object shows its arrows
  const QPoint c1 = screenOf(centreOf(1));
  QVERIFY(gesture(XK_s, c1 + QPoint(40, 0), c1 + QPoint(104, 0), {}));
  QVERIFY2(std::abs(modeller.objectAt(1).transform.scale.x /
                        modeller.objectAt(0).transform.scale.x / 0.25f / 2.6f -
                    1.0f) < 0.1f,
           qPrintable(QString::number(modeller.objectAt(1).transform.scale.x)));
  const Box middleBall = worldBox(modeller, 1);

  // 4–5. The head, as large as Add makes it, seated on the middle ball with G.
  QVERIFY(add("actionAddSphere"));
  Box head = worldBox(modeller, 2);
  QVERIFY(moveTo({0, middleBall.centre.y + middleBall.half.y + head.half.y * 0.8f, 0}));
  head = worldBox(modeller, 2);

  // 6–7. The hat: a cylinder, upright as Add stands it, put on the head with G.
  QVERIFY(add("actionAddCylinder"));
  QCOMPARE(modeller.objectAt(3).transform.rotationDegrees.x, -90.0f); // its z axis up
  Box hat = worldBox(modeller, 3);
  QVERIFY(moveTo({0, head.centre.y + head.half.y + hat.half.y * 0.7f, 0}));

  const auto typeGesture = [&](KeySym key, const std::vector<KeySym>& typed) {
    const int k = modeller.activeObject();
    input.moveTo(screenOf(centreOf(k)));
    input.press({key});
    if (!QTest::qWaitFor([&] { return mode->kind() != ObjectTransformMode::Kind::None; }, 2000))
      return false;
    for (const KeySym t : typed)
      input.press({t});
    input.press({XK_Return});
    ++actions;
    return QTest::qWaitFor([&] { return mode->kind() == ObjectTransformMode::Kind::None; }, 2000);
  };
  const auto digits = [](double value) {
    std::vector<KeySym> keys;
    for (const QChar ch : QString::number(value, 'f', 2))
      keys.push_back(ch == u'.' ? XK_period : static_cast<KeySym>(ch.toLatin1()));
    return keys;
  };

  // 8–11. Two eyes: Shift+A on the face, a little above its middle and to one side, Sphere,
  //       then S 0.2.
  for (const float side : {-1.0f, 1.0f}) {
    QVERIFY(addAt(screenOf({side * 0.35f * head.half.x, head.centre.y + 0.3f * head.half.y, 0}),
                  "actionAddSphere"));
    QVERIFY(typeGesture(XK_s, {XK_0, XK_period, XK_2}));
  }

  // 12–13. The carrot nose: Shift+A on the middle of the face, Capsule: it stands out of the
  //        face; S 0.5 makes it a carrot's size.
  QVERIFY(addAt(screenOf(head.centre), "actionAddCapsule"));
  QVERIFY(typeGesture(XK_s, {XK_0, XK_period, XK_5}));

  // 14–16. The scarf: a torus, lying flat as Add stands it, moved with G to where the head
  //        meets the middle ball, then S to the neck's size (typed).
  QVERIFY(add("actionAddTorus"));
  const float neckY =
      0.5f * (middleBall.centre.y + middleBall.half.y + head.centre.y - head.half.y);
  QVERIFY(moveTo({0, neckY, 0}));
  // Its rim 0.95 of the head's radius: the tube (0.7 to 1 of the rim) half in the neck, whose
  // radius is about 0.6 of the head's where the head sits 0.8 of its radius into the ball.
  const float ringRadius = worldBox(modeller, 7).half.x;
  QVERIFY(typeGesture(XK_s, digits(0.95 * head.half.x / ringRadius)));

  // The snowman: eight objects named by their shapes, stacked bottom to hat, face in front,
  // the scarf around the neck.
  QVERIFY2(actions < 20, qPrintable(QString("%1 actions").arg(actions)));
  QCOMPARE(modeller.objectCount(), 8);
  QStringList names;
  for (int k = 0; k < modeller.objectCount(); ++k)
    names << QString::fromStdString(modeller.objectAt(k).name);
  QCOMPARE(names, QStringList({"Model", "Sphere", "Sphere.001", "Cylinder", "Sphere.002",
                               "Sphere.003", "Capsule", "Torus"}));
  std::vector<Box> boxes;
  for (int k = 0; k < 8; ++k)
    boxes.push_back(worldBox(modeller, k));
  QString layout;
  for (int k = 0; k < 8; ++k)
    layout += QString("%1: (%2, %3, %4) ± (%5, %6, %7)\n")
                  .arg(names[k])
                  .arg(double(boxes[k].centre.x), 0, 'f', 2)
                  .arg(double(boxes[k].centre.y), 0, 'f', 2)
                  .arg(double(boxes[k].centre.z), 0, 'f', 2)
                  .arg(double(boxes[k].half.x), 0, 'f', 2)
                  .arg(double(boxes[k].half.y), 0, 'f', 2)
                  .arg(double(boxes[k].half.z), 0, 'f', 2);
  const QByteArray whyText = layout.toUtf8();
  const char* why = whyText.constData();
  // Stacked in y, each part touching the one below (the tops overlap the bottoms a little).
  for (int k = 1; k <= 3; ++k) {
    QVERIFY2(boxes[k].centre.y > boxes[k - 1].centre.y, why);
    const float gap =
        (boxes[k].centre.y - boxes[k].half.y) - (boxes[k - 1].centre.y + boxes[k - 1].half.y);
    QVERIFY2(gap < 0 && gap > -boxes[k].half.y, why);
    QVERIFY2(std::abs(boxes[k].centre.x) < 0.05f && std::abs(boxes[k].centre.z) < 0.05f, why);
  }
  // Smaller going up.
  QVERIFY2(boxes[0].half.x > boxes[1].half.x && boxes[1].half.x > boxes[2].half.x, why);
  // Nose and eyes on the head's front: at its height, in front of its centre by its radius.
  for (int k = 4; k <= 6; ++k) {
    QVERIFY2(std::abs(boxes[k].centre.y - boxes[2].centre.y) < boxes[2].half.y * 0.5f, why);
    QVERIFY2(boxes[k].centre.z > boxes[2].centre.z + 0.8f * boxes[2].half.z, why);
  }
  QVERIFY2(boxes[4].centre.x < -0.1f * boxes[2].half.x &&
               boxes[5].centre.x > 0.1f * boxes[2].half.x,
           why);
  QVERIFY2(std::abs(boxes[6].centre.x) < 0.05f * boxes[2].half.x, why);
  QVERIFY2(boxes[6].half.z > boxes[6].half.x, why); // the carrot points out of the face
  // The scarf: flat, centred on the neck's axis at its height, its hole narrower than the neck
  // (0.6 of the head's radius there) and its rim wider: it goes around the neck.
  const Box& scarf = boxes[7];
  QVERIFY2(scarf.half.y < 0.5f * scarf.half.x && std::abs(scarf.half.x - scarf.half.z) < 0.01f,
           why);
  QVERIFY2(std::abs(scarf.centre.x) < 0.05f && std::abs(scarf.centre.z) < 0.05f, why);
  QVERIFY2(std::abs(scarf.centre.y - neckY) < 0.2f * head.half.y, why);
  const float hole = scarf.half.x * 0.4f, neck = 0.6f * boxes[2].half.x;
  QVERIFY2(hole < neck && scarf.half.x > neck, why);
  qInfo("%s%d actions", why, actions);
}

QTEST_MAIN(SnowmanRenderTest)
#include "snowman_render_test.moc"
