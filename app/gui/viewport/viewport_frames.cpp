// The viewport's frames. The model alone on a plain background is drawn straight into the GL
// window's framebuffer; anything more (side by side, a gradient, another prop) is rendered by
// VTK into its own framebuffer, the model drawn inside VTK's pass, then blitted into the window's.

#include "viewport_frames.h"

#include "camera_control.h"
#include "current_context.h"
#include "data_folders.h"
#include "model_prop.h"
#include "modeller.h"
#include "sculpt_session.h"
#include "viewport_widget.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QPainter>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkPropCollection.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstring>

namespace octaclay::app {

ViewportFrames::ViewportFrames(ViewportWidget& widget, Modeller& modeller)
    : widget_(widget), modeller_(modeller) {
  renderWindow_->SetOwnContext(false);
  renderWindow_->SetFrameBlitModeToNoBlit();
  renderWindow_->SetReadyForRendering(false);
  renderWindow_->SetForceMaximumHardwareLineWidth(1);
  // VTK's default 4x multisampling triples the frame time on a software rasterizer, and the
  // model's per-pixel shading does not need it.
  renderWindow_->SetMultiSamples(0);
  // VTK asks whether the widget's context is current, and to make it current; the trap is to
  // make it current again when it already is (Qt would rebind its framebuffer while VTK builds
  // its own, leaving VTK's with no attachments).
  for (unsigned long event : {vtkCommand::WindowIsCurrentEvent, vtkCommand::WindowMakeCurrentEvent})
    renderWindow_->AddObserver(event, this, &ViewportFrames::onContextEvent);
  renderWindow_->AddRenderer(renderer_);
  // A plain clear: a gradient is one more full-screen pass per frame on a software rasterizer.
  renderer_->SetBackground(0.27, 0.29, 0.33);
  renderer_->SetBackgroundAlpha(1.0); // Qt composes the widget with its alpha
  renderer_->AddViewProp(prop_);
  prop_->draw = [this](vtkRenderer* r) { drawModel(r); };
  // Side by side: the LOD in the right half, seen through the same camera.
  lodRenderer_->SetBackground(0.27, 0.29, 0.33);
  lodRenderer_->SetBackgroundAlpha(1.0);
  lodRenderer_->SetActiveCamera(renderer_->GetActiveCamera());
  lodRenderer_->AddViewProp(lodProp_);
  lodRenderer_->SetViewport(0.5, 0, 1, 1);
  lodProp_->draw = [this](vtkRenderer* r) { drawModel(r); };
  modeller_.followChanges([this](const gpu::DocumentChange& change) { follow(change); });
}

void ViewportFrames::onContextEvent(vtkObject*, unsigned long event, void* callData) {
  const bool current = widget_.context() && QOpenGLContext::currentContext() == widget_.context();
  if (event == vtkCommand::WindowIsCurrentEvent)
    *static_cast<bool*>(callData) = current;
  else if (event == vtkCommand::WindowMakeCurrentEvent && !current)
    widget_.makeCurrent();
}

ViewportFrames::~ViewportFrames() {
  renderWindow_->Finalize();
}

bool ViewportFrames::glStarted(QString& error) {
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->OpenGLInitContext();
  try {
    model_ = std::make_unique<gpu::ModelRenderer>();
  } catch (const std::exception& e) {
    error = QStringLiteral("OpenGL 4.3 core is needed for sculpting: %1").arg(e.what());
    return false;
  }
  try {
    model_->setEnvironment(core::readImage(resourceFolder() / "environment/studio.png", 3));
  } catch (const core::Error& e) { // reflective paint then shows no reflection, nothing more
    error_ = QStringLiteral("environment map: %1").arg(e.what());
  }
  return true;
}

void ViewportFrames::glStopping() {
  model_.reset();
}

void ViewportFrames::resize(int width, int height) {
  renderWindow_->SetSize(width, height);
}

void ViewportFrames::follow(const gpu::DocumentChange& change) {
  // Normals (and with them the stretch map) read the positions around each texel.
  if (!model_ || change.layer != core::EditLayer::Positions) return;
  gpu::GpuDocument& document = modeller_.session().gpuDocument();
  if (change.kind == gpu::ChangeKind::NewDocument) return; // documentReplaced() redraws all
  try {
    model_->refreshNormals(document,
                           normalRectsAround(change.rects, document.side(), document.rows()));
  } catch (const std::exception& e) {
    modeller_.fail(QString::fromUtf8(e.what()));
  }
}

void ViewportFrames::documentReplaced() {
  if (!model_) return;
  gpu::GpuDocument& document = modeller_.session().gpuDocument();
  const int n = std::max(document.grid().width, document.grid().height);
  // Until the caller picks a level: one of at most 256 a side (N/1 of a 4096 image would build
  // a 33-million-triangle index buffer first).
  divisor_ = std::min(std::max(divisor_, std::max(1, n / 256)), std::max(1, n / 2));
  divisor_ = gpu::ModelRenderer::fittingDivisor(document.grid(), divisor_);
  model_->setLevel(document.grid(), divisor_);
  model_->refreshAllNormals(document);
  model_->setLodMesh({}); // the previous document's LOD is not this one's
  pendingLod_.reset();
  // A new scene or another object made active: the others drawn as they now are.
  others_.rebuild(*renderer_, modeller_);
  updateBounds();
}

void ViewportFrames::setLevelDivisor(int divisor) {
  divisor_ = std::max(1, divisor);
  if (!modeller_.session().hasDocument() || !model_) return;
  const core::SampleGrid& grid = modeller_.session().gpuDocument().grid();
  divisor_ = gpu::ModelRenderer::fittingDivisor(grid, divisor_);
  CurrentContext current(widget_);
  model_->setLevel(grid, divisor_);
}

void ViewportFrames::setLodDisplay(LodDisplay display) {
  lodDisplay_ = display;
  const bool sideBySide = display == LodDisplay::SideBySide;
  renderer_->SetViewport(0, 0, sideBySide ? 0.5 : 1.0, 1);
  if (sideBySide && !renderWindow_->HasRenderer(lodRenderer_))
    renderWindow_->AddRenderer(lodRenderer_);
  else if (!sideBySide && renderWindow_->HasRenderer(lodRenderer_))
    renderWindow_->RemoveRenderer(lodRenderer_);
}

long long ViewportFrames::lodTriangles() const {
  return model_ ? model_->lodTriangles() : 0;
}

long long ViewportFrames::displayedTriangles() const {
  if (!model_ || !modeller_.session().hasDocument()) return 0;
  if (lodDisplay_ == LodDisplay::Lod && lodTriangles() > 0) return lodTriangles();
  return model_->displayedTriangles();
}

const std::array<double, 6>& ViewportFrames::updateBounds() {
  if (!modeller_.session().hasDocument()) return prop_->bounds;
  // The scene's world bounds: the edited object's tile bounds under its transform, and every
  // other visible object's samples under its own.
  core::BoundingBox local;
  const core::TileBounds& b = modeller_.session().gpuDocument().bounds();
  for (int t = 0; t < b.tileCount(); ++t) {
    local.extend(b.box(t).min);
    local.extend(b.box(t).max);
  }
  core::BoundingBox box = widget_.placement().boxToWorld(local);
  for (int k = 0; k < modeller_.objectCount(); ++k) {
    const core::SceneObject& object = modeller_.objectAt(k);
    if (k == modeller_.activeObject() || !object.visible) continue;
    const core::BoundingBox other = core::worldBounds(object);
    if (other.empty()) continue;
    box.extend(other.min);
    box.extend(other.max);
  }
  prop_->bounds = {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
  return prop_->bounds;
}

const std::array<double, 6>& ViewportFrames::bounds() const {
  return prop_->bounds;
}

vtkRenderer* ViewportFrames::renderer() const {
  return renderer_.Get();
}
vtkRenderer* ViewportFrames::lodRenderer() const {
  return lodRenderer_.Get();
}
vtkGenericOpenGLRenderWindow* ViewportFrames::renderWindow() const {
  return renderWindow_.Get();
}

void ViewportFrames::drawModel(vtkRenderer* r) {
  if (!modeller_.session().hasDocument() || !model_) return;
  // The Objects dock's eye hides the edited object too (it stays the one brushes would use).
  if (!modeller_.activeShown()) return;
  vtkCamera* camera = r->GetActiveCamera();
  // The renderer works in the object's space: its transform folded into the matrix, the eye
  // (and applyLooks' view axes) brought into that space.
  const ObjectPlacement placement = widget_.placement();
  gpu::ModelView view;
  view.objectToClip = objectToClip(*camera, r->GetTiledAspectRatio(), placement.objectToWorld());
  view.eye = placement.toLocal(toVec(camera->GetPosition()));
  view.showDiffuse = showDiffuse_;
  view.showMask = showMask_;
  view.preview = preview_;
  applyLooks(view, r);
  if (ring_) {
    view.showBrush = true;
    view.brushCentre = ring_->centre;
    view.brushRadius = ring_->radius;
    view.brushColour = ring_->inverted ? std::array<float, 3>{1.0f, 0.45f, 0.35f}
                                       : std::array<float, 3>{1.0f, 1.0f, 1.0f};
  }
  vtkOpenGLState* state = renderWindow_->GetState();
  state->vtkglEnable(GL_DEPTH_TEST);
  state->vtkglDepthMask(GL_TRUE);
  state->vtkglDisable(GL_BLEND);
  // A closed surface never shows its back faces: culling halves what the rasterizer sees. A
  // plane is an open sheet, seen from both sides.
  if (modeller_.session().gpuDocument().topology() == core::Topology::Plane)
    state->vtkglDisable(GL_CULL_FACE);
  else
    state->vtkglEnable(GL_CULL_FACE);
  state->vtkglCullFace(GL_BACK);
  try {
    gpu::GpuDocument& document = modeller_.session().gpuDocument();
    const bool lod =
        r == lodRenderer_.Get() || (lodDisplay_ == LodDisplay::Lod && model_->lodTriangles() > 0);
    lod ? model_->drawLod(document, view) : model_->draw(document, view);
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
  }
  // What VTK believes is bound is no longer so.
  renderWindow_->GetShaderCache()->ReleaseCurrentShader();
  state->vtkglDisable(GL_CULL_FACE);
  state->ResetGLActiveTexture();
}

void ViewportFrames::renderVtkFrame() {
  vtkOpenGLState* state = renderWindow_->GetState();
  state->Reset(); // the engine and Qt changed GL state behind VTK's cache
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  renderer_->ResetCameraClippingRange(prop_->bounds.data());
  if (lodDisplay_ == LodDisplay::SideBySide)
    lodRenderer_->ResetCameraClippingRange(prop_->bounds.data());
  renderWindow_->Render();
  state->Pop();
}

bool ViewportFrames::drawsDirectly() const {
  return lodDisplay_ != LodDisplay::SideBySide && !looks_.gradient &&
         renderer_->GetViewProps()->GetNumberOfItems() == 1;
}

void ViewportFrames::renderDirectFrame(QSize size) {
  QOpenGLExtraFunctions* gl = widget_.context()->extraFunctions();
  renderWindow_->GetState()->Reset(); // drawModel sets state through VTK's cache
  gl->glBindFramebuffer(GL_FRAMEBUFFER, widget_.defaultFramebufferObject());
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
  renderer_->ResetCameraClippingRange(prop_->bounds.data());
  drawModel(renderer_.Get());
}

void ViewportFrames::paint(QSize size, const std::optional<BrushRing>& ring) {
  QOpenGLExtraFunctions* gl = widget_.context()->extraFunctions();
  if (!model_) {
    gl->glClearColor(0.2f, 0.2f, 0.22f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    return;
  }
  if (pendingLod_) {
    try {
      model_->setLodMesh(*pendingLod_);
    } catch (const std::exception& e) {
      error_ = QString::fromUtf8(e.what());
    }
    pendingLod_.reset();
  }
  ring_ = ring;
  if (drawsDirectly()) {
    renderDirectFrame(size);
  } else {
    renderVtkFrame();
    const GLuint fbo = widget_.defaultFramebufferObject();
    gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    const GLenum buffer = fbo == 0 ? GL_BACK : GL_COLOR_ATTACHMENT0;
    gl->glDrawBuffers(1, &buffer);
    gl->glDisable(GL_SCISSOR_TEST);
    renderWindow_->BlitDisplayFramebuffer(0, 0, 0, size.width(), size.height(), 0, 0, size.width(),
                                          size.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  ring_.reset();
  renderWindow_->GetState()->Reset();
}

void ViewportFrames::paintMarks(QPaintDevice& device) {
  if ((!framePainter_ && !gizmoPainter_) || !model_ || modeller_.uploading()) return;
  {
    // Qt's GL paint engine sets and resets its own state; VTK's cache of it is stale after.
    QPainter painter(&device);
    if (gizmoPainter_) gizmoPainter_(painter);
    if (framePainter_) framePainter_(painter);
  }
  renderWindow_->GetState()->Reset();
}

void ViewportFrames::setLooks(const ViewLooks& looks) {
  looks_ = looks;
  for (vtkRenderer* r : {renderer_.Get(), lodRenderer_.Get()}) {
    const QColor& top = looks.backgroundTop;
    const QColor& bottom = looks.gradient ? looks.backgroundBottom : looks.backgroundTop;
    // VTK's Background is the bottom of a gradient, Background2 its top.
    r->SetBackground(bottom.redF(), bottom.greenF(), bottom.blueF());
    r->SetBackground2(top.redF(), top.greenF(), top.blueF());
    r->SetGradientBackground(looks.gradient);
  }
}

void ViewportFrames::applyLooks(gpu::ModelView& view, vtkRenderer* r) {
  view.wireframe = looks_.wireframe;
  if (looks_.material == "lit" || !model_) return;
  if (loadedMatcap_ != looks_.material) {
    loadedMatcap_ = looks_.material; // tried once: a broken file is reported, not retried
    try {
      model_->setMatcap(core::readImage(matcapPath(looks_.material).toStdString(), 3));
    } catch (const std::exception& e) {
      error_ = QStringLiteral("Could not load the %1 matcap: %2").arg(looks_.material, e.what());
    }
  }
  view.matcap = model_->hasMatcap();
  // The view matrix's first two rows: the camera's right and up axes in world space, carried
  // into object space (exact for a rotation and a uniform scale; under a non-uniform scale the
  // matcap is looked up as if the normal were not renormalized).
  vtkMatrix4x4* m = r->GetActiveCamera()->GetViewTransformMatrix();
  const ObjectPlacement placement = widget_.placement();
  view.viewRight = core::normalize(placement.directionToLocal(
      {float(m->GetElement(0, 0)), float(m->GetElement(0, 1)), float(m->GetElement(0, 2))}));
  view.viewUp = core::normalize(placement.directionToLocal(
      {float(m->GetElement(1, 0)), float(m->GetElement(1, 1)), float(m->GetElement(1, 2))}));
}

int ViewportFrames::maxImageSide() {
  if (!model_) return 0;
  CurrentContext current(widget_, CurrentContext::Mode::IfNotCurrent);
  QOpenGLExtraFunctions* gl = widget_.context()->extraFunctions();
  GLint texture = 0, renderbuffer = 0, viewport[2] = {0, 0};
  gl->glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
  gl->glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  gl->glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({8192, int(texture), int(renderbuffer), int(viewport[0]), int(viewport[1])});
}

QImage ViewportFrames::renderImage(QSize size, bool background) {
  const int side = maxImageSide();
  if (side <= 0 || size.isEmpty() || size.width() > side || size.height() > side) return {};
  const int w = size.width(), h = size.height();
  vtkNew<vtkUnsignedCharArray> pixels;
  {
    CurrentContext current(widget_, CurrentContext::Mode::IfNotCurrent);
    modeller_.drainGlErrors();
    const int* shown = renderWindow_->GetSize();
    const int shownWidth = shown[0], shownHeight = shown[1];
    const double alpha = background ? 1.0 : 0.0;
    renderer_->SetBackgroundAlpha(alpha);
    lodRenderer_->SetBackgroundAlpha(alpha);
    renderWindow_->SetSize(w, h);
    renderVtkFrame(); // no brush ring: ring_ is only set inside paint()
    // front = 1: the display framebuffer, the one paintGL shows.
    renderWindow_->GetRGBACharPixelData(0, 0, w - 1, h - 1, 1, pixels);
    renderWindow_->GetState()->Reset();
    renderer_->SetBackgroundAlpha(1.0);
    lodRenderer_->SetBackgroundAlpha(1.0);
    renderWindow_->SetSize(shownWidth, shownHeight);
  }
  widget_.update();
  if (pixels->GetNumberOfValues() != vtkIdType(w) * h * 4) return {};
  QImage image(w, h, QImage::Format_RGBA8888);
  for (int y = 0; y < h; ++y) // GL's rows run bottom up
    std::memcpy(image.scanLine(h - 1 - y), pixels->GetPointer(vtkIdType(y) * w * 4),
                std::size_t(w) * 4);
  return background ? image.convertToFormat(QImage::Format_RGB888) : image;
}

} // namespace octaclay::app
