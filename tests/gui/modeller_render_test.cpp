// The modeller end to end, drawing through the real VTK viewport (xcb under Xvfb, llvmpipe):
// pixels read back, synthetic mouse drags, undo, plugins, files and crash recovery.
#include "brush_panel.h"
#include "layers_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/measure/stretch.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QImage>
#include <QProgressDialog>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>

using namespace octaclay;
using app::MainWindow;
using app::testing::bitEqual;
using app::testing::positionsOf;

namespace {

// A PID no process has (checked by the recovery store's own tests): a "crashed" session.
constexpr qint64 kDeadPid = 0x7ffffff0;

// The brush outline follows the cursor; a Leave event hides it, so images show only the model.
void hideBrushOutline(QWidget* view) {
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(view, &leave);
}

float luminance(QRgb c) {
  return static_cast<float>(0.299 * qRed(c) + 0.587 * qGreen(c) + 0.114 * qBlue(c));
}

class ModellerRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void viewportRendersTheDefaultSphere();
  void dragSculptsUnderTheCursorAndUndoRestoresBitExactly();
  void fineBumpShowsInTheShadingAtLevelEighth();
  void modifiersKeysAndPenPressureShapeTheStroke();
  void pluginDroppedInAtRunTimeAppearsWithItsForm();
  void strokeWithANonFiniteResultIsUndoneWithAMessage();
  void shineReflectionAndChannelPreviewsFollowTheFeatureLayer();
  void stretchPreviewIsColdOnASphereAndHotOnAPulledLimb();
  void splatLaysMaterialInOneStroke();
  void otherPressesDuringAStrokeLeaveItWhole();
  void corruptFileFromTheFileMenuKeepsTheDocument();
  void importTurnsAMeshIntoAModelOrSaysWhyNot();
  void autosaveSurvivesACrashAndIsRecovered();
  void largeDocumentsLoadAndSaveWithProgressWhileTheWindowResponds();

private:
  std::unique_ptr<MainWindow> makeWindow(MainWindow::Options options = {});
  void stroke(MainWindow& w, const QString& brush, float radius, float strength, QPointF from,
              QPointF to);

  QTemporaryDir dir_;
  QString pluginDir_;
  std::unique_ptr<MainWindow> window_;
};

void ModellerRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("modeller_render_test");
  pluginDir_ = dir_.filePath("plugins");
  QVERIFY(QDir().mkpath(pluginDir_));
  // Read by the brush catalog when the viewport's GL starts.
  qputenv("OCTACLAY_PLUGIN_PATH", pluginDir_.toUtf8());
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void ModellerRenderTest::init() {
  QSettings().clear();
}
void ModellerRenderTest::cleanup() {
  window_.reset();
}

std::unique_ptr<MainWindow> ModellerRenderTest::makeWindow(MainWindow::Options options) {
  auto w = app::testing::openTestWindow(dir_.filePath("recovery"), std::move(options));
  if (w) w->brushState()->selectBrush("push");
  return w;
}

// A stroke as the mouse makes it: press, moves in small steps, release.
void ModellerRenderTest::stroke(MainWindow& w, const QString& brush, float radius, float strength,
                                QPointF from, QPointF to) {
  QVERIFY(w.brushState()->selectBrush(brush));
  w.brushState()->setRadius(radius);
  w.brushState()->setStrength(strength);
  QWidget* view = w.viewport();
  QTest::mousePress(view, Qt::LeftButton, {}, from.toPoint());
  for (int k = 1; k <= 10; ++k)
    QTest::mouseMove(view, (from + (to - from) * (k / 10.0)).toPoint());
  QTest::mouseRelease(view, Qt::LeftButton, {}, to.toPoint());
}

void ModellerRenderTest::viewportRendersTheDefaultSphere() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 1024, true));
  QCOMPARE(window_->viewport()->modeller().document().size(), 1024);
  const QImage image = window_->viewport()->grabFramebuffer();
  QVERIFY(!image.isNull());
  const int w = image.width(), h = image.height();
  const QRgb centre = image.pixel(w / 2, h / 2);
  // Background: the same blue-grey in all four corners.
  const QRgb topLeft = image.pixel(2, 2);
  for (QRgb corner : {image.pixel(w - 3, 2), image.pixel(2, h - 3), image.pixel(w - 3, h - 3)})
    QCOMPARE(corner, topLeft);
  QVERIFY(qBlue(topLeft) > qRed(topLeft) + 8); // bluish; the clay is not
  QVERIFY(luminance(topLeft) < 110);
  // The model covers the centre: clay is near grey and much brighter than the background there.
  QVERIFY2(luminance(centre) > 150, qPrintable(QString::number(luminance(centre))));
  QVERIFY(std::abs(qRed(centre) - qBlue(centre)) < 25);
  // Shading varies: the headlit centre is brighter than near the silhouette, smoothly.
  const int radiusPixels = [&] {
    int x = w / 2;
    while (x < w - 1 && std::abs(qRed(image.pixel(x, h / 2)) - qBlue(image.pixel(x, h / 2))) < 25 &&
           luminance(image.pixel(x, h / 2)) > luminance(image.pixel(w - 3, h / 2)) + 10)
      ++x;
    return x - w / 2;
  }();
  QVERIFY2(radiusPixels > h / 6, qPrintable(QString::number(radiusPixels)));
  const float nearRim = luminance(image.pixel(w / 2 + radiusPixels * 9 / 10, h / 2));
  QVERIFY2(luminance(centre) - nearRim > 40,
           qPrintable(QString("%1 vs %2").arg(luminance(centre)).arg(nearRim)));
}

