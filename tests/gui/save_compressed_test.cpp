// File › Save Compressed… (issue 8), offscreen: the dialog offers every codec, previews the
// size and error of the current choice off the GUI thread (figures equal to compressing and
// measuring directly, recomputed when the choice changes, a finer quality costing more bytes
// for less error), and the options it hands back round-trip through a written .ocz that
// File › Open's reader (readModelFile) opens again.

#include "save_compressed_dialog.h"

#include "octaclay/core/codec/codec.h"
#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QComboBox>
#include <QFileInfo>
#include <QLabel>
#include <QSignalSpy>
#include <QSlider>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace octaclay;
using namespace octaclay::app;

class SaveCompressedTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void offersEveryCodec();
  void previewMatchesDirectMeasurement();
  void finerQualityCostsBytesAndGainsPsnr();
  void sliderRunsFromSmallFileToExact();
  void losslessPreviewIsExact();
  void roundTripThroughFile();

private:
  // Waits for the preview of the dialog's current choice.
  static bool waitForPreview(SaveCompressedDialog& dialog) {
    QSignalSpy spy(&dialog, &SaveCompressedDialog::previewUpdated);
    for (int k = 0; k < 100 && !dialog.preview() && dialog.previewError().isEmpty(); ++k)
      spy.wait(200);
    return dialog.preview().has_value();
  }
  std::shared_ptr<const core::Document> doc_;
  QTemporaryDir dir_;
};

void SaveCompressedTest::initTestCase() {
  QVERIFY(dir_.isValid());
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 64));
  // A painted diffuse layer, so the round trip carries a non-uniform layer too.
  doc.diffuse.texels.resize(doc.positions.texelCount() * 4);
  for (std::size_t k = 0; k < doc.diffuse.texels.size(); ++k)
    doc.diffuse.texels[k] = static_cast<float>(k % 97) / 97.0f;
  doc_ = std::make_shared<const core::Document>(std::move(doc));
}

void SaveCompressedTest::offersEveryCodec() {
  SaveCompressedDialog dialog(doc_);
  auto* codecs = dialog.findChild<QComboBox*>("codecCombo");
  QVERIFY(codecs);
  QCOMPARE(codecs->count(), static_cast<int>(core::codecs().size()));
  for (const core::Codec& c : core::codecs())
    QVERIFY(dialog.setCodec(QString::fromStdString(std::string(c.info.id))));
  QVERIFY(!dialog.setCodec("jpeg2000"));
  QVERIFY(dialog.setCodec("exr"));
  QVERIFY(dialog.setMode("half"));
  QCOMPARE(QString::fromStdString(dialog.options().params.mode), QString("half"));
  QVERIFY(dialog.setCodec("lossless"));
  QVERIFY(!dialog.setMode("half")); // modes are exr's alone
  QVERIFY(waitForPreview(dialog));
}

void SaveCompressedTest::previewMatchesDirectMeasurement() {
  SaveCompressedDialog dialog(doc_);
  QVERIFY(dialog.setCodec("dct"));
  QVERIFY(dialog.setQuality(50));
  QVERIFY(waitForPreview(dialog));
  const CompressionPreview shown = *dialog.preview();
  const core::CompressOptions options = dialog.options();
  QCOMPARE(options.codec, std::string("dct"));
  QCOMPARE(options.params.quality, 50.0);

  const std::vector<std::uint8_t> bytes = core::compressDocument(*doc_, options);
  QCOMPARE(shown.bytes, bytes.size());
  QCOMPARE(shown.bitsPerVertex, 8.0 * static_cast<double>(bytes.size()) / (64 * 64 + 2));
  const core::Document decoded = core::decompressDocument(bytes);
  double worst = 0;
  for (std::size_t k = 0; k < decoded.positions.texelCount(); ++k)
    worst = std::max(worst, static_cast<double>(core::length(doc_->positions.texels()[k].xyz() -
                                                             decoded.positions.texels()[k].xyz())));
  QVERIFY(!shown.exact);
  QCOMPARE(shown.maxError, worst);
  QVERIFY(worst > 0);
  QVERIFY2(shown.psnr > 40 && shown.psnr < 200, qPrintable(QString::number(shown.psnr)));
  QVERIFY(shown.maxError < 0.05 * shown.diagonal);
  // The labels show the figures.
  const QString size = dialog.findChild<QLabel*>("sizeLabel")->text();
  const QString error = dialog.findChild<QLabel*>("errorLabel")->text();
  QVERIFY2(size.contains(QString::number(shown.bitsPerVertex, 'f', 2)), qPrintable(size));
  // In words a newcomer reads (% of the model's size), the PSNR in the tooltip.
  const double percent = 100 * shown.maxError / shown.diagonal;
  QVERIFY2(error.contains(QString::number(percent, 'g', 3) + " % of the model's size"),
           qPrintable(error));
  QVERIFY(!error.contains("PSNR"));
  const QString tip = dialog.findChild<QLabel*>("errorLabel")->toolTip();
  QVERIFY2(tip.contains(QString::number(shown.psnr, 'f', 1)), qPrintable(tip));
}

