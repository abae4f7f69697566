#include "viewport_widget.h"

#include "brush_setup.h"
#include "camera_control.h"
#include "current_context.h"
#include "data_folders.h"
#include "model_prop.h"
#include "viewport_overlay.h"
#include "viewport_surface.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QSurfaceFormat>
#include <QTabletEvent>
#include <QWheelEvent>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace octaclay::app {

ViewportWidget::ViewportWidget(QWidget* parent) : QWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(4, 3); // the brush engine's compute-free passes need 4.3 core (SSBOs)
  format.setProfile(QSurfaceFormat::CoreProfile);
  // Depth for the frames drawn straight into the window's framebuffer (the others are VTK's blit).
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(0);
  format.setSwapInterval(0); // frames/s are measured, not capped by vsync
  surface_ = new ViewportSurface(*this);
  surface_->setFormat(format);
  // No layout: the widget's size hint stays a plain widget's, so the main window sizes the view
  // as it did a QOpenGLWidget.
  container_ = QWidget::createWindowContainer(surface_, this);
  container_->setFocusPolicy(Qt::NoFocus);
  container_->setMouseTracking(true);
  connect(surface_, &QOpenGLWindow::frameSwapped, this, &ViewportWidget::frameSwapped);
  setFocusPolicy(Qt::WheelFocus); // a click or a wheel turn takes the keys back from a dock
  setMouseTracking(true);
  setMinimumSize(320, 240);
  clock_.start();

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
  renderWindow_->AddObserver(vtkCommand::WindowIsCurrentEvent, this,
                             &ViewportWidget::onRenderWindowEvent);
  renderWindow_->AddObserver(vtkCommand::WindowMakeCurrentEvent, this,
                             &ViewportWidget::onRenderWindowEvent);
  renderWindow_->AddRenderer(renderer_);
  // A plain clear: a gradient is one more full-screen pass per frame on a software rasterizer.
  renderer_->SetBackground(0.27, 0.29, 0.33);
  renderer_->SetBackgroundAlpha(1.0); // Qt composes the widget with its alpha
  renderer_->AddViewProp(prop_);
  prop_->draw = [this](vtkRenderer* r) { drawModel(r); };
  connect(&saliency_, &SaliencyKeeper::jobFinished, this, &ViewportWidget::cpuSaliencyFinished);
  connect(&saliency_, &SaliencyKeeper::failed, this, &ViewportWidget::fail);
  // Side by side: the LOD in the right half, seen through the same camera.
  lodRenderer_->SetBackground(0.27, 0.29, 0.33);
  lodRenderer_->SetBackgroundAlpha(1.0);
  lodRenderer_->SetActiveCamera(renderer_->GetActiveCamera());
  lodRenderer_->AddViewProp(lodProp_);
  lodRenderer_->SetViewport(0.5, 0, 1, 1);
  lodProp_->draw = [this](vtkRenderer* r) { drawModel(r); };
  overlay_ = new ViewportOverlay(this);
}

ViewportWidget::~ViewportWidget() {
  saliency_.waitForJob();
  CurrentContext current(*this);
  session_.releaseGpu();
  saliency_.releaseGpu();
  model_.reset();
  library_.reset();
  context_.reset();
  renderWindow_->Finalize();
}

void ViewportWidget::onRenderWindowEvent(vtkObject*, unsigned long event, void* callData) {
  const bool current = context() && QOpenGLContext::currentContext() == context();
  if (event == vtkCommand::WindowIsCurrentEvent)
    *static_cast<bool*>(callData) = current;
  else if (event == vtkCommand::WindowMakeCurrentEvent && !current)
    makeCurrent();
}

void ViewportWidget::resizeEvent(QResizeEvent* event) {
  container_->setGeometry(rect());
  QWidget::resizeEvent(event);
}

void ViewportWidget::update() {
  if (surface_) surface_->update();
}

QOpenGLContext* ViewportWidget::context() const {
  return surface_->context();
}

void ViewportWidget::makeCurrent() {
  surface_->makeCurrent();
}

void ViewportWidget::doneCurrent() {
  surface_->doneCurrent();
}

GLuint ViewportWidget::defaultFramebufferObject() const {
  return surface_->defaultFramebufferObject();
}

QImage ViewportWidget::grabFramebuffer() {
  if (!surface_->isValid()) return {};
  makeCurrent();
  paintGL(); // into the back buffer, read before any swap shows it
  QImage image = surface_->grabFramebuffer();
  doneCurrent();
  return image;
}

