// A scene of several objects in the modeller (issue 33, item 3): File ▸ Open and Save keep every
// object, the active one is edited and switching it keeps the others' work. Drawn through the
// real VTK viewport (xcb under Xvfb, llvmpipe).
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

#include <cstring>
#include <memory>

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

} // namespace

class SceneObjectsRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void cleanup();
  void openSculptSaveKeepsEveryObject();
  void switchingTheActiveObjectKeepsEachOnesWork();

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

  // Switching: the edited body goes back into the scene, the box is uploaded; the history was
  // the body's, so it starts anew (the status bar says so) and the scene stays modified.
  QVERIFY(!modeller.setActiveObject(3));
  QVERIFY(!modeller.setActiveObject(-1));
  QVERIFY(modeller.setActiveObject(1));
  QCOMPARE(modeller.activeObject(), 1);
  QVERIFY(samePositions(modeller.document(), original.objects[1].document));
  QVERIFY(!modeller.canUndo());
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

QTEST_MAIN(SceneObjectsRenderTest)
#include "scene_objects_render_test.moc"
