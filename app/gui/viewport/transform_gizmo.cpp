#include "transform_gizmo.h"

#include "camera_control.h"
#include "modeller.h"
#include "object_transform_mode.h"
#include "viewport_widget.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <cmath>
#include <numbers>

namespace octaclay::app {
namespace {

// The distance from p to the segment ab (pixels).
double distanceToSegment(QPointF p, QPointF a, QPointF b) {
  const QPointF ab = b - a;
  const double squared = QPointF::dotProduct(ab, ab);
  const double t =
      squared > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / squared, 0.0, 1.0) : 0.0;
  const QPointF d = p - (a + ab * t);
  return std::hypot(d.x(), d.y());
}

// A circle as straight segments, each its own line: Qt's GL paint engine on the viewport's
// native window (no stencil buffer) fills an ellipse's or a multi-line stroke as its bounding
// box there; one line at a time it draws right.
void drawCircle(QPainter& p, QPointF centre, double radius, int segments) {
  QPointF last = centre + QPointF(radius, 0);
  for (int k = 1; k <= segments; ++k) {
    const double angle = 2 * std::numbers::pi * k / segments;
    const QPointF next = centre + QPointF(radius * std::cos(angle), radius * std::sin(angle));
    p.drawLine(last, next);
    last = next;
  }
}

} // namespace

TransformGizmo::TransformGizmo(ViewportWidget* viewport, ObjectTransformMode* mode, QObject* parent)
    : QObject(parent), viewport_(viewport), mode_(mode) {
  viewport->installEventFilter(this);
}

void TransformGizmo::setShown(bool shown) {
  if (shown_ == shown || !viewport_) return;
  shown_ = shown;
  if (shown)
    viewport_->setGizmoPainter([this](QPainter& p) { paint(p); });
  else
    viewport_->setGizmoPainter({});
}

std::optional<std::array<TransformGizmo::Arrow, 3>> TransformGizmo::arrows() const {
  if (!shown_ || !viewport_) return std::nullopt;
  const Modeller& modeller = viewport_->modeller();
  if (!modeller.hasDocument() || modeller.objectCount() == 0 || !modeller.activeShown())
    return std::nullopt;
  vtkCamera& camera = *viewport_->renderer()->GetActiveCamera();
  const QRectF view = viewport_->modelRect();
  const core::Vec3f c = modeller.objectAt(modeller.activeObject()).transform.translation;
  // In front of the eye only: a point behind it projects mirrored.
  double direction[3];
  camera.GetDirectionOfProjection(direction);
  const core::Vec3f eye = toVec(camera.GetPosition());
  const core::Vec3f forward{float(direction[0]), float(direction[1]), float(direction[2])};
  const float depth = core::dot(c - eye, forward);
  if (!(depth > 0)) return std::nullopt;
  // World units per pixel at the origin's depth, measured along the screen's right.
  double up[3];
  camera.GetViewUp(up);
  const core::Vec3f right =
      core::normalize(core::cross(forward, core::Vec3f{float(up[0]), float(up[1]), float(up[2])}));
  const float probe = 0.01f * depth;
  const QPointF c0 = projectToView(camera, view, c);
  const QPointF r0 = projectToView(camera, view, c + right * probe);
  const double pixelsPerUnit = std::hypot(r0.x() - c0.x(), r0.y() - c0.y()) / double(probe);
  if (!(pixelsPerUnit > 0) || !std::isfinite(pixelsPerUnit)) return std::nullopt;
  const float length = static_cast<float>(kArrowPixels / pixelsPerUnit);
  const QColor colours[3] = {QColor(230, 40, 40), QColor(40, 200, 40), QColor(40, 90, 255)};
  std::array<Arrow, 3> out;
  for (int k = 0; k < 3; ++k) {
    const core::Vec3f axis{float(k == 0), float(k == 1), float(k == 2)};
    out[std::size_t(k)] = {c0, projectToView(camera, view, c + axis * length), colours[k]};
  }
  return out;
}

int TransformGizmo::arrowAt(QPointF p) const {
  const auto drawn = arrows();
  if (!drawn) return -1;
  int best = -1;
  double nearest = kGrabPixels;
  for (int k = 0; k < 3; ++k) {
    const Arrow& a = (*drawn)[std::size_t(k)];
    const double length = std::hypot(a.to.x() - a.from.x(), a.to.y() - a.from.y());
    if (length < 6) continue; // seen end-on: nothing to take hold of
    // Not right at the origin, where the three meet: there the surface is sculpted.
    if (std::hypot(p.x() - a.from.x(), p.y() - a.from.y()) < 10) continue;
    const double d = distanceToSegment(p, a.from, a.to);
    if (d <= nearest) {
      nearest = d;
      best = k;
    }
  }
  if (best >= 0) return best;
  const QPointF c0 = (*drawn)[0].from;
  const double fromCentre = std::hypot(p.x() - c0.x(), p.y() - c0.y());
  return std::abs(fromCentre - kRingPixels) <= kGrabPixels ? kRing : -1;
}

void TransformGizmo::paint(QPainter& p) const {
  const auto drawn = arrows();
  if (!drawn) return;
  p.setRenderHint(QPainter::Antialiasing);
  const int active = mode_ && mode_->kind() == ObjectTransformMode::Kind::Move ? mode_->axis() : -1;
  for (int k = 0; k < 3; ++k) {
    const Arrow& a = (*drawn)[std::size_t(k)];
    const QPointF d = a.to - a.from;
    const double length = std::hypot(d.x(), d.y());
    if (length < 1) continue;
    const QPointF unit = d / length, side(-unit.y(), unit.x());
    const QColor colour = k == active ? a.colour.lighter(130) : a.colour;
    p.setPen(QPen(colour, k == active ? 5 : 4, Qt::SolidLine, Qt::RoundCap));
    p.drawLine(a.from, a.to - unit * std::min(12.0, length / 2));
    QPainterPath head;
    head.moveTo(a.to);
    head.lineTo(a.to - unit * 14 + side * 6);
    head.lineTo(a.to - unit * 14 - side * 6);
    head.closeSubpath();
    p.setPen(Qt::NoPen);
    p.setBrush(colour);
    p.drawPath(head);
  }
  const QPointF c0 = (*drawn)[0].from;
  p.setPen(QPen(QColor(255, 255, 255, 230), 2));
  drawCircle(p, c0, 5, 12);
  const bool scaling = mode_ && mode_->kind() == ObjectTransformMode::Kind::Scale;
  p.setPen(QPen(QColor(255, 255, 255, scaling ? 255 : 220), scaling ? 4 : 3));
  drawCircle(p, c0, kRingPixels, 96);
}

bool TransformGizmo::eventFilter(QObject* watched, QEvent* event) {
  if (watched != viewport_ || event->type() != QEvent::MouseButtonPress || !mode_) return false;
  auto* mouse = static_cast<QMouseEvent*>(event);
  if (mouse->button() != Qt::LeftButton || mouse->modifiers() != Qt::NoModifier) return false;
  if (mode_->kind() != ObjectTransformMode::Kind::None) return false;
  const int handle = arrowAt(mouse->position());
  if (handle < 0) return false;
  if (handle == kRing) return mode_->beginScaleDrag(mouse->position());
  return mode_->beginAxisDrag(handle, mouse->position());
}

} // namespace octaclay::app
