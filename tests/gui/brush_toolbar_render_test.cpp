// The brush tool bar, the header and F / Shift+F on the canvas, driven with the mouse and keys
// through the real window (xcb under Xvfb): each icon picks its brush as the Brushes dock does;
// the drags change the radius by the dragged amount and the strength, Esc and a right click put
// them back; a fresh window (no settings at all) is one click and one drag from a changed
// surface; and a pull at the default strength leaves no triangle crossing another.
#include "../mesh_self_intersections.h"
#include "brush_header.h"
#include "brush_panel.h"
#include "brush_shortcuts.h"
#include "brush_state.h"
#include "brush_toolbar.h"
#include "canvas_brush_adjust.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <QApplication>
#include <QCheckBox>
#include <QDockWidget>
#include <QFile>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QToolButton>
#include <QTreeWidget>
#include <QUndoStack>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <map>
#include <memory>

using namespace octaclay;
using app::BrushToolBar;
using app::CanvasBrushAdjust;
using app::MainWindow;

namespace {

std::vector<core::Vec3f> positionsOf(const MainWindow& w) {
  const core::GeometryImage& image = w.viewport()->modeller().document().positions;
  std::vector<core::Vec3f> out;
  for (int j = 0; j <= image.size(); ++j)
    for (int i = 0; i <= image.size(); ++i)
      out.push_back(image.at(i, j).xyz());
  return out;
}

float largestMove(const std::vector<core::Vec3f>& a, const std::vector<core::Vec3f>& b) {
  float largest = 0;
  for (std::size_t k = 0; k < a.size(); ++k)
    largest = std::max(largest, core::length(b[k] - a[k]));
  return largest;
}

QString treeCurrentId(const MainWindow& w) {
  const auto* tree = w.brushPanel()->findChild<QTreeWidget*>(QStringLiteral("brushList"));
  return tree && tree->currentItem() ? tree->currentItem()->data(0, Qt::UserRole).toString()
                                     : QString();
}

// Moves the pointer to p over view and waits until the view has seen it: on xcb the move
// travels through the X server, and F and the F-drag read where the view last saw the pointer.
void moveSeen(QWidget* view, QPoint p) {
  // At the application: during F the canvas adjust takes the moves before the view does.
  struct LastMove : QObject {
    QPointF at{-1, -1};
    bool eventFilter(QObject*, QEvent* e) override {
      if (e->type() == QEvent::MouseMove) at = static_cast<QMouseEvent*>(e)->globalPosition();
      return false;
    }
  } seen;
  qApp->installEventFilter(&seen);
  QTest::mouseMove(view, p);
  const QPointF global = view->mapToGlobal(QPointF(p));
  if (!QTest::qWaitFor([&] { return seen.at == global; }, 2000))
    qWarning("the move to (%d, %d) did not reach the view", p.x(), p.y());
  qApp->removeEventFilter(&seen);
}

// Puts the pointer at p over view: from a pixel beside it, since Qt drops a move to where the
// pointer already is.
void pointAt(QWidget* view, QPoint p) {
  moveSeen(view, p - QPoint(1, 1));
  moveSeen(view, p);
}

// Makes w the active window: shortcuts reach only that, and under Xvfb, with no window manager,
// activation does not last by itself.
bool activate(MainWindow& w) {
  QApplication::setActiveWindow(&w);
  return QApplication::activeWindow() == &w;
}

// The ring's radius on screen (pixels) for brush radius r at surface point p: how far p and
// the point r · diagonal to its right on the camera's plane lie apart.
double ringPixels(const app::ViewportWidget& view, core::Vec3f p, float r) {
  vtkCamera* camera = view.renderer()->GetActiveCamera();
  double d[3], up[3];
  camera->GetDirectionOfProjection(d);
  camera->GetViewUp(up);
  const core::Vec3f right =
      core::normalize(core::cross(core::Vec3f{float(d[0]), float(d[1]), float(d[2])},
                                  core::Vec3f{float(up[0]), float(up[1]), float(up[2])}));
  const QPointF a = view.project(p),
                b = view.project(p + right * (r * view.modeller().modelDiagonal()));
  return std::hypot(b.x() - a.x(), b.y() - a.y());
}

} // namespace

class BrushToolBarRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void freshWindowIsOneClickAndOneDragFromAChangedSurface();
  void eachIconSelectsItsBrushAndFollowsTheDock();
  void brushShortcutsPickBrushesAndClashWithNothing();
  void fDragChangesTheRadiusByTheDraggedAmountAndEscRestoresIt();
  void shiftFDragChangesTheStrengthAndRightClickRestoresIt();
  void headerFollowsTheDockAndStaysWhenDocksClose();
  void defaultStrengthPullLeavesNoCrossingTriangle();

