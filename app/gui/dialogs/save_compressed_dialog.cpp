#include "save_compressed_dialog.h"

#include "octaclay/core/codec/codec.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/surface_distance.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QtConcurrent>

#include <cmath>
#include <filesystem>

namespace octaclay::app {
namespace {

// The qualities offered per codec, coarse to fine (the codec's default is added if missing).
std::vector<double> qualitiesFor(const core::Codec& codec, int n) {
  const std::string_view id = codec.info.id;
  std::vector<double> list;
  if (id == "bytepack") {
    for (int r = 1; r <= std::min(n, 256); r *= 4)
      list.push_back(r);
  } else if (id == "dct") {
    list = {10, 30, 50, 75, 90, 95, 100};
  } else if (id == "wavelet") {
    list = {1e-3, 3e-4, 1e-4, 3e-5, 1e-5, 3e-6, 1e-6};
  }
  const double fallback = codec.info.defaultQuality;
  if (!list.empty() && fallback > 0 &&
      std::find(list.begin(), list.end(), fallback) == list.end()) {
    list.push_back(fallback);
    std::sort(list.begin(), list.end(), [&](double a, double b) {
      return id == "wavelet" ? a > b : a < b; // wavelet: a larger bound is coarser
    });
  }
  return list;
}

QString formatBytes(std::size_t bytes) {
  if (bytes < 10 * 1024) return QObject::tr("%1 bytes").arg(bytes);
  if (bytes < 10 * 1024 * 1024)
    return QObject::tr("%1 KB").arg(static_cast<double>(bytes) / 1024.0, 0, 'f', 1);
  return QObject::tr("%1 MB").arg(static_cast<double>(bytes) / (1024.0 * 1024.0), 0, 'f', 2);
}

} // namespace

CompressionPreview previewCompression(const core::Document& doc,
                                      const core::CompressOptions& options) {
  CompressionPreview p;
  const std::vector<std::uint8_t> bytes = core::compressDocument(doc, options);
  const core::Document decoded = core::decompressDocument(bytes);
  const int n = doc.size();
  p.bytes = bytes.size();
  p.bitsPerVertex = 8.0 * static_cast<double>(p.bytes) / (static_cast<double>(n) * n + 2);
  const auto a = doc.positions.texels(), b = decoded.positions.texels();
  p.exact = std::equal(a.begin(), a.end(), b.begin(), b.end());
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    p.maxError = std::max(p.maxError, static_cast<double>(core::length(a[k].xyz() - b[k].xyz())));
  const core::TriangleMesh original = core::extractMesh(doc.positions);
  p.diagonal = core::boundingBox(original).diagonal();
  p.psnr = p.exact ? std::numeric_limits<double>::infinity()
                   : core::compareSurfaces(original, core::extractMesh(decoded.positions),
                                           {.samplesPerSurface = 0})
                         .psnr;
  return p;
}

core::Document readModelFile(const QString& path) {
  const std::filesystem::path file(path.toStdString());
  if (QFileInfo(path).suffix().compare("ocz", Qt::CaseInsensitive) == 0)
    return core::readCompressedDocument(file);
  return core::readDocument(file);
}

SaveCompressedDialog::SaveCompressedDialog(std::shared_ptr<const core::Document> doc,
                                           QWidget* parent)
    : QDialog(parent), doc_(std::move(doc)) {
  setWindowTitle(tr("Save compressed"));
  auto* form = new QFormLayout(this);
  codec_ = new QComboBox(this);
  codec_->setObjectName("codecCombo");
  for (const core::Codec& c : core::codecs())
    codec_->addItem(QString::fromUtf8(c.info.id.data(), static_cast<int>(c.info.id.size())));
  quality_ = new QSlider(Qt::Horizontal, this);
  quality_->setObjectName("qualitySlider");
  quality_->setPageStep(1);
  quality_->setTickPosition(QSlider::TicksBelow);
  qualityValue_ = new QLabel(this);
  qualityValue_->setObjectName("qualityValue");
  mode_ = new QComboBox(this);
  mode_->setObjectName("modeCombo");
  for (const char* m : {"zip", "piz", "pxr24", "half"})
    mode_->addItem(m);
  qualityHelp_ = new QLabel(this);
  qualityHelp_->setWordWrap(true);
  size_ = new QLabel(this);
  size_->setObjectName("sizeLabel");
  error_ = new QLabel(this);
  error_->setObjectName("errorLabel");
  form->addRow(tr("Codec"), codec_);
  auto* qualityRow = new QHBoxLayout;
  qualityRow->addWidget(new QLabel(tr("Smaller file"), this));
  qualityRow->addWidget(quality_, 1);
  qualityRow->addWidget(new QLabel(tr("More exact"), this));
  form->addRow(tr("Detail kept"), qualityRow);
  form->addRow(QString(), qualityValue_);
  form->addRow(tr("EXR mode"), mode_);
  form->addRow(qualityHelp_);
  form->addRow(tr("Size"), size_);
  form->addRow(tr("Error (% of size)"), error_);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Save | QDialogButtonBox::Cancel, this);
  form->addRow(buttons);
  connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);

  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(150);
  connect(debounce_, &QTimer::timeout, this, &SaveCompressedDialog::startPreview);
  connect(&watcher_, &QFutureWatcher<Outcome>::finished, this, &SaveCompressedDialog::showPreview);
  connect(codec_, &QComboBox::currentIndexChanged, this, [this] {
    fillQualities();
    schedulePreview();
  });
  connect(quality_, &QSlider::valueChanged, this, [this] {
    showQualityValue();
    schedulePreview();
  });
  connect(mode_, &QComboBox::currentIndexChanged, this, &SaveCompressedDialog::schedulePreview);
  const int wavelet = codec_->findText("wavelet");
  codec_->setCurrentIndex(wavelet >= 0 ? wavelet : 0);
  fillQualities();
  schedulePreview();
}

