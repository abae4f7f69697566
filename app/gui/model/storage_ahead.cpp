// A document's textures made on a worker thread with a shared context (storage_ahead.h).
#include "storage_ahead.h"

#include <QCoreApplication>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QThread>

#include <exception>

namespace octaclay::app {

StorageAhead::StorageAhead() = default;
StorageAhead::~StorageAhead() = default;

gpu::GpuDocument::Storage StorageAhead::make(QOpenGLContext* shareWith,
                                             const core::SampleGrid& grid,
                                             const std::function<void()>& wait) {
  if (!shareWith) return {};
  if (!context_ || sharing_ != shareWith) {
    surface_ = std::make_unique<QOffscreenSurface>();
    surface_->setFormat(shareWith->format());
    surface_->create();
    context_ = std::make_unique<QOpenGLContext>();
    context_->setFormat(shareWith->format());
    context_->setShareContext(shareWith);
    sharing_ = shareWith;
    if (!surface_->isValid() || !context_->create() || !context_->shareContext()) {
      context_.reset();
      return {};
    }
  }
  gpu::GpuDocument::Storage storage;
  bool made = false;
  QThread* worker = QThread::create([&] {
    if (!context_->makeCurrent(surface_.get())) return;
    try {
      storage = gpu::GpuDocument::makeStorage(grid);
      context_->functions()->glFinish(); // made before the GUI context uses them
      made = true;
    } catch (const std::exception&) {
      storage = {}; // deleted here, in the context that made them
    }
    context_->doneCurrent();
    context_->moveToThread(QCoreApplication::instance()->thread());
  });
  context_->moveToThread(worker);
  worker->start();
  while (!worker->wait(10))
    if (wait) wait();
  delete worker;
  if (!made) context_.reset(); // not again: the upload makes its own
  return storage;
}

} // namespace octaclay::app