private:
  std::unique_ptr<MainWindow> openWindow(int n);
  // A drag as the mouse makes it: press, moves in small steps, release.
  static void drag(QWidget* view, QPoint from, QPoint to, Qt::KeyboardModifiers mods = {});

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void BrushToolBarRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName(QStringLiteral("OctaclayTest"));
  QCoreApplication::setApplicationName(QStringLiteral("brush_toolbar_render_test"));
  // Settings in a folder of the test's own: the first window finds none at all.
  QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, dir_.filePath("settings"));
  QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, dir_.filePath("settings"));
  QVERIFY(QSettings().fileName().startsWith(dir_.path()));
  QVERIFY(!QFile::exists(QSettings().fileName()));
  QVERIFY(QDir().mkpath(dir_.filePath("plugins")));
  qputenv("OCTACLAY_PLUGIN_PATH", dir_.filePath("plugins").toUtf8());
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void BrushToolBarRenderTest::init() {}

void BrushToolBarRenderTest::cleanup() {
  window_.reset();
  QSettings().clear();
}

std::unique_ptr<MainWindow> BrushToolBarRenderTest::openWindow(int n) {
  auto w = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (!w || !w->newDocument(core::BaseShape::Sphere, n, true)) return nullptr;
  auto* bar = w->findChild<BrushToolBar*>(QStringLiteral("BrushToolBar"));
  if (!bar || !QTest::qWaitFor([&] { return bar->brushIds().size() >= 12; }, 10000)) return nullptr;
  return w;
}

void BrushToolBarRenderTest::drag(QWidget* view, QPoint from, QPoint to,
                                  Qt::KeyboardModifiers mods) {
  pointAt(view, from);
  QTest::mousePress(view, Qt::LeftButton, mods, from);
  for (int k = 1; k <= 16; ++k)
    QTest::mouseMove(view, from + (to - from) * k / 16);
  QTest::mouseRelease(view, Qt::LeftButton, mods, to);
}