void SaveCompressedTest::finerQualityCostsBytesAndGainsPsnr() {
  SaveCompressedDialog dialog(doc_);
  QVERIFY(dialog.setCodec("wavelet"));
  QVERIFY(dialog.setQuality(1e-3));
  QVERIFY(waitForPreview(dialog));
  const CompressionPreview coarse = *dialog.preview();
  QVERIFY(dialog.setQuality(1e-5));
  QVERIFY(!dialog.preview()); // a new choice invalidates the old figures at once
  QVERIFY(waitForPreview(dialog));
  const CompressionPreview fine = *dialog.preview();
  QVERIFY2(fine.bytes > coarse.bytes,
           qPrintable(QString("%1 %2").arg(fine.bytes).arg(coarse.bytes)));
  QVERIFY(fine.psnr > coarse.psnr);
  QVERIFY(fine.maxError < coarse.maxError);
}

void SaveCompressedTest::sliderRunsFromSmallFileToExact() {
  SaveCompressedDialog dialog(doc_);
  QVERIFY(dialog.setCodec("wavelet"));
  auto* slider = dialog.findChild<QSlider*>("qualitySlider");
  QVERIFY(slider);
  QVERIFY(slider->isEnabled());
  // No raw numbers in view: the slider's ends say what they give, the value is in tooltips.
  QVERIFY(slider->toolTip().contains("error bound"));
  slider->setValue(slider->minimum());
  QCOMPARE(dialog.options().params.quality, 1e-3); // the coarsest: the smallest file
  const QString value = dialog.findChild<QLabel*>("qualityValue")->toolTip();
  QVERIFY2(value.contains("0.001"), qPrintable(value));
  QVERIFY(waitForPreview(dialog));
  const CompressionPreview small = *dialog.preview();
  slider->setValue(slider->maximum());
  QCOMPARE(dialog.options().params.quality, 1e-6); // the finest
  QVERIFY(waitForPreview(dialog));
  const CompressionPreview exact = *dialog.preview();
  QVERIFY2(exact.bytes > small.bytes,
           qPrintable(QString("%1 %2").arg(exact.bytes).arg(small.bytes)));
  QVERIFY(exact.maxError < small.maxError);
  // A lossless codec has nothing to choose.
  QVERIFY(dialog.setCodec("lossless"));
  QVERIFY(!slider->isEnabled());
}

void SaveCompressedTest::losslessPreviewIsExact() {
  SaveCompressedDialog dialog(doc_);
  QVERIFY(dialog.setCodec("lossless"));
  QVERIFY(waitForPreview(dialog));
  QVERIFY(dialog.preview()->exact);
  QCOMPARE(dialog.preview()->maxError, 0.0);
  QVERIFY(std::isinf(dialog.preview()->psnr));
  QVERIFY(dialog.findChild<QLabel*>("errorLabel")->text().contains("exactly"));
}

void SaveCompressedTest::roundTripThroughFile() {
  SaveCompressedDialog dialog(doc_);
  QVERIFY(dialog.setCodec("wavelet"));
  QVERIFY(dialog.setQuality(1e-4));
  QVERIFY(waitForPreview(dialog));
  const QString path = dir_.filePath("model.ocz");
  core::writeCompressedDocument(*doc_, dialog.options(), path.toStdString());
  QCOMPARE(static_cast<std::size_t>(QFileInfo(path).size()), dialog.preview()->bytes);

  const core::Document opened = readModelFile(path);
  QCOMPARE(opened.size(), doc_->size());
  double worst = 0;
  for (std::size_t k = 0; k < opened.positions.texelCount(); ++k)
    worst = std::max(worst, static_cast<double>(core::length(doc_->positions.texels()[k].xyz() -
                                                             opened.positions.texels()[k].xyz())));
  QCOMPARE(worst, dialog.preview()->maxError);           // what the preview promised
  QCOMPARE(opened.diffuse.texels, doc_->diffuse.texels); // painted layers: lossless
  // .exr still opens through the same reader.
  const QString exr = dir_.filePath("model.exr");
  core::writeDocument(*doc_, exr.toStdString());
  QCOMPARE(readModelFile(exr).positions.texelCount(), doc_->positions.texelCount());
}

QTEST_MAIN(SaveCompressedTest)
#include "save_compressed_test.moc"
