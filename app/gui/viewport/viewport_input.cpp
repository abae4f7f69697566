// The viewport's input: a left-drag sculpts, other drags orbit or pan, the wheel zooms, pen
// pressure is kept for the strokes, [ and ] step the brush.

#include "camera_control.h"
#include "viewport_widget.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QTabletEvent>
#include <QWheelEvent>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>

namespace octaclay::app {

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
  // One pick a press: on the surface or within the brush ring of it, a left press sculpts.
  std::optional<core::PickHit> hit;
  if (event->button() == Qt::LeftButton && !(mods & Qt::AltModifier)) hit = pressPick(lastPos_);
  if (hit) {
    emit strokePressed({std::clamp(hit->u, 0.0f, 1.0f), std::clamp(hit->v, 0.0f, 1.0f)});
    drag_ = Drag::Sculpt;
    beginStrokeAt(lastPos_, *hit, mods);
    if (!session_.stroking()) drag_ = Drag::None;
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
    orbitCamera(*camera, delta, orbitMode_);
    update();
    break;
  case Drag::Pan:
    panCamera(*camera, delta, height());
    update();
    break;
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
  // About the point under the cursor: the surface there, else the focal plane's point.
  vtkCamera* camera = renderer_->GetActiveCamera();
  core::Vec3f anchor;
  if (const auto hit = pickAt(event->position())) {
    anchor = hit->position;
  } else {
    const QRectF view = modelRect();
    QPointF p = event->position();
    if (p.x() >= view.width()) p.rx() -= view.width();
    const core::Ray ray = viewRay(*camera, view.size(), p);
    const core::Vec3f forward =
        core::normalize(toVec(camera->GetFocalPoint()) - toVec(camera->GetPosition()));
    const float along = std::max(core::dot(ray.direction, forward), 1e-3f);
    anchor = ray.origin + ray.direction * (static_cast<float>(camera->GetDistance()) / along);
  }
  zoomCameraAt(*camera, anchor, std::pow(1.15, steps));
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
    QWidget::keyPressEvent(event);
    return;
  }
  update();
}

void ViewportWidget::leaveEvent(QEvent* event) {
  hover_.reset();
  update();
  QWidget::leaveEvent(event);
}

} // namespace octaclay::app