vtkRenderer* ViewportWidget::renderer() const {
  return renderer_.Get();
}
vtkGenericOpenGLRenderWindow* ViewportWidget::renderWindow() const {
  return renderWindow_.Get();
}

void ViewportWidget::drainGlErrors() {
  // Qt and VTK may leave an error pending; the engine checks errors after its own calls.
  QOpenGLFunctions* gl = context()->functions();
  for (int k = 0; k < 16 && gl->glGetError() != GL_NO_ERROR; ++k) {
  }
}

void ViewportWidget::fail(const QString& message) {
  error_ = message;
  emit errorOccurred(message);
}

void ViewportWidget::initializeGL() {
  glStarted_ = true;
  // A QOpenGLWindow calls this even when it could make no context (a display without OpenGL 4.3).
  if (!context() || !context()->isValid() || QOpenGLContext::currentContext() != context()) {
    fail(tr("OpenGL 4.3 core is needed for sculpting: the display gave no OpenGL 4.3 context"));
    return;
  }
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->OpenGLInitContext();
  try {
    context_ = std::make_unique<gpu::GlContext>(gpu::GlContext::adoptCurrent());
    library_ = std::make_unique<gpu::BrushLibrary>(
        gpu::BrushCatalog::defaultSearchPath(builtInBrushFolder()));
    model_ = std::make_unique<gpu::ModelRenderer>();
    const QString renderer = QString::fromLatin1(
        reinterpret_cast<const char*>(context()->functions()->glGetString(GL_RENDERER)));
    saliency_.setOnCpu(renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                       renderer.contains("SwiftShader"));
    materials_.scan(gpu::MaterialCatalog::defaultSearchPath(builtInMaterialFolder()));
    library_->engine().setMaterials(materials_);
    try {
      model_->setEnvironment(core::readImage(resourceFolder() / "environment/studio.png", 3));
    } catch (const core::Error& e) { // reflective paint then shows no reflection, nothing more
      materialErrors_ << QStringLiteral("environment map: %1").arg(e.what());
    }
  } catch (const std::exception& e) {
    library_.reset();
    model_.reset();
    fail(QStringLiteral("OpenGL 4.3 core is needed for sculpting: %1").arg(e.what()));
    return;
  }
  session_.setBrushes(library_->engine(), library_->catalog());
  emit brushesChanged();
  if (pending_) {
    core::Document document = std::move(*pending_);
    pending_.reset();
    uploadDocument(std::move(document));
  }
}

void ViewportWidget::resizeGL(int width, int height) {
  const qreal ratio = devicePixelRatioF();
  renderWindow_->SetSize(static_cast<int>(width * ratio), static_cast<int>(height * ratio));
}

bool ViewportWidget::setDocument(core::Document document, bool keepView) {
  if (!glStarted_) {
    pending_ = std::move(document);
    session_.history().clear();
    return true;
  }
  bool ok = false;
  {
    CurrentContext current(*this);
    ok = uploadDocument(std::move(document), keepView);
  }
  update();
  return ok;
}

bool ViewportWidget::uploadDocument(core::Document document, bool keepView) {
  if (!model_) {
    pending_ = std::move(document); // kept so it can still be saved
    return false;
  }
  const int n = document.size();
  try {
    drainGlErrors();
    // The upload is GL work, so it stays on this thread; between its bands the event loop runs
    // (timers, repaints, the progress dialog) but no user input: nothing may edit meanwhile.
    QElapsedTimer sinceEvents;
    sinceEvents.start();
    session_.setDocument(std::move(document), [&](float) {
      if (sinceEvents.elapsed() < 30) return;
      uploading_ = true;
      QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
      uploading_ = false;
      makeCurrent(); // a repaint in between may have left another context current
      sinceEvents.restart();
    });
    // Until the caller picks a level: one of at most 256 a side (N/1 of a 4096 image would
    // build a 33-million-triangle index buffer first).
    divisor_ = std::max(divisor_, std::max(1, n / 256));
    divisor_ = std::min(divisor_, std::max(1, n / 2));
    model_->setLevel(n, divisor_);
    model_->refreshAllNormals(session_.gpuDocument());
    model_->setLodMesh({}); // the previous document's LOD is not this one's
    pendingLod_.reset();
  } catch (const std::exception& e) {
    fail(QStringLiteral("Could not load the model onto the GPU: %1").arg(e.what()));
    return false;
  }
  surfaceEdited();
  refreshSaliency();
  if (!keepView) resetCamera();
  emit statsChanged();
  emit surfaceChanged();
  return true;
}

