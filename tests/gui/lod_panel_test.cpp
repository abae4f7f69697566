// The Level of detail dock's automatic-LOD controls (offscreen) and the live generator behind
// them: generation off the GUI thread to the target, requests folding while one runs, and the
// error readout against the full resolution.
#include "lod_follow.h"
#include "lod_generator.h"
#include "lod_panel.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/lod/saliency.h"

#include <QComboBox>
#include <QLabel>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

#include <cmath>

using namespace octaclay;
using app::LodPanel;

class LodPanelTest : public QObject {
  Q_OBJECT

private slots:
  void defaultsAreTheLiveTarget() {
    LodPanel panel;
    QCOMPARE(panel.method(), core::ResampleMethod::Auto);
    QCOMPARE(panel.targetTriangles(), 20000);
    QCOMPARE(panel.display(), LodPanel::Display::FullResolution);
    QVERIFY(!panel.lodShown());
    const core::LodOptions options = panel.lodOptions();
    QCOMPARE(options.method, core::ResampleMethod::Auto);
    QVERIFY(options.autoMayCollapse); // the export: adaptive or the collapse, per image
    QCOMPARE(options.targetTriangles, std::size_t{20000});
    QCOMPARE(options.size, 0); // chosen from the target
    // The live LOD: auto keeps to salient-point, which reads the saliency.
    QVERIFY(!panel.liveLodOptions().autoMayCollapse);
    QCOMPARE(panel.liveLodOptions().targetTriangles, std::size_t{20000});
    QVERIFY(panel.liveLodReadsSaliency());
    auto* methods = panel.findChild<QComboBox*>(QStringLiteral("lodMethod"));
    QVERIFY(methods);
    QStringList names, technical;
    for (int k = 0; k < methods->count(); ++k) {
      names << methods->itemText(k);
      technical << methods->itemData(k, Qt::ToolTipRole).toString().section(':', 0, 0);
    }
    // Words for a newcomer; the technical names in the tooltips.
    QCOMPARE(names, (QStringList{"Nearest sample", "Smooth", "Soft features", "Sharp features",
                                 "Adaptive", "Collapse", "Best"}));
    QCOMPARE(technical, (QStringList{"point", "average", "salient-average", "salient-point",
                                     "adaptive", "collapse", "auto"}));
    QCOMPARE(methods->currentText(), QStringLiteral("Best"));
    QCOMPARE(panel.lodText(), QStringLiteral("LOD: —"));
    QCOMPARE(panel.errorText(), QStringLiteral("Error: —"));
  }

  void controlsEmitWhatChanged() {
    LodPanel panel;
    QSignalSpy options(&panel, &LodPanel::lodOptionsChanged);
    QSignalSpy display(&panel, &LodPanel::displayChanged);
    QSignalSpy exported(&panel, &LodPanel::exportRequested);
    panel.findChild<QComboBox*>(QStringLiteral("lodMethod"))->setCurrentIndex(0);
    QCOMPARE(panel.method(), core::ResampleMethod::Point);
    QCOMPARE(options.count(), 1);
    auto* target = panel.findChild<QSpinBox*>(QStringLiteral("lodTarget"));
    target->setValue(5000);
    QCOMPARE(panel.lodOptions().targetTriangles, std::size_t{5000});
    QCOMPARE(options.count(), 2);
    panel.setTargetTriangles(1); // below the smallest target vertex collapse accepts
    QCOMPARE(panel.targetTriangles(), LodPanel::kMinTargetTriangles);
    panel.setMethod(core::ResampleMethod::SalientAverage);
    QCOMPARE(panel.findChild<QComboBox*>(QStringLiteral("lodMethod"))->currentText(),
             QStringLiteral("Soft features"));
    panel.findChild<QComboBox*>(QStringLiteral("lodDisplay"))->setCurrentIndex(2);
    QCOMPARE(display.count(), 1);
    QCOMPARE(display.front().front().value<LodPanel::Display>(), LodPanel::Display::SideBySide);
    QVERIFY(panel.lodShown());
    panel.setDisplay(LodPanel::Display::FullResolution);
    QCOMPARE(display.count(), 2);
    QVERIFY(!panel.lodShown());
    panel.findChild<QPushButton*>(QStringLiteral("exportLod"))->click();
    QCOMPARE(exported.count(), 1);
  }