void BrushToolBarRenderTest::freshWindowIsOneClickAndOneDragFromAChangedSurface() {
  QVERIFY(!QFile::exists(QSettings().fileName())); // no settings: a first start
  window_ = openWindow(256);
  QVERIFY(window_);
  auto* bar = window_->findChild<BrushToolBar*>(QStringLiteral("BrushToolBar"));
  QVERIFY(bar->isVisible());
  app::ViewportWidget* view = window_->viewport();
  const std::vector<core::Vec3f> before = positionsOf(*window_);

  // One click on the Inflate icon, one drag across the model.
  QWidget* button = bar->widgetForAction(bar->brushAction(QStringLiteral("inflate")));
  QVERIFY(button && button->isVisible());
  QTest::mouseClick(button, Qt::LeftButton);
  QCOMPARE(window_->brushState()->currentBrushId(), QStringLiteral("inflate"));
  const QPoint centre(view->width() / 2, view->height() / 2);
  drag(view, centre - QPoint(60, 0), centre + QPoint(60, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 1);

  // The surface swelled where the drag went, visibly but like clay: the largest move is a tenth
  // to a half of the default radius (a horn or a trench would be more).
  const float radius = window_->brushState()->radius() * view->modeller().modelDiagonal();
  const float moved = largestMove(before, positionsOf(*window_));
  qInfo("first stroke: largest move %.4f, %.2f of the radius", double(moved),
        double(moved / radius));
  QVERIFY2(moved > 0.1f * radius && moved < 0.5f * radius,
           qPrintable(QString("moved %1, radius %2").arg(moved).arg(radius)));
}

void BrushToolBarRenderTest::eachIconSelectsItsBrushAndFollowsTheDock() {
  window_ = openWindow(64);
  QVERIFY(window_);
  auto* bar = window_->findChild<BrushToolBar*>(QStringLiteral("BrushToolBar"));
  const QStringList ids = bar->brushIds();
  QCOMPARE(ids, window_->brushState()->brushIds()); // the same brushes in the same order
  for (const QString& id : ids) {
    QAction* action = bar->brushAction(id);
    QVERIFY(action);
    QCOMPARE(action->parent(), window_.get());
    QVERIFY(window_->actions().contains(action)); // its shortcut works with the bar hidden
    QWidget* button = bar->widgetForAction(action);
    QVERIFY(button);
    QTest::mouseClick(button, Qt::LeftButton);
    QCOMPARE(window_->brushState()->currentBrushId(), id);
    QCOMPARE(treeCurrentId(*window_), id);
    QCOMPARE(
        QString::fromStdString(window_->viewport()->modeller().brushState().settings().brushId),
        id);
    QVERIFY(action->isChecked());
    // The tooltip names the brush and its shortcut.
    const QKeySequence key = app::brushShortcut(id);
    QVERIFY(action->toolTip().startsWith(action->text()));
    if (!key.isEmpty())
      QVERIFY2(action->toolTip().contains(key.toString(QKeySequence::NativeText)),
               qPrintable(action->toolTip()));
  }
  // The dock leads as well: picking in its list checks the icon.
  QVERIFY(window_->brushState()->selectBrush(QStringLiteral("smooth")));
  QVERIFY(bar->brushAction(QStringLiteral("smooth"))->isChecked());
  QVERIFY(!bar->brushAction(ids.back())->isChecked());
}

void BrushToolBarRenderTest::brushShortcutsPickBrushesAndClashWithNothing() {
  window_ = openWindow(64);
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  view->setFocus();
  const std::map<int, QString> keys{
      {Qt::Key_S, "smooth"},      {Qt::Key_I, "inflate"}, {Qt::Key_T, "flatten"},
      {Qt::Key_R, "relax"},       {Qt::Key_P, "paint"},   {Qt::Key_M, "mask"},
      {Qt::Key_X, "push"},        {Qt::Key_G, "grab"},    {Qt::Key_K, "snake-hook"},
      {Qt::Key_C, "clay-strips"}, {Qt::Key_L, "layer"}};
  QVERIFY(activate(*window_));
  for (const auto& [key, id] : keys) {
    QTest::keyClick(view, Qt::Key(key));
    QCOMPARE(window_->brushState()->currentBrushId(), id);
  }
  // Each brush key, F and Shift+F belong to one action of the window alone (Move, Rotate and
  // Scale show G, R and S but answer them only inside their menu out of Object Mode).
  std::map<QString, QStringList> owners;
  for (QAction* a : window_->findChildren<QAction*>())
    for (const QKeySequence& k : a->shortcuts())
      if (a->shortcutContext() != Qt::WidgetShortcut)
        owners[k.toString(QKeySequence::PortableText)] << a->objectName();
  for (const auto& [key, id] : keys) {
    const QString text = QKeySequence(key).toString(QKeySequence::PortableText);
    QCOMPARE(owners[text], QStringList{QStringLiteral("actionBrush_") + id});
  }
  QCOMPARE(owners[QStringLiteral("F")], QStringList{QStringLiteral("actionAdjustRadius")});
  QCOMPARE(owners[QStringLiteral("Shift+F")], QStringList{QStringLiteral("actionAdjustStrength")});
}

void BrushToolBarRenderTest::fDragChangesTheRadiusByTheDraggedAmountAndEscRestoresIt() {
  window_ = openWindow(256);
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  app::BrushState* brushes = window_->brushState();
  auto* adjust = window_->findChild<CanvasBrushAdjust*>(QStringLiteral("canvasBrushAdjust"));
  auto* slider = window_->findChild<QSlider*>(QStringLiteral("headerRadius"));
  QVERIFY(adjust && slider);
  const float r0 = brushes->radius();
  const QPoint centre(view->width() / 2, view->height() / 2);
  const auto hit = view->pickAt(centre);
  QVERIFY(hit);
  const double ring0 = ringPixels(*view, hit->position, r0);
  QVERIFY2(ring0 > 10, qPrintable(QString::number(ring0)));

  // F, then 40 pixels to the right: the ring's edge follows the pointer, live.
  QVERIFY(activate(*window_));
  pointAt(view, centre);
  QTest::keyClick(view, Qt::Key_F);
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::Radius);
  moveSeen(view, centre + QPoint(20, 3));
  moveSeen(view, centre + QPoint(40, 7));
  const float r1 = brushes->radius();
  QVERIFY2(
      std::abs(ringPixels(*view, hit->position, r1) - (ring0 + 40)) < 1.0,
      qPrintable(
          QString("ring %1 px -> %2 px").arg(ring0).arg(ringPixels(*view, hit->position, r1))));
  QCOMPARE(view->modeller().brushState().settings().radius,
           r1); // the ring is drawn with it already
  QCOMPARE(slider->value(), app::BrushHeader::radiusToPosition(r1));
  // Esc puts it back exactly; nothing was sculpted.
  QTest::keyClick(view, Qt::Key_Escape);
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::None);
  QCOMPARE(brushes->radius(), r0);
  QCOMPARE(view->modeller().brushState().settings().radius, r0);
  QTRY_COMPARE(window_->undoStack()->count(), 0);

  // Leftwards shrinks it; a click sets it, and the click sculpts nothing.
  pointAt(view, centre); // F starts from where the pointer is
  QTest::keyClick(view, Qt::Key_F);
  QCOMPARE(adjust->origin(), QPointF(centre));
  const int shrink = int(ring0 / 2);
  moveSeen(view, centre - QPoint(shrink, 0));
  const float r2 = brushes->radius();
  QVERIFY2(std::abs(ringPixels(*view, hit->position, r2) - (ring0 - shrink)) < 1.0,
           qPrintable(QString::number(ringPixels(*view, hit->position, r2))));
  QTest::mouseClick(view, Qt::LeftButton, {}, centre - QPoint(shrink, 0));
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::None);
  QCOMPARE(brushes->radius(), r2);
  QTRY_COMPARE(window_->undoStack()->count(), 0);
  // The next press sculpts again.
  drag(view, centre, centre + QPoint(30, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  // F during a stroke does nothing: the stroke goes on and ends as usual.
  pointAt(view, centre);
  QTest::mousePress(view, Qt::LeftButton, {}, centre);
  moveSeen(view, centre + QPoint(10, 0));
  QTest::keyClick(view, Qt::Key_F);
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::None);
  moveSeen(view, centre + QPoint(20, 0));
  QTest::mouseRelease(view, Qt::LeftButton, {}, centre + QPoint(20, 0));
  QTRY_COMPARE(window_->undoStack()->count(), 2);
  QCOMPARE(brushes->radius(), r2);
}