bool ViewportWidget::hasDocument() const {
  return session_.hasDocument() || pending_.has_value();
}

const core::Document& ViewportWidget::document() const {
  if (!session_.hasDocument()) return *pending_;
  if (!session_.gpuDocument().mirrorStale()) return session_.document();
  // Mid-stroke (autosave, save): the session reads the deferred paint back, which is GL work.
  CurrentContext current(const_cast<ViewportWidget&>(*this), CurrentContext::Mode::IfNotCurrent);
  return session_.document();
}

void ViewportWidget::updateBounds() {
  if (!session_.hasDocument()) return;
  core::BoundingBox box;
  const core::TileBounds& b = session_.gpuDocument().bounds();
  for (int t = 0; t < b.tilesPerSide() * b.tilesPerSide(); ++t) {
    box.extend(b.box(t).min);
    box.extend(b.box(t).max);
  }
  prop_->bounds = {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
}

void ViewportWidget::resetCamera() {
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, 1);
  setViewDirection(*camera, ViewDirection::Front);
  frameModel();
}

void ViewportWidget::frameFrom(core::Vec3f towardEye) {
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(towardEye.x, towardEye.y, towardEye.z);
  camera->SetViewUp(0, 1, 0);
  frameModel();
}

void ViewportWidget::frameModel() {
  updateBounds();
  renderer_->ResetCamera(prop_->bounds.data());
  update();
}

void ViewportWidget::setView(ViewDirection direction) {
  setViewDirection(*renderer_->GetActiveCamera(), direction);
  update();
}

bool ViewportWidget::orthographic() const {
  return renderer_->GetActiveCamera()->GetParallelProjection();
}

void ViewportWidget::setOrthographic(bool orthographic) {
  const std::array<double, 6>& b = prop_->bounds;
  const double diagonal = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
  vtkCamera* camera = renderer_->GetActiveCamera();
  const core::Vec3f centre{static_cast<float>(b[0] + b[1]) / 2, static_cast<float>(b[2] + b[3]) / 2,
                           static_cast<float>(b[4] + b[5]) / 2};
  // Far enough back that the whole model lies in front of the eye.
  const double reach = core::length(toVec(camera->GetFocalPoint()) - centre) + diagonal;
  setParallelProjection(*camera, orthographic, reach);
  update();
}

void ViewportWidget::updateClipping() {
  renderer_->ResetCameraClippingRange(prop_->bounds.data());
}

void ViewportWidget::setBrushSettings(const BrushSettings& settings) {
  settings_ = settings;
  stabilizer_.setStrength(settings.stabilizer);
  update();
}

void ViewportWidget::setPaintTarget(core::EditLayer layer) {
  paintTarget_ = layer;
}
void ViewportWidget::setShowDiffuse(bool show) {
  showDiffuse_ = show;
  update();
}
void ViewportWidget::setLodDisplay(LodDisplay display) {
  lodDisplay_ = display;
  applyLodDisplay();
  overlay_->setLodDisplay(display);
  update();
}

void ViewportWidget::applyLodDisplay() {
  const bool sideBySide = lodDisplay_ == LodDisplay::SideBySide;
  renderer_->SetViewport(0, 0, sideBySide ? 0.5 : 1.0, 1);
  if (sideBySide && !renderWindow_->HasRenderer(lodRenderer_))
    renderWindow_->AddRenderer(lodRenderer_);
  else if (!sideBySide && renderWindow_->HasRenderer(lodRenderer_))
    renderWindow_->RemoveRenderer(lodRenderer_);
}

void ViewportWidget::setLodMesh(std::shared_ptr<const core::LodMesh> lod) {
  pendingLod_ = std::move(lod);
  update();
}

long long ViewportWidget::lodTriangles() const {
  return model_ ? model_->lodTriangles() : 0;
}

std::shared_ptr<const core::GeometryImage> ViewportWidget::positionsSnapshot() const {
  if (!hasDocument()) return nullptr;
  return std::make_shared<const core::GeometryImage>(document().positions);
}

