// The Objects dock, locks, Add and Delete (issue 33, item 3): the dock lists the scene and
// switches, shows, hides, locks and renames its objects; a locked object is not sculpted; Add ▸
// Sphere adds uniquely named objects that are saved; Delete removes the edited one. Drawn
// through the real VTK viewport (xcb under Xvfb, llvmpipe).
#include "history_list.h"
#include "main_window.h"
#include "modeller.h"
#include "objects_panel.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QAction>
#include <QDockWidget>
#include <QMenuBar>
#include <QPushButton>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTreeWidget>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <memory>

using namespace octaclay;
using app::MainWindow;
using app::ObjectsPanel;
using app::testing::bitEqual;
using app::testing::positionsOf;

namespace {

core::Document sphere() {
  return core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64));
}

// Body (a unit sphere at the origin, edited), Box at x = 3 and Lump at x = -3, halved, shown.
core::Scene threeObjects() {
  core::Scene scene = core::sceneOf(sphere(), "Body");
  scene.objects.push_back({"Box",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 64)),
                           {{3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Lump",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 64)),
                           {{-3.0f, 0.0f, 0.0f}, {}, {0.5f, 0.5f, 0.5f}},
                           true,
                           false});
  return scene;
}

QStringList rowNames(const QTreeWidget& list) {
  QStringList names;
  for (int k = 0; k < list.topLevelItemCount(); ++k)
    names << list.topLevelItem(k)->text(ObjectsPanel::Name);
  return names;
}

// How many pixels differ from the background (the top-left corner's) in columns [fromX, toX).
int drawnPixels(const QImage& image, int fromX, int toX) {
  const QRgb background = image.pixel(0, 0);
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = std::max(0, fromX); x < std::min(toX, image.width()); ++x) {
      const QRgb c = image.pixel(x, y);
      count +=
          std::max({std::abs(qRed(c) - qRed(background)), std::abs(qGreen(c) - qGreen(background)),
                    std::abs(qBlue(c) - qBlue(background))}) > 8;
    }
  return count;
}

} // namespace

class ObjectsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void dockListsSwitchesAndRenames();
  void untickingTheEyeHidesTheObject();
  void lockedObjectIsNotSculpted();
  void addSphereTwiceThenDelete();

private:
  // Opens scene in a new test window; the Objects dock's list.
  QTreeWidget* open(const core::Scene& scene, const QString& name);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void ObjectsRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("objects_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void ObjectsRenderTest::cleanup() {
  window_.reset();
}

QTreeWidget* ObjectsRenderTest::open(const core::Scene& scene, const QString& name) {
  const QString path = dir_.filePath(name);
  core::writeScene(scene, path.toStdString());
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (!window_ || !window_->openDocument(path)) return nullptr;
  window_->findChild<QDockWidget*>("ObjectsDock")->raise(); // a tab behind Layers at first
  QCoreApplication::processEvents();
  return window_->objectsPanel()->list();
}

void ObjectsRenderTest::dockListsSwitchesAndRenames() {
  QTreeWidget* list = open(threeObjects(), "three.exr");
  QVERIFY(list);
  app::Modeller& modeller = *window_->modeller();
  QCOMPARE(rowNames(*list), QStringList({"Body", "Box", "Lump"}));
  QCOMPARE(list->currentItem(), list->topLevelItem(0));

  // A click on Lump's row edits Lump.
  const QRect lumpRow = list->visualItemRect(list->topLevelItem(2));
  QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, lumpRow.center());
  QCOMPARE(modeller.activeObject(), 2);
  // Another object made active elsewhere (as Alt+click does): the row follows.
  QVERIFY(modeller.setActiveObject(1));
  QCOMPARE(list->currentItem(), list->topLevelItem(1));

  // A name another object has is refused, and the status bar says why; a free one is taken.
  QVERIFY(!window_->isModified());
  list->topLevelItem(1)->setText(ObjectsPanel::Name, "Lump");
  QCOMPARE(modeller.objectAt(1).name, std::string("Box"));
  QCOMPARE(list->topLevelItem(1)->text(ObjectsPanel::Name), QString("Box"));
  QVERIFY2(window_->statusBar()->currentMessage().contains("already named Lump"),
           qPrintable(window_->statusBar()->currentMessage()));
  list->topLevelItem(1)->setText(ObjectsPanel::Name, "Crate");
  QCOMPARE(modeller.objectAt(1).name, std::string("Crate"));
  QVERIFY(window_->isModified());
  const QString saved = dir_.filePath("renamed.exr");
  QVERIFY(window_->saveDocument(saved));
  QCOMPARE(core::readScene(saved.toStdString()).names(),
           std::vector<std::string>({"Body", "Crate", "Lump"}));
}

