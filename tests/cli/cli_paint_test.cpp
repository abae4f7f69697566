// octaclay-cli and the paint brushes: `brushes` lists the specular and reflectivity brushes with
// their value and mode parameters, and `stroke` runs them in both modes by option name.

#include "cli_support.h"

#include <QJsonArray>
#include <QTemporaryDir>

#include <cmath>

class CliPaintTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void brushesListsTheFeaturePaintBrushes();
  void strokesPaintAndEraseByModeName();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString sphere_;
};

void CliPaintTest::initTestCase() {
  QVERIFY(dir_.isValid());
  sphere_ = file("sphere.exr");
  RUN_JSON(created, "new", "--size", "64", "-o", sphere_, "--json");
  QVERIFY(QFileInfo::exists(sphere_));
}

void CliPaintTest::brushesListsTheFeaturePaintBrushes() {
  RUN_JSON(listed, "brushes", "--json");
  QJsonObject found[2];
  const QString ids[2] = {"paint-specular", "paint-reflectivity"};
  for (const QJsonValue& b : listed["brushes"].toArray())
    for (int k = 0; k < 2; ++k)
      if (b.toObject()["id"].toString() == ids[k]) found[k] = b.toObject();
  const double defaults[2] = {0.9, 0.8};
  for (int k = 0; k < 2; ++k) {
    QVERIFY2(!found[k].isEmpty(), qPrintable(ids[k] + " not listed"));
    QCOMPARE(found[k]["category"].toString(), QString("paint"));
    QCOMPARE(found[k]["writes"].toArray(), QJsonArray{"feature"});
    const QJsonArray parameters = found[k]["parameters"].toArray();
    QCOMPARE(parameters.size(), 2);
    QCOMPARE(parameters[0].toObject()["id"].toString(), QString("value"));
    QVERIFY(std::abs(parameters[0].toObject()["default"].toArray()[0].toDouble() - defaults[k]) <
            1e-6);
    QCOMPARE(parameters[1].toObject()["id"].toString(), QString("mode"));
    QCOMPARE(parameters[1].toObject()["type"].toString(), QString("enum"));
  }
}

void CliPaintTest::strokesPaintAndEraseByModeName() {
  for (const char* brush : {"paint", "mask", "paint-specular", "paint-reflectivity"}) {
    const QString painted = file(QString("%1-painted.exr").arg(brush));
    RUN_JSON(paint, "stroke", sphere_, "--brush", brush, "--path", "0.5,0.5", "--radius", "0.2",
             "--strength", "1", "--param", "mode=paint", "-o", painted, "--json");
    QVERIFY2(paint["changed_tiles"].toInt() > 0, brush);
    EXPECT_FAILURE(kUsage, file("never.exr"), "stroke", sphere_, "--brush", brush, "--path",
                   "0.5,0.5", "--param", "mode=smudge", "-o", file("never.exr"));
    // Erasing reads the painted layer back from the file (a painted mask is saved too).
    const QString erased = file(QString("%1-erased.exr").arg(brush));
    RUN_JSON(erase, "stroke", painted, "--brush", brush, "--path", "0.5,0.5", "--radius", "0.2",
             "--strength", "1", "--param", "mode=erase", "-o", erased, "--json");
    QVERIFY2(erase["changed_tiles"].toInt() > 0, brush);
  }
}

QTEST_APPLESS_MAIN(CliPaintTest)
#include "cli_paint_test.moc"
