// The live level of detail in the modeller, drawn through the real viewport (xcb under Xvfb,
// llvmpipe): the saliency heat map red on a sharp bump and blue on the smooth sphere, the side
// by side view showing two models, and a stroke updating the LOD at its target.
#include "brush_panel.h"
#include "layers_panel.h"
#include "lod_generator.h"
#include "lod_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/geometry/base_shapes.h"

#include <QFile>
#include <QImage>
#include <QPushButton>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <memory>

using namespace octaclay;
using app::LodPanel;
using app::MainWindow;

namespace {

void hideBrushOutline(QWidget* view) {
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(view, &leave);
}

// Whether a pixel shows the model rather than the blue-grey background.
bool isModel(QRgb c, QRgb background) {
  return std::abs(qRed(c) - qRed(background)) + std::abs(qGreen(c) - qGreen(background)) +
             std::abs(qBlue(c) - qBlue(background)) >
         30;
}

} // namespace

class LodRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void heatMapIsRedOnASharpBumpAndBlueOnSmoothClay();
  void sideBySideShowsTheFullResolutionAndTheLod();
  void strokeUpdatesTheLiveLodAtItsTarget();
  void exportWritesTheLodWithItsNormalMap();

private:
  std::unique_ptr<MainWindow> makeWindow();
  // Waits until the generator has made (and the viewport uploaded) an LOD newer than `count`.
  bool waitForLod(QSignalSpy& generated, int count);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void LodRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("lod_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void LodRenderTest::init() {
  QSettings().clear();
}

void LodRenderTest::cleanup() {
  window_.reset();
}

std::unique_ptr<MainWindow> LodRenderTest::makeWindow() {
  return app::testing::openTestWindow(dir_.filePath("recovery"));
}

bool LodRenderTest::waitForLod(QSignalSpy& generated, int count) {
  return QTest::qWaitFor(
      [&] {
        return generated.count() > count && !window_->lodGenerator()->busy() &&
               window_->viewport()->lodTriangles() > 0;
      },
      30000);
}

void LodRenderTest::heatMapIsRedOnASharpBumpAndBlueOnSmoothClay() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  // A small, sharp bump in front of the camera, a little off centre.
  QVERIFY(window_->brushState()->selectBrush("inflate"));
  window_->brushState()->setRadius(0.03f);
  window_->brushState()->setStrength(1.0f);
  const QPointF bump(view->width() / 2.0 + 40, view->height() / 2.0 - 30);
  for (int k = 0; k < 3; ++k) {
    view->beginStrokeAt(bump);
    QVERIFY(view->stroking());
    view->endStroke();
  }
  view->modeller().setSaliencyOnCpu(
      false); // the GPU pass, whatever the GL (llvmpipe takes the CPU's)
  window_->layersPanel()->setPreview(6);
  QVERIFY(
      view->modeller().saliencyCurrent()); // computed on the GPU when the heat map was asked for
  hideBrushOutline(view);
  const QImage image = view->grabFramebuffer();
  // The reddest pixel within 25 px of the bump (its rim and top are where the normal turns).
  QRgb onBump = image.pixel(bump.toPoint());
  for (int dy = -25; dy <= 25; ++dy)
    for (int dx = -25; dx <= 25; ++dx) {
      const QRgb c = image.pixel(bump.toPoint() + QPoint(dx, dy));
      if (qRed(c) - qBlue(c) > qRed(onBump) - qBlue(onBump)) onBump = c;
    }
  // Smooth clay: the far side of the sphere's visible disc from the bump.
  const QPoint smooth(view->width() / 2 - 80, view->height() / 2 + 60);
  const QRgb onSmooth = image.pixel(smooth);
  const auto describe = [](QRgb c) {
    return QString("(%1, %2, %3)").arg(qRed(c)).arg(qGreen(c)).arg(qBlue(c));
  };
  QVERIFY2(qRed(onBump) > qBlue(onBump) + 60, qPrintable(describe(onBump)));
  QVERIFY2(qBlue(onSmooth) > qRed(onSmooth) + 60, qPrintable(describe(onSmooth)));
  // The saliency is in the positions' alpha: low on the smooth part.
  const core::GeometryImage& positions = view->modeller().document().positions;
  const auto far = view->pickAt(smooth);
  QVERIFY(far);
  QVERIFY(positions.at(far->sample).w < 0.1f);
  // Undo: the sphere's saliency comes back along with its shape (recomputed, so current).
  for (int k = 0; k < 3; ++k)
    window_->action("actionUndo")->trigger();
  QVERIFY(view->modeller().saliencyCurrent());
  float peak = 0;
  for (const core::Vec4f& t : positions.texels())
    peak = std::max(peak, t.w);
  QCOMPARE(peak, 1.0f); // normalised by its maximum
}

