#include "viewport_widget.h"

#include "camera_control.h"
#include "current_context.h"
#include "modeller.h"
#include "object_pick.h"
#include "screen_radius.h"
#include "viewport_overlay.h"
#include "viewport_surface.h"

#include <QGuiApplication>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QSurfaceFormat>
#include <QTabletEvent>
#include <QWheelEvent>
#include <vtkCamera.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

ViewportWidget::ViewportWidget(Modeller& modeller, QWidget* parent)
    : QWidget(parent), modeller_(modeller), strokes_(*this) {
  QSurfaceFormat format = QSurfaceFormat::defaultFormat();
  format.setVersion(4, 3); // the brush engine's compute-free passes need 4.3 core (SSBOs)
  format.setProfile(QSurfaceFormat::CoreProfile);
  // Depth for the frames drawn straight into the window's framebuffer (the others are VTK's blit).
  format.setDepthBufferSize(24);
  format.setStencilBufferSize(0);
  format.setSwapInterval(0); // frames/s are measured, not capped by vsync
  surface_ = new ViewportSurface(*this);
  surface_->setFormat(format);
  // No layout: the widget's size hint stays a plain widget's.
  container_ = QWidget::createWindowContainer(surface_, this);
  container_->setFocusPolicy(Qt::NoFocus);
  container_->setMouseTracking(true);
  connect(surface_, &QOpenGLWindow::frameSwapped, this, &ViewportWidget::frameSwapped);
  setFocusPolicy(Qt::WheelFocus); // a click or a wheel turn takes the keys back from a dock
  setMouseTracking(true);
  setMinimumSize(320, 240);
  clock_.start();
  frames_ = std::make_unique<ViewportFrames>(*this, modeller_);
  overlay_ = new ViewportOverlay(this);
  connect(&modeller_, &Modeller::documentReplaced, this, &ViewportWidget::documentReplaced);
  connect(&modeller_, &Modeller::surfaceChanged, this, [this] { update(); });
  connect(&modeller_, &Modeller::objectsChanged, this, [this] { objectMoved(-1); });
  connect(&modeller_, &Modeller::objectMoved, this, &ViewportWidget::objectMoved);
  connect(&modeller_.brushState(), &BrushState::changed, this, [this] { update(); });
}

