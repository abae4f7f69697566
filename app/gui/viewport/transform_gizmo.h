#pragma once

#include <QColor>
#include <QObject>
#include <QPointF>
#include <QPointer>

#include <array>
#include <optional>

class QPainter;

namespace octaclay::app {

class ObjectTransformMode;
class ViewportWidget;

/// The move gizmo (issue 33): three arrows from the edited object's origin along the world's
/// X (red), Y (green) and Z (blue) axes, about kArrowPixels long on screen whatever the zoom,
/// and a white ring of kRingPixels around them, painted over the model while shown (Object
/// Mode). A left press on an arrow (within kGrabPixels of it) starts
/// ObjectTransformMode::beginAxisDrag along that axis instead of a stroke: the object follows
/// the pointer along the axis and the release places it (one step). A left press on the ring
/// starts ObjectTransformMode::beginScaleDrag: the object scales by the pointer's distance to
/// its origin on screen against the ring's radius, placed at the release. GUI thread.
class TransformGizmo : public QObject {
  Q_OBJECT
public:
  static constexpr double kArrowPixels = 90;
  static constexpr double kRingPixels = 115;
  static constexpr double kGrabPixels = 8;
  static constexpr int kRing = 3; ///< arrowAt's answer for the ring

  TransformGizmo(ViewportWidget* viewport, ObjectTransformMode* mode, QObject* parent = nullptr);

  void setShown(bool shown);
  bool shown() const { return shown_; }

  /// One arrow on screen (viewport pixels): from the origin's place to its tip.
  struct Arrow {
    QPointF from, to;
    QColor colour;
  };
  /// The arrows as they are drawn now (X, Y, Z); none while hidden, without a visible edited
  /// object or when its origin is behind the eye.
  std::optional<std::array<Arrow, 3>> arrows() const;
  /// The axis (0, 1, 2) of the arrow a press at p (viewport pixels) takes, kRing for the ring,
  /// or -1.
  int arrowAt(QPointF p) const;

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void paint(QPainter& painter) const;

  QPointer<ViewportWidget> viewport_;
  QPointer<ObjectTransformMode> mode_;
  bool shown_ = false;
};

} // namespace octaclay::app