void LodRenderTest::sideBySideShowsTheFullResolutionAndTheLod() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  QSignalSpy generated(window_->lodGenerator(), &app::LodGenerator::generated);
  window_->lodPanel()->setTargetTriangles(2000);
  window_->lodPanel()->setDisplay(LodPanel::Display::SideBySide);
  QVERIFY(waitForLod(generated, 0));
  QVERIFY(QTest::qWaitFor([&] { return window_->lodPanel()->errorText() != "Error: —"; }, 30000));
  QVERIFY2(window_->lodPanel()->lodText().contains("triangles"),
           qPrintable(window_->lodPanel()->lodText()));
  hideBrushOutline(view);
  const QImage image = view->grabFramebuffer();
  if (qEnvironmentVariableIsSet("LOD_RENDER_TEST_SAVE")) image.save("/tmp/lod_side_by_side.png");
  const int w = image.width(), h = image.height();
  const QRgb background = image.pixel(2, 2);
  // One model centred in each half, the same size: model pixels along the row a quarter down
  // from the top of the models (the halves touch at the middle row in a narrow view).
  const int row = h / 2 - h / 8;
  const auto modelSpan = [&](int from, int to) {
    int count = 0;
    double sum = 0;
    for (int x = from; x < to; ++x)
      if (isModel(image.pixel(x, row), background)) ++count, sum += x;
    return std::pair{count, count > 0 ? sum / count : 0.0};
  };
  const auto [left, leftCentre] = modelSpan(0, w / 2);
  const auto [right, rightCentre] = modelSpan(w / 2, w);
  QVERIFY2(left > w / 8 && std::abs(left - right) <= 4,
           qPrintable(QString("%1 vs %2 pixels").arg(left).arg(right)));
  QVERIFY2(std::abs(leftCentre - w / 4.0) < 3 && std::abs(rightCentre - 3 * w / 4.0) < 3,
           qPrintable(QString("centres %1, %2 of %3").arg(leftCentre).arg(rightCentre).arg(w)));
  // Both clay-shaded alike at their centres (a normal-mapped LOD looks like the full mesh).
  const QRgb a = image.pixel(w / 4, h / 2), b = image.pixel(3 * w / 4, h / 2);
  QVERIFY2(std::abs(qRed(a) - qRed(b)) < 12 && std::abs(qGreen(a) - qGreen(b)) < 12,
           qPrintable(QString("%1 vs %2").arg(qRed(a)).arg(qRed(b))));
  // Back to full resolution: one model in the middle.
  window_->lodPanel()->setDisplay(LodPanel::Display::FullResolution);
  const QImage single = view->grabFramebuffer();
  QVERIFY(isModel(single.pixel(w / 2, h / 2), single.pixel(2, 2)));
}