void ModellerRenderTest::dragSculptsUnderTheCursorAndUndoRestoresBitExactly() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  const QPointF from(view->width() / 2.0 - 40, view->height() / 2.0);
  const QPointF to(view->width() / 2.0 + 40, view->height() / 2.0);
  const auto start = view->pickAt(from), end = view->pickAt(to);
  QVERIFY(start && end);
  // The surface under the cursor's path, where the dabs may be centred.
  std::vector<core::Vec3f> path;
  for (int k = 0; k <= 40; ++k) {
    const auto hit = view->pickAt(from + (to - from) * (k / 40.0));
    QVERIFY(hit);
    path.push_back(hit->position);
  }
  const std::vector<float> before = positionsOf(*window_);

  stroke(*window_, "push", 0.05f, 0.2f, from, to);
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  QVERIFY(window_->isModified());
  const std::vector<float> after = positionsOf(*window_);
  QVERIFY(!bitEqual(before, after));

  // Every moved sample lies near the surface path the cursor swept: within a brush radius
  // (0.05 of the unit sphere's bounding-box diagonal, 2√3), plus the push itself, which moves
  // later dab centres off the original surface. And the samples under both ends moved.
  const float reach = 0.05f * 3.4641f * 1.5f;
  int moved = 0;
  for (std::size_t k = 0; k < before.size(); k += 4) {
    if (before[k] == after[k] && before[k + 1] == after[k + 1] && before[k + 2] == after[k + 2])
      continue;
    ++moved;
    const core::Vec3f p{before[k], before[k + 1], before[k + 2]};
    float nearest = 1e9f;
    for (const core::Vec3f& q : path)
      nearest = std::min(nearest, core::length(p - q));
    QVERIFY2(nearest < reach, qPrintable(QString("a sample %1 from the path moved").arg(nearest)));
  }
  QVERIFY(moved > 100);
  const int side = view->modeller().document().size() + 1;
  auto movedAt = [&](core::Sample s) {
    const std::size_t k = (std::size_t(s.j) * side + s.i) * 4;
    return before[k] != after[k] || before[k + 1] != after[k + 1] || before[k + 2] != after[k + 2];
  };
  QVERIFY(movedAt(start->sample));
  QVERIFY(movedAt(end->sample));

  window_->action("actionUndo")->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), before));
  QVERIFY(!window_->isModified());
  window_->action("actionRedo")->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), after));
}

void ModellerRenderTest::fineBumpShowsInTheShadingAtLevelEighth() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 1024, true));
  app::ViewportWidget* view = window_->viewport();
  view->setLevelDivisor(8);
  QCOMPARE(view->stats().displayedTriangles, 2LL * 128 * 128);
  const QImage plain = view->grabFramebuffer();
  // One dab of a bump 1 % of the diagonal wide: about 9 samples of N = 1024, 1 displayed cell.
  QVERIFY(window_->brushState()->selectBrush("inflate"));
  window_->brushState()->setRadius(0.01f);
  window_->brushState()->setStrength(1.0f);
  const QPointF centre(view->width() / 2.0 + 15, view->height() / 2.0 - 10);
  for (int k = 0; k < 4; ++k) { // four dabs in place: a bump about a third as high as wide
    view->beginStrokeAt(centre);
    QVERIFY(view->stroking());
    view->endStroke();
  }
  QTRY_COMPARE(window_->undoStack()->count(), 4);
  hideBrushOutline(view);
  const QImage bumped = view->grabFramebuffer();
  int changed = 0, far = 0;
  float largest = 0;
  for (int y = 0; y < plain.height(); ++y)
    for (int x = 0; x < plain.width(); ++x) {
      const float d = std::abs(luminance(plain.pixel(x, y)) - luminance(bumped.pixel(x, y)));
      if (d < 12) continue; // rasterization noise stays far below this
      ++changed;
      largest = std::max(largest, d);
      if (std::hypot(x - centre.x(), y - centre.y()) > 60) ++far;
    }
  QVERIFY2(changed > 30 && largest > 40,
           qPrintable(QString("%1 pixels changed, largest %2").arg(changed).arg(largest)));
  QCOMPARE(far, 0); // the change is where the bump is
  // Undo brings the image back (the normal map is refreshed too).
  for (int k = 0; k < 4; ++k)
    window_->action("actionUndo")->trigger();
  hideBrushOutline(view);
  const QImage undone = view->grabFramebuffer();
  int differ = 0;
  for (int y = 0; y < plain.height(); ++y)
    for (int x = 0; x < plain.width(); ++x)
      if (std::abs(luminance(plain.pixel(x, y)) - luminance(undone.pixel(x, y))) > 3) ++differ;
  QCOMPARE(differ, 0);
}