  void readoutsSayTheNumbers() {
    const QLocale previous;
    QLocale::setDefault(QLocale(QLocale::English, QLocale::UnitedStates));
    LodPanel panel;
    panel.setLodResult(19998, 12.345);
    QCOMPARE(panel.lodText(), QStringLiteral("LOD: 19,998 triangles in 12.3 ms"));
    core::SurfaceDistance d;
    d.rms = 0.00123;
    d.hausdorff = 0.0101;
    d.psnr = 20 * std::log10(1 / d.rms);
    panel.setLodError(d);
    QCOMPARE(panel.errorText(),
             QStringLiteral("Error (% of size): 0.123 % average, 1.01 % at most"));
    const QString tip = panel.findChild<QLabel*>(QStringLiteral("lodError"))->toolTip();
    QVERIFY2(tip.startsWith("RMS 0.00123 · Hausdorff 0.0101 · PSNR 58.2 dB"), qPrintable(tip));
    panel.setLodError(std::nullopt);
    QCOMPARE(panel.errorText(), QStringLiteral("Error: —"));
    QLocale::setDefault(previous);
  }

  void generatorMakesTheTargetOffTheGuiThreadAndMeasuresIt() {
    auto image =
        std::make_shared<core::GeometryImage>(core::makeBaseShape(core::BaseShape::Blob, 128));
    core::computeSaliency(*image);
    int snapshots = 0;
    app::LodGenerator generator([&] {
      ++snapshots;
      return std::shared_ptr<const core::GeometryImage>(image);
    });
    core::LodOptions options;
    options.targetTriangles = 2000;
    generator.setOptions(options);
    generator.setErrorSamples(20000);
    QSignalSpy generated(&generator, &app::LodGenerator::generated);
    QSignalSpy measured(&generator, &app::LodGenerator::measured);
    QSignalSpy failed(&generator, &app::LodGenerator::failed);
    // Five requests while the first runs fold into one more generation.
    for (int k = 0; k < 5; ++k)
      generator.request();
    QVERIFY(generator.busy());
    QVERIFY(QTest::qWaitFor([&] { return !generator.busy(); }, 30000));
    QCOMPARE(failed.count(), 0);
    QCOMPARE(generated.count(), 2);
    QCOMPARE(snapshots, 2);
    QVERIFY(generator.lod());
    const std::size_t triangles = generator.lod()->mesh.triangles.size();
    QVERIFY2(triangles <= 2000 && triangles >= 1980, qPrintable(QString::number(triangles)));
    // Measured once, for the newest LOD: a blob at 2 k triangles is close but not exact.
    QCOMPARE(measured.count(), 1);
    const auto error = measured.front().front().value<core::SurfaceDistance>();
    QVERIFY2(error.rms > 0 && error.rms < 0.01, qPrintable(QString::number(error.rms)));
    QVERIFY(error.hausdorff >= error.rms);
    QVERIFY(error.psnr > 40);
  }

  void followerMovesEachVertexWithItsSourceSample() {
    core::GeometryImage then = core::makeBaseShape(core::BaseShape::Blob, 64);
    core::LodOptions options;
    options.method = core::ResampleMethod::Point;
    options.targetTriangles = 500;
    const core::LodMesh lod = core::generateLod(then, options);
    const app::LodFollower follower(lod, then);
    // Unchanged surface: the LOD as made, bit for bit.
    const core::LodMesh same = follower.follow(then);
    QVERIFY(same.mesh.positions == lod.mesh.positions);
    // Lift the samples with x > 0.3 by 0.1 in z (a stand-in for a stroke).
    core::GeometryImage now = then;
    for (core::Vec4f& t : now.texels())
      if (t.x > 0.3f) t.z += 0.1f;
    const core::LodMesh moved = follower.follow(now);
    QCOMPARE(moved.mesh.triangles, lod.mesh.triangles); // connectivity (and count) kept
    QCOMPARE(moved.cornerUv.size(), lod.cornerUv.size());
    int lifted = 0, kept = 0;
    for (std::size_t v = 0; v < lod.mesh.positions.size(); ++v) {
      const core::Sample s = follower.sources()[v];
      const float dz = moved.mesh.positions[v].z - lod.mesh.positions[v].z;
      QCOMPARE(moved.mesh.positions[v].x, lod.mesh.positions[v].x);
      if (then.at(s).x > 0.3f) {
        QVERIFY(std::abs(dz - 0.1f) < 1e-6f);
        ++lifted;
      } else {
        QCOMPARE(dz, 0.0f);
        ++kept;
      }
    }
    QVERIFY(lifted > 20 && kept > 20);
    // The source is the sample of the vertex's corner coordinates (or one identified with it,
    // for a seam vertex whose other copy another triangle named).
    for (std::size_t t = 0; t < lod.mesh.triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k) {
        const core::Vec2f uv = lod.cornerUv[t][k];
        const core::Sample corner{static_cast<int>(std::lround(uv.x * 64)),
                                  static_cast<int>(std::lround(uv.y * 64))};
        const core::Sample s = follower.sources()[lod.mesh.triangles[t][k]];
        QVERIFY(core::canonical(64, s) == core::canonical(64, corner));
      }
  }
};

QTEST_MAIN(LodPanelTest)
#include "lod_panel_test.moc"
