// The viewport's camera as a user drives it (xcb under Xvfb, llvmpipe): the numeric keypad's
// standard views read back in pixels on a sphere painted by axis, Home framing, the
// orthographic toggle, turntable and trackball orbits, the wheel zooming about the cursor, Save
// Image's PNG, Esc handing the keys back from a spin box, and the idle frame rate.
#include "../core/shared_data.h"
#include "brush_panel.h"
#include "file_suggestion.h"
#include "main_window.h"
#include "modeller.h"
#include "save_image_dialog.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QFile>
#include <QImage>
#include <QLabel>
#include <QRadioButton>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUndoStack>
#include <QWheelEvent>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>

using namespace octaclay;
using app::MainWindow;

namespace {

using Vec3 = std::array<double, 3>;

Vec3 normalized(Vec3 v) {
  const double l = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / l, v[1] / l, v[2] / l};
}
Vec3 cross(Vec3 a, Vec3 b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double distance(Vec3 a, Vec3 b) {
  return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}

vtkCamera* cameraOf(const MainWindow& w) {
  return w.viewport()->renderer()->GetActiveCamera();
}
Vec3 directionOfProjection(vtkCamera* c) {
  const double* d = c->GetDirectionOfProjection();
  return {d[0], d[1], d[2]};
}
Vec3 viewUp(vtkCamera* c) {
  const double* u = c->GetViewUp();
  return normalized({u[0], u[1], u[2]});
}
/// The screen's horizontal in the model.
Vec3 screenRight(vtkCamera* c) {
  return normalized(cross(directionOfProjection(c), viewUp(c)));
}

// A closed lat-long sphere (y up) with a nose and two eyes on its +z side, as OBJ text.
QByteArray headObj(int rings, int segments) {
  QByteArray obj;
  const auto radius = [](double x, double y, double z) {
    const auto bump = [&](double cx, double cy, double width, double height) {
      const double a =
          std::acos(std::clamp(x * cx + y * cy + z * std::sqrt(1 - cx * cx - cy * cy), -1.0, 1.0)) /
          width;
      return height * std::exp(-a * a);
    };
    return 1 + bump(0, 0, 0.12, 0.25) + bump(-0.3, 0.3, 0.1, -0.08) + bump(0.3, 0.3, 0.1, -0.08);
  };
  obj += "v 0 1 0\n";
  for (int r = 1; r < rings; ++r)
    for (int k = 0; k < segments; ++k) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * k / segments;
      const double x = std::sin(theta) * std::sin(phi), y = std::cos(theta),
                   z = std::sin(theta) * std::cos(phi), l = radius(x, y, z);
      obj += QByteArray("v ") + QByteArray::number(x * l) + ' ' + QByteArray::number(y * l) + ' ' +
             QByteArray::number(z * l) + '\n';
    }
  obj += "v 0 -1 0\n";
  const auto at = [&](int r, int k) { return 2 + (r - 1) * segments + (k % segments); };
  const int last = 2 + (rings - 1) * segments;
  for (int k = 0; k < segments; ++k) {
    obj += QStringLiteral("f 1 %1 %2\n").arg(at(1, k)).arg(at(1, k + 1)).toUtf8();
    obj += QStringLiteral("f %1 %2 %3\n")
               .arg(last)
               .arg(at(rings - 1, k + 1))
               .arg(at(rings - 1, k))
               .toUtf8();
    for (int r = 1; r + 1 < rings; ++r) {
      obj += QStringLiteral("f %1 %2 %3\n")
                 .arg(at(r, k))
                 .arg(at(r + 1, k))
                 .arg(at(r + 1, k + 1))
                 .toUtf8();
      obj += QStringLiteral("f %1 %2 %3\n")
                 .arg(at(r, k))
                 .arg(at(r + 1, k + 1))
                 .arg(at(r, k + 1))
                 .toUtf8();
    }
  }
  return obj;
}

