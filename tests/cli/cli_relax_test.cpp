// octaclay-cli relax and stroke --keep-detail (issue 21): the limb of the issue evened out from
// the command line with its figures, keep-detail on and off, and bad input refused with the
// usual exit codes and no output file.
#include "cli_support.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>

class CliRelaxTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void relaxEvensOutTheLimb();
  void keepDetailKeepsTheLimbsSamples();
  void refusesBadInput();

private:
  QString path(const QString& name) const { return dir_.filePath(name); }
  // The limb at N = 64: 15 one-dab strokes at the pole, each at full strength.
  void pullLimb(const QString& file, const QString& keepDetail, int size = 64);
  QTemporaryDir dir_;
};

void CliRelaxTest::initTestCase() {
  QVERIFY(dir_.isValid());
}

void CliRelaxTest::pullLimb(const QString& file, const QString& keepDetail, int size) {
  const QStringList create{"new", "--shape", "sphere", "--size", QString::number(size), "-o", file};
  const Result made = runCli(create);
  QVERIFY2(made.exitCode == kOk, qPrintable(describe(create, made)));
  for (int i = 0; i < 15; ++i) {
    const QStringList args{
        "stroke",        file,       "--brush",    "push", "--path",    "0.5,0.5;0.5,0.5",
        "--radius",      "0.06",     "--strength", "1",    "--spacing", "1",
        "--keep-detail", keepDetail, "-o",         file};
    const Result r = runCli(args);
    QVERIFY2(r.exitCode == kOk, qPrintable(describe(args, r)));
  }
}

void CliRelaxTest::relaxEvensOutTheLimb() {
  pullLimb(path("limb.exr"), "off");
  RUN_JSON(reply, "relax", path("limb.exr"), "-o", path("even.exr"), "--json");
  const double before = reply["before"].toObject()["longest_over_median"].toDouble();
  const double after = reply["after"].toObject()["longest_over_median"].toDouble();
  qInfo("relax: longest/median %.1f -> %.1f, moved RMS %.5f, Hausdorff %.4f, %.0f ms", before,
        after, reply["rms"].toDouble(), reply["hausdorff"].toDouble(), reply["ms"].toDouble());
  QVERIFY(before > 20);
  QVERIFY(reply["ms"].toDouble() > 0);
  QVERIFY(QFileInfo::exists(path("even.exr")));
  RUN_JSON(info, "info", path("even.exr"), "--json");
  QCOMPARE(info["euler"].toInt(), 2);
  QVERIFY(info["closed"].toBool());
  QCOMPARE(info["stretch"].toObject()["longest_over_median"].toDouble(), after);
  const QStringList human{"relax", path("limb.exr"), "-o", path("even2.exr")};
  const Result r = runCli(human);
  QVERIFY2(r.exitCode == kOk, qPrintable(describe(human, r)));
  // Issue 30: the even-out checks its result. At N = 64 this limb's even-out would move the
  // surface by 0.017 % of the diagonal (RMS), over the 0.01 % it allows, at every step it
  // tries: the document is written unchanged and the reason said.
  if (!reply["changed"].toBool()) {
    qInfo("unchanged: %s", qPrintable(reply["reason"].toString()));
    QVERIFY(!reply["reason"].toString().isEmpty());
    QCOMPARE(after, before);
    QCOMPARE(reply["rms"].toDouble(), 0.0);
    QVERIFY(r.out.contains("unchanged"));
    return;
  }
  QVERIFY(after < before);
  QVERIFY(reply["rms"].toDouble() <= 1e-4);
  QVERIFY(reply["hausdorff"].toDouble() <= 1e-3);
  QVERIFY(r.out.contains("longest edge"));
}

// At N = 256: keep-detail keeps each click's relaxation within 0.1 % of the diagonal
// (Hausdorff), which at N = 64 lets through little of it (longest edge 38x the median on, 48x
// off) and at N = 256 most (5.0x on, 129x off).
void CliRelaxTest::keepDetailKeepsTheLimbsSamples() {
  pullLimb(path("off.exr"), "off", 256);
  pullLimb(path("on.exr"), "on", 256);
  RUN_JSON(off, "info", path("off.exr"), "--json");
  RUN_JSON(on, "info", path("on.exr"), "--json");
  const double offRatio = off["stretch"].toObject()["longest_over_median"].toDouble();
  const double onRatio = on["stretch"].toObject()["longest_over_median"].toDouble();
  const double offTop = off["bbox"].toObject()["max"].toArray()[2].toDouble();
  const double onTop = on["bbox"].toObject()["max"].toArray()[2].toDouble();
  qInfo("keep-detail off: longest/median %.1f, top %.2f; on: %.1f, top %.2f", offRatio, offTop,
        onRatio, onTop);
  QVERIFY(onRatio < offRatio / 4);
  QVERIFY(onTop >= 0.9 * offTop); // the limb is as long
  QCOMPARE(on["euler"].toInt(), 2);
}

void CliRelaxTest::refusesBadInput() {
  pullLimb(path("bad-limb.exr"), "off");
  for (const QStringList& args :
       {QStringList{"relax", path("bad-limb.exr"), "-o", path("x.exr"), "--iterations", "0"},
        QStringList{"relax", path("bad-limb.exr"), "-o", path("x.exr"), "--iterations",
                    "1000000000"},
        QStringList{"relax", path("bad-limb.exr"), "-o", path("x.exr"), "--iterations", "nan"},
        QStringList{"stroke", path("bad-limb.exr"), "--brush", "push", "--path", "0.5,0.5",
                    "--keep-detail", "maybe", "-o", path("x.exr")}}) {
    const Result r = runCli(args);
    QVERIFY2(!r.crashed && r.exitCode == kUsage, qPrintable(describe(args, r)));
    QVERIFY(!QFileInfo::exists(path("x.exr")));
  }
  // A damaged document: not an EXR at all, then truncated.
  QFile junk(path("junk.exr"));
  QVERIFY(junk.open(QIODevice::WriteOnly));
  junk.write("not an image");
  junk.close();
  QFile whole(path("bad-limb.exr"));
  QVERIFY(whole.open(QIODevice::ReadOnly));
  const QByteArray bytes = whole.readAll();
  QFile cut(path("cut.exr"));
  QVERIFY(cut.open(QIODevice::WriteOnly));
  cut.write(bytes.left(bytes.size() / 2));
  cut.close();
  for (const QString& input : {path("junk.exr"), path("cut.exr")}) {
    const QStringList args{"relax", input, "-o", path("x.exr")};
    const Result r = runCli(args);
    QVERIFY2(!r.crashed && r.exitCode == kInvalidInput, qPrintable(describe(args, r)));
    QVERIFY(!QFileInfo::exists(path("x.exr")));
  }
  const QStringList missing{"relax", path("none.exr"), "-o", path("x.exr")};
  const Result r = runCli(missing);
  QVERIFY2(!r.crashed && r.exitCode == kIo, qPrintable(describe(missing, r)));
  QVERIFY(!QFileInfo::exists(path("x.exr")));
}

QTEST_GUILESS_MAIN(CliRelaxTest)
#include "cli_relax_test.moc"
