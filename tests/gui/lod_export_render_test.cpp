// The Level of detail dock's Export… writes what File ▸ Export Mesh writes: a painted model's
// GLB, read back with tinygltf, has a base colour texture holding the paint and a tangent-space
// normalTexture (with the TANGENT attribute that decodes it); its OBJ's MTL names the paint maps
// beside the normal map. Driven through the real window (xcb under Xvfb, llvmpipe).
#include "brush_panel.h"
#include "lod_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/geometry/base_shapes.h"

#include <QFile>
#include <QPushButton>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>
#include <tiny_gltf.h>

#include <array>
#include <map>
#include <memory>
#include <string>

using namespace octaclay;
using app::MainWindow;

namespace {

// How many distinct 8-bit colours the image's first three channels take.
std::size_t colourCount(const tinygltf::Image& image) {
  std::map<std::array<unsigned char, 3>, int> seen;
  const auto c = static_cast<std::size_t>(image.component);
  for (std::size_t k = 0; k + c <= image.image.size(); k += c)
    seen[{image.image[k], image.image[k + 1], image.image[k + 2]}] = 1;
  return seen.size();
}

const tinygltf::Image* textureImage(const tinygltf::Model& model, int texture) {
  if (texture < 0 || static_cast<std::size_t>(texture) >= model.textures.size()) return nullptr;
  const int source = model.textures[static_cast<std::size_t>(texture)].source;
  return source < 0 ? nullptr : &model.images[static_cast<std::size_t>(source)];
}

} // namespace

class LodExportRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void dockExportCarriesThePaintAndATangentNormalMap();

private:
  QTemporaryDir dir_;
};

void LodExportRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("lod_export_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QSettings().clear();
}

void LodExportRenderTest::dockExportCarriesThePaintAndATangentNormalMap() {
  std::unique_ptr<MainWindow> window = app::testing::openTestWindow(dir_.filePath("recovery"));
  QVERIFY(window);
  QVERIFY(window->newDocument(core::BaseShape::Sphere, 128, true));
  // A paint stroke across the front.
  app::ViewportWidget* view = window->viewport();
  QVERIFY(window->brushState()->selectBrush("paint"));
  window->brushState()->setRadius(0.15f);
  window->brushState()->setStrength(1.0f);
  const QPointF from(view->width() / 2.0 - 60, view->height() / 2.0);
  const QPointF to(view->width() / 2.0 + 60, view->height() / 2.0);
  QTest::mousePress(view, Qt::LeftButton, {}, from.toPoint());
  for (int k = 1; k <= 10; ++k)
    QTest::mouseMove(view, (from + (to - from) * (k / 10.0)).toPoint());
  QTest::mouseRelease(view, Qt::LeftButton, {}, to.toPoint());
  QTRY_VERIFY(!view->modeller().document().diffuse.uniform());

  window->lodPanel()->setTargetTriangles(1000);
  QString path;
  window->setFileChooser([&](MainWindow::FileRequest request) {
    return request == MainWindow::FileRequest::ExportLod ? path : QString();
  });
  auto* button = window->lodPanel()->findChild<QPushButton*>(QStringLiteral("exportLod"));
  QVERIFY(button);

  path = dir_.filePath("painted_lod.glb");
  button->click();
  QVERIFY2(window->lastError().isEmpty(), qPrintable(window->lastError()));
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  QVERIFY2(loader.LoadBinaryFromFile(&model, &err, &warn, path.toStdString()), err.c_str());
  QCOMPARE(model.materials.size(), std::size_t(1));
  const tinygltf::Material& material = model.materials[0];
  const tinygltf::Image* normal = textureImage(model, material.normalTexture.index);
  QVERIFY2(normal, "no normalTexture");
  QCOMPARE(normal->width, 128); // one texel per full-resolution sample
  QVERIFY(!material.extras.Has("octaclay_object_space_normal_texture"));
  const tinygltf::Image* base =
      textureImage(model, material.pbrMetallicRoughness.baseColorTexture.index);
  QVERIFY2(base, "no base colour texture");
  QCOMPARE(base->width, 128);
  QVERIFY2(colourCount(*base) >= 2, "the base colour is uniform: the paint was dropped");
  QVERIFY(material.pbrMetallicRoughness.metallicRoughnessTexture.index >= 0);
  const tinygltf::Primitive& primitive = model.meshes.at(0).primitives.at(0);
  for (const char* attribute : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"})
    QVERIFY2(primitive.attributes.count(attribute) == 1, attribute);

  // The OBJ carries the same paint maps beside its normal map.
  path = dir_.filePath("painted_lod.obj");
  button->click();
  QVERIFY2(window->lastError().isEmpty(), qPrintable(window->lastError()));
  QFile mtl(dir_.filePath("painted_lod.mtl"));
  QVERIFY(mtl.open(QIODevice::ReadOnly));
  const QByteArray text = mtl.readAll();
  for (const char* line : {"map_Kd painted_lod_diffuse.png", "map_Ks painted_lod_specular.png",
                           "map_Bump painted_lod_normal.png", "tangent-space"})
    QVERIFY2(text.contains(line), text.constData());
  QVERIFY(QFileInfo::exists(dir_.filePath("painted_lod_diffuse.png")));
}

QTEST_MAIN(LodExportRenderTest)
#include "lod_export_render_test.moc"
