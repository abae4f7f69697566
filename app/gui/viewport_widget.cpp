#include "viewport_widget.h"

#include "model_prop.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"
#include "octaclay/gpu/saliency.h"
#include "octaclay/gpu/stroke.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QSurfaceFormat>
#include <QTabletEvent>
#include <QWheelEvent>
#include <QtConcurrent/QtConcurrentRun>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkMatrix4x4.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLShaderCache.h>
#include <vtkOpenGLState.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace octaclay::app {

struct ViewportWidget::ActiveStroke {
  std::string brushId;
  float unit = 1;     // object units per radius fraction: the diagonal when the stroke began
  float dabShare = 1; // share of the strength each dab applies (the brush's spacing)
  gpu::BrushManifest manifest; // the session refers to it
  float sign = 1;
  std::unique_ptr<gpu::StrokeSession> session;
  std::vector<std::pair<core::Sample, float>> queue; // sample, pressure
  bool ended = false;
};

namespace {

std::string variantKey(const gpu::BrushManifest& m) {
  std::string key{gpu::toManifestName(m.area)};
  key += '|';
  key += gpu::toManifestName(m.falloff);
  for (core::EditLayer l : m.writes) {
    key += '|';
    key += gpu::toManifestName(l);
  }
  return key;
}

core::Vec3f toVec(const double* d) {
  return {static_cast<float>(d[0]), static_cast<float>(d[1]), static_cast<float>(d[2])};
}

} // namespace

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(4, 3); // the brush engine's compute-free passes need 4.3 core (SSBOs)
  format.setProfile(QSurfaceFormat::CoreProfile);
  // VTK renders into its own framebuffer with depth; the widget's only receives the colour blit.
  format.setDepthBufferSize(0);
  format.setStencilBufferSize(0);
  format.setSwapInterval(0); // frames/s are measured, not capped by vsync
  setFormat(format);
  setFocusPolicy(Qt::StrongFocus);
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
  connect(&saliencyJob_, &QFutureWatcher<std::vector<float>>::finished, this,
          &ViewportWidget::cpuSaliencyFinished);
  // Side by side: the LOD in the right half, seen through the same camera.
  lodRenderer_->SetBackground(0.27, 0.29, 0.33);
  lodRenderer_->SetBackgroundAlpha(1.0);
  lodRenderer_->SetActiveCamera(renderer_->GetActiveCamera());
  lodRenderer_->AddViewProp(lodProp_);
  lodRenderer_->SetViewport(0.5, 0, 1, 1);
  lodProp_->draw = [this](vtkRenderer* r) { drawModel(r); };
}

ViewportWidget::~ViewportWidget() {
  saliencyJob_.waitForFinished();
  makeCurrent();
  stroke_.reset();
  document_.reset();
  saliency_.reset();
  model_.reset();
  library_.reset();
  context_.reset();
  renderWindow_->Finalize();
  doneCurrent();
}