void ModellerRenderTest::modifiersKeysAndPenPressureShapeTheStroke() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  const QPoint centre(view->width() / 2, view->height() / 2);
  const auto hit = view->pickAt(centre);
  QVERIFY(hit);
  auto radial = [&] { // distance from the sphere's centre of the sample under the cursor
    const auto p = view->modeller().document().positions.at(hit->sample.i, hit->sample.j);
    return core::length(core::Vec3f{p.x, p.y, p.z});
  };
  QVERIFY(window_->brushState()->selectBrush("push"));
  window_->brushState()->setRadius(0.05f);
  window_->brushState()->setStrength(1.0f);
  auto click = [&](Qt::KeyboardModifiers mods) {
    QTest::mousePress(view, Qt::LeftButton, mods, centre);
    QTest::mouseRelease(view, Qt::LeftButton, mods, centre);
  };
  // push raises along the normal; Ctrl pulls back by the same amount; two undoable strokes.
  const float r0 = radial();
  click({});
  const float pushed = radial();
  QVERIFY2(pushed > r0 + 0.01f, qPrintable(QString("%1 -> %2").arg(r0).arg(pushed)));
  click(Qt::ControlModifier);
  QVERIFY2(std::abs(radial() - r0) < 0.002f, qPrintable(QString::number(radial() - r0)));
  QTRY_COMPARE(window_->undoStack()->count(), 2);
  // Shift smooths instead of pushing: it lowers a fresh bump's top.
  click({});
  const float bumped = radial();
  QVERIFY(bumped > r0 + 0.01f);
  const std::vector<float> beforeSmooth = positionsOf(*window_);
  click(Qt::ShiftModifier);
  QTRY_COMPARE(window_->undoStack()->text(window_->undoStack()->count() - 1),
               QString("Stroke (smooth)"));
  QVERIFY(!bitEqual(beforeSmooth, positionsOf(*window_)));
  QVERIFY(radial() <= bumped); // smoothing never lifts a bump's top

  // [ and ] scale the radius, Shift+[ and Shift+] the strength.
  const float radius = window_->brushState()->radius();
  QTest::keyClick(view, Qt::Key_BracketRight);
  QVERIFY(std::abs(window_->brushState()->radius() - radius * 1.1f) < 1e-3f);
  QTest::keyClick(view, Qt::Key_BracketLeft);
  QTest::keyClick(view, Qt::Key_BracketLeft);
  QVERIFY(window_->brushState()->radius() < radius);
  window_->brushState()->setStrength(0.5f);
  const float strength = window_->brushState()->strength();
  QTest::keyClick(view, Qt::Key_BraceRight, Qt::ShiftModifier);
  QVERIFY(std::abs(window_->brushState()->strength() - strength * 1.1f) < 1e-3f);
  QTest::keyClick(view, Qt::Key_BracketLeft, Qt::ShiftModifier);
  QVERIFY(std::abs(window_->brushState()->strength() - strength) < 1e-3f);

  // Pen pressure scales strength: a dab at pressure 0.25 moves a quarter as far.
  window_->brushState()->setRadius(0.05f);
  window_->brushState()->setStrength(1.0f);
  window_->brushState()->setPressureTarget(app::PressureTarget::Strength);
  auto penDab = [&](qreal pressure) {
    const QPointingDevice* pen = QPointingDevice::primaryPointingDevice();
    QTabletEvent press(QEvent::TabletPress, pen, QPointF(centre), QPointF(centre), pressure, 0, 0,
                       0, 0, 0, {}, Qt::LeftButton, Qt::LeftButton);
    QCoreApplication::sendEvent(view, &press);
    const float r = radial();
    QTest::mousePress(view, Qt::LeftButton, {}, centre);
    QTest::mouseRelease(view, Qt::LeftButton, {}, centre);
    QTabletEvent release(QEvent::TabletRelease, pen, QPointF(centre), QPointF(centre), 0, 0, 0, 0,
                         0, 0, {}, Qt::LeftButton, Qt::NoButton);
    QCoreApplication::sendEvent(view, &release);
    return radial() - r;
  };
  const float full = penDab(1.0), light = penDab(0.25);
  QVERIFY2(full > 0.01f && std::abs(light / full - 0.25f) < 0.05f,
           qPrintable(QString("full %1, light %2").arg(full).arg(light)));
}

