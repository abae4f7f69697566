#include "object_transform_mode.h"

#include "camera_control.h"
#include "modeller.h"
#include "object_transform_edit.h"
#include "viewport_widget.h"

#include <QApplication>
#include <QCursor>
#include <QKeyEvent>
#include <QMouseEvent>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>

namespace octaclay::app {
namespace {

constexpr const char* kAxisNames[3] = {"X", "Y", "Z"};

core::Vec3f towardEye(vtkCamera& camera) {
  double d[3];
  camera.GetDirectionOfProjection(d);
  return core::normalize(core::Vec3f{float(-d[0]), float(-d[1]), float(-d[2])});
}

// The parameter t of the point c + t·a (a unit) nearest ray; nullopt when they are parallel.
std::optional<double> nearestAlong(core::Vec3f c, core::Vec3f a, const core::Ray& ray) {
  const core::Vec3f w = c - ray.origin;
  const double b = core::dot(a, ray.direction);
  const double denominator = 1.0 - b * b;
  if (denominator < 1e-6) return std::nullopt;
  return (b * core::dot(ray.direction, w) - core::dot(a, w)) / denominator;
}

// Where ray meets the plane through c facing the view (normal n); c when it does not.
core::Vec3f onViewPlane(core::Vec3f c, core::Vec3f n, const core::Ray& ray) {
  const float along = core::dot(ray.direction, n);
  if (std::abs(along) < 1e-6f) return c;
  return ray.origin + ray.direction * (core::dot(c - ray.origin, n) / along);
}

core::Vec3f toVec3f(const Direction& d) {
  return {float(d[0]), float(d[1]), float(d[2])};
}

} // namespace

ObjectTransformMode::ObjectTransformMode(ViewportWidget* viewport, QObject* parent)
    : QObject(parent), viewport_(viewport) {
  viewport->installEventFilter(this);
  lastPos_ = QPointF(-1, -1); // not seen yet
  Modeller* modeller = &viewport->modeller();
  // The object's index means another object after these: the gesture stops, nothing kept.
  const auto abandon = [this] {
    if (kind_ == Kind::None) return;
    object_ = -1;
    end(false);
  };
  connect(modeller, &Modeller::activeObjectChanged, this, abandon);
  connect(modeller, &Modeller::sceneChanged, this, abandon);
}

ObjectTransformMode::~ObjectTransformMode() {
  qApp->removeEventFilter(this);
}

bool ObjectTransformMode::begin(Kind kind) {
  if (!viewport_ || kind == Kind::None) return false;
  if (kind_ != Kind::None) { // G, R or S while one runs: that one, from the start
    if (dragging_) return false;
    kind_ = kind;
    frame_ = Frame::Free;
    axis_ = -1;
    typed_.clear();
    moveTo(lastPos_);
    return true;
  }
  if (viewport_->stroking() || QGuiApplication::mouseButtons() != Qt::NoButton) return false;
  const QRectF view = viewport_->modelRect();
  const QPointF cursor = viewport_->mapFromGlobal(QCursor::pos());
  return start(kind, view.contains(lastPos_) ? lastPos_
                     : view.contains(cursor) ? cursor
                                             : view.center());
}

bool ObjectTransformMode::beginAxisDrag(int axis, QPointF pressPos) {
  if (!viewport_ || kind_ != Kind::None || axis < 0 || axis > 2 || viewport_->stroking())
    return false;
  dragging_ = true;
  if (!start(Kind::Move, pressPos)) {
    dragging_ = false;
    return false;
  }
  setAxis(axis);
  return true;
}

bool ObjectTransformMode::beginScaleDrag(QPointF pressPos) {
  if (!viewport_ || kind_ != Kind::None || viewport_->stroking()) return false;
  dragging_ = true;
  if (!start(Kind::Scale, pressPos)) {
    dragging_ = false;
    return false;
  }
  return true;
}

bool ObjectTransformMode::start(Kind kind, QPointF origin) {
  Modeller& modeller = viewport_->modeller();
  if (!modeller.hasDocument() || modeller.objectCount() == 0) return false;
  const int k = modeller.activeObject();
  const core::SceneObject& object = modeller.objectAt(k);
  const QString name = QString::fromStdString(object.name);
  if (object.locked) {
    emit modeller.refused(tr("%1 is locked: unlock it in the Objects dock to move it").arg(name));
    return false;
  }
  if (!object.visible) {
    emit modeller.refused(tr("%1 is hidden: show it in the Objects dock to move it").arg(name));
    return false;
  }
  kind_ = kind;
  frame_ = Frame::Free;
  axis_ = -1;
  object_ = k;
  before_ = current_ = object.transform;
  origin_ = lastPos_ = origin;
  typed_.clear();
  amount_ = kind == Kind::Scale ? 1 : 0;
  qApp->installEventFilter(this);
  show();
  return true;
}

void ObjectTransformMode::confirm() {
  if (kind_ != Kind::None) end(true);
}

void ObjectTransformMode::cancel() {
  if (kind_ != Kind::None) end(false);
}

QString ObjectTransformMode::text() const {
  if (kind_ == Kind::None) return {};
  QString name = kind_ == Kind::Move     ? tr("Move")
                 : kind_ == Kind::Rotate ? tr("Rotate")
                                         : tr("Scale");
  if (axis_ >= 0)
    name += frame_ == Frame::Local ? tr(" local %1").arg(kAxisNames[axis_])
                                   : QStringLiteral(" ") + kAxisNames[axis_];
  QString value;
  if (!typed_.isEmpty()) {
    value = typed_ + QStringLiteral("|");
  } else if (kind_ == Kind::Move && axis_ < 0) {
    const core::Vec3f d = current_.translation - before_.translation;
    value = QStringLiteral("%1, %2, %3")
                .arg(double(d.x), 0, 'f', 3)
                .arg(double(d.y), 0, 'f', 3)
                .arg(double(d.z), 0, 'f', 3);
  } else {
    value = QString::number(amount_, 'f', kind_ == Kind::Rotate ? 1 : 3);
  }
  if (kind_ == Kind::Rotate) value += QStringLiteral("°");
  return tr("%1: %2   (X Y Z constrain, type a number, Enter or click keeps, Esc cancels)")
      .arg(name, value);
}

double ObjectTransformMode::amountAt(QPointF p) const {
  vtkCamera& camera = *viewport_->renderer()->GetActiveCamera();
  const QRectF view = viewport_->modelRect();
  const core::Vec3f c = before_.translation;
  const QPointF c0 = projectToView(camera, view, c);
  if (kind_ == Kind::Move) {
    const core::Vec3f a = frame_ == Frame::Local ? toVec3f(localAxisDirection(before_, axis_))
                                                 : core::Vec3f{float(axis_ == 0), float(axis_ == 1),
                                                               float(axis_ == 2)};
    const auto now = nearestAlong(c, a, viewRay(camera, view.size(), p));
    const auto then = nearestAlong(c, a, viewRay(camera, view.size(), origin_));
    return now && then ? *now - *then : amount_;
  }
  if (kind_ == Kind::Rotate) {
    // Counter-clockwise on screen (y down) is a positive turn about the axis toward the eye.
    const double turn = std::atan2(-(p.y() - c0.y()), p.x() - c0.x()) -
                        std::atan2(-(origin_.y() - c0.y()), origin_.x() - c0.x());
    double degrees = std::remainder(turn * 180.0 / std::numbers::pi, 360.0);
    if (axis_ >= 0) {
      const core::Vec3f a =
          frame_ == Frame::Local
              ? toVec3f(localAxisDirection(before_, axis_))
              : core::Vec3f{float(axis_ == 0), float(axis_ == 1), float(axis_ == 2)};
      if (core::dot(a, towardEye(camera)) < 0) degrees = -degrees;
    }
    return degrees;
  }
  const double from = std::hypot(origin_.x() - c0.x(), origin_.y() - c0.y());
  return std::hypot(p.x() - c0.x(), p.y() - c0.y()) / std::max(from, 4.0);
}

core::ObjectTransform ObjectTransformMode::transformFor(double amount) const {
  switch (kind_) {
  case Kind::Move: {
    if (frame_ == Frame::Local)
      return translated(before_, toVec3f(localAxisDirection(before_, axis_)) * float(amount));
    core::Vec3f offset{};
    (axis_ == 1 ? offset.y : axis_ == 2 ? offset.z : offset.x) = float(amount);
    return translated(before_, offset);
  }
  case Kind::Rotate: {
    if (axis_ < 0) {
      const core::Vec3f eye = towardEye(*viewport_->renderer()->GetActiveCamera());
      return rotatedAbout(before_, {eye.x, eye.y, eye.z}, amount);
    }
    return frame_ == Frame::Local ? rotatedAboutLocalAxis(before_, axis_, amount)
                                  : rotatedAboutWorldAxis(before_, axis_, amount);
  }
  case Kind::Scale:
    if (axis_ < 0) return scaled(before_, amount);
    return scaled(before_, amount,
                  frame_ == Frame::Local ? axis_ : localAxisNearest(before_, axis_));
  case Kind::None:
    break;
  }
  return before_;
}

core::ObjectTransform ObjectTransformMode::transformAt(QPointF p) const {
  if (kind_ == Kind::Move && axis_ < 0 && typed_.isEmpty()) {
    vtkCamera& camera = *viewport_->renderer()->GetActiveCamera();
    const QRectF view = viewport_->modelRect();
    const core::Vec3f c = before_.translation, n = towardEye(camera);
    return translated(before_, onViewPlane(c, n, viewRay(camera, view.size(), p)) -
                                   onViewPlane(c, n, viewRay(camera, view.size(), origin_)));
  }
  return transformFor(amount_);
}

void ObjectTransformMode::moveTo(QPointF p) {
  if (kind_ == Kind::None || !viewport_) return;
  lastPos_ = p;
  if (typed_.isEmpty() && !(kind_ == Kind::Move && axis_ < 0)) amount_ = amountAt(p);
  show();
}

void ObjectTransformMode::show() {
  if (!typed_.isEmpty()) {
    bool ok = false;
    const double value = typed_.toDouble(&ok);
    amount_ = ok ? value : (kind_ == Kind::Scale ? 1.0 : 0.0); // "-" or "." alone: nothing yet
  }
  const core::ObjectTransform wanted = transformAt(lastPos_);
  // A transform beyond the bounds (a scale of 0 typed) is not shown; the last one stays.
  if (viewport_->modeller().previewObjectTransform(object_, wanted)) current_ = wanted;
  emit textChanged(text());
}

void ObjectTransformMode::setAxis(int axis) {
  if (axis_ != axis) {
    axis_ = axis;
    frame_ = Frame::World;
  } else if (frame_ == Frame::World) {
    frame_ = Frame::Local;
  } else {
    axis_ = -1;
    frame_ = Frame::Free;
  }
  if (typed_.isEmpty()) amount_ = amountAt(lastPos_);
  show();
}

bool ObjectTransformMode::typeKey(int key, const QString& text) {
  if (key == Qt::Key_Backspace) {
    typed_.chop(1);
    if (typed_.isEmpty()) amount_ = amountAt(lastPos_);
  } else if (key == Qt::Key_Minus) {
    typed_ = typed_.startsWith(u'-') ? typed_.mid(1) : QStringLiteral("-") + typed_;
  } else if (key == Qt::Key_Period || key == Qt::Key_Comma) {
    if (typed_.contains(u'.')) return true;
    typed_ += u'.';
  } else if (text.size() == 1 && text[0].isDigit()) {
    typed_ += text;
  } else {
    return false;
  }
  show();
  return true;
}

void ObjectTransformMode::end(bool confirmed) {
  kind_ = Kind::None;
  dragging_ = false;
  if (swallowRelease_ == Qt::NoButton) qApp->removeEventFilter(this);
  emit textChanged({});
  if (viewport_ && object_ >= 0) {
    Modeller& modeller = viewport_->modeller();
    // The preview goes back bit for bit; a kept gesture then places the object through the
    // one door, so the step it records runs from the transform before.
    modeller.previewObjectTransform(object_, before_);
    if (confirmed && current_ != before_) {
      const QString why = modeller.setObjectTransform(object_, current_);
      if (!why.isEmpty()) {
        emit modeller.refused(why);
        confirmed = false;
      }
    }
  }
  object_ = -1;
  emit finished(confirmed);
}

bool ObjectTransformMode::eventFilter(QObject* watched, QEvent* event) {
  const QEvent::Type type = event->type();
  if (kind_ == Kind::None) {
    // The pointer's place over the viewport, where the next gesture begins.
    if (watched == viewport_ && type == QEvent::MouseMove)
      lastPos_ = static_cast<QMouseEvent*>(event)->position();
    // The release of the click that ended a gesture must not reach anything.
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
    moveTo(viewport_->mapFromGlobal(static_cast<QMouseEvent*>(event)->globalPosition()));
    return true;
  }
  case QEvent::MouseButtonPress:
  case QEvent::MouseButtonDblClick: {
    const Qt::MouseButton button = static_cast<QMouseEvent*>(event)->button();
    if (button == Qt::LeftButton && !dragging_) swallowRelease_ = Qt::LeftButton; // kept then
    if (button == Qt::RightButton) {
      swallowRelease_ = Qt::RightButton;
      end(false);
    }
    return true;
  }
  case QEvent::MouseButtonRelease: {
    const Qt::MouseButton button = static_cast<QMouseEvent*>(event)->button();
    if (dragging_ && button == Qt::LeftButton) {
      end(true);
    } else if (button == swallowRelease_) {
      swallowRelease_ = Qt::NoButton;
      if (button == Qt::LeftButton) end(true);
    }
    return true;
  }
  case QEvent::ShortcutOverride:
  case QEvent::KeyPress: {
    // Every key is the gesture's while it runs (as in Blender): no shortcut (an undo, a brush,
    // Delete) acts on the scene under a preview. Only its own keys do something.
    auto* keyEvent = static_cast<QKeyEvent*>(event);
    const int key = keyEvent->key();
    event->accept();
    if (type != QEvent::KeyPress || keyEvent->isAutoRepeat()) return true;
    if (keyEvent->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier))
      return true;
    if (key == Qt::Key_Escape) {
      end(false);
    } else if (key == Qt::Key_Return || key == Qt::Key_Enter) {
      end(true);
    } else if (key == Qt::Key_X || key == Qt::Key_Y || key == Qt::Key_Z) {
      setAxis(key - Qt::Key_X);
    } else if (key == Qt::Key_G || key == Qt::Key_R || key == Qt::Key_S) {
      begin(key == Qt::Key_G ? Kind::Move : key == Qt::Key_R ? Kind::Rotate : Kind::Scale);
    } else {
      typeKey(key, keyEvent->text());
    }
    return true;
  }
  default:
    return false;
  }
}

} // namespace octaclay::app