ViewportWidget::~ViewportWidget() {
  CurrentContext current(*this);
  modeller_.glStopping();
  frames_->glStopping();
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

QString ViewportWidget::error() const {
  if (!glError_.isEmpty()) return glError_;
  return modeller_.error().isEmpty() ? frames_->error() : modeller_.error();
}

void ViewportWidget::initializeGL() {
  glStarted_ = true;
  // A QOpenGLWindow calls this even when it could make no context (a display without OpenGL 4.3).
  if (!context() || !context()->isValid() || QOpenGLContext::currentContext() != context()) {
    glError_ = tr("OpenGL 4.3 core is needed for sculpting: the display gave no OpenGL 4.3 "
                  "context");
    modeller_.fail(glError_);
    return;
  }
  if (!frames_->glStarted(glError_)) {
    modeller_.fail(glError_);
    return;
  }
  glOk_ = modeller_.glStarted(*this); // uploads a document given before
}

void ViewportWidget::resizeGL(int width, int height) {
  const qreal ratio = devicePixelRatioF();
  frames_->resize(static_cast<int>(width * ratio), static_cast<int>(height * ratio));
}

void ViewportWidget::paintGL() {
  if (modeller_.uploading()) return; // a document is half uploaded: keep the last frame
  if (!context()->isValid() || QOpenGLContext::currentContext() != context()) return; // no GL
  const qint64 now = clock_.elapsed();
  frameTimes_.push_back(now);
  while (!frameTimes_.empty() && now - frameTimes_.front() > 2000)
    frameTimes_.pop_front();
  modeller_.drainGlErrors();
  frames_->paint(size() * devicePixelRatioF(), ring());
  if (stroking()) emit statsChanged();
  if (modeller_.session().hasDocument()) emit framePainted();
}

std::optional<BrushRing> ViewportWidget::ring() const {
  const std::optional<core::PickHit>& hover = strokes_.hover();
  if (!hover || drag_ == Drag::Orbit || drag_ == Drag::Pan) return std::nullopt;
  return BrushRing{hover->position, viewBrushObjectRadius(*this, hover->position),
                   (QGuiApplication::keyboardModifiers() & Qt::ControlModifier) != 0};
}

void ViewportWidget::documentReplaced(bool keepView) {
  try {
    CurrentContext current(*this, CurrentContext::Mode::IfNotCurrent);
    frames_->documentReplaced();
  } catch (const std::exception& e) {
    modeller_.fail(QString::fromUtf8(e.what()));
  }
  if (!keepView) resetCamera();
  emit statsChanged();
  update();
}

void ViewportWidget::setLooks(const ViewLooks& looks) {
  frames_->setLooks(looks);
  update();
}
void ViewportWidget::setPreview(gpu::ModelView::Preview preview) {
  frames_->setPreview(preview);
  overlay_->setPreview(preview);
  update();
}
void ViewportWidget::setShowDiffuse(bool show) {
  frames_->setShowDiffuse(show);
  update();
}
void ViewportWidget::setShowMask(bool show) {
  frames_->setShowMask(show);
  update();
}
void ViewportWidget::setLodDisplay(LodDisplay display) {
  frames_->setLodDisplay(display);
  overlay_->setLodDisplay(display);
  update();
}
void ViewportWidget::setLodMesh(std::shared_ptr<const core::LodMesh> lod) {
  frames_->setLodMesh(std::move(lod));
  update();
}
void ViewportWidget::setFramePainter(std::function<void(QPainter&)> paint) {
  frames_->setFramePainter(std::move(paint));
  update();
}
void ViewportWidget::setGizmoPainter(std::function<void(QPainter&)> paint) {
  frames_->setGizmoPainter(std::move(paint));
  update();
}

void ViewportWidget::setLevelDivisor(int divisor) {
  try {
    frames_->setLevelDivisor(divisor);
  } catch (const std::exception& e) {
    modeller_.fail(e.what());
  }
  if (!modeller_.session().hasDocument() || !frames_->ready()) return;
  emit statsChanged();
  update();
}

void ViewportWidget::resetCamera() {
  vtkCamera* camera = renderer()->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(0, 0, 1);
  setViewDirection(*camera, ViewDirection::Front);
  frameModel();
}

void ViewportWidget::frameFrom(core::Vec3f towardEye) {
  vtkCamera* camera = renderer()->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(towardEye.x, towardEye.y, towardEye.z);
  camera->SetViewUp(0, 1, 0);
  frameModel();
}

void ViewportWidget::frameModel() {
  std::array<double, 6> bounds = frames_->updateBounds();
  renderer()->ResetCamera(bounds.data());
  update();
}

void ViewportWidget::setView(ViewDirection direction) {
  setViewDirection(*renderer()->GetActiveCamera(), direction);
  update();
}

bool ViewportWidget::orthographic() const {
  return renderer()->GetActiveCamera()->GetParallelProjection();
}

void ViewportWidget::setOrthographic(bool orthographic) {
  setParallelProjectionAround(*renderer()->GetActiveCamera(), orthographic, frames_->bounds());
  update();
}

QRectF ViewportWidget::modelRect() const {
  return {0, 0, lodDisplay() == LodDisplay::SideBySide ? width() / 2.0 : double(width()),
          double(height())};
}

std::optional<core::PickHit> ViewportWidget::pickAt(QPointF p) const {
  const SculptSession& session = modeller_.session();
  if (!session.hasDocument() || width() <= 0 || height() <= 0 || !modeller_.activeShown())
    return std::nullopt; // hidden (the Objects dock's eye): nothing to touch
  // Side by side, both halves show the model through one camera: the right half picks as the
  // left does.
  const QRectF view = modelRect();
  if (p.x() >= view.width()) p.rx() -= view.width();
  const core::Ray ray =
      placement().rayToLocal(viewRay(*renderer()->GetActiveCamera(), view.size(), p));
  // The modeller's document: mid-stroke on a GPU the positions' read-backs wait, and it syncs
  // them with the context current.
  return core::pickRay(modeller_.document().positions, session.gpuDocument().bounds(), ray);
}

QPointF ViewportWidget::project(core::Vec3f p) const {
  return projectToView(*renderer()->GetActiveCamera(), modelRect(), placement().toWorld(p));
}

ObjectPlacement ViewportWidget::placement() const {
  if (modeller_.objectCount() == 0) return {};
  return ObjectPlacement(modeller_.objectAt(modeller_.activeObject()).transform);
}

void ViewportWidget::beginStrokeAt(QPointF p, Qt::KeyboardModifiers modifiers) {
  if (const std::optional<core::PickHit> hit = pressPick(p)) strokes_.begin(p, *hit, modifiers);
  update();
}

bool ViewportWidget::stroking() const {
  return modeller_.strokes().stroking();
}

ViewportStats ViewportWidget::stats() const {
  ViewportStats s;
  const qint64 now = clock_.elapsed();
  s.framesPerSecond = static_cast<double>(std::count_if(frameTimes_.begin(), frameTimes_.end(),
                                                        [&](qint64 t) { return now - t <= 1000; }));
  const SculptSession& session = modeller_.session();
  s.lastDabMs = session.lastDabMs();
  s.dabs = session.dabs();
  if (session.hasDocument()) {
    s.n = session.gpuDocument().size();
    s.fullTriangles =
        2LL * session.gpuDocument().grid().width * session.gpuDocument().grid().height;
    s.displayedTriangles = frames_->displayedTriangles();
  }
  return s;
}

// Input: a left press on the surface (or within the brush ring) sculpts, other drags orbit or
// pan, the wheel zooms, pen pressure is kept for the strokes, [ and ] step the brush.

void ViewportWidget::mousePressEvent(QMouseEvent* event) {
  event->accept();
  // One drag at a time: another button pressed during a stroke or an orbit does nothing, so the
  // release of the button that began it always ends it.
  if (drag_ != Drag::None) return;
  dragButton_ = event->button();
  lastPos_ = pressPos_ = event->position();
  const Qt::KeyboardModifiers mods = event->modifiers();
  if (event->button() == Qt::LeftButton && (mods & Qt::AltModifier) &&
      !(mods & Qt::ShiftModifier) && modeller_.objectCount() > 1) {
    drag_ = Drag::ObjectClick;
    return;
  }
  // One pick a press: on the surface or within the brush ring of it, a left press sculpts.
  std::optional<core::PickHit> hit;
  if (event->button() == Qt::LeftButton && !(mods & Qt::AltModifier)) hit = pressPick(lastPos_);
  if (hit) {
    emit strokePressed({std::clamp(hit->u, 0.0f, 1.0f), std::clamp(hit->v, 0.0f, 1.0f)});
    drag_ = strokes_.begin(lastPos_, *hit, mods) ? Drag::Sculpt : Drag::None;
    update();
  } else if (event->button() == Qt::MiddleButton) {
    drag_ = (mods & Qt::ShiftModifier) ? Drag::Pan : Drag::Orbit;
  } else if (event->button() == Qt::RightButton) {
    drag_ = (mods & Qt::ControlModifier) ? Drag::Pan : Drag::Orbit;
  } else if (event->button() == Qt::LeftButton) {
    drag_ = (mods & Qt::ShiftModifier) ? Drag::Pan : Drag::Orbit; // off the model
  }
}

void ViewportWidget::mouseMoveEvent(QMouseEvent* event) {
  const QPointF p = event->position();
  const QPointF delta = p - lastPos_;
  lastPos_ = p;
  vtkCamera* camera = renderer()->GetActiveCamera();
  if (drag_ == Drag::ObjectClick && (p - pressPos_).manhattanLength() > 3) drag_ = Drag::Orbit;
  if (drag_ == Drag::Sculpt) {
    strokes_.moveTo(p);
  } else if (drag_ == Drag::Orbit) {
    orbitCamera(*camera, delta, orbitMode_);
  } else if (drag_ == Drag::Pan) {
    panCamera(*camera, delta, height());
  } else {
    strokes_.setHover(pickAt(p));
  }
  update();
  event->accept();
}

void ViewportWidget::mouseReleaseEvent(QMouseEvent* event) {
  event->accept();
  if (drag_ != Drag::None && event->button() != dragButton_) return; // another button's
  // The window goes on answering while keep detail relaxes the stroke beside it.
  if (drag_ == Drag::Sculpt) strokes_.end(StrokeDriver::Relax::Background);
  const bool objectClick = drag_ == Drag::ObjectClick;
  drag_ = Drag::None;
  if (objectClick) selectObjectAt(event->position());
  strokes_.setHover(pickAt(event->position()));
}

void ViewportWidget::wheelEvent(QWheelEvent* event) {
  const double steps = event->angleDelta().y() / 120.0;
  // About the point under the cursor: the surface there, else the focal plane's point.
  vtkCamera* camera = renderer()->GetActiveCamera();
  core::Vec3f anchor;
  if (const auto hit = pickAt(event->position())) {
    anchor = placement().toWorld(hit->position);
  } else {
    const QRectF view = modelRect();
    QPointF p = event->position();
    if (p.x() >= view.width()) p.rx() -= view.width();
    anchor = focalPlanePoint(*camera, viewRay(*camera, view.size(), p));
  }
  zoomCameraAt(*camera, anchor, std::pow(1.15, steps));
  update();
  event->accept();
}

void ViewportWidget::tabletEvent(QTabletEvent* event) {
  if (event->type() == QEvent::TabletRelease)
    strokes_.setPenPressure(std::nullopt);
  else if (event->type() == QEvent::TabletPress || event->type() == QEvent::TabletMove)
    strokes_.setPenPressure(static_cast<float>(event->pressure()));
  event->ignore(); // Qt then delivers the matching mouse event, which drives the stroke
}

void ViewportWidget::keyPressEvent(QKeyEvent* event) {
  const bool shift = event->modifiers() & Qt::ShiftModifier;
  const int key = event->key();
  if (key == Qt::Key_BracketLeft || key == Qt::Key_BraceLeft)
    shift ? emit strengthStepRequested(1 / 1.1f) : emit radiusStepRequested(1 / 1.1f);
  else if (key == Qt::Key_BracketRight || key == Qt::Key_BraceRight)
    shift ? emit strengthStepRequested(1.1f) : emit radiusStepRequested(1.1f);
  else
    return QWidget::keyPressEvent(event);
  update();
}

void ViewportWidget::leaveEvent(QEvent* event) {
  strokes_.setHover(std::nullopt);
  update();
  QWidget::leaveEvent(event);
}

} // namespace octaclay::app
