// octaclay-cli compress / decompress (issue 8): every codec round-trips a document through
// .ocz with the figures --json promises (bytes, bits per vertex, times, and the error of lossy
// codecs, seams closed); lossless modes restore the positions bit for bit; unknown codecs, bad
// qualities and broken .ocz files are refused with a message and the right exit code; and
// --sweep writes the rate-distortion table and a plot that holds curves.

#include "cli_support.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/document/image_io.h"

#include <QDir>
#include <QFile>
#include <QJsonArray>
#include <QSet>
#include <QTemporaryDir>

#include <cmath>

class CliCompressTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void roundTripEveryCodec_data();
  void roundTripEveryCodec();
  void exrModes();
  void qualityChangesSizeAndError();
  void refusesBadArguments();
  void refusesBrokenCompressedFiles();
  void sweepWritesTableAndPlot();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString document_;
  static constexpr int kN = 32;
};

void CliCompressTest::initTestCase() {
  QVERIFY(dir_.isValid());
  document_ = file("blob.exr");
  RUN_JSON(created, "new", "--shape", "blob", "--size", QString::number(kN), "-o", document_,
           "--json");
}

void CliCompressTest::roundTripEveryCodec_data() {
  QTest::addColumn<QString>("codec");
  QTest::addColumn<bool>("lossy");
  for (const char* id : {"bytepack", "dct", "exr", "wavelet", "lossless"})
    QTest::newRow(id) << QString(id) << (QString(id) != "lossless"); // exr: zip by default
}

void CliCompressTest::roundTripEveryCodec() {
  QFETCH(QString, codec);
  QFETCH(bool, lossy);
  const QString ocz = file(codec + ".ocz"), back = file(codec + "_back.exr");
  RUN_JSON(compressed, "compress", document_, "--codec", codec, "-o", ocz, "--json");
  QCOMPARE(compressed["codec"].toString(), codec);
  QCOMPARE(compressed["n"].toInt(), kN);
  const qint64 bytes = QFileInfo(ocz).size();
  QVERIFY(bytes > 0);
  QCOMPARE(compressed["bytes"].toDouble(), static_cast<double>(bytes));
  QCOMPARE(compressed["bits_per_vertex"].toDouble(),
           8.0 * static_cast<double>(bytes) / (kN * kN + 2));
  QVERIFY(compressed["encode_ms"].toDouble() >= 0);
  QVERIFY(compressed["decode_ms"].toDouble() >= 0);
  QCOMPARE(compressed["lossy"].toBool(), lossy);

  const octaclay::core::Document original = octaclay::core::readDocument(document_.toStdString());
  RUN_JSON(decompressed, "decompress", ocz, "-o", back, "--json");
  QCOMPARE(decompressed["n"].toInt(), kN);
  const octaclay::core::Document restored = octaclay::core::readDocument(back.toStdString());
  QCOMPARE(restored.size(), kN);
  double worst = 0;
  for (std::size_t k = 0; k < original.positions.texelCount(); ++k) {
    const auto a = original.positions.texels()[k], b = restored.positions.texels()[k];
    worst = std::max({worst, std::abs(double(a.x) - b.x), std::abs(double(a.y) - b.y),
                      std::abs(double(a.z) - b.z)});
  }
  if (compressed["exact"].toBool()) {
    QCOMPARE(worst, 0.0);
    QVERIFY(!compressed.contains("psnr"));
  } else {
    QVERIFY2(lossy, "a lossless codec must restore the positions exactly");
    QVERIFY(worst > 0);
    QVERIFY2(compressed["psnr"].toDouble() > 40,
             qPrintable(QString::number(compressed["psnr"].toDouble())));
    QVERIFY(compressed["rms"].toDouble() > 0);
    QVERIFY(compressed["hausdorff"].toDouble() >= compressed["rms"].toDouble());
    QVERIFY(compressed["hausdorff"].toDouble() < 0.05);
    QVERIFY(compressed["normal_angle_deg"].toDouble() > 0);
    QVERIFY(compressed["normal_angle_deg"].toDouble() < 20);
    QCOMPARE(compressed["max_seam_gap"].toDouble(), 0.0); // no cracks
  }
  if (!lossy || codec == "exr") QVERIFY(compressed["exact"].toBool());
}

void CliCompressTest::exrModes() {
  qint64 zipBytes = 0, halfBytes = 0;
  for (const char* mode : {"zip", "piz", "pxr24", "half"}) {
    const QString ocz = file(QString("exr_%1.ocz").arg(mode));
    RUN_JSON(c, "compress", document_, "--codec", "exr", "--mode", mode, "-o", ocz, "--json");
    QCOMPARE(c["mode"].toString(), QString(mode));
    const bool lossless = QString(mode) == "zip" || QString(mode) == "piz";
    QVERIFY2(c["exact"].toBool() == lossless, mode);
    if (!lossless) QCOMPARE(c["max_seam_gap"].toDouble(), 0.0);
    if (QString(mode) == "zip") zipBytes = QFileInfo(ocz).size();
    if (QString(mode) == "half") halfBytes = QFileInfo(ocz).size();
  }
  QVERIFY2(halfBytes < zipBytes, "half floats take less room than float32");
}

