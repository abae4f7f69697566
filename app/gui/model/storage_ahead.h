#pragma once

#include "octaclay/core/geometry/sample_grid.h"
#include "octaclay/gpu/gpu_document.h"

#include <functional>
#include <memory>

class QOffscreenSurface;
class QOpenGLContext;

namespace octaclay::app {

/// A document's textures made on a worker thread, in a context that shares the GUI context's
/// objects, while the GUI thread keeps running its event loop: a software rasterizer zeroes a
/// new texture's memory as it makes it (0.6 GB at N = 4096, up to seconds on a busy machine),
/// which would stall the window. Made once per GUI context; when a shared context cannot be
/// made (or made current), make() gives empty storage and the upload makes its own as before.
class StorageAhead {
public:
  StorageAhead();
  ~StorageAhead();
  StorageAhead(const StorageAhead&) = delete;
  StorageAhead& operator=(const StorageAhead&) = delete;

  /// The textures for `grid`, made beside `shareWith` (current on this, the GUI, thread); while
  /// they are made, `wait` is called every few milliseconds (it may process events). Leaves no
  /// context current: the caller makes its own current again.
  gpu::GpuDocument::Storage make(QOpenGLContext* shareWith, const core::SampleGrid& grid,
                                 const std::function<void()>& wait);

private:
  std::unique_ptr<QOffscreenSurface> surface_;
  std::unique_ptr<QOpenGLContext> context_;
  QOpenGLContext* sharing_ = nullptr; // the context context_ was made to share with
};

} // namespace octaclay::app