void LodRenderTest::strokeUpdatesTheLiveLodAtItsTarget() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 256, true));
  app::ViewportWidget* view = window_->viewport();
  QSignalSpy generated(window_->lodGenerator(), &app::LodGenerator::generated);
  constexpr int kTarget = 5000;
  window_->lodPanel()->setTargetTriangles(kTarget);
  window_->lodPanel()->setDisplay(LodPanel::Display::Lod);
  QVERIFY(waitForLod(generated, 0));
  const std::shared_ptr<const core::LodMesh> before = window_->lodGenerator()->lod();
  QVERIFY(before);
  const int count = static_cast<int>(generated.count());
  // A push stroke across the front of the sphere.
  QVERIFY(window_->brushState()->selectBrush("push"));
  window_->brushState()->setRadius(0.1f);
  window_->brushState()->setStrength(0.8f);
  const QPointF from(view->width() / 2.0 - 60, view->height() / 2.0);
  const QPointF to(view->width() / 2.0 + 60, view->height() / 2.0);
  QTest::mousePress(view, Qt::LeftButton, {}, from.toPoint());
  for (int k = 1; k <= 10; ++k)
    QTest::mouseMove(view, (from + (to - from) * (k / 10.0)).toPoint());
  QTest::mouseRelease(view, Qt::LeftButton, {}, to.toPoint());
  // salient-point reads the saliency: it follows the stroke (on a worker under llvmpipe), and
  // the LOD is made again with it.
  QVERIFY(QTest::qWaitFor([&] { return view->modeller().saliencyCurrent(); }, 30000));
  QVERIFY(waitForLod(generated, count));
  const std::shared_ptr<const core::LodMesh> after = window_->lodGenerator()->lod();
  QVERIFY(after && after != before);
  // The target holds (vertex collapse meets it within 1 %) and the surface moved.
  for (const auto& lod : {before, after}) {
    const auto t = static_cast<int>(lod->mesh.triangles.size());
    QVERIFY2(t <= kTarget && t >= kTarget * 99 / 100, qPrintable(QString::number(t)));
  }
  QCOMPARE(view->lodTriangles(), static_cast<long long>(after->mesh.triangles.size()));
  // The stroke pushed the front in: the LOD's frontmost point (+z, towards the camera) moved.
  const auto frontmost = [](const core::LodMesh& lod) {
    float z = -1e9f;
    for (const core::Vec3f& p : lod.mesh.positions)
      z = std::max(z, p.z);
    return z;
  };
  const float moved = std::abs(frontmost(*after) - frontmost(*before));
  QVERIFY2(moved > 0.01f, qPrintable(QString::number(moved)));
}

void LodRenderTest::exportWritesTheLodWithItsNormalMap() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Blob, 128, true));
  window_->lodPanel()->setTargetTriangles(1000);
  const QString obj = dir_.filePath("blob_lod.obj");
  window_->setFileChooser([&](MainWindow::FileRequest request) {
    return request == MainWindow::FileRequest::ExportLod ? obj : QString();
  });
  window_->lodPanel()->findChild<QPushButton*>(QStringLiteral("exportLod"))->click();
  QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
  // The OBJ's faces are the LOD's (within the collapse's 1 %), and its map lies beside it.
  QFile file(obj);
  QVERIFY(file.open(QIODevice::ReadOnly));
  int faces = 0;
  while (!file.atEnd())
    faces += file.readLine().startsWith("f ");
  QVERIFY2(faces <= 1000 && faces >= 990, qPrintable(QString::number(faces)));
  QVERIFY(QFileInfo::exists(dir_.filePath("blob_lod.mtl")));
  const QImage map(dir_.filePath("blob_lod_normal.png"));
  QCOMPARE(map.width(), 128);
  // A bad extension is refused with a message, writing nothing.
  QVERIFY(!window_->exportLod(dir_.filePath("blob_lod.ply")));
  QVERIFY(window_->lastError().contains(".obj or .glb"));
  QVERIFY(!QFileInfo::exists(dir_.filePath("blob_lod.ply")));
}

QTEST_MAIN(LodRenderTest)
#include "lod_render_test.moc"
