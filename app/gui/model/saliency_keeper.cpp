#include "saliency_keeper.h"

#include "octaclay/core/lod/saliency.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/saliency.h"

#include <QtConcurrent/QtConcurrentRun>

namespace octaclay::app {

SaliencyKeeper::SaliencyKeeper(QObject* parent) : QObject(parent) {
  connect(&job_, &QFutureWatcher<std::vector<float>>::finished, this, &SaliencyKeeper::jobFinished);
}

SaliencyKeeper::~SaliencyKeeper() {
  job_.waitForFinished();
}

void SaliencyKeeper::surfaceEdited() {
  stale_ = true;
  ++surfaceVersion_;
}

void SaliencyKeeper::refresh(gpu::GpuDocument& document) {
  if (!wanted_ || !stale_) return;
  if (onCpu_) {
    if (job_.isRunning()) return; // its end starts the next one
    auto image = std::make_shared<core::GeometryImage>(document.document().positions);
    jobVersion_ = surfaceVersion_;
    job_.setFuture(QtConcurrent::run([image] {
      std::vector<float> values;
      try {
        core::computeSaliency(*image);
      } catch (const std::exception&) {
        return values; // empty: nothing written, the saliency stays stale
      }
      values.reserve(image->texelCount());
      for (const core::Vec4f& t : image->texels())
        values.push_back(t.w);
      return values;
    }));
    return;
  }
  try {
    if (!pass_) pass_ = std::make_unique<gpu::SaliencyPass>();
    pass_->run(document);
    stale_ = false;
  } catch (const std::exception& e) {
    emit failed(QStringLiteral("Could not compute the saliency: %1").arg(e.what()));
  }
}

bool SaliencyKeeper::storeJob(gpu::GpuDocument& document) {
  const std::vector<float> values = job_.result();
  if (jobVersion_ != surfaceVersion_) return true;
  if (values.size() != document.document().positions.texelCount()) return false;
  try {
    document.writeSaliency(values);
    stale_ = false;
  } catch (const std::exception& e) {
    emit failed(QStringLiteral("Could not store the saliency: %1").arg(e.what()));
  }
  return false;
}

void SaliencyKeeper::releaseGpu() {
  pass_.reset();
}

} // namespace octaclay::app