// A unit sphere painted by its caps: red where x is the largest coordinate and over 0.65, green
// for y, blue for z; clay elsewhere. Its +x, +y, +z ends are told apart by colour on screen.
core::Document paintedSphere(int n) {
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
  const int side = n + 1;
  doc.diffuse.texels.resize(std::size_t(side) * side * 4);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const auto p = doc.positions.at(i, j);
      std::array<float, 4> c = doc.diffuse.fill;
      if (p.x > 0.65f && p.x >= p.y && p.x >= p.z) c = {0.9f, 0.08f, 0.08f, 1};
      if (p.y > 0.65f && p.y >= p.x && p.y >= p.z) c = {0.08f, 0.8f, 0.08f, 1};
      if (p.z > 0.65f && p.z >= p.x && p.z >= p.y) c = {0.08f, 0.15f, 0.95f, 1};
      std::copy(c.begin(), c.end(), doc.diffuse.texels.begin() + (std::size_t(j) * side + i) * 4);
    }
  return doc;
}

// R, G, B for the painted caps, C for clay, '-' for the background, '?' for anything else.
char colourClass(QRgb c, QRgb background) {
  const int r = qRed(c), g = qGreen(c), b = qBlue(c);
  if (std::abs(r - qRed(background)) + std::abs(g - qGreen(background)) +
          std::abs(b - qBlue(background)) <
      12)
    return '-';
  if (r > g + 40 && r > b + 40) return 'R';
  if (g > r + 30 && g > b + 30) return 'G';
  if (b > r + 30 && b > g + 30) return 'B';
  if (std::max({r, g, b}) - std::min({r, g, b}) < 30) return 'C';
  return '?';
}

void wheel(QWidget* view, QPointF at, int notches) {
  QWheelEvent event(at, view->mapToGlobal(at), QPoint(), QPoint(0, 120 * notches), Qt::NoButton,
                    Qt::NoModifier, Qt::NoScrollPhase, false);
  QCoreApplication::sendEvent(view, &event);
}

// A right-button drag (orbit) through the given offsets from the centre.
void orbitDrag(QWidget* view, const std::vector<QPoint>& path) {
  const QPoint centre(view->width() / 2, view->height() / 2);
  QTest::mousePress(view, Qt::RightButton, {}, centre + path.front());
  for (const QPoint& p : path)
    QTest::mouseMove(view, centre + p);
  QTest::mouseRelease(view, Qt::RightButton, {}, centre + path.back());
}

const std::vector<QPoint> kLoop = {{0, 0},   {60, 0}, {120, 0}, {120, 60},  {120, 120}, {60, 120},
                                   {0, 120}, {0, 60}, {0, 0},   {-80, -40}, {-40, -90}, {30, -20}};

QImage grab(const MainWindow& w) {
  w.viewport()->repaint();
  return w.viewport()->grabFramebuffer();
}

} // namespace

class ViewsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void viewKeysTurnTheCameraAndPutEachAxisWhereItBelongs();
  void homeFramesTheModelFromTheCurrentDirection();
  void orthographicToggleChangesTheProjectionAndPicksStraight();
  void turntableKeepsUpUpAndTrackballIsRememberedAndRolls();
  void wheelZoomsAboutThePointUnderTheCursor();
  void saveImageWritesAPngOfTheRequestedSize();
  void saveImageDialogAsksSizeAndBackground();
  void escapeInASpinBoxHandsTheKeysBackWithoutAStroke();
  void idleStatusBarShowsNoZeroFrameRate();
  void importedModelIsShownFromTheFront();

private:
  std::unique_ptr<MainWindow> openSphere();

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void ViewsRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("views_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void ViewsRenderTest::init() {
  QSettings().clear();
}
void ViewsRenderTest::cleanup() {
  window_.reset();
}

std::unique_ptr<MainWindow> ViewsRenderTest::openSphere() {
  auto w = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (!w || !w->viewport()->modeller().setDocument(paintedSphere(64))) return nullptr;
  w->viewport()->setLevelDivisor(1);
  // Keyboard focus needs the window active (no window manager under Xvfb: asked for).
  w->activateWindow();
  w->viewport()->setFocus();
  if (!QTest::qWaitForWindowActive(w.get())) return nullptr;
  QEvent leave(QEvent::Leave); // no brush outline in the pictures
  QCoreApplication::sendEvent(w->viewport(), &leave);
  return w;
}