void BrushToolBarRenderTest::shiftFDragChangesTheStrengthAndRightClickRestoresIt() {
  window_ = openWindow(256);
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  app::BrushState* brushes = window_->brushState();
  auto* adjust = window_->findChild<CanvasBrushAdjust*>(QStringLiteral("canvasBrushAdjust"));
  auto* slider = window_->findChild<QSlider*>(QStringLiteral("headerStrength"));
  QVERIFY(adjust && slider);
  const float s0 = brushes->strength();
  const QPoint centre(view->width() / 2, view->height() / 2);
  QVERIFY(activate(*window_));
  pointAt(view, centre);
  QTest::keyClick(view, Qt::Key_F, Qt::ShiftModifier);
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::Strength);
  QCOMPARE(adjust->origin(), QPointF(centre));
  moveSeen(view, centre - QPoint(60, 0));
  const float expected = s0 - float(60 / CanvasBrushAdjust::kPixelsPerStrength);
  QVERIFY2(std::abs(brushes->strength() - expected) < 1e-4f,
           qPrintable(QString("%1 vs %2").arg(brushes->strength()).arg(expected)));
  QCOMPARE(view->modeller().brushState().settings().strength, brushes->strength());
  QCOMPARE(slider->value(), int(std::lround(expected * 100)));
  // A right click cancels: the strength comes back and the camera did not orbit.
  double eye[3];
  view->renderer()->GetActiveCamera()->GetPosition(eye);
  QTest::mousePress(view, Qt::RightButton, {}, centre - QPoint(60, 0));
  moveSeen(view, centre + QPoint(40, 30));
  QTest::mouseRelease(view, Qt::RightButton, {}, centre + QPoint(40, 30));
  QCOMPARE(adjust->mode(), CanvasBrushAdjust::Mode::None);
  QCOMPARE(brushes->strength(), s0);
  double after[3];
  view->renderer()->GetActiveCamera()->GetPosition(after);
  QCOMPARE(after[0], eye[0]);
  QCOMPARE(after[1], eye[1]);
  QCOMPARE(after[2], eye[2]);
  // Far to the right clamps at 100 %; Enter keeps it.
  QTest::keyClick(view, Qt::Key_F, Qt::ShiftModifier);
  moveSeen(view, adjust->origin().toPoint() + QPoint(320, 0)); // 107 % more
  QTest::keyClick(view, Qt::Key_Return);
  QCOMPARE(brushes->strength(), 1.0f);
}