SaveCompressedDialog::~SaveCompressedDialog() {
  watcher_.waitForFinished(); // the worker reads doc_
}

core::CompressOptions SaveCompressedDialog::options() const {
  core::CompressOptions o;
  o.codec = codec_->currentText().toStdString();
  o.params.quality = quality_->isEnabled() && !qualities_.empty()
                         ? qualities_[static_cast<std::size_t>(quality_->value())]
                         : -1;
  if (o.codec == "exr") o.params.mode = mode_->currentText().toStdString();
  return o;
}

bool SaveCompressedDialog::setCodec(const QString& id) {
  const int k = codec_->findText(id);
  if (k < 0) return false;
  codec_->setCurrentIndex(k);
  return true;
}

bool SaveCompressedDialog::setQuality(double quality) {
  const auto it = std::find(qualities_.begin(), qualities_.end(), quality);
  if (it == qualities_.end() || !quality_->isEnabled()) return false;
  quality_->setValue(static_cast<int>(it - qualities_.begin()));
  return true;
}

bool SaveCompressedDialog::setMode(const QString& mode) {
  const int k = mode_->findText(mode);
  if (k < 0 || !mode_->isEnabled()) return false;
  mode_->setCurrentIndex(k);
  return true;
}

void SaveCompressedDialog::fillQualities() {
  const core::Codec* codec = core::findCodec(codec_->currentText().toStdString());
  const QSignalBlocker block(quality_);
  qualities_.clear();
  if (codec == nullptr) return;
  qualities_ = qualitiesFor(*codec, doc_->size());
  const auto k = std::find(qualities_.begin(), qualities_.end(), codec->info.defaultQuality);
  quality_->setRange(0, std::max(static_cast<int>(qualities_.size()) - 1, 0));
  quality_->setValue(k != qualities_.end() ? static_cast<int>(k - qualities_.begin()) : 0);
  quality_->setEnabled(!qualities_.empty());
  mode_->setEnabled(codec->info.id == "exr");
  // What the value means is for those who want it: the tooltip.
  qualityHelp_->setText(codec->info.lossy ? QString() : tr("This codec keeps the model exactly."));
  quality_->setToolTip(
      QString::fromUtf8(codec->info.quality.data(), static_cast<int>(codec->info.quality.size())));
  showQualityValue();
}

void SaveCompressedDialog::showQualityValue() {
  if (!quality_->isEnabled() || qualities_.empty()) {
    qualityValue_->clear();
    return;
  }
  const int k = quality_->value();
  qualityValue_->setText(tr("step %1 of %2").arg(k + 1).arg(qualities_.size()));
  qualityValue_->setToolTip(
      tr("The codec's quality value: %1").arg(qualities_[static_cast<std::size_t>(k)], 0, 'g', 6));
}

void SaveCompressedDialog::schedulePreview() {
  preview_.reset();
  previewError_.clear();
  size_->setText(tr("measuring…"));
  error_->setText(tr("measuring…"));
  debounce_->start();
}

void SaveCompressedDialog::startPreview() {
  if (watcher_.isRunning()) {
    rerun_ = true; // measured again once the running one ends
    return;
  }
  rerun_ = false;
  watcher_.setFuture(QtConcurrent::run([doc = doc_, options = options()]() {
    Outcome out;
    try {
      out.preview = previewCompression(*doc, options);
    } catch (const std::exception& e) {
      out.error = QString::fromUtf8(e.what());
    }
    return out;
  }));
}

void SaveCompressedDialog::showPreview() {
  if (rerun_) {
    startPreview();
    return;
  }
  const Outcome outcome = watcher_.result();
  preview_ = outcome.preview;
  if (!preview_) {
    previewError_ = outcome.error;
    size_->setText(tr("—"));
    error_->setText(tr("cannot compress: %1").arg(previewError_));
    emit previewUpdated();
    return;
  }
  const CompressionPreview& p = *preview_;
  size_->setText(
      tr("%1 (%2 bits per vertex)").arg(formatBytes(p.bytes)).arg(p.bitsPerVertex, 0, 'f', 2));
  if (p.exact) {
    error_->setText(tr("none: positions restored exactly"));
    error_->setToolTip({});
  } else {
    error_->setText(tr("at most %1 % of the model's size")
                        .arg(100 * p.maxError / std::max(p.diagonal, 1e-30), 0, 'g', 3));
    error_->setToolTip(tr("PSNR %1 dB; largest displacement %2 (model units); size is the "
                          "bounding-box diagonal")
                           .arg(p.psnr, 0, 'f', 1)
                           .arg(p.maxError, 0, 'g', 3));
  }
  emit previewUpdated();
}

} // namespace octaclay::app