void ModellerRenderTest::shineReflectionAndChannelPreviewsFollowTheFeatureLayer() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  const QPoint centre(view->width() / 2, view->height() / 2);
  const QPoint side(view->width() / 2 + view->height() / 5, view->height() / 2);
  auto grab = [&] {
    hideBrushOutline(view);
    return view->grabFramebuffer();
  };
  auto lum = [](const QImage& image, QPoint p) { return luminance(image.pixel(p)); };
  // The specular preview of the unpainted clay: its default 0.25 everywhere.
  window_->layersPanel()->setPreview(3);
  QVERIFY(std::abs(lum(grab(), centre) - 0.25f * 255) < 4);
  window_->layersPanel()->setPreview(0);
  const QImage plain = grab();

  // More shine: the headlight's highlight at the centre brightens where specular was raised.
  // (radius and strength are remembered per brush: set them after choosing it)
  QVERIFY(window_->brushState()->selectBrush("paint-specular"));
  window_->brushState()->setRadius(0.06f);
  window_->brushState()->setStrength(1.0f);
  view->beginStrokeAt(centre);
  view->endStroke();
  QVERIFY2(lum(grab(), centre) > lum(plain, centre) + 5,
           qPrintable(QString("%1 -> %2").arg(lum(plain, centre)).arg(lum(grab(), centre))));
  window_->action("actionUndo")->trigger();
  QCOMPARE(grab().pixel(centre), plain.pixel(centre));

  // Full reflectivity at the centre: the environment shows there, nowhere else.
  QVERIFY(window_->brushState()->selectBrush("paint-reflectivity"));
  window_->brushState()->setRadius(0.06f);
  window_->brushState()->setStrength(1.0f);
  view->beginStrokeAt(centre);
  view->endStroke();
  const QImage reflective = grab();
  QVERIFY2(std::abs(lum(reflective, centre) - lum(plain, centre)) > 15,
           qPrintable(QString("%1 -> %2").arg(lum(plain, centre)).arg(lum(reflective, centre))));
  QCOMPARE(reflective.pixel(side), plain.pixel(side));
  // The reflectivity channel alone: bright where painted (value 0.8), black elsewhere.
  window_->layersPanel()->setPreview(4);
  const QImage channel = grab();
  QVERIFY(std::abs(lum(channel, centre) - 0.8f * 255) < 8);
  QVERIFY(lum(channel, side) < 2);
  window_->layersPanel()->setPreview(0);
}

