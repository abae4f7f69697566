// File ▸ Save Compressed of a scene (issue 33, item 4): the modeller writes every object into the
// .ocz (names, transforms, visibility, locks, positions exact with an exact codec) and File ▸
// Open reads it back as the same scene; a lone object at the identity keeps today's one-document
// format (version 1). Through the real window (xcb under Xvfb).
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QFile>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <memory>

using namespace octaclay;
using app::MainWindow;

namespace {

core::Scene threeObjects() {
  core::Scene scene =
      core::sceneOf(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 32)), "Body");
  scene.objects.push_back({"Box",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Cube, 16)),
                           {{3.0f, 0.25f, 0.0f}, {0.0f, 30.0f, 0.0f}, {0.5f, 0.75f, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Lump",
                           core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 32)),
                           {{-3.0f, 0.0f, 0.5f}, {10.0f, 0.0f, -20.0f}, {0.4f, 0.4f, 0.8f}},
                           false,
                           true});
  return scene;
}

void requireSameScene(const core::Scene& a, const core::Scene& b) {
  QCOMPARE(b.objects.size(), a.objects.size());
  for (std::size_t k = 0; k < a.objects.size(); ++k) {
    const core::SceneObject& x = a.objects[k];
    const core::SceneObject& y = b.objects[k];
    QCOMPARE(y.name, x.name);
    QVERIFY2(x.transform == y.transform, x.name.c_str());
    QCOMPARE(y.visible, x.visible);
    QCOMPARE(y.locked, x.locked);
    const auto p = x.document.positions.texels(), q = y.document.positions.texels();
    QCOMPARE(q.size(), p.size());
    for (std::size_t t = 0; t < p.size(); ++t) // xyz bit-exact (saliency is derived data)
      QVERIFY2(std::memcmp(&p[t], &q[t], 12) == 0, x.name.c_str());
  }
}

std::uint16_t versionOf(const QString& path) {
  QFile file(path);
  if (!file.open(QIODevice::ReadOnly)) return 0;
  const QByteArray head = file.read(6);
  return head.size() < 6 ? 0 : std::uint16_t(std::uint8_t(head[4]) | std::uint8_t(head[5]) << 8);
}

} // namespace

class SaveCompressedSceneTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() {
    QVERIFY(dir_.isValid());
    QStandardPaths::setTestModeEnabled(true);
    QCoreApplication::setOrganizationName("OctaclayTest");
    QCoreApplication::setApplicationName("save_compressed_scene_test");
    qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  }
  void cleanup() { window_.reset(); }

  void severalObjectsSavedAndOpenedAsAScene() {
    const core::Scene original = threeObjects();
    const QString exr = dir_.filePath("three.exr"), ocz = dir_.filePath("three.ocz");
    core::writeScene(original, exr.toStdString());
    window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
    QVERIFY(window_);
    QVERIFY(window_->openDocument(exr));
    QCOMPARE(window_->viewport()->modeller().objectCount(), 3);
    QVERIFY(window_->saveCompressed(ocz, {"lossless", {}, "lossless"}));
    QCOMPARE(versionOf(ocz), core::kCompressedSceneVersion);
    requireSameScene(original, core::readCompressedScene(ocz.toStdString()));

    window_.reset();
    window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
    QVERIFY(window_->openDocument(ocz));
    app::Modeller& modeller = window_->viewport()->modeller();
    QCOMPARE(modeller.objectCount(), 3);
    requireSameScene(original, modeller.scene());
  }

  void aLoneObjectKeepsTodaysFormat() {
    const QString exr = dir_.filePath("one.exr"), ocz = dir_.filePath("one.ocz");
    core::writeDocument(core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 32)),
                        exr.toStdString());
    window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
    QVERIFY(window_->openDocument(exr));
    QVERIFY(window_->saveCompressed(ocz, {"lossless", {}, "lossless"}));
    QCOMPARE(versionOf(ocz), std::uint16_t{1});
    QVERIFY(window_->openDocument(ocz));
    QCOMPARE(window_->viewport()->modeller().objectCount(), 1);
  }

private:
  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

QTEST_MAIN(SaveCompressedSceneTest)
#include "save_compressed_scene_test.moc"
