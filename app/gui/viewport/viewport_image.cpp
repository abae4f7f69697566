// The viewport drawn offscreen at any size for File ▸ Save Image: VTK's own framebuffers are
// resized for one frame, drawn as paintGL draws them, read back and sized back.

#include "current_context.h"
#include "model_prop.h"
#include "viewport_widget.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>
#include <utility>

namespace octaclay::app {

int ViewportWidget::maxImageSide() {
  if (!model_) return 0;
  CurrentContext current(*this, CurrentContext::Mode::IfNotCurrent);
  QOpenGLExtraFunctions* gl = context()->extraFunctions();
  GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
  gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  gl->glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({8192, int(texture), int(renderbuffer), int(viewport[0]), int(viewport[1])});
}

QImage ViewportWidget::renderImage(QSize size, bool background) {
  const int side = maxImageSide();
  if (side <= 0 || size.isEmpty() || size.width() > side || size.height() > side) return {};
  const int w = size.width(), h = size.height();
  vtkNew<vtkUnsignedCharArray> pixels;
  {
    CurrentContext current(*this, CurrentContext::Mode::IfNotCurrent);
    drainGlErrors();
    const std::optional<core::PickHit> hover = std::exchange(hover_, std::nullopt);
    const int* shown = renderWindow_->GetSize();
    const int shownWidth = shown[0], shownHeight = shown[1];
    const double alpha = background ? 1.0 : 0.0;
    renderer_->SetBackgroundAlpha(alpha);
    lodRenderer_->SetBackgroundAlpha(alpha);
    renderWindow_->SetSize(w, h);

    renderVtkFrame();
    // front = 1: the display framebuffer, the one paintGL shows.
    renderWindow_->GetRGBACharPixelData(0, 0, w - 1, h - 1, 1, pixels);
    renderWindow_->GetState()->Reset();

    renderer_->SetBackgroundAlpha(1.0);
    lodRenderer_->SetBackgroundAlpha(1.0);
    renderWindow_->SetSize(shownWidth, shownHeight);
    hover_ = hover;
  }
  update();
  if (pixels->GetNumberOfValues() != vtkIdType(w) * h * 4) return {};
  QImage image(w, h, QImage::Format_RGBA8888);
  for (int y = 0; y < h; ++y) // GL's rows run bottom up
    std::memcpy(image.scanLine(h - 1 - y), pixels->GetPointer(vtkIdType(y) * w * 4),
                std::size_t(w) * 4);
  return background ? image.convertToFormat(QImage::Format_RGB888) : image;
}

} // namespace octaclay::app