// The Stretch preview (layers panel row 7) computes the stretch on the GPU from the positions
// and colours it as the saliency: a fresh sphere (stretch 0.6×–1.7×) is blue wherever the
// model shows; a thin limb pulled out of it (the CPU limb of stretch_test, here along +x so the
// camera on +z sees it side on, and across the image's fold at sample (N, N/2)) is red.
void ModellerRenderTest::stretchPreviewIsColdOnASphereAndHotOnAPulledLimb() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* view = window_->viewport();
  window_->layersPanel()->setPreview(7);
  QCOMPARE(window_->layersPanel()->preview(), app::LayersPanel::Preview::Stretch);
  const auto describe = [](QRgb c) {
    return QString("(%1, %2, %3)").arg(qRed(c)).arg(qGreen(c)).arg(qBlue(c));
  };
  // Model pixels on a lattice, away from the silhouette (where pixels blend in the
  // background): those whose pick and four neighbours' picks 3 px away hit the model.
  const auto modelPixels = [&](const std::function<bool(const core::Vec3f&)>& keep, int step) {
    std::vector<QPoint> out;
    for (int y = 6; y < view->height() - 6; y += step)
      for (int x = 6; x < view->width() - 6; x += step) {
        const auto hit = view->pickAt(QPointF(x, y));
        bool inside = hit && keep(hit->position);
        for (const QPoint d : {QPoint(3, 0), QPoint(-3, 0), QPoint(0, 3), QPoint(0, -3)})
          inside = inside && view->pickAt(QPointF(x + d.x(), y + d.y()));
        if (inside) out.emplace_back(x, y);
      }
    return out;
  };
  hideBrushOutline(view);
  QImage image = view->grabFramebuffer();
  const std::vector<QPoint> sphere = modelPixels([](const core::Vec3f&) { return true; }, 12);
  QVERIFY2(sphere.size() > 100, qPrintable(QString::number(sphere.size())));
  for (const QPoint p : sphere) {
    const QRgb c = image.pixel(p);
    QVERIFY2(qRed(c) < 20 && qGreen(c) < 40 && qBlue(c) > 100,
             qPrintable(QString("(%1, %2): %3").arg(p.x()).arg(p.y()).arg(describe(c))));
  }

  // The limb: samples within 0.2 rad of +x moved out along x by 4.3 (1 − θ/0.2)².
  core::Document limb = view->modeller().document();
  for (core::Vec4f& t : limb.positions.texels()) {
    const double theta = std::acos(std::clamp(double(t.x), -1.0, 1.0));
    if (theta < 0.2) t.x += float(4.3 * (1.0 - theta / 0.2) * (1.0 - theta / 0.2));
  }
  const double cpuMax = [&] {
    const core::StretchMap map = core::measureStretch(limb.positions);
    return double(*std::max_element(map.stretch.begin(), map.stretch.end()));
  }();
  const QString path = dir_.filePath("limb.exr");
  core::writeDocument(limb, path.toStdString());
  QVERIFY(window_->openDocument(path));
  view->resetCamera(); // the limb from the side (opening shows it end-on, as the model's "front")
  QCOMPARE(window_->layersPanel()->preview(), app::LayersPanel::Preview::Stretch);
  hideBrushOutline(view);
  image = view->grabFramebuffer();
  const std::vector<QPoint> onLimb =
      modelPixels([](const core::Vec3f& p) { return p.x > 2.0f; }, 3);
  QVERIFY2(onLimb.size() > 20, qPrintable(QString::number(onLimb.size())));
  int hot = 0;
  for (const QPoint p : onLimb)
    if (qRed(image.pixel(p)) > qBlue(image.pixel(p)) + 60) ++hot;
  qInfo("limb: %d of %zu limb pixels hot (CPU stretch up to %.1f)", hot, onLimb.size(), cpuMax);
  QVERIFY2(hot * 2 > int(onLimb.size()), qPrintable(describe(image.pixel(onLimb.front()))));
  // The body away from the limb stays cold.
  const std::vector<QPoint> body =
      modelPixels([](const core::Vec3f& p) { return p.x < 0.0f && core::length(p) < 1.01f; }, 12);
  QVERIFY(body.size() > 20);
  for (const QPoint p : body)
    QVERIFY2(qBlue(image.pixel(p)) > qRed(image.pixel(p)) + 60,
             qPrintable(describe(image.pixel(p))));
  window_->layersPanel()->setPreview(0);
}