void ViewsRenderTest::viewKeysTurnTheCameraAndPutEachAxisWhereItBelongs() {
  window_ = openSphere();
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  vtkCamera* camera = cameraOf(*window_);
  struct Case {
    const char* name;
    Qt::Key key;
    bool ctrl;
    Vec3 dop, up;
    const char* colours; // at the centre, right, left, top and bottom of the sphere
  };
  // Blender's keypad: 1 front, Ctrl+1 back, 3 right, Ctrl+3 left, 7 top, Ctrl+7 bottom; the
  // model's front faces +z, its up is +y.
  const Case cases[] = {
      {"front", Qt::Key_1, false, {0, 0, -1}, {0, 1, 0}, "BRCGC"},
      {"back", Qt::Key_1, true, {0, 0, 1}, {0, 1, 0}, "CCRGC"},
      {"right", Qt::Key_3, false, {-1, 0, 0}, {0, 1, 0}, "RCBGC"},
      {"left", Qt::Key_3, true, {1, 0, 0}, {0, 1, 0}, "CBCGC"},
      {"top", Qt::Key_7, false, {0, -1, 0}, {0, 0, -1}, "GRCCB"},
      {"bottom", Qt::Key_7, true, {0, 1, 0}, {0, 0, 1}, "CRCBC"},
  };
  const QRgb background = grab(*window_).pixel(2, 2);
  for (const Case& c : cases) {
    orbitDrag(view, {{0, 0}, {37, 11}, {70, 29}}); // start from somewhere else each time
    const double distanceBefore = camera->GetDistance();
    QTest::keyClick(view, c.key,
                    Qt::KeypadModifier | (c.ctrl ? Qt::ControlModifier : Qt::NoModifier));
    QVERIFY2(distance(directionOfProjection(camera), c.dop) < 1e-6, c.name);
    QVERIFY2(distance(viewUp(camera), c.up) < 1e-6, c.name);
    QVERIFY2(std::abs(camera->GetDistance() - distanceBefore) < 1e-9, c.name); // zoom kept

    const QImage image = grab(*window_);
    const double* f = camera->GetFocalPoint();
    const core::Vec3f focal{float(f[0]), float(f[1]), float(f[2])};
    const Vec3 u = viewUp(camera);
    const QPointF centre = view->project(focal);
    const double radius =
        QLineF(centre, view->project(focal + core::Vec3f{float(u[0]), float(u[1]), float(u[2])}))
            .length();
    QVERIFY2(radius > 100, c.name);
    const double r = 0.85 * radius;
    const QPointF spots[] = {centre, centre + QPointF(r, 0), centre - QPointF(r, 0),
                             centre - QPointF(0, r), centre + QPointF(0, r)};
    QString seen;
    for (const QPointF& s : spots)
      seen += QChar(colourClass(image.pixel(s.toPoint()), background));
    QVERIFY2(seen == QLatin1String(c.colours),
             qPrintable(QString("%1: %2, expected %3").arg(c.name, seen, c.colours)));
  }
  // The View menu holds them too, with their keys.
  QCOMPARE(window_->action("actionViewTop")->shortcut(),
           QKeySequence(Qt::KeypadModifier | Qt::Key_7));
  window_->action("actionViewFront")->trigger();
  QVERIFY(distance(directionOfProjection(camera), {0, 0, -1}) < 1e-6);
}

void ViewsRenderTest::homeFramesTheModelFromTheCurrentDirection() {
  window_ = openSphere();
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  vtkCamera* camera = cameraOf(*window_);
  // Lost: zoomed far in off to one side, then turned.
  for (int k = 0; k < 6; ++k)
    wheel(view, QPointF(view->width() * 0.8, view->height() * 0.2), 3);
  orbitDrag(view, {{0, 0}, {50, 20}, {90, 40}});
  const Vec3 direction = directionOfProjection(camera);
  QTest::keyClick(view, Qt::Key_Home);
  QVERIFY(distance(directionOfProjection(camera), direction) < 1e-6); // the direction stays
  // Every corner of the bounding box projects inside the view, and the box fills a good part.
  double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
  for (int k = 0; k < 8; ++k) {
    const QPointF p =
        view->project({k & 1 ? 1.0f : -1.0f, k & 2 ? 1.0f : -1.0f, k & 4 ? 1.0f : -1.0f});
    left = std::min(left, p.x());
    right = std::max(right, p.x());
    top = std::min(top, p.y());
    bottom = std::max(bottom, p.y());
  }
  QVERIFY2(left >= 0 && top >= 0 && right <= view->width() && bottom <= view->height(),
           qPrintable(QString("%1 %2 %3 %4").arg(left).arg(top).arg(right).arg(bottom)));
  // VTK's framing fits the box's bounding sphere in the view: the box's outline fills over half.
  QVERIFY2(bottom - top > 0.5 * view->height(), qPrintable(QString::number(bottom - top)));
  // And the model is in the picture's middle.
  const QImage image = grab(*window_);
  QVERIFY(colourClass(image.pixel(image.width() / 2, image.height() / 2), image.pixel(2, 2)) !=
          '-');
}