void ObjectsRenderTest::untickingTheEyeHidesTheObject() {
  QTreeWidget* list = open(threeObjects(), "eye.exr");
  QVERIFY(list);
  app::ViewportWidget* view = window_->viewport();
  // From (0, 0, 20) towards -z: the box (x = 3) right of x = 1.5, the body left of it.
  vtkCamera* camera = view->renderer()->GetActiveCamera();
  camera->SetParallelProjection(false);
  camera->SetPosition(0, 0, 20);
  camera->SetFocalPoint(0, 0, 0);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(30);
  view->renderer()->ResetCameraClippingRange();
  QEvent leave(QEvent::Leave); // no brush outline
  QCoreApplication::sendEvent(view, &leave);
  auto boxAndBody = [&] {
    const QImage image = view->grabFramebuffer();
    // World x = 1.5 at depth 0: half the view's half-width is 20 · tan 15° · aspect.
    const double halfWidth = 20 * std::tan(15 * M_PI / 180) * image.width() / image.height();
    const int split = qRound((0.5 + 1.5 / halfWidth * 0.5) * image.width());
    return std::pair{drawnPixels(image, split, image.width()), drawnPixels(image, 0, split)};
  };
  const auto [boxBefore, bodyBefore] = boxAndBody();
  QVERIFY2(boxBefore > 500, qPrintable(QString::number(boxBefore)));
  list->topLevelItem(1)->setCheckState(ObjectsPanel::Visible, Qt::Unchecked);
  QVERIFY(!window_->modeller()->objectAt(1).visible);
  QVERIFY(window_->isModified());
  const auto [boxAfter, bodyAfter] = boxAndBody();
  QCOMPARE(boxAfter, 0);
  QVERIFY2(bodyAfter > 500 && std::abs(bodyAfter - bodyBefore) <= bodyBefore / 100,
           qPrintable(QString("%1 then %2").arg(bodyBefore).arg(bodyAfter)));
  const QString saved = dir_.filePath("eye-saved.exr");
  QVERIFY(window_->saveDocument(saved));
  QVERIFY(!core::readScene(saved.toStdString()).objects[1].visible);
  // Alt+click where the hidden box was does not pick it.
  const double halfWidth = 20 * std::tan(15 * M_PI / 180) * view->width() / view->height();
  const QPoint boxCentre(qRound((0.5 + 3 / halfWidth * 0.5) * view->width()), view->height() / 2);
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, boxCentre);
  QCOMPARE(window_->modeller()->activeObject(), 0);
  // Shown again: its pixels are back, and Alt+click there edits it.
  list->topLevelItem(1)->setCheckState(ObjectsPanel::Visible, Qt::Checked);
  QCOMPARE(boxAndBody().first, boxBefore);
  QTest::mouseClick(view, Qt::LeftButton, Qt::AltModifier, boxCentre);
  QCOMPARE(window_->modeller()->activeObject(), 1);
  QCOMPARE(list->currentItem(), list->topLevelItem(1));
}