// Presses during a stroke (a double click's, another button's) neither replace the stroke nor
// end it: its dabs land, it is one undo entry, and the next press starts a new stroke.
void ModellerRenderTest::otherPressesDuringAStrokeLeaveItWhole() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  QVERIFY(window_->brushState()->selectBrush("push"));
  window_->brushState()->setRadius(0.1f);
  window_->brushState()->setStrength(0.5f);
  app::ViewportWidget* view = window_->viewport();
  const std::vector<float> before = positionsOf(*window_);
  const QPoint from(view->width() / 2 - 30, view->height() / 2);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  // The press's dab runs in paintGL; a window shown just now may take a few events to paint.
  view->repaint();
  QTRY_VERIFY(!bitEqual(before, positionsOf(*window_)));
  QMouseEvent doubleClick(QEvent::MouseButtonDblClick, QPointF(from),
                          view->mapToGlobal(QPointF(from)), Qt::LeftButton, Qt::LeftButton, {});
  QCoreApplication::sendEvent(view, &doubleClick);
  for (int k = 1; k <= 3; ++k)
    QTest::mouseMove(view, from + QPoint(10 * k, 0));
  // The right button pressed and released mid-stroke: no orbit, and the stroke goes on.
  QTest::mousePress(view, Qt::RightButton, {}, from + QPoint(30, 0));
  QTest::mouseRelease(view, Qt::RightButton, {}, from + QPoint(30, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 0); // not ended by the other button's release
  for (int k = 4; k <= 6; ++k)
    QTest::mouseMove(view, from + QPoint(10 * k, 0));
  QTest::mouseRelease(view, Qt::LeftButton, {}, from + QPoint(60, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  const std::vector<float> stroked = positionsOf(*window_);
  // Nothing is left hanging: the next press and release make a second stroke.
  QTest::mousePress(view, Qt::LeftButton, {}, from, 500);
  QTest::mouseRelease(view, Qt::LeftButton, {}, from);
  QTRY_COMPARE(window_->undoStack()->count(), 2);
  window_->undoStack()->undo();
  QVERIFY(bitEqual(stroked, positionsOf(*window_)));
  window_->undoStack()->undo();
  QVERIFY(bitEqual(before, positionsOf(*window_))); // one undo takes the whole first stroke back
}

void ModellerRenderTest::splatLaysMaterialInOneStroke() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  QVERIFY(window_->viewport()->modeller().materialIds().contains("brick"));
  QVERIFY(window_->brushState()->selectBrush("splat"));
  QVERIFY(qobject_cast<QComboBox*>(window_->brushPanel()->parameterWidget("material")));
  app::ViewportWidget* view = window_->viewport();
  const std::vector<float> before = positionsOf(*window_);
  // Mid-stroke the paint is only on the GPU (read back at the stroke's end); the document the
  // window saves or autosaves must hold it already.
  window_->brushState()->setRadius(0.08f);
  window_->brushState()->setStrength(1.0f);
  const QPoint from(view->width() / 2 - 40, view->height() / 2);
  QTest::mousePress(view, Qt::LeftButton, {}, from);
  for (int k = 1; k <= 5; ++k)
    QTest::mouseMove(view, from + QPoint(8 * k, 0));
  // The queued dabs run in paintGL; a window shown just now may take a few events to paint.
  view->repaint();
  QTRY_VERIFY(!view->modeller().document().diffuse.uniform());
  const core::Document& midStroke = view->modeller().document();
  const int side = midStroke.size() + 1;
  int painted = 0;
  for (std::size_t k = 0; k < midStroke.diffuse.texels.size(); k += 4)
    painted += std::abs(midStroke.diffuse.texels[k] - midStroke.diffuse.fill[0]) > 0.05f;
  QVERIFY2(painted > side, qPrintable(QString::number(painted)));
  for (int k = 6; k <= 10; ++k)
    QTest::mouseMove(view, from + QPoint(8 * k, 0));
  QTest::mouseRelease(view, Qt::LeftButton, {}, from + QPoint(80, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  const core::Document& d = view->modeller().document();
  QVERIFY(!bitEqual(before, positionsOf(*window_)));     // relief
  QVERIFY(!d.diffuse.uniform() && !d.feature.uniform()); // colour, shine, reflectivity
  // One undo takes all of it back.
  window_->action("actionUndo")->trigger();
  QVERIFY(bitEqual(before, positionsOf(*window_)));
  const core::Document& undone = view->modeller().document();
  for (std::size_t k = 0; k < undone.diffuse.texels.size(); k += 4)
    QVERIFY(std::abs(undone.diffuse.texels[k] - undone.diffuse.fill[0]) < 1e-6f);
}

void ModellerRenderTest::pluginDroppedInAtRunTimeAppearsWithItsForm() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  QVERIFY(!window_->brushState()->brushIds().contains("test-ridge"));
  const std::filesystem::path source =
      std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/examples/template-brush";
  const std::filesystem::path target = std::filesystem::path(pluginDir_.toStdString()) / "ridge";
  std::filesystem::create_directories(target);
  std::filesystem::copy_file(source / "brush.glsl", target / "brush.glsl");
  std::ifstream in(source / "manifest.json");
  std::string manifest((std::istreambuf_iterator<char>(in)), {});
  manifest.replace(manifest.find("\"template-brush\""), 16, "\"test-ridge\"");
  std::ofstream(target / "manifest.json") << manifest;

  // The window polls the brush folders once a second.
  QTRY_VERIFY_WITH_TIMEOUT(window_->brushState()->brushIds().contains("test-ridge"), 8000);
  QVERIFY(window_->brushState()->selectBrush("test-ridge"));
  QWidget* height = window_->brushPanel()->parameterWidget("height");
  QVERIFY(height);
  QCOMPARE(height->metaObject()->className(), "QDoubleSpinBox");
  QCOMPARE(window_->brushState()->settings().brushId, std::string("test-ridge"));
  // And it sculpts.
  const std::vector<float> before = positionsOf(*window_);
  app::ViewportWidget* view = window_->viewport();
  view->beginStrokeAt({view->width() / 2.0, view->height() / 2.0});
  view->endStroke();
  QVERIFY(!bitEqual(before, positionsOf(*window_)));
  std::filesystem::remove_all(target);
}

// Issue 20: a brush whose result is NaN is refused when the stroke ends; the model is as it
// was, nothing joins the undo stack, the status bar says why, and the next stroke works.
void ModellerRenderTest::strokeWithANonFiniteResultIsUndoneWithAMessage() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  const std::filesystem::path target = std::filesystem::path(pluginDir_.toStdString()) / "nan";
  std::filesystem::create_directories(target);
  std::ofstream(target / "brush.glsl")
      << "vec4 brush(vec4 value, BrushInput b) {\n"
         "  return b.weight > 0.0 ? vec4(uintBitsToFloat(0x7fc00000u)) : value;\n}\n";
  std::ofstream(target / "manifest.json")
      << R"({"id": "test-nan", "name": "NaN", "api": 1, "shader": "brush.glsl",
             "writes": ["positions"], "area": "volume", "falloff": "constant"})";
  QTRY_VERIFY_WITH_TIMEOUT(window_->brushState()->brushIds().contains("test-nan"), 8000);
  const std::vector<float> before = positionsOf(*window_);
  app::ViewportWidget* view = window_->viewport();
  const QPointF centre(view->width() / 2.0, view->height() / 2.0);
  stroke(*window_, "test-nan", 0.05f, 0.2f, centre, centre + QPointF(20, 0));
  QVERIFY(bitEqual(before, positionsOf(*window_)));
  QTRY_COMPARE(window_->undoStack()->count(), 0);
  const QString message = window_->statusBar()->currentMessage();
  QVERIFY2(message.contains("non-finite value"), qPrintable(message));
  stroke(*window_, "push", 0.05f, 0.2f, centre, centre + QPointF(20, 0));
  QVERIFY(!bitEqual(before, positionsOf(*window_)));
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  std::filesystem::remove_all(target);
}