void ViewsRenderTest::orthographicToggleChangesTheProjectionAndPicksStraight() {
  window_ = openSphere();
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  vtkCamera* camera = cameraOf(*window_);
  const QPointF centre = view->project({0, 0, 0});
  const double perspectiveRadius = QLineF(centre, view->project({0, 1, 0})).length();
  const QImage perspective = grab(*window_);
  QVERIFY(!camera->GetParallelProjection());
  QVERIFY(QLineF(view->project({0.5f, 0, 0.8f}), view->project({0.5f, 0, -0.8f})).length() > 10);

  QTest::keyClick(view, Qt::Key_5, Qt::KeypadModifier);
  QVERIFY(camera->GetParallelProjection());
  QVERIFY(window_->action("actionOrthographic")->isChecked());
  // The focal plane keeps its size on screen.
  const double orthoRadius = QLineF(view->project({0, 0, 0}), view->project({0, 1, 0})).length();
  QVERIFY2(std::abs(orthoRadius - perspectiveRadius) < 1.0,
           qPrintable(QString("%1 vs %2").arg(orthoRadius).arg(perspectiveRadius)));
  // In parallel projection depth does not move a point on screen; in perspective a nearer
  // point lies further from the centre. And the sphere's outline is its equator.
  const QImage ortho = grab(*window_);
  QVERIFY(ortho != perspective);
  QVERIFY(QLineF(view->project({0.5f, 0, 0.8f}), view->project({0.5f, 0, -0.8f})).length() < 0.01);
  const QRgb background = ortho.pixel(2, 2);
  int outline = int(centre.x());
  while (outline < ortho.width() - 1 &&
         colourClass(ortho.pixel(outline, int(centre.y())), background) != '-')
    ++outline;
  QVERIFY2(std::abs(outline - centre.x() - orthoRadius) < 1.5,
           qPrintable(QString("%1 vs %2").arg(outline - centre.x()).arg(orthoRadius)));
  // Picking follows the projection: off centre, a pick lands where the cursor is, and its
  // point lies straight behind the cursor (the same screen point, any depth).
  const QPointF cursor = centre + QPointF(0.6 * orthoRadius, -0.3 * orthoRadius);
  const auto hit = view->pickAt(cursor);
  QVERIFY(hit);
  QVERIFY(QLineF(view->project(hit->position), cursor).length() < 1.0);
  QVERIFY(std::abs(hit->position.x - 0.6f) < 0.02f && std::abs(hit->position.y - 0.3f) < 0.02f);

  QTest::keyClick(view, Qt::Key_5, Qt::KeypadModifier);
  QVERIFY(!camera->GetParallelProjection());
  QVERIFY(!window_->action("actionOrthographic")->isChecked());
  QVERIFY(std::abs(QLineF(view->project({0, 0, 0}), view->project({0, 1, 0})).length() -
                   perspectiveRadius) < 1.0);
}

void ViewsRenderTest::turntableKeepsUpUpAndTrackballIsRememberedAndRolls() {
  window_ = openSphere();
  QVERIFY(window_);
  QVERIFY(window_->action("actionOrbitTurntable")->isChecked()); // the default
  vtkCamera* camera = cameraOf(*window_);
  const Vec3 before = directionOfProjection(camera);
  orbitDrag(window_->viewport(), kLoop);
  QVERIFY(distance(directionOfProjection(camera), before) > 0.1); // it did turn
  // The screen's horizontal stays level: the model's up axis (+y) stays vertical on screen.
  QVERIFY2(std::abs(screenRight(camera)[1]) < 1e-4,
           qPrintable(QString::number(screenRight(camera)[1])));
  QVERIFY(viewUp(camera)[1] > 0);

  window_->action("actionOrbitTrackball")->trigger();
  QCOMPARE(QSettings().value("view/orbit").toString(), QString("trackball"));
  window_.reset();
  window_ = openSphere(); // remembered
  QVERIFY(window_);
  QVERIFY(window_->action("actionOrbitTrackball")->isChecked());
  QCOMPARE(window_->viewport()->orbitMode(), app::OrbitMode::Trackball);
  camera = cameraOf(*window_);
  orbitDrag(window_->viewport(), kLoop);
  QVERIFY2(std::abs(screenRight(camera)[1]) > 0.05, // the same loop rolls the model
           qPrintable(QString::number(screenRight(camera)[1])));
  // Back to turntable: the next drag levels the view.
  window_->action("actionOrbitTurntable")->trigger();
  orbitDrag(window_->viewport(), {{0, 0}, {10, 0}});
  QVERIFY(std::abs(screenRight(camera)[1]) < 1e-4);
}