void ObjectsRenderTest::lockedObjectIsNotSculpted() {
  QTreeWidget* list = open(threeObjects(), "lock.exr");
  QVERIFY(list);
  list->topLevelItem(0)->setCheckState(ObjectsPanel::Locked, Qt::Checked);
  QVERIFY(window_->modeller()->activeLocked());
  // The lock is a step; the refused stroke records none.
  QCOMPARE(window_->modeller()->history().undoCount(), std::size_t(1));
  QCOMPARE(window_->undoStack()->undoText(), QString("Lock Body"));
  const std::vector<float> before = positionsOf(*window_);
  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(bitEqual(positionsOf(*window_), before));
  QCOMPARE(window_->modeller()->history().undoCount(), std::size_t(1));
  QCOMPARE(window_->undoStack()->undoText(), QString("Lock Body"));
  QVERIFY2(window_->statusBar()->currentMessage() == "Body is locked",
           qPrintable(window_->statusBar()->currentMessage()));
  const QString saved = dir_.filePath("lock-saved.exr");
  QVERIFY(window_->saveDocument(saved));
  QVERIFY(core::readScene(saved.toStdString()).objects[0].locked);
  // Unlocked, the same stroke changes it.
  list->topLevelItem(0)->setCheckState(ObjectsPanel::Locked, Qt::Unchecked);
  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(!bitEqual(positionsOf(*window_), before));
  // The edited object's own eye hides it: its pixels go, and a stroke there touches nothing.
  app::ViewportWidget* view = window_->viewport();
  QEvent leave(QEvent::Leave); // no brush outline
  QCoreApplication::sendEvent(view, &leave);
  const QImage shown = view->grabFramebuffer();
  const std::vector<float> sculpted = positionsOf(*window_);
  list->topLevelItem(0)->setCheckState(ObjectsPanel::Visible, Qt::Unchecked);
  QCOMPARE(window_->modeller()->activeObject(), 0);
  const QImage hidden = view->grabFramebuffer();
  const int drawnShown = drawnPixels(shown, 0, shown.width()),
            drawnHidden = drawnPixels(hidden, 0, hidden.width());
  QVERIFY2(drawnShown - drawnHidden > 500,
           qPrintable(QString("%1 then %2").arg(drawnShown).arg(drawnHidden)));
  app::testing::pushStrokeAcross(*window_, 0);
  QVERIFY(bitEqual(positionsOf(*window_), sculpted));
}

void ObjectsRenderTest::addSphereTwiceThenDelete() {
  QTreeWidget* list = open(core::sceneOf(sphere(), "Body"), "one.exr");
  QVERIFY(list);
  app::Modeller& modeller = *window_->modeller();
  QMenu* add = window_->menuBar()->findChild<QMenu*>("menuAdd");
  QVERIFY(add);
  QAction* addSphere = window_->action("actionAddSphere");
  QVERIFY(addSphere);
  double focal[3];
  window_->viewport()->renderer()->GetActiveCamera()->GetFocalPoint(focal);
  addSphere->trigger();
  QCOMPARE(modeller.objectCount(), 2);
  QCOMPARE(modeller.activeObject(), 1);
  QCOMPARE(modeller.document().size(), 64); // the edited object's N
  // A quarter of the scene's size (the body alone: the same unit sphere), at the focal point.
  const core::ObjectTransform& placed = modeller.objectAt(1).transform;
  QVERIFY2(std::abs(placed.scale.x - 0.25f) < 1e-5f, qPrintable(QString::number(placed.scale.x)));
  QCOMPARE(placed.translation.x, float(focal[0]));
  QCOMPARE(placed.translation.y, float(focal[1]));
  QCOMPARE(placed.translation.z, float(focal[2]));
  addSphere->trigger();
  QCOMPARE(rowNames(*list), QStringList({"Body", "Sphere", "Sphere.001"}));
  QCOMPARE(list->currentItem(), list->topLevelItem(2));
  QVERIFY(window_->isModified());
  const QString saved = dir_.filePath("added.exr");
  QVERIFY(window_->saveDocument(saved));
  const core::Scene back = core::readScene(saved.toStdString());
  QCOMPARE(back.names(), std::vector<std::string>({"Body", "Sphere", "Sphere.001"}));
  QCOMPARE(back.objects[2].document.size(), 64);

  // The Delete key on the viewport removes the edited one; the one before it is edited next.
  QApplication::setActiveWindow(window_.get());
  window_->viewport()->setFocus();
  QTest::keyClick(window_->viewport(), Qt::Key_Delete);
  QCOMPARE(rowNames(*list), QStringList({"Body", "Sphere"}));
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY(window_->objectsPanel()->deleteButton()->isEnabled());
  window_->objectsPanel()->deleteButton()->click();
  QCOMPARE(rowNames(*list), QStringList({"Body"}));
  QVERIFY(!window_->objectsPanel()->deleteButton()->isEnabled());
  // The last object stays, and the status bar says why.
  window_->action("actionDeleteObject")->trigger();
  QCOMPARE(modeller.objectCount(), 1);
  QVERIFY2(window_->statusBar()->currentMessage().contains("last object"),
           qPrintable(window_->statusBar()->currentMessage()));
}

QTEST_MAIN(ObjectsRenderTest)
#include "objects_render_test.moc"
