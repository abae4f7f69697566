#pragma once

#include "octaclay/core/document/object_transform.h"
#include "octaclay/core/geometry/vec.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

namespace octaclay::app {

class ViewportWidget;

/// G / R / S on the canvas (issue 33, Blender's keys): moves, rotates or scales the edited
/// object as the pointer moves, about its origin (its translation).
///
/// - Move: the origin follows the pointer in the plane through it facing the view; along one
///   axis, the point of that axis nearest the pointer's ray.
/// - Rotate: about the view's axis (counter-clockwise on screen as the pointer goes round the
///   origin's place on screen counter-clockwise); about a world axis with X / Y / Z.
/// - Scale: uniformly by the pointer's distance to the origin's place on screen against the
///   distance when it began; along one axis with X / Y / Z (the object's own axis nearest it).
///
/// X, Y or Z constrains to that world axis; the same key again to the object's own axis, a
/// third time back to none. Typing a number (digits, '.', '-', Backspace) sets the amount
/// exactly: scene units along the axis (X without one), degrees, a factor. text() says what
/// runs ("Move X: 0.5"); textChanged follows it. Every change is shown with
/// Modeller::previewObjectTransform (nothing recorded). Enter or a left click (at its release)
/// keeps it: the preview goes back to the transform before and one Modeller::setObjectTransform
/// places the object (one step). Esc, a right click or a refused transform cancels: the object
/// is shown under its transform before, bit for bit. While it runs it watches the whole
/// application's input and lets no click and no key through (no shortcut, Ctrl+Z included,
/// acts under a preview). GUI thread.
class ObjectTransformMode : public QObject {
  Q_OBJECT
public:
  enum class Kind { None, Move, Rotate, Scale };
  enum class Frame { Free, World, Local };

  explicit ObjectTransformMode(ViewportWidget* viewport, QObject* parent = nullptr);
  ~ObjectTransformMode() override;

  /// Starts kind on the edited object at the pointer's place over the viewport (its centre
  /// when the pointer is elsewhere). Refused (false) without a document, while a stroke runs or
  /// a mouse button is held, and for a hidden or locked object (Modeller::refused says why).
  /// G / R / S while one runs switches to that kind from the transform before.
  bool begin(Kind kind);
  /// The gizmo's drag: a move along world axis (0, 1, 2) from pointer position pressPos
  /// (viewport pixels) whose left-button release keeps it. Refused as begin().
  bool beginAxisDrag(int axis, QPointF pressPos);
  /// The gizmo's ring: a uniform scale from pressPos whose left-button release keeps it.
  bool beginScaleDrag(QPointF pressPos);
  void confirm();
  void cancel();

  Kind kind() const { return kind_; }
  Frame frame() const { return frame_; }
  int axis() const { return axis_; }
  /// The object being placed and its transform when the gesture began.
  int object() const { return object_; }
  const core::ObjectTransform& before() const { return before_; }
  /// The transform shown now.
  const core::ObjectTransform& current() const { return current_; }
  /// "Move X: 0.25", "Rotate: 30°", "Scale: 2 (typed)"; empty when none runs.
  QString text() const;

signals:
  void textChanged(const QString& text);
  /// The gesture ended: kept (confirmed) or cancelled.
  void finished(bool confirmed);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  bool start(Kind kind, QPointF origin);
  void moveTo(QPointF viewportPos);
  void setAxis(int axis);
  bool typeKey(int key, const QString& text);
  // The transform for the pointer at p, or for the typed amount when one is typed.
  core::ObjectTransform transformAt(QPointF p) const;
  core::ObjectTransform transformFor(double amount) const;
  double amountAt(QPointF p) const; // what the pointer gives: units, degrees or a factor
  void show();
  void end(bool confirmed);

  QPointer<ViewportWidget> viewport_;
  Kind kind_ = Kind::None;
  Frame frame_ = Frame::Free;
  int axis_ = -1;
  int object_ = -1;
  core::ObjectTransform before_, current_;
  QPointF origin_;  // where the pointer was as it began (viewport pixels)
  QPointF lastPos_; // the pointer's last place over the viewport
  QString typed_;   // the typed amount, as typed
  double amount_ = 0;
  bool dragging_ = false; // the gizmo's drag: the left release keeps it
  Qt::MouseButton swallowRelease_ = Qt::NoButton;
};

} // namespace octaclay::app