void ModellerRenderTest::corruptFileFromTheFileMenuKeepsTheDocument() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Blob, 128, true));
  app::ViewportWidget* view = window_->viewport();
  stroke(*window_, "push", 0.05f, 0.2f, {view->width() / 2.0, view->height() / 2.0},
         {view->width() / 2.0 + 20, view->height() / 2.0});
  const QString saved = dir_.filePath("kept.exr");
  QVERIFY(window_->saveDocument(saved));
  const std::vector<float> before = positionsOf(*window_);

  const QString garbage = dir_.filePath("garbage.exr");
  std::ofstream(garbage.toStdString()) << "this is not an OpenEXR file";
  const QString missing = dir_.filePath("missing.exr");
  const QString foreign =
      QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/" +
      QDir(QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0").entryList(QDir::Files).value(0);
  for (const QString& bad : {garbage, missing, foreign}) {
    window_->setFileChooser([&](MainWindow::FileRequest r) {
      return r == MainWindow::FileRequest::Open ? bad : QString();
    });
    window_->action("actionOpen")->trigger();
    QVERIFY2(!window_->lastError().isEmpty(), qPrintable(bad));
    QVERIFY2(window_->lastError().contains(QFileInfo(bad).fileName()),
             qPrintable(window_->lastError()));
    QVERIFY(bitEqual(positionsOf(*window_), before));
    QCOMPARE(window_->currentPath(), QFileInfo(saved).absoluteFilePath());
    QTRY_COMPARE(window_->undoStack()->count(), 1);
  }
  // A torus (issue 33's topologies) of W ≠ H opens as the edited object.
  const QString ring = dir_.filePath("ring.exr");
  core::writeDocument(core::makeDocument(core::makeTorus({}, 64, 32)), ring.toStdString());
  window_->setFileChooser([&](MainWindow::FileRequest) { return ring; });
  window_->action("actionOpen")->trigger();
  QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
  QCOMPARE(window_->viewport()->modeller().document().positions.topology(), core::Topology::Torus);
  QCOMPARE(window_->viewport()->modeller().document().positions.height(), 32);
  // The saved file itself opens and holds the stroke.
  window_->setFileChooser([&](MainWindow::FileRequest) { return saved; });
  window_->action("actionOpen")->trigger();
  QVERIFY(window_->lastError().isEmpty());
  QVERIFY(bitEqual(positionsOf(*window_), before));
}

void ModellerRenderTest::importTurnsAMeshIntoAModelOrSaysWhyNot() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  const QString meshes = QString(OCTACLAY_SHARED_DATA) + "/meshes/";
  // A genus-1 mesh is refused with its reason and the sphere stays.
  const std::vector<float> sphere = positionsOf(*window_);
  window_->setFileChooser([&](MainWindow::FileRequest r) {
    return r == MainWindow::FileRequest::Import ? meshes + "invalid/bob_genus1.obj" : QString();
  });
  window_->action("actionImport")->trigger();
  QVERIFY2(window_->lastError().contains("genus 1"), qPrintable(window_->lastError()));
  QVERIFY(bitEqual(positionsOf(*window_), sphere));
  // Spot becomes a closed 512 model ready to sculpt (the menu's size without a dialog).
  window_->setFileChooser([&](MainWindow::FileRequest r) {
    return r == MainWindow::FileRequest::Import ? meshes + "genus0/spot.obj" : QString();
  });
  window_->action("actionImport")->trigger();
  QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
  const core::Document& d = window_->viewport()->modeller().document();
  QCOMPARE(d.size(), 512);
  QCOMPARE(core::maxSeamGap(d.positions), 0.0f);
  QVERIFY(window_->isModified());
  stroke(*window_, "push", 0.05f, 0.5f,
         {window_->viewport()->width() / 2.0, window_->viewport()->height() / 2.0},
         {window_->viewport()->width() / 2.0 + 20, window_->viewport()->height() / 2.0});
  QTRY_COMPARE(window_->undoStack()->count(), 2); // the import, then the stroke
}