void ViewsRenderTest::wheelZoomsAboutThePointUnderTheCursor() {
  window_ = openSphere();
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  vtkCamera* camera = cameraOf(*window_);
  // On the model: the surface point under the cursor stays under it.
  const QPointF cursor = view->project({0, 0, 0}) + QPointF(110, -70);
  const auto hit = view->pickAt(cursor);
  QVERIFY(hit);
  const double distanceBefore = camera->GetDistance();
  wheel(view, cursor, 3);
  QVERIFY(camera->GetDistance() < distanceBefore / 1.4); // 1.15³ closer
  QVERIFY2(QLineF(view->project(hit->position), cursor).length() < 1.0,
           qPrintable(QString("%1").arg(QLineF(view->project(hit->position), cursor).length())));
  const auto again = view->pickAt(cursor);
  QVERIFY(again);
  QVERIFY(std::hypot(again->position.x - hit->position.x, again->position.y - hit->position.y,
                     again->position.z - hit->position.z) < 0.01f);
  wheel(view, cursor, -3); // and back out
  QVERIFY(std::abs(camera->GetDistance() - distanceBefore) < 1e-6 * distanceBefore);
  QVERIFY(QLineF(view->project(hit->position), cursor).length() < 1.0);

  // Off the model: the focal plane scales about the cursor, so the model's centre moves away
  // from it by the zoom factor.
  const QPointF corner(40, 40);
  QVERIFY(!view->pickAt(corner));
  const QPointF centreBefore = view->project({0, 0, 0});
  wheel(view, corner, 2);
  const QPointF expected = corner + (centreBefore - corner) * (1.15 * 1.15);
  QVERIFY2(QLineF(view->project({0, 0, 0}), expected).length() < 1.5,
           qPrintable(QString("%1,%2 vs %3,%4")
                          .arg(view->project({0, 0, 0}).x())
                          .arg(view->project({0, 0, 0}).y())
                          .arg(expected.x())
                          .arg(expected.y())));

  // Orthographic too.
  QTest::keyClick(view, Qt::Key_Home);
  QTest::keyClick(view, Qt::Key_5, Qt::KeypadModifier);
  const QPointF cursor2 = view->project({0, 0, 0}) + QPointF(-90, 60);
  const auto hit2 = view->pickAt(cursor2);
  QVERIFY(hit2);
  const double scaleBefore = camera->GetParallelScale();
  wheel(view, cursor2, 4);
  QVERIFY(camera->GetParallelScale() < scaleBefore / 1.6);
  QVERIFY(QLineF(view->project(hit2->position), cursor2).length() < 1.0);
}

