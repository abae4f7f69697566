#pragma once

#include <QFutureWatcher>
#include <QObject>
#include <QString>

#include <cstdint>
#include <memory>
#include <vector>

namespace octaclay::gpu {
class GpuDocument;
class SaliencyPass;
} // namespace octaclay::gpu

namespace octaclay::app {

/// Keeps the positions' alpha the saliency of the current surface while it is wanted (the
/// saliency heat map, a salient LOD): recomputed when stale, on the GPU (gpu::SaliencyPass) at
/// once, or with the CPU reference (core::computeSaliency) on a worker thread. GUI thread; the
/// calls marked so need the document's GL context current.
class SaliencyKeeper : public QObject {
  Q_OBJECT
public:
  explicit SaliencyKeeper(QObject* parent = nullptr);
  ~SaliencyKeeper() override;

  void setWanted(bool wanted) { wanted_ = wanted; }
  bool wanted() const { return wanted_; }
  /// Whether the positions' alpha is the saliency of the current surface.
  bool current() const { return !stale_; }
  bool stale() const { return stale_; }
  /// Computes on a worker thread instead of on the GPU.
  void setOnCpu(bool onCpu) { onCpu_ = onCpu; }
  bool onCpu() const { return onCpu_; }

  /// The surface changed: the saliency is stale.
  void surfaceEdited();
  /// GL current: if wanted and stale, computes it on the GPU now, or starts the CPU job (unless
  /// one runs: jobFinished comes first). Emits failed if the GPU pass throws.
  void refresh(gpu::GpuDocument& document);
  /// GL current, after jobFinished: writes the job's values into document if they are the
  /// current surface's (emits failed if that throws). Returns whether the surface changed while
  /// the job ran (then its values were dropped and the caller may refresh again).
  bool storeJob(gpu::GpuDocument& document);
  /// Waits for the CPU job, if any.
  void waitForJob() { job_.waitForFinished(); }
  /// GL current: frees the GPU pass (before its context goes).
  void releaseGpu();

signals:
  /// A CPU job ended: call storeJob with the GL context current.
  void jobFinished();
  void failed(const QString& message);

private:
  std::unique_ptr<gpu::SaliencyPass> pass_;
  bool wanted_ = false, stale_ = true, onCpu_ = false;
  std::uint64_t surfaceVersion_ = 0, jobVersion_ = 0; // the job's result fits its version
  QFutureWatcher<std::vector<float>> job_;
};

} // namespace octaclay::app