void ViewportWidget::onRenderWindowEvent(vtkObject*, unsigned long event, void* callData) {
  const bool current = context() && QOpenGLContext::currentContext() == context();
  if (event == vtkCommand::WindowIsCurrentEvent)
    *static_cast<bool*>(callData) = current;
  else if (event == vtkCommand::WindowMakeCurrentEvent && !current)
    makeCurrent();
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
  renderWindow_->SetReadyForRendering(true);
  renderWindow_->OpenGLInitContext();
  try {
    context_ = std::make_unique<gpu::GlContext>(gpu::GlContext::adoptCurrent());
    library_ = std::make_unique<gpu::BrushLibrary>(
        gpu::BrushCatalog::defaultSearchPath(OCTACLAY_SOURCE_BRUSHES));
    model_ = std::make_unique<gpu::ModelRenderer>();
    const QString renderer = QString::fromLatin1(
        reinterpret_cast<const char*>(context()->functions()->glGetString(GL_RENDERER)));
    saliencyOnCpu_ = renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                     renderer.contains("SwiftShader");
    materials_.scan(gpu::MaterialCatalog::defaultSearchPath(
        std::filesystem::path(OCTACLAY_SOURCE_RESOURCES) / "materials"));
    library_->engine().setMaterials(materials_);
    try {
      model_->setEnvironment(core::readImage(
          std::filesystem::path(OCTACLAY_SOURCE_RESOURCES) / "environment/studio.png", 3));
    } catch (const core::Error& e) { // reflective paint then shows no reflection, nothing more
      materialErrors_ << QStringLiteral("environment map: %1").arg(e.what());
    }
  } catch (const std::exception& e) {
    library_.reset();
    model_.reset();
    fail(QStringLiteral("OpenGL 4.3 core is needed for sculpting: %1").arg(e.what()));
    return;
  }
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

bool ViewportWidget::setDocument(core::Document document) {
  if (!glStarted_) {
    pending_ = std::move(document);
    history_.clear();
    return true;
  }
  makeCurrent();
  const bool ok = uploadDocument(std::move(document));
  doneCurrent();
  update();
  return ok;
}

bool ViewportWidget::uploadDocument(core::Document document) {
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
    auto uploaded = std::make_unique<gpu::GpuDocument>(std::move(document), [&](float) {
      if (sinceEvents.elapsed() < 30) return;
      uploading_ = true;
      QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
      uploading_ = false;
      makeCurrent(); // a repaint in between may have left another context current
      sinceEvents.restart();
    });
    stroke_.reset();
    document_ = std::move(uploaded);
    // Until the caller picks a level: one of at most 256 a side (N/1 of a 4096 image would
    // build a 33-million-triangle index buffer first).
    divisor_ = std::max(divisor_, std::max(1, n / 256));
    divisor_ = std::min(divisor_, std::max(1, n / 2));
    model_->setLevel(n, divisor_);
    model_->refreshAllNormals(*document_);
    model_->setLodMesh({}); // the previous document's LOD is not this one's
    pendingLod_.reset();
  } catch (const std::exception& e) {
    fail(QStringLiteral("Could not load the model onto the GPU: %1").arg(e.what()));
    return false;
  }
  history_.clear();
  surfaceEdited();
  refreshSaliency();
  resetCamera();
  emit statsChanged();
  emit surfaceChanged();
  return true;
}

bool ViewportWidget::hasDocument() const {
  return document_ != nullptr || pending_.has_value();
}

const core::Document& ViewportWidget::document() const {
  if (document_ && document_->mirrorStale()) {
    // Mid-stroke (autosave, save): the paint the stroke deferred is read back first.
    auto* self = const_cast<ViewportWidget*>(this);
    const bool wasCurrent = QOpenGLContext::currentContext() == context();
    if (!wasCurrent) self->makeCurrent();
    document_->syncMirror();
    if (!wasCurrent) self->doneCurrent();
  }
  return document_ ? document_->document() : *pending_;
}

float ViewportWidget::diagonal() const {
  return document_ ? std::max(document_->bounds().diagonal(), 1e-6f) : 1.0f;
}

