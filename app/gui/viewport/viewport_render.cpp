// The viewport's frames. The model alone on a plain background is drawn straight into the GL
// window's framebuffer; anything more (side by side, a gradient, another prop) is rendered by
// VTK into its own framebuffer, the model drawn inside VTK's pass, then blitted into the window's.

#include "camera_control.h"
#include "model_prop.h"
#include "viewport_widget.h"

#include "octaclay/gpu/model_renderer.h"

#include <QGuiApplication>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QPainter>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>

namespace octaclay::app {

void ViewportWidget::drawModel(vtkRenderer* r) {
  if (!session_.hasDocument() || !model_) return;
  vtkCamera* camera = r->GetActiveCamera();
  gpu::ModelView view;
  view.objectToClip = objectToClip(*camera, r->GetTiledAspectRatio());
  view.eye = toVec(camera->GetPosition());
  view.showDiffuse = showDiffuse_;
  view.showMask = showMask_;
  view.preview = preview_;
  applyLooks(view, r);
  if (hover_ && drag_ != Drag::Orbit && drag_ != Drag::Pan) {
    view.showBrush = true;
    view.brushCentre = hover_->position;
    view.brushRadius = settings_.radius * session_.diagonal();
    const bool inverted = QGuiApplication::keyboardModifiers() & Qt::ControlModifier;
    view.brushColour = inverted ? std::array<float, 3>{1.0f, 0.45f, 0.35f}
                                : std::array<float, 3>{1.0f, 1.0f, 1.0f};
  }
  vtkOpenGLState* state = renderWindow_->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  // A closed surface never shows its back faces: culling halves what the rasterizer sees.
  state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  try {
    const bool lod =
        r == lodRenderer_.Get() || (lodDisplay_ == LodDisplay::Lod && model_->lodTriangles() > 0);
    if (lod)
      model_->drawLod(session_.gpuDocument(), view);
    else
      model_->draw(session_.gpuDocument(), view);
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
  }
  // What VTK believes is bound is no longer so.
  renderWindow_->GetShaderCache()->ReleaseCurrentShader();
  state->vtkglDisable(GL_CULL_FACE);
  state->ResetGLActiveTexture();
}

void ViewportWidget::renderVtkFrame() {
  vtkOpenGLState* state = renderWindow_->GetState();
  state->Reset(); // the engine and Qt changed GL state behind VTK's cache
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  updateClipping();
  if (lodDisplay_ == LodDisplay::SideBySide)
    lodRenderer_->ResetCameraClippingRange(prop_->bounds.data());
  renderWindow_->Render();
  state->Pop();
}

bool ViewportWidget::drawsDirectly() const {
  return lodDisplay_ != LodDisplay::SideBySide && !looks_.gradient &&
         renderer_->GetViewProps()->GetNumberOfItems() == 1;
}

void ViewportWidget::renderDirectFrame(QSize size) {
  QOpenGLExtraFunctions* gl = context()->extraFunctions();
  renderWindow_->GetState()->Reset(); // drawModel sets state through VTK's cache
  gl->glBindFramebuffer(GL_FRAMEBUFFER, defaultFramebufferObject());
  gl->glViewport(0, 0, size.width(), size.height());
  gl->glDisable(GL_SCISSOR_TEST);
  const QColor& background = looks_.backgroundTop;
  gl->glClearColor(float(background.redF()), float(background.greenF()), float(background.blueF()),
                   1.0f);
  gl->glDepthMask(GL_TRUE);
  gl->glClearDepthf(1.0f);
  gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  gl->glDepthFunc(GL_LEQUAL);
  if (!prop_->GetVisibility()) return;
  updateClipping();
  drawModel(renderer_.Get());
}

void ViewportWidget::paintGL() {
  if (uploading_) return; // a document is half uploaded: keep the last frame
  if (!context()->isValid() || QOpenGLContext::currentContext() != context()) return; // no GL
  const qint64 now = clock_.elapsed();
  frameTimes_.push_back(now);
  while (!frameTimes_.empty() && now - frameTimes_.front() > 2000)
    frameTimes_.pop_front();
  QOpenGLExtraFunctions* gl = context()->extraFunctions();
  if (!model_) {
    gl->glClearColor(0.2f, 0.2f, 0.22f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  drainGlErrors();
  const bool dabbed = runQueuedDabs() > 0;
  if (pendingLod_) {
    try {
      model_->setLodMesh(*pendingLod_);
    } catch (const std::exception& e) {
      error_ = QString::fromUtf8(e.what());
    }
    pendingLod_.reset();
  }

  const QSize size = this->size() * devicePixelRatioF();
  if (drawsDirectly()) {
    renderDirectFrame(size);
  } else {
    renderVtkFrame();
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
    const GLenum buffer = defaultFramebufferObject() == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0;
    gl->glDrawBuffers(1, &buffer);
    gl->glDisable(GL_SCISSOR_TEST);
    renderWindow_->BlitDisplayFramebuffer(0, 0, 0, size.width(), size.height(), 0, 0, size.width(),
                                          size.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  renderWindow_->GetState()->Reset();
  if (dabbed || session_.stroking()) emit statsChanged();
  if (dabbed) emit surfaceChanged();
  if (session_.hasDocument()) emit framePainted();
}

void ViewportWidget::setFramePainter(std::function<void(QPainter&)> paint) {
  framePainter_ = std::move(paint);
  update();
}

void ViewportWidget::paintMarks(QPaintDevice& device) {
  if (!framePainter_ || !model_ || uploading_) return;
  {
    // Qt's GL paint engine sets and resets its own state; VTK's cache of it is stale after.
    QPainter painter(&device);
    framePainter_(painter);
  }
  renderWindow_->GetState()->Reset();
}

} // namespace octaclay::app