void ModellerRenderTest::autosaveSurvivesACrashAndIsRecovered() {
  const QString folder = dir_.filePath("crash-recovery");
  std::vector<float> stroked;
  {
    MainWindow::Options crashing;
    crashing.recoveryFolder = folder;
    crashing.sessionPid = kDeadPid; // this session "crashes": its lock outlives its process
    std::unique_ptr<MainWindow> first = makeWindow(crashing);
    QVERIFY(first);
    first->startSession();
    QVERIFY(!first->pendingRecovery());
    QVERIFY(first->newDocument(core::BaseShape::Sphere, 128, true));
    app::ViewportWidget* view = first->viewport();
    stroke(*first, "inflate", 0.05f, 0.3f, {view->width() / 2.0, view->height() / 2.0},
           {view->width() / 2.0 + 30, view->height() / 2.0 + 10});
    stroke(*first, "paint", 0.06f, 0.8f, {view->width() / 2.0 - 30, view->height() / 2.0},
           {view->width() / 2.0, view->height() / 2.0 + 30});
    QCOMPARE(first->undoStack()->count(), 2);
    QVERIFY(first->autosaveNow());
    stroked = positionsOf(*first);
    // The crash: the window goes away without closing, so the session never ends cleanly.
  }
  window_ = makeWindow({folder, 0, 0, false});
  QVERIFY(window_);
  window_->startSession();
  QVERIFY(window_->pendingRecovery().has_value());
  QVERIFY(window_->recover());
  QVERIFY(bitEqual(positionsOf(*window_), stroked));
  QVERIFY(
      !window_->viewport()->modeller().document().diffuse.uniform()); // the paint stroke came back
  QVERIFY(window_->isModified());
  QVERIFY(!window_->pendingRecovery());
}

void ModellerRenderTest::largeDocumentsLoadAndSaveWithProgressWhileTheWindowResponds() {
  window_ = makeWindow();
  QVERIFY(window_);
  // Ticks of a GUI-thread timer and sightings of the progress dialog while the work runs.
  int ticks = 0, progressSeen = 0;
  QTimer probe;
  QObject::connect(&probe, &QTimer::timeout, [&] {
    ++ticks;
    for (QProgressDialog* p : window_->findChildren<QProgressDialog*>())
      if (p->isVisible()) ++progressSeen;
  });
  probe.start(20);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 4096, true));
  QCOMPARE(window_->viewport()->modeller().document().size(), 4096);
  // The person sees the model before saving it: its first frame (the one that builds its mesh)
  // is drawn before the save, as it is when the window is on screen.
  QSignalSpy painted(window_->viewport(), &app::ViewportWidget::framePainted);
  window_->viewport()->update();
  QTRY_VERIFY(painted.count() > 0);
  const QString path = dir_.filePath("large.exr");
  // The GUI thread must keep running through the work (the probe ticks every 20 ms), and work
  // long enough for a person to notice (over 300 ms here) must have shown the dialog.
  QElapsedTimer clock;
  auto check = [&](const char* what) {
    const qint64 ms = clock.elapsed();
    const QString figures = QString("%1: %2 ms, %3 ticks, progress seen %4")
                                .arg(what)
                                .arg(ms)
                                .arg(ticks)
                                .arg(progressSeen);
    qInfo("%s", qPrintable(figures));
    QVERIFY2(ms < 60 || ticks >= ms / 20 / 4, qPrintable(figures));
    QVERIFY2(ms < 300 || progressSeen > 0, qPrintable(figures));
  };
  ticks = progressSeen = 0;
  clock.start();
  QVERIFY(window_->saveDocument(path));
  check("save");
  QVERIFY(window_->newDocument(core::BaseShape::Cube, 64, true));
  ticks = progressSeen = 0;
  clock.start();
  QVERIFY(window_->openDocument(path));
  check("open");
  QCOMPARE(window_->viewport()->modeller().document().size(), 4096);
  ticks = 0;
  QVERIFY(window_->exportMesh(dir_.filePath("large.ply"), 4));
  QVERIFY(ticks > 0);
  QVERIFY(QFileInfo(dir_.filePath("large.ply")).size() > 1 << 20);
}

} // namespace

QTEST_MAIN(ModellerRenderTest)
#include "modeller_render_test.moc"