void ViewportWidget::resetCamera() {
  if (document_) {
    core::BoundingBox box;
    const core::TileBounds& b = document_->bounds();
    for (int t = 0; t < b.tilesPerSide() * b.tilesPerSide(); ++t) {
      box.extend(b.box(t).min);
      box.extend(b.box(t).max);
    }
    prop_->bounds = {box.min.x, box.max.x, box.min.y, box.max.y, box.min.z, box.max.z};
  }
  vtkCamera* camera = renderer_->GetActiveCamera();
  camera->SetViewUp(0, 1, 0);
  camera->SetPosition(0, 0, 1);
  camera->SetFocalPoint(0, 0, 0);
  renderer_->ResetCamera(prop_->bounds.data());
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

void ViewportWidget::setPaintTarget(int brushLayer) {
  paintTarget_ = brushLayer;
}
void ViewportWidget::setShowDiffuse(bool show) {
  showDiffuse_ = show;
  update();
}
void ViewportWidget::setLodDisplay(int display) {
  lodDisplay_ = std::clamp(display, 0, 2);
  applyLodDisplay();
  update();
}

void ViewportWidget::applyLodDisplay() {
  const bool sideBySide = lodDisplay_ == 2;
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
  saliencyWanted_ = wanted;
  if (!wanted || !saliencyStale_ || !document_) return;
  makeCurrent();
  refreshSaliency();
  doneCurrent();
  update();
  emit surfaceChanged();
}

void ViewportWidget::surfaceEdited() {
  saliencyStale_ = true;
  ++surfaceVersion_;
}

void ViewportWidget::refreshSaliency() {
  if (!saliencyWanted_ || !saliencyStale_ || !document_ || !model_) return;
  if (saliencyOnCpu_) {
    if (saliencyJob_.isRunning()) return; // cpuSaliencyFinished starts the next one
    auto image = std::make_shared<core::GeometryImage>(document_->document().positions);
    saliencyJobVersion_ = surfaceVersion_;
    saliencyJob_.setFuture(QtConcurrent::run([image] {
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
    if (!saliency_) saliency_ = std::make_unique<gpu::SaliencyPass>();
    saliency_->run(*document_);
    saliencyStale_ = false;
  } catch (const std::exception& e) {
    fail(QStringLiteral("Could not compute the saliency: %1").arg(e.what()));
  }
}

void ViewportWidget::cpuSaliencyFinished() {
  if (!document_) return;
  const std::vector<float> values = saliencyJob_.result();
  makeCurrent();
  if (saliencyJobVersion_ == surfaceVersion_ &&
      values.size() == document_->document().positions.texelCount()) {
    try {
      document_->writeSaliency(values);
      saliencyStale_ = false;
    } catch (const std::exception& e) {
      fail(QStringLiteral("Could not store the saliency: %1").arg(e.what()));
    }
  } else if (saliencyJobVersion_ != surfaceVersion_ && !stroke_) {
    refreshSaliency(); // the surface changed meanwhile (a stroke's end starts its own)
  }
  doneCurrent();
  if (!saliencyStale_) {
    update();
    emit surfaceChanged(); // a salient LOD is regenerated with it
  }
}

QRectF ViewportWidget::modelRect() const {
  return {0, 0, lodDisplay_ == 2 ? width() / 2.0 : double(width()), double(height())};
}

void ViewportWidget::setPreview(int channel) {
  preview_ = std::clamp(channel, 0, 6);
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
  if (!document_ || !model_) return;
  const int n = document_->size();
  while (divisor_ > 1 && n / divisor_ < 2)
    divisor_ /= 2;
  makeCurrent();
  try {
    model_->setLevel(n, divisor_);
  } catch (const std::exception& e) {
    fail(e.what());
  }
  doneCurrent();
  emit statsChanged();
  update();
}

ViewportStats ViewportWidget::stats() const {
  ViewportStats s;
  const qint64 now = clock_.elapsed();
  s.framesPerSecond = static_cast<double>(std::count_if(frameTimes_.begin(), frameTimes_.end(),
                                                        [&](qint64 t) { return now - t <= 1000; }));
  s.lastDabMs = lastDabMs_;
  s.dabs = dabCount_;
  if (hasDocument()) {
    s.n = document().size();
    s.fullTriangles = 2LL * s.n * s.n;
    s.displayedTriangles = model_ && document_ ? model_->displayedTriangles() : 0;
    if (lodDisplay_ == 1 && lodTriangles() > 0) s.displayedTriangles = lodTriangles();
  }
  return s;
}

QStringList ViewportWidget::reloadBrushes() {
  QStringList failed;
  if (!library_) return failed;
  makeCurrent();
  const gpu::BrushLibrary::ReloadReport report = library_->reloadChanged();
  doneCurrent();
  for (const std::string& f : report.failed)
    failed << QString::fromStdString(f);
  for (const std::string& id : report.reloaded)
    loadedVariant_.erase(id);
  if (!report.reloaded.empty() || !report.failed.empty() || !report.added.empty() ||
      !report.removed.empty())
    emit brushesChanged();
  return failed;
}

std::optional<gpu::BrushManifest> ViewportWidget::prepareBrush(const std::string& id) {
  const gpu::BrushManifest* base = library_ ? library_->catalog().find(id) : nullptr;
  if (!base || !library_->engine().has(id)) {
    fail(QStringLiteral("The brush \"%1\" is not loaded (see the Brushes panel for errors)")
             .arg(QString::fromStdString(id)));
    return std::nullopt;
  }
  gpu::BrushManifest variant = *base;
  if (id == settings_.brushId) {
    variant.area = settings_.area;
    variant.falloff = settings_.falloff;
    if (variant.falloff == gpu::Falloff::Curve && variant.falloffCurve.empty())
      variant.falloff = gpu::Falloff::Smooth;
  }
  // The Layers dock's paint target redirects colour paint (a brush writing only diffuse);
  // brushes made for another layer (mask, specular, reflectivity) keep theirs.
  if (variant.category == gpu::Category::Paint &&
      variant.writes == std::vector<core::EditLayer>{core::EditLayer::Diffuse})
    variant.writes = {static_cast<core::EditLayer>(paintTarget_)};
  const std::string key = variantKey(variant);
  auto found = loadedVariant_.find(id);
  if (found == loadedVariant_.end() ? key != variantKey(*base) : found->second != key) {
    try {
      library_->engine().load(variant, gpu::BrushCatalog::shaderSource(*base));
      loadedVariant_[id] = key;
    } catch (const std::exception& e) {
      fail(QString::fromUtf8(e.what()));
      return std::nullopt;
    }
  }
  return variant;
}

std::optional<core::PickHit> ViewportWidget::pickAt(QPointF p) const {
  if (!document_ || width() <= 0 || height() <= 0) return std::nullopt;
  // Side by side, both halves show the model through one camera: the right half picks as the
  // left does.
  const QRectF view = modelRect();
  if (p.x() >= view.width()) p.rx() -= view.width();
  vtkCamera* c = renderer_->GetActiveCamera();
  core::Camera camera;
  camera.eye = toVec(c->GetPosition());
  camera.target = toVec(c->GetFocalPoint());
  camera.up = toVec(c->GetViewUp());
  camera.fovYDegrees = static_cast<float>(c->GetViewAngle());
  const core::Ray ray =
      core::cameraRay(camera, static_cast<int>(view.width()), static_cast<int>(view.height()),
                      static_cast<float>(p.x()), static_cast<float>(p.y()));
  return core::pickRay(document_->document().positions, document_->bounds(), ray);
}

QPointF ViewportWidget::project(core::Vec3f p) const {
  vtkCamera* c = renderer_->GetActiveCamera();
  const QRectF view = modelRect(); // side by side: where it appears in the left half
  const double aspect = view.height() > 0 ? view.width() / view.height() : 1.0;
  vtkMatrix4x4* m = c->GetCompositeProjectionTransformMatrix(aspect, -1, 1);
  const double in[4] = {p.x, p.y, p.z, 1.0};
  double out[4];
  m->MultiplyPoint(in, out);
  const double x = out[0] / out[3], y = out[1] / out[3];
  return {(x * 0.5 + 0.5) * view.width(), (0.5 - y * 0.5) * view.height()};
}

void ViewportWidget::drawModel(vtkRenderer* r) {
  if (!document_ || !model_) return;
  vtkCamera* camera = r->GetActiveCamera();
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(r->GetTiledAspectRatio(), -1, 1);
  gpu::ModelView view;
  for (int row = 0; row < 4; ++row)
    for (int col = 0; col < 4; ++col)
      view.objectToClip[static_cast<std::size_t>(col * 4 + row)] =
          static_cast<float>(m->GetElement(row, col));
  view.eye = toVec(camera->GetPosition());
  view.showDiffuse = showDiffuse_;
  view.showMask = showMask_;
  view.preview = static_cast<gpu::ModelView::Preview>(preview_);
  if (hover_ && drag_ != Drag::Orbit && drag_ != Drag::Pan) {
    view.showBrush = true;
    view.brushCentre = hover_->position;
    view.brushRadius = settings_.radius * diagonal();
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
    const bool lod = r == lodRenderer_.Get() || (lodDisplay_ == 1 && model_->lodTriangles() > 0);
    if (lod)
      model_->drawLod(*document_, view);
    else
      model_->draw(*document_, view);
  } catch (const std::exception& e) {
    error_ = QString::fromUtf8(e.what());
  }
  // What VTK believes is bound is no longer so.
  renderWindow_->GetShaderCache()->ReleaseCurrentShader();
  state->vtkglDisable(GL_CULL_FACE);
  state->ResetGLActiveTexture();
}

void ViewportWidget::paintGL() {
  if (uploading_) return; // a document is half uploaded: keep the last frame
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
  if (stroke_ && stroke_->ended) finishStroke();
  if (pendingLod_) {
    try {
      model_->setLodMesh(*pendingLod_);
    } catch (const std::exception& e) {
      error_ = QString::fromUtf8(e.what());
    }
    pendingLod_.reset();
  }

  vtkOpenGLState* state = renderWindow_->GetState();
  state->Reset(); // the engine and Qt changed GL state behind VTK's cache
  state->Push();
  state->vtkglDepthFunc(GL_LEQUAL);
  updateClipping();
  if (lodDisplay_ == 2) lodRenderer_->ResetCameraClippingRange(prop_->bounds.data());
  renderWindow_->Render();
  state->Pop();

  const QSize size = this->size() * devicePixelRatioF();
  gl->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum buffer = GL_COLOR_ATTACHMENT0;
  gl->glDrawBuffers(1, &buffer);
  gl->glDisable(GL_SCISSOR_TEST);
  renderWindow_->BlitDisplayFramebuffer(0, 0, 0, size.width(), size.height(), 0, 0, size.width(),
                                        size.height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
  state->Reset();
  if (dabbed || stroke_) emit statsChanged();
  if (dabbed) emit surfaceChanged();
  if (document_) emit framePainted();
}

// ---------------------------------------------------------------------------------- strokes

void ViewportWidget::beginStrokeAt(QPointF p, Qt::KeyboardModifiers modifiers) {
  if (!document_ || !library_ || stroke_) return; // one stroke at a time
  const std::optional<core::PickHit> hit = pickAt(p);
  if (!hit) return;
  std::string id = settings_.brushId;
  if (modifiers & Qt::ShiftModifier) id = "smooth";
  makeCurrent(); // a changed area or falloff recompiles the brush
  std::optional<gpu::BrushManifest> brush = prepareBrush(id);
  if (!brush) {
    doneCurrent();
    return;
  }
  auto stroke = std::make_unique<ActiveStroke>();
  stroke->brushId = id;
  stroke->manifest = std::move(*brush);
  stroke->sign = (modifiers & Qt::ControlModifier) ? -1.0f : 1.0f;
  // Fixed for the stroke: a stroke that grows the model must not grow its own brush.
  stroke->unit = diagonal();
  // A sculpt stroke's strength is how far it moves the surface per radius travelled, whatever
  // the spacing: each dab applies strength × spacing, as overlapping dabs add up. Paint and
  // splats blend toward a target, so overlaps converge instead of piling up: full strength.
  stroke->dabShare = stroke->manifest.category == gpu::Category::Sculpt
                         ? std::clamp(stroke->manifest.spacing, 0.01f, 1.0f)
                         : 1.0f;
  gpu::StrokeSettings s;
  s.brush = id;
  s.radius = settings_.radius * stroke->unit;
  s.strength = settings_.strength;
  s.symmetry = settings_.symmetry;
  if (id == settings_.brushId) s.parameters = settings_.parameters;
  s.viewEye = toVec(renderer_->GetActiveCamera()->GetPosition()); // splats project from here
  try {
    stroke->session =
        std::make_unique<gpu::StrokeSession>(library_->engine(), *document_, stroke->manifest, s);
  } catch (const std::exception& e) {
    doneCurrent();
    fail(QString::fromUtf8(e.what()));
    return;
  }
  doneCurrent();
  stroke_ = std::move(stroke);
  stabilizer_.begin({static_cast<float>(p.x()), static_cast<float>(p.y())});
  stroke_->queue.emplace_back(hit->sample, tabletDown_ ? tabletPressure_ : 1.0f);
  hover_ = hit;
  update();
}

void ViewportWidget::continueStrokeTo(QPointF p) {
  if (!stroke_) return;
  for (const Point2& q : stabilizer_.moveTo({static_cast<float>(p.x()), static_cast<float>(p.y())}))
    queueStrokePoint({q.x, q.y});
  update();
}

void ViewportWidget::queueStrokePoint(QPointF p) {
  const std::optional<core::PickHit> hit = pickAt(p);
  if (!hit) return; // off the model: the stroke resumes where the pointer comes back
  hover_ = hit;
  stroke_->queue.emplace_back(hit->sample, tabletDown_ ? tabletPressure_ : 1.0f);
}

void ViewportWidget::endStroke() {
  if (!stroke_) return;
  stroke_->ended = true;
  // Finish now rather than at the next paint: the document and undo must be complete when
  // the caller (a mouse release, a test, a save) looks.
  makeCurrent();
  drainGlErrors();
  runQueuedDabs();
  finishStroke();
  doneCurrent();
  update();
}

int ViewportWidget::runQueuedDabs() {
  if (!stroke_ || stroke_->queue.empty()) return 0;
  int made = 0;
  const auto start = std::chrono::steady_clock::now();
  try {
    for (const auto& [sample, pressure] : stroke_->queue) {
      float radius = settings_.radius * stroke_->unit;
      float strength = settings_.strength * stroke_->dabShare;
      if (settings_.pressureTarget == PressureTarget::Radius)
        radius *= std::max(pressure, 0.05f);
      else if (settings_.pressureTarget == PressureTarget::Strength)
        strength *= pressure;
      made += stroke_->session->moveTo(sample, radius, stroke_->sign * strength, 1.0f);
    }
    if (made > 0) surfaceEdited();
    refreshNormalsAround(stroke_->session->takeTouched());
  } catch (const std::exception& e) {
    fail(QString::fromUtf8(e.what()));
  }
  stroke_->queue.clear();
  dabCount_ += made;
  if (made > 0)
    lastDabMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                     .count() /
                 made;
  return made;
}

void ViewportWidget::finishStroke() {
  if (!stroke_) return;
  const std::string label = stroke_->brushId;
  const int dabs = stroke_->session->dabs();
  core::Stroke record = stroke_->session->finish(label);
  stroke_.reset();
  if (dabs == 0 || record.tiles.empty()) return;
  history_.record(std::move(record));
  refreshSaliency(); // at stroke end: the whole image's normalisation may have changed
  emit strokeFinished(QString::fromStdString(label));
  emit surfaceChanged();
}

void ViewportWidget::refreshNormalsAround(std::vector<core::TexelRect> rects) {
  if (rects.empty() || !document_) return;
  const int side = document_->size() + 1;
  bool border = false;
  for (core::TexelRect& r : rects) {
    // A texel's normal reads its neighbours: grow by one.
    const int x0 = std::max(0, r.x - 1), y0 = std::max(0, r.y - 1);
    const int x1 = std::min(side, r.x + r.width + 1), y1 = std::min(side, r.y + r.height + 1);
    r = {x0, y0, x1 - x0, y1 - y0};
    border = border || x0 == 0 || y0 == 0 || x1 == side || y1 == side;
  }
  if (border) // neighbours across a seam sit on the opposite border
    for (core::TexelRect r :
         {core::TexelRect{0, 0, side, 2}, core::TexelRect{0, side - 2, side, 2},
          core::TexelRect{0, 0, 2, side}, core::TexelRect{side - 2, 0, 2, side}})
      rects.push_back(r);
  model_->refreshNormals(*document_, core::mergeRects(rects));
}

void ViewportWidget::refreshAfterHistory(const core::Stroke& stroke) {
  std::vector<core::TexelRect> rects;
  for (const core::TileChange& t : stroke.tiles)
    rects.push_back({t.region.x, t.region.y, t.region.width, t.region.height});
  refreshNormalsAround(std::move(rects));
}

bool ViewportWidget::undoStroke() {
  return stepHistory(&core::EditHistory::canUndo, &core::EditHistory::undo);
}

bool ViewportWidget::redoStroke() {
  return stepHistory(&core::EditHistory::canRedo, &core::EditHistory::redo);
}

bool ViewportWidget::stepHistory(
    bool (core::EditHistory::*can)() const,
    const core::Stroke* (core::EditHistory::*step)(const core::TileApplier&)) {
  if (!document_ || !(history_.*can)() || stroke_) return false;
  makeCurrent();
  const core::Stroke* s = nullptr;
  try {
    s = (history_.*step)(gpu::undoApplier(*document_));
    if (s) {
      refreshAfterHistory(*s);
      surfaceEdited();
      refreshSaliency();
    }
  } catch (const std::exception& e) {
    fail(QString::fromUtf8(e.what()));
  }
  doneCurrent();
  update();
  if (s) emit surfaceChanged();
  return s != nullptr;
}

// ------------------------------------------------------------------------------------ input

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  // One drag at a time: another button pressed during a stroke or an orbit does nothing, so the
  // release of the button that began it always ends it.
  if (drag_ != Drag::None) {
    event->accept();
    return;
  }
  dragButton_ = event->button();
  lastPos_ = event->position();
  const Qt::KeyboardModifiers mods = event->modifiers();
  if (event->button() == Qt::LeftButton && !(mods & Qt::AltModifier) && pickAt(lastPos_)) {
    drag_ = Drag::Sculpt;
    beginStrokeAt(lastPos_, mods);
    if (!stroke_) drag_ = Drag::None;
  } else if (event->button() == Qt::MiddleButton) {
    drag_ = (mods & Qt::ShiftModifier) ? Drag::Pan : Drag::Orbit;
  } else if (event->button() == Qt::RightButton) {
    drag_ = (mods & Qt::ControlModifier) ? Drag::Pan : Drag::Orbit;
  } else if (event->button() == Qt::LeftButton) {
    drag_ = (mods & Qt::ShiftModifier) ? Drag::Pan : Drag::Orbit; // off the model
  }
  event->accept();
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPointF p = event->position();
  const QPointF delta = p - lastPos_;
  lastPos_ = p;
  vtkCamera* camera = renderer_->GetActiveCamera();
  switch (drag_) {
  case Drag::Sculpt:
    continueStrokeTo(p);
    break;
  case Drag::Orbit:
    camera->Azimuth(-0.4 * delta.x());
    camera->Elevation(0.4 * delta.y());
    camera->OrthogonalizeViewUp();
    update();
    break;
  case Drag::Pan: {
    // Move eye and target together by the pixel size at the target's depth.
    double position[3], focal[3], up[3];
    camera->GetPosition(position);
    camera->GetFocalPoint(focal);
    camera->GetViewUp(up);
    const core::Vec3f eye = toVec(position), target = toVec(focal), vup = toVec(up);
    const core::Vec3f forward = core::normalize(target - eye);
    const core::Vec3f right = core::normalize(core::cross(forward, vup));
    const core::Vec3f upv = core::cross(right, forward);
    const float scale =
        2.0f * core::length(target - eye) *
        std::tan(static_cast<float>(camera->GetViewAngle()) * 3.14159265f / 360.0f) /
        static_cast<float>(std::max(1, height()));
    const core::Vec3f move = right * (-static_cast<float>(delta.x()) * scale) +
                             upv * (static_cast<float>(delta.y()) * scale);
    camera->SetPosition(eye.x + move.x, eye.y + move.y, eye.z + move.z);
    camera->SetFocalPoint(target.x + move.x, target.y + move.y, target.z + move.z);
    update();
    break;
  }
  case Drag::None:
    hover_ = pickAt(p);
    update();
    break;
  }
  event->accept();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  if (drag_ != Drag::None && event->button() != dragButton_) {
    event->accept(); // another button than the drag's
    return;
  }
  if (drag_ == Drag::Sculpt) endStroke();
  drag_ = Drag::None;
  hover_ = pickAt(event->position());
  event->accept();
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  renderer_->GetActiveCamera()->Dolly(std::pow(1.15, steps));
  update();
  event->accept();
}

void ViewportWidget::tabletEvent(QTabletEvent* event) {
  tabletPressure_ = static_cast<float>(event->pressure());
  if (event->type() == QEvent::TabletPress) tabletDown_ = true;
  if (event->type() == QEvent::TabletRelease) tabletDown_ = false;
  event->ignore(); // Qt then delivers the matching mouse event, which drives the stroke
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  const bool shift = event->modifiers() & Qt::ShiftModifier;
  switch (event->key()) {
  case Qt::Key_BracketLeft:
  case Qt::Key_BraceLeft:
    shift ? emit strengthStepRequested(1 / 1.1f) : emit radiusStepRequested(1 / 1.1f);
    break;
  case Qt::Key_BracketRight:
  case Qt::Key_BraceRight:
    shift ? emit strengthStepRequested(1.1f) : emit radiusStepRequested(1.1f);
    break;
  default:
    QOpenGLWidget::keyPressEvent(event);
    return;
  }
  update();
}

void ViewportWidget::leaveEvent(QEvent* event) {
  hover_.reset();
  update();
  QOpenGLWidget::leaveEvent(event);
}

} // namespace octaclay::app