void BrushToolBarRenderTest::headerFollowsTheDockAndStaysWhenDocksClose() {
  window_ = openWindow(64);
  QVERIFY(window_);
  app::BrushState* brushes = window_->brushState();
  auto* header = window_->findChild<app::BrushHeader*>(QStringLiteral("BrushHeader"));
  auto* radius = window_->findChild<QSlider*>(QStringLiteral("headerRadius"));
  auto* strength = window_->findChild<QSlider*>(QStringLiteral("headerStrength"));
  auto* mirrorX = window_->findChild<QAction*>(QStringLiteral("headerSymmetryX"));
  auto* dockX = window_->brushPanel()->findChild<QCheckBox*>(QStringLiteral("symmetryX"));
  QVERIFY(header && radius && strength && mirrorX && dockX);
  // Header → dock.
  radius->setValue(app::BrushHeader::radiusToPosition(0.1f));
  QVERIFY(std::abs(brushes->radius() - 0.1f) < 0.1f * 0.01f); // within the slider's 0.7 % step
  strength->setValue(30);
  QCOMPARE(brushes->strength(), 0.3f);
  mirrorX->trigger();
  QCOMPARE(brushes->settings().symmetry, 1u);
  QVERIFY(dockX->isChecked());
  // Dock → header, also after switching brushes (each brush keeps its own values).
  brushes->setStrength(0.75f);
  QCOMPARE(strength->value(), 75);
  dockX->setChecked(false);
  QVERIFY(!mirrorX->isChecked());
  QVERIFY(brushes->selectBrush(QStringLiteral("smooth")));
  QCOMPARE(strength->value(), int(std::lround(brushes->strength() * 100)));
  QCOMPARE(radius->value(), app::BrushHeader::radiusToPosition(brushes->radius()));
  // Every dock closed: the header is still there, and its tool bar menu cannot hide it.
  for (QDockWidget* dock : window_->findChildren<QDockWidget*>())
    dock->close();
  QVERIFY(header->isVisible());
  QVERIFY(!header->toggleViewAction()->isVisible());
  auto* bar = window_->findChild<BrushToolBar*>(QStringLiteral("BrushToolBar"));
  const int viewTop = window_->viewport()->mapTo(window_.get(), QPoint(0, 0)).y();
  QVERIFY(bar->y() < header->y() && header->y() < viewTop); // icons, header, viewport
}

void BrushToolBarRenderTest::defaultStrengthPullLeavesNoCrossingTriangle() {
  window_ = openWindow(256);
  QVERIFY(window_);
  app::ViewportWidget* view = window_->viewport();
  auto* bar = window_->findChild<BrushToolBar*>(QStringLiteral("BrushToolBar"));
  QTest::mouseClick(bar->widgetForAction(bar->brushAction(QStringLiteral("push"))), Qt::LeftButton);
  const core::GeometryImage start0 = view->modeller().document().positions;
  const core::TriangleMesh start = core::extractMesh(start0);
  QCOMPARE(testing::selfIntersections(start, std::vector<bool>(start.positions.size(), true)), 0);
  // The newcomer's stroke: Ctrl and a drag across the model, back and forth over the trench.
  const QPoint centre(view->width() / 2, view->height() / 2);
  const QPoint a = centre - QPoint(80, 0), b = centre + QPoint(80, 0);
  pointAt(view, a);
  QTest::mousePress(view, Qt::LeftButton, Qt::ControlModifier, a);
  for (int pass = 0; pass < 4; ++pass)
    for (int k = 1; k <= 16; ++k)
      QTest::mouseMove(view, pass % 2 == 0 ? a + (b - a) * k / 16 : b + (a - b) * k / 16);
  QTest::mouseRelease(view, Qt::LeftButton, Qt::ControlModifier, a);
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  for (const int step : {1, 4}) { // the full resolution and N/4, the level shown at N = 1024
    const core::TriangleMesh before = core::extractMesh(start0, step);
    const core::TriangleMesh pulled =
        core::extractMesh(view->modeller().document().positions, step);
    const std::vector<bool> changed = testing::changedVertices(before, pulled);
    const auto count = std::count(changed.begin(), changed.end(), true);
    QVERIFY2(count > 100, qPrintable(QString::number(count)));
    qInfo("pull, level N/%d: %lld samples moved, deepest %.4f (radius %.4f)", step,
          static_cast<long long>(count), double(largestMove(before.positions, pulled.positions)),
          double(window_->brushState()->radius() * view->modeller().modelDiagonal()));
    QCOMPARE(testing::selfIntersections(pulled, changed), 0);
  }
}

QTEST_MAIN(BrushToolBarRenderTest)
#include "brush_toolbar_render_test.moc"