void ViewsRenderTest::saveImageWritesAPngOfTheRequestedSize() {
  QCOMPARE(app::suggestedSavePath("/models/clay/head.exr", {}, "png", "/pictures"),
           QString("/models/clay/head.png"));
  QCOMPARE(app::suggestedSavePath({}, {}, "png", "/pictures"), QString("/pictures/untitled.png"));

  window_ = openSphere();
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  const QImage shown = grab(*window_);
  const QRgb background = shown.pixel(2, 2);

  // A chosen size, larger than the window and of another aspect; the model fills the middle.
  const QString big = dir_.filePath("big.png");
  QVERIFY(window_->saveImage(big, QSize(1600, 900), true));
  QImage image(big);
  QCOMPARE(image.size(), QSize(1600, 900));
  QCOMPARE(colourClass(image.pixel(800, 450), background), 'B'); // the front's blue cap
  QCOMPARE(image.pixel(3, 3), background);
  QCOMPARE(qAlpha(image.pixel(3, 3)), 255);
  // The view on screen is unchanged afterwards (same size, same picture).
  const QImage after = grab(*window_);
  QCOMPARE(after.size(), shown.size());
  QCOMPARE(after.pixel(after.width() / 2, after.height() / 2),
           shown.pixel(shown.width() / 2, shown.height() / 2));

  // Without the background: transparent corners, an opaque model.
  const QString clear = dir_.filePath("clear.png");
  QVERIFY(window_->saveImage(clear, QSize(500, 400), false));
  image = QImage(clear);
  QCOMPARE(image.size(), QSize(500, 400));
  QVERIFY(image.hasAlphaChannel());
  QCOMPARE(qAlpha(image.pixel(2, 2)), 0);
  QCOMPARE(qAlpha(image.pixel(497, 397)), 0);
  QCOMPARE(qAlpha(image.pixel(250, 200)), 255);
  QCOMPARE(colourClass(image.pixel(250, 200), background), 'B');

  // The menu at the window's size (a file chooser set: no dialog), and it matches the screen.
  const QString menuPath = dir_.filePath("menu"); // no suffix: .png is added
  window_->setFileChooser([&](MainWindow::FileRequest r) {
    return r == MainWindow::FileRequest::SaveImage ? menuPath : QString();
  });
  window_->action("actionSaveImage")->trigger();
  image = QImage(menuPath + ".png");
  QCOMPARE(image.size(), view->size() * view->devicePixelRatioF());
  // The same picture, but that the 2×2 quads the shader takes derivatives over pair other pixels
  // in the screen's top-down rows than offscreen: a few pixels at folds differ a little.
  const app::testing::PixelDifference d = app::testing::comparePixels(image, shown, 7);
  QVERIFY2(d.differing * 200 <= d.compared && d.worst <= 40,
           qPrintable(QString("%1 of %2, worst %3").arg(d.differing).arg(d.compared).arg(d.worst)));

  // Out of range: refused with a message, nothing written.
  QVERIFY(!window_->saveImage(dir_.filePath("huge.png"), QSize(100000, 10), true));
  QVERIFY(!QFile::exists(dir_.filePath("huge.png")));
  QVERIFY(window_->statusBar()->currentMessage().contains("at most"));
}

void ViewsRenderTest::saveImageDialogAsksSizeAndBackground() {
  app::SaveImageDialog dialog(QSize(800, 600), 4096);
  app::ImageRequest r = dialog.request(); // by default the view's size with its background
  QCOMPARE(r.size, QSize(800, 600));
  QVERIFY(r.background);
  const auto buttons = dialog.findChildren<QRadioButton*>();
  const auto boxes = dialog.findChildren<QSpinBox*>();
  QCOMPARE(buttons.size(), 2);
  QCOMPARE(boxes.size(), 2);
  QVERIFY(!boxes[0]->isEnabled());
  buttons[1]->click(); // Custom
  QVERIFY(boxes[0]->isEnabled() && boxes[1]->isEnabled());
  boxes[0]->setValue(3000);
  boxes[1]->setValue(9000); // clamped to the largest side
  dialog.findChild<QCheckBox*>()->setChecked(true);
  r = dialog.request();
  QCOMPARE(r.size, QSize(3000, 4096));
  QVERIFY(!r.background);
}