void ViewportWidget::setSaliencyWanted(bool wanted) {
  saliency_.setWanted(wanted);
  if (!wanted || !saliency_.stale() || !session_.hasDocument()) return;
  {
    CurrentContext current(*this);
    refreshSaliency();
  }
  update();
  emit surfaceChanged();
}

void ViewportWidget::surfaceEdited() {
  saliency_.surfaceEdited();
}

void ViewportWidget::refreshSaliency() {
  if (session_.hasDocument() && model_) saliency_.refresh(session_.gpuDocument());
}

void ViewportWidget::cpuSaliencyFinished() {
  if (!session_.hasDocument()) return;
  {
    CurrentContext current(*this);
    // The surface changed meanwhile: again (a stroke's end starts its own).
    if (saliency_.storeJob(session_.gpuDocument()) && !session_.stroking()) refreshSaliency();
  }
  if (saliency_.current()) {
    update();
    emit surfaceChanged(); // a salient LOD is regenerated with it
  }
}

QRectF ViewportWidget::modelRect() const {
  return {0, 0, lodDisplay_ == LodDisplay::SideBySide ? width() / 2.0 : double(width()),
          double(height())};
}

void ViewportWidget::setPreview(gpu::ModelView::Preview preview) {
  preview_ = preview;
  overlay_->setPreview(preview);
  update();
}

QStringList ViewportWidget::materialIds() const {
  QStringList ids;
  for (const gpu::Material& m : materials_.materials())
    ids << QString::fromStdString(m.id);
  return ids;
}

QStringList ViewportWidget::materialErrors() const {
  QStringList errors = materialErrors_;
  for (const std::string& e : materials_.errors())
    errors << QString::fromStdString(e);
  return errors;
}

void ViewportWidget::setShowMask(bool show) {
  showMask_ = show;
  update();
}

void ViewportWidget::setLevelDivisor(int divisor) {
  divisor_ = std::max(1, divisor);
  if (!session_.hasDocument() || !model_) return;
  const int n = session_.gpuDocument().size();
  while (divisor_ > 1 && n / divisor_ < 2)
    divisor_ /= 2;
  try {
    CurrentContext current(*this);
    model_->setLevel(n, divisor_);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  emit statsChanged();
  update();
}

ViewportStats ViewportWidget::stats() const {
  ViewportStats s;
  const qint64 now = clock_.elapsed();
  s.framesPerSecond = static_cast<double>(std::count_if(frameTimes_.begin(), frameTimes_.end(),
                                                        [&](qint64 t) { return now - t <= 1000; }));
  s.lastDabMs = session_.lastDabMs();
  s.dabs = session_.dabs();
  if (hasDocument()) {
    s.n = document().size();
    s.fullTriangles = 2LL * s.n * s.n;
    s.displayedTriangles = model_ && session_.hasDocument() ? model_->displayedTriangles() : 0;
    if (lodDisplay_ == LodDisplay::Lod && lodTriangles() > 0) s.displayedTriangles = lodTriangles();
  }
  return s;
}

QStringList ViewportWidget::reloadBrushes() {
  QStringList failed;
  if (!library_) return failed;
  gpu::BrushLibrary::ReloadReport report;
  {
    CurrentContext current(*this);
    report = library_->reloadChanged();
  }
  for (const std::string& f : report.failed)
    failed << QString::fromStdString(f);
  session_.brushesReloaded(report.reloaded);
  if (!report.reloaded.empty() || !report.failed.empty() || !report.added.empty() ||
      !report.removed.empty())
    emit brushesChanged();
  return failed;
}

std::optional<core::PickHit> ViewportWidget::pickAt(QPointF p) const {
  if (!session_.hasDocument() || width() <= 0 || height() <= 0) return std::nullopt;
  // Side by side, both halves show the model through one camera: the right half picks as the
  // left does.
  const QRectF view = modelRect();
  if (p.x() >= view.width()) p.rx() -= view.width();
  const core::Ray ray = viewRay(*renderer_->GetActiveCamera(), view.size(), p);
  const gpu::GpuDocument& document = session_.gpuDocument();
  return core::pickRay(document.document().positions, document.bounds(), ray);
}

QPointF ViewportWidget::project(core::Vec3f p) const {
  // Side by side: where it appears in the left half.
  return projectToView(*renderer_->GetActiveCamera(), modelRect(), p);
}

} // namespace octaclay::app
