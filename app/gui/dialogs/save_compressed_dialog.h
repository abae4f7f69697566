#pragma once

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document.h"

#include <QDialog>
#include <QFutureWatcher>
#include <QString>

#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QSlider;
class QTimer;

namespace octaclay::app {

/// What a compressed save of the document would give, measured before writing.
struct CompressionPreview {
  std::size_t bytes = 0;    ///< the whole .ocz
  double bitsPerVertex = 0; ///< 8·bytes / (N² + 2)
  bool exact = false;       ///< positions decode bit for bit
  double psnr = 0;          ///< dB of the decoded surface; +inf when exact
  double maxError = 0;      ///< largest sample displacement, object units
  double diagonal = 0;      ///< bounding-box diagonal, object units
};

/// Compresses `doc` with options, decodes it and measures the result (runs in the caller's
/// thread; the dialog calls it on a worker).
CompressionPreview previewCompression(const core::Document& doc,
                                      const core::CompressOptions& options);

/// A model file by extension: .ocz through the compressed container, else an Octaclay EXR.
core::Document readModelFile(const QString& path);

/// File › Save Compressed…: codec, a slider from "Smaller file" to "More exact" over the codec's
/// qualities (the technical value in its tooltip), or the EXR mode, and a live preview of the
/// size and error (as a percentage of the model's size; PSNR in the tooltip), computed in the
/// background whenever the choice changes, before anything is written.
class SaveCompressedDialog : public QDialog {
  Q_OBJECT
public:
  SaveCompressedDialog(std::shared_ptr<const core::Document> doc, QWidget* parent = nullptr);
  ~SaveCompressedDialog() override;

  core::CompressOptions options() const;
  /// Selects a codec (by id) and a quality (the codec's own value, e.g. 1e-5 for wavelet) or
  /// mode offered for it; false when not offered.
  bool setCodec(const QString& id);
  bool setQuality(double quality);
  bool setMode(const QString& mode);

  /// The preview of the current choice, once computed (nullopt while it is being computed).
  const std::optional<CompressionPreview>& preview() const { return preview_; }
  QString previewError() const { return previewError_; }

signals:
  /// The preview of the current choice is ready (or failed: previewError()).
  void previewUpdated();

private:
  void fillQualities();
  void showQualityValue();
  void schedulePreview();
  void startPreview();
  void showPreview();

  std::shared_ptr<const core::Document> doc_;
  QComboBox* codec_ = nullptr;
  QSlider* quality_ = nullptr;    // index into qualities_, coarse (small file) to fine
  std::vector<double> qualities_; // the codec's, coarse to fine; empty: no quality
  QLabel* qualityValue_ = nullptr;
  QComboBox* mode_ = nullptr;
  QLabel* qualityHelp_ = nullptr;
  QLabel* size_ = nullptr;
  QLabel* error_ = nullptr;
  QTimer* debounce_ = nullptr;
  struct Outcome {
    std::optional<CompressionPreview> preview;
    QString error;
  };
  QFutureWatcher<Outcome> watcher_;
  bool rerun_ = false; // the choice changed while it ran
  std::optional<CompressionPreview> preview_;
  QString previewError_;
};

} // namespace octaclay::app