void ViewsRenderTest::escapeInASpinBoxHandsTheKeysBackWithoutAStroke() {
  window_ = openSphere();
  QVERIFY(window_);
  window_->brushState()->selectBrush("push");
  app::ViewportWidget* view = window_->viewport();
  auto* radius = window_->brushPanel()->findChild<QDoubleSpinBox*>("radius");
  QVERIFY(radius);
  const core::GeometryImage before = view->modeller().document().positions;

  radius->setFocus();
  QVERIFY(QTest::qWaitFor([&] { return radius->hasFocus(); }));
  QTest::keyClick(radius, Qt::Key_Up);
  QTest::keyClick(radius, Qt::Key_3, Qt::KeypadModifier); // a digit in the box goes to the box
  QVERIFY(radius->hasFocus());
  QTest::keyClick(radius, Qt::Key_Escape);
  QVERIFY(view->hasFocus());
  // The next keys reach the model: keypad 3 turns to the right view.
  QTest::keyClick(QApplication::focusWidget(), Qt::Key_3, Qt::KeypadModifier);
  QVERIFY(distance(directionOfProjection(cameraOf(*window_)), {-1, 0, 0}) < 1e-6);
  // And a wheel turn or a right click on the viewport takes the keys back as well.
  radius->setFocus();
  QVERIFY(QTest::qWaitFor([&] { return radius->hasFocus(); }));
  QTest::mouseClick(view, Qt::RightButton, {}, QPoint(view->width() / 2, view->height() / 2));
  QVERIFY(view->hasFocus());
  // A left click on the model while the box has the keys takes them back without a stroke.
  radius->setFocus();
  QVERIFY(QTest::qWaitFor([&] { return radius->hasFocus(); }));
  QTest::mouseClick(view, Qt::LeftButton, {}, QPoint(view->width() / 2, view->height() / 2));
  QVERIFY(view->hasFocus());
  // Nothing was stroked.
  QTRY_COMPARE(window_->undoStack()->count(), 0);
  QCOMPARE(view->stats().dabs, 0LL);
  QVERIFY(view->modeller().document().positions.at(10, 20).x == before.at(10, 20).x);
}

void ViewsRenderTest::idleStatusBarShowsNoZeroFrameRate() {
  window_ = openSphere();
  QVERIFY(window_);
  const auto frameLabels = [&] {
    QStringList texts;
    for (QLabel* l : window_->statusBar()->findChildren<QLabel*>())
      if (l->text().contains("frames/s")) texts << l->text();
    return texts;
  };
  // Drawing: a figure.
  for (int k = 0; k < 8; ++k) {
    window_->viewport()->update();
    QTest::qWait(40);
  }
  QVERIFY(QTest::qWaitFor([&] { return !frameLabels().isEmpty(); }, 1500));
  QVERIFY2(!frameLabels().front().startsWith("0 "), qPrintable(frameLabels().front()));
  // Idle over a second: no "0 frames/s".
  QTest::qWait(1700);
  QVERIFY2(frameLabels().isEmpty(), qPrintable(frameLabels().join(", ")));
}

// An imported model is first seen from the side it faces (core::guessFacing), framed, +y up,
// whatever view came before (the back): spot and Max Planck face -z in their files; a head whose
// face looks along +z stays on +z.
void ViewsRenderTest::importedModelIsShownFromTheFront() {
  const QString folder = QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/";
  const QString spot = folder + "spot.obj", planck = folder + "max_planck_decimated.obj";
  if (!QFile::exists(spot)) OCTACLAY_MISSING_SHARED_DATA("spot.obj");
  if (!QFile::exists(planck)) OCTACLAY_MISSING_SHARED_DATA("max_planck_decimated.obj");
  const QString head = dir_.filePath("head.obj");
  {
    QFile file(head);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(headObj(48, 96));
  }
  window_ = openSphere();
  QVERIFY(window_);
  vtkCamera* camera = cameraOf(*window_);
  for (const auto& [mesh, towardEye] :
       {std::pair{spot, Vec3{0, 0, -1}}, {planck, Vec3{0, 0, -1}}, {head, Vec3{0, 0, 1}}}) {
    window_->viewport()->setView(app::ViewDirection::Back);
    QVERIFY(distance(directionOfProjection(camera), {0, 0, 1}) < 1e-6);
    if (mesh == spot) { // through the menu, as a user imports
      window_->setFileChooser([&](MainWindow::FileRequest r) {
        return r == MainWindow::FileRequest::Import ? mesh : QString();
      });
      window_->action("actionImport")->trigger();
    } else { // File ▸ Import would first ask to save the import before
      QVERIFY(window_->importMesh(mesh, 128));
    }
    QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
    const Vec3 looking{-towardEye[0], -towardEye[1], -towardEye[2]};
    QVERIFY2(distance(directionOfProjection(camera), looking) < 1e-6, qPrintable(mesh));
    QVERIFY(distance(viewUp(camera), {0, 1, 0}) < 1e-6);
    const QImage image = grab(*window_);
    QVERIFY(colourClass(image.pixel(image.width() / 2, image.height() / 2), image.pixel(2, 2)) !=
            '-');
  }
}

QTEST_MAIN(ViewsRenderTest)
#include "views_render_test.moc"
