// octaclay-cli and the material splat: `stroke --brush splat --param material=<id>` lays a
// material's relief, colour and shine in one stroke headless, projecting along the centre
// normal or from a --view eye; unknown materials and bad views are usage errors.

#include "cli_support.h"

#include "octaclay/core/document/document_io.h"

#include <QTemporaryDir>

class CliSplatTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void splatsEveryShippedMaterial();
  void viewEyeChangesTheProjection();
  void badMaterialsAndViewsAreUsageErrors();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString sphere_;
};

void CliSplatTest::initTestCase() {
  QVERIFY(dir_.isValid());
  sphere_ = file("sphere.exr");
  RUN_JSON(created, "new", "--size", "128", "-o", sphere_, "--json");
}

void CliSplatTest::splatsEveryShippedMaterial() {
  const octaclay::core::Document before = octaclay::core::readDocument(sphere_.toStdString());
  for (const char* material : {"brick", "stone", "wood", "red-plastic", "mirror"}) {
    const QString out = file(QString("splat-%1.exr").arg(material));
    RUN_JSON(stroke, "stroke", sphere_, "--brush", "splat", "--param",
             QString("material=%1").arg(material), "--path", "0.4,0.5;0.6,0.5", "--radius", "0.1",
             "--strength", "1", "-o", out, "--json");
    QVERIFY(stroke["dabs"].toInt() > 1);
    const octaclay::core::Document after = octaclay::core::readDocument(out.toStdString());
    QVERIFY2(!after.diffuse.uniform() && !after.feature.uniform(), material);
    // The shine of the material reached the feature layer's specular channel at the centre.
    const std::size_t centre = (64 * 129 + 64) * 3;
    QVERIFY2(after.feature.texels[centre + 1] != before.feature.fill[1], material);
  }
}

void CliSplatTest::viewEyeChangesTheProjection() {
  const QString normal = file("normal.exr"), viewed = file("viewed.exr");
  RUN_JSON(a, "stroke", sphere_, "--brush", "splat", "--param", "material=brick", "--path",
           "0.5,0.5", "--radius", "0.15", "--strength", "1", "-o", normal, "--json");
  RUN_JSON(b, "stroke", sphere_, "--brush", "splat", "--param", "material=brick", "--path",
           "0.5,0.5", "--radius", "0.15", "--strength", "1", "--view", "3,1,2", "-o", viewed,
           "--json");
  const auto x = octaclay::core::readDocument(normal.toStdString());
  const auto y = octaclay::core::readDocument(viewed.toStdString());
  QVERIFY(x.diffuse.texels != y.diffuse.texels); // the bricks run another way
}

void CliSplatTest::badMaterialsAndViewsAreUsageErrors() {
  const QString never = file("never.exr");
  const QStringList base{"stroke", sphere_, "--brush", "splat", "--path", "0.5,0.5", "-o", never};
  Result r = runCli(base + QStringList{"--param", "material=velvet"});
  QCOMPARE(r.exitCode, kUsage);
  QVERIFY2(r.err.contains("velvet") && r.err.contains("brick"), r.err.constData());
  QVERIFY(!QFileInfo::exists(never));
  r = runCli(base + QStringList{"--view", "1,2"});
  QCOMPARE(r.exitCode, kUsage);
  QVERIFY(r.err.contains("--view"));
  // A broken user material is reported and skipped; the shipped ones still work.
  QTemporaryDir user;
  QDir(user.path()).mkpath("broken");
  QFile manifest(user.filePath("broken/material.json"));
  QVERIFY(manifest.open(QIODevice::WriteOnly));
  manifest.write("{ not json");
  manifest.close();
  r = runCli(base + QStringList{"--param", "material=brick"},
             {"OCTACLAY_MATERIAL_PATH=" + user.path()});
  QCOMPARE(r.exitCode, kOk);
  QVERIFY2(r.err.contains("broken/material.json"), r.err.constData());
}

QTEST_APPLESS_MAIN(CliSplatTest)
#include "cli_splat_test.moc"