void CliCompressTest::qualityChangesSizeAndError() {
  // A coarser error bound gives a smaller file and a larger error.
  RUN_JSON(fine, "compress", document_, "--codec", "wavelet", "--quality", "1e-5", "-o",
           file("fine.ocz"), "--json");
  RUN_JSON(coarse, "compress", document_, "--codec", "wavelet", "--quality", "1e-2", "-o",
           file("coarse.ocz"), "--json");
  QCOMPARE(fine["quality"].toDouble(), 1e-5);
  QVERIFY(coarse["bytes"].toDouble() < fine["bytes"].toDouble());
  QVERIFY(coarse["psnr"].toDouble() < fine["psnr"].toDouble());
  RUN_JSON(dctLow, "compress", document_, "--codec", "dct", "--quality", "20", "-o",
           file("dct20.ocz"), "--json");
  RUN_JSON(dctHigh, "compress", document_, "--codec", "dct", "--quality", "95", "-o",
           file("dct95.ocz"), "--json");
  QVERIFY(dctLow["bytes"].toDouble() < dctHigh["bytes"].toDouble());
  QVERIFY(dctLow["psnr"].toDouble() < dctHigh["psnr"].toDouble());
}

void CliCompressTest::refusesBadArguments() {
  const QString out = file("refused.ocz");
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "jpeg2000", "-o", out);
  const Result r = runCli({"compress", document_, "--codec", "jpeg2000", "-o", out});
  QVERIFY2(r.err.contains("wavelet"), r.err.constData()); // names the codecs there are
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "dct", "--quality", "1000", "-o",
                 out);
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "dct", "--quality", "-3", "-o",
                 out);
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "wavelet", "--quality", "nan", "-o",
                 out);
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "wavelet", "--mode", "zip", "-o",
                 out);
  EXPECT_FAILURE(kUsage, out, "compress", document_, "--codec", "exr", "--mode", "jpeg", "-o", out);
  EXPECT_FAILURE(kUsage, out, "compress", document_, "-o", out); // no codec
  EXPECT_FAILURE(kUsage, file("x.exr"), "compress", document_, "--codec", "lossless", "-o",
                 file("x.exr"));
  EXPECT_FAILURE(kIo, out, "compress", file("missing.exr"), "--codec", "lossless", "-o", out);
  EXPECT_FAILURE(kIo, file("y.exr"), "decompress", file("missing.ocz"), "-o", file("y.exr"));
}

void CliCompressTest::refusesBrokenCompressedFiles() {
  const QString good = file("good.ocz");
  RUN_JSON(c, "compress", document_, "--codec", "lossless", "-o", good, "--json");
  QFile in(good);
  QVERIFY(in.open(QIODevice::ReadOnly));
  const QByteArray bytes = in.readAll();
  auto writeVariant = [&](const QString& name, const QByteArray& content) {
    QFile f(file(name));
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(content);
  };
  QByteArray wrongMagic = bytes;
  wrongMagic[0] = 'X';
  writeVariant("magic.ocz", wrongMagic);
  writeVariant("truncated.ocz", bytes.left(bytes.size() / 2));
  writeVariant("empty.ocz", {});
  QByteArray flipped = bytes;
  flipped[flipped.size() / 2] = static_cast<char>(flipped[flipped.size() / 2] ^ 0x5a);
  writeVariant("flipped.ocz", flipped);
  for (const char* name : {"magic.ocz", "truncated.ocz", "empty.ocz", "flipped.ocz"}) {
    const QString out = file(QString(name) + ".exr");
    EXPECT_FAILURE(kInvalidInput, out, "decompress", file(name), "-o", out);
  }
  // The intact file still decodes: the refusals above were about the damage.
  RUN_JSON(d, "decompress", good, "-o", file("good.exr"), "--json");
  QCOMPARE(d["bytes"].toDouble(), static_cast<double>(bytes.size()));
}

void CliCompressTest::sweepWritesTableAndPlot() {
  const QString report = file("report");
  RUN_JSON(sweep, "compress", "--sweep", document_, "-o", report, "--json");
  for (const char* name : {"rd.md", "rd.csv", "rd.png"})
    QVERIFY2(QFileInfo(QDir(report).filePath(name)).size() > 0, name);
  QCOMPARE(sweep["plot"].toString(), QDir(report).filePath("rd.png"));

  QFile csv(QDir(report).filePath("rd.csv"));
  QVERIFY(csv.open(QIODevice::ReadOnly | QIODevice::Text));
  const QStringList lines = QString::fromUtf8(csv.readAll()).split('\n', Qt::SkipEmptyParts);
  QSet<QString> codecs;
  int draco = 0;
  for (int k = 1; k < lines.size(); ++k) {
    const QStringList fields = lines[k].split(',');
    QCOMPARE(fields.size(), 13);
    codecs.insert(fields[0]);
    if (fields[0] == "draco") ++draco;
    QVERIFY2(fields[4].toDouble() > 0, qPrintable(lines[k])); // bits per vertex
  }
  for (const char* id : {"bytepack", "dct", "exr", "wavelet", "lossless", "draco"})
    QVERIFY2(codecs.contains(id), id);
  QCOMPARE(draco, 9); // quantization 8 … 16 bits
  QVERIFY(sweep["points"].toArray().size() == lines.size() - 1);

  // The plot holds curves: many coloured (not grey) pixels in each half.
  const octaclay::core::RasterImage plot =
      octaclay::core::readImage(QDir(report).filePath("rd.png").toStdString(), 3);
  QVERIFY(plot.width >= 1000 && plot.height >= 500);
  int coloured[2] = {0, 0};
  for (int y = 0; y < plot.height; ++y)
    for (int x = 0; x < plot.width; ++x) {
      const float r = plot.at(x, y, 0), g = plot.at(x, y, 1), b = plot.at(x, y, 2);
      if (std::max({r, g, b}) - std::min({r, g, b}) > 0.25f) ++coloured[x * 2 / plot.width];
    }
  QVERIFY2(coloured[0] > 500 && coloured[1] > 500,
           qPrintable(QString("%1 %2").arg(coloured[0]).arg(coloured[1])));
}

QTEST_GUILESS_MAIN(CliCompressTest)
#include "cli_compress_test.moc"
