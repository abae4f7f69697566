#include "canvas_brush_adjust.h"

#include "brush_state.h"
#include "modeller.h"
#include "radius_field.h"
#include "viewport_widget.h"

#include <QApplication>
#include <QCursor>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>

namespace octaclay::app {
namespace {

// What the adjustment shows over the viewport: the value, and a ring (with the strength as a
// filled disc inside it) where the surface's own ring cannot show it. Painted into the GL
// window's frame over the model, so the model stays in sight around them.
void paintMarks(QPainter& p, const CanvasBrushAdjust::Marks& marks) {
  p.setRenderHint(QPainter::Antialiasing);
  if (marks.drawRing && marks.ringPixels > 0) {
    p.setPen(QPen(QColor(255, 255, 255, 220), 1.5));
    p.setBrush(Qt::NoBrush);
    p.drawEllipse(marks.centre, marks.ringPixels, marks.ringPixels);
    if (marks.strength >= 0) {
      p.setPen(Qt::NoPen);
      p.setBrush(QColor(255, 255, 255, 90));
      const double r = marks.ringPixels * marks.strength;
      p.drawEllipse(marks.centre, r, r);
    }
  }
  const QFontMetricsF metrics(p.font());
  const QRectF box(marks.centre + QPointF(14, 14),
                   QSizeF(metrics.horizontalAdvance(marks.text) + 12, metrics.height() + 6));
  p.setPen(Qt::NoPen);
  p.setBrush(QColor(0, 0, 0, 150));
  p.drawRoundedRect(box, 4, 4);
  p.setPen(Qt::white);
  p.drawText(box, Qt::AlignCenter, marks.text);
}

} // namespace

CanvasBrushAdjust::CanvasBrushAdjust(ViewportWidget* viewport, BrushState* state, QObject* parent)
    : QObject(parent), viewport_(viewport), state_(state) {
  viewport->installEventFilter(this);
  lastPos_ = QPointF(-1, -1); // not seen yet
}

CanvasBrushAdjust::~CanvasBrushAdjust() {
  qApp->removeEventFilter(this);
}

bool CanvasBrushAdjust::begin(Mode mode) {
  if (!viewport_ || !state_ || mode == Mode::None || !state_->currentBrush()) return false;
  // Not in the middle of a stroke or an orbit: their release would never reach the viewport.
  if (viewport_->stroking() || QGuiApplication::mouseButtons() != Qt::NoButton) return false;
  if (mode_ != Mode::None) end(false);
  mode_ = mode;
  const QRectF view = viewport_->rect();
  const QPointF cursor = viewport_->mapFromGlobal(QCursor::pos());
  origin_ = view.contains(lastPos_) ? lastPos_ : view.contains(cursor) ? cursor : view.center();
  start_ = mode == Mode::Radius ? state_->radiusInUnit() : state_->strength();

  // How far the ring's edge moves on screen per unit of radius, at the ring's centre.
  const auto hit = viewport_->pickAt(origin_);
  vtkCamera* camera = viewport_->renderer()->GetActiveCamera();
  double direction[3], up[3], focal[3];
  camera->GetDirectionOfProjection(direction);
  camera->GetViewUp(up);
  camera->GetFocalPoint(focal);
  // In the edited object's space, as the pick and the radius are.
  const ObjectPlacement placement = viewport_->placement();
  const core::Vec3f right = core::normalize(placement.directionToLocal(
      core::cross(core::Vec3f{float(direction[0]), float(direction[1]), float(direction[2])},
                  core::Vec3f{float(up[0]), float(up[1]), float(up[2])})));
  const core::Vec3f centre =
      hit ? hit->position
          : placement.toLocal(core::Vec3f{float(focal[0]), float(focal[1]), float(focal[2])});
  const float step = 0.1f * viewport_->modeller().modelDiagonal();
  const QPointF a = viewport_->project(centre), b = viewport_->project(centre + right * step);
  pixelsPerRadius_ = std::hypot(b.x() - a.x(), b.y() - a.y()) / 0.1;
  if (!std::isfinite(pixelsPerRadius_) || pixelsPerRadius_ < 1e-3)
    pixelsPerRadius_ = std::max(1, viewport_->height());
  if (state_->radiusUnit() == RadiusUnit::View) pixelsPerRadius_ = 1; // a pixel is a pixel

  marks_ = Marks{};
  marks_.centre = origin_;
  marks_.drawRing = mode == Mode::Strength || !hit;
  viewport_->setFramePainter([this](QPainter& p) { paintMarks(p, marks_); });
  qApp->installEventFilter(this);
  moveTo(origin_);
  return true;
}

void CanvasBrushAdjust::confirm() {
  if (mode_ != Mode::None) end(true);
}

void CanvasBrushAdjust::cancel() {
  if (mode_ != Mode::None) end(false);
}

void CanvasBrushAdjust::moveTo(QPointF p) {
  if (!state_ || mode_ == Mode::None) return;
  const double dx = p.x() - origin_.x();
  if (mode_ == Mode::Radius) {
    state_->setRadiusInUnit(static_cast<float>(start_ + dx / pixelsPerRadius_));
    marks_.strength = -1;
    marks_.text = tr("Radius %1").arg(radiusText(state_->radiusUnit(), state_->radiusInUnit()));
  } else {
    state_->setStrength(static_cast<float>(start_ + dx / kPixelsPerStrength));
    marks_.strength = state_->strength();
    marks_.text = tr("Strength %1 %").arg(std::lround(state_->strength() * 100.0f));
  }
  marks_.ringPixels = double(state_->radiusInUnit()) * pixelsPerRadius_;
  if (viewport_) viewport_->update();
}

void CanvasBrushAdjust::end(bool confirmed) {
  const Mode mode = mode_;
  mode_ = Mode::None;
  if (!confirmed && state_) {
    if (mode == Mode::Radius) state_->setRadiusInUnit(start_);
    if (mode == Mode::Strength) state_->setStrength(start_);
  }
  if (swallowRelease_ == Qt::NoButton) qApp->removeEventFilter(this);
  if (viewport_) {
    viewport_->setFramePainter({});
    viewport_->update();
  }
  emit finished(confirmed);
}

bool CanvasBrushAdjust::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if (mode_ == Mode::None) {
    // The pointer's place over the viewport, where the next adjustment begins.
    if (watched == viewport_ && (type == QEvent::MouseMove || type == QEvent::Enter)) {
      if (type == QEvent::MouseMove) lastPos_ = static_cast<QMouseEvent*>(event)->position();
      return false;
    }
    // The release of the click that ended an adjustment must not reach anything.
    if (type == QEvent::MouseButtonRelease && swallowRelease_ != Qt::NoButton &&
        static_cast<QMouseEvent*>(event)->button() == swallowRelease_) {
      swallowRelease_ = Qt::NoButton;
      qApp->removeEventFilter(this);
      return true;
    }
    return false;
  }
  switch (type) {
  case QEvent::MouseMove: {
    if (!viewport_) return false;
    const QPointF p = viewport_->mapFromGlobal(static_cast<QMouseEvent*>(event)->globalPosition());
    lastPos_ = p;
    moveTo(p);
    return true;
  }
  case QEvent::MouseButtonPress:
  case QEvent::MouseButtonDblClick: {
    const Qt::MouseButton button = static_cast<QMouseEvent*>(event)->button();
    if (button == Qt::LeftButton) swallowRelease_ = Qt::LeftButton; // confirmed at the release
    if (button == Qt::RightButton) {
      swallowRelease_ = Qt::RightButton;
      end(false);
    }
    return true;
  }
  case QEvent::MouseButtonRelease: {
    const Qt::MouseButton button = static_cast<QMouseEvent*>(event)->button();
    if (button == swallowRelease_) {
      swallowRelease_ = Qt::NoButton;
      if (button == Qt::LeftButton) end(true);
    }
    return true;
  }
  case QEvent::ShortcutOverride:
  case QEvent::KeyPress: {
    const int key = static_cast<QKeyEvent*>(event)->key();
    const bool handled = key == Qt::Key_Escape || key == Qt::Key_Return || key == Qt::Key_Enter;
    if (!handled) return false;
    event->accept();
    if (type == QEvent::KeyPress) end(key != Qt::Key_Escape);
    return true;
  }
  default:
    return false;
  }
}

} // namespace octaclay::app
