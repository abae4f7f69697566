#pragma once

#include "stroke_driver.h"
#include "stroke_stabilizer.h"

#include "octaclay/core/geometry/ray_pick.h"

#include <QPointF>

#include <optional>

namespace octaclay::app {

class ViewportWidget;

/// The viewport's pointer turned into the modeller's strokes: a press picks once (the surface
/// under the pointer, else the nearest within the brush ring), the lazy-mouse stabilizer trails
/// the pointer, each sample becomes a move (an image point, or a dragging brush's ray), and the
/// release ends the stroke. Pen pressure comes from tablet events.
class StrokeInput {
public:
  explicit StrokeInput(ViewportWidget& view);

  /// The surface point a press at p sculpts: the one under p, else the nearest within the brush
  /// ring's radius on screen (a press just off a thin limb or the silhouette sculpts there, as
  /// Blender's does); none: the press orbits.
  std::optional<core::PickHit> pressPick(QPointF p) const;
  /// Begins a stroke at p, picked as hit (Shift: smooth, Ctrl: inverted). Returns whether one
  /// began.
  bool begin(QPointF p, const core::PickHit& hit, Qt::KeyboardModifiers modifiers);
  void moveTo(QPointF p);
  void end(StrokeDriver::Relax relax);
  /// Pen pressure while the pen is down (tablet events), else none.
  void setPenPressure(std::optional<float> pressure) { pen_ = pressure; }
  /// The point the ring is drawn at (the pointer's pick, the stroke's last).
  const std::optional<core::PickHit>& hover() const { return hover_; }
  void setHover(std::optional<core::PickHit> hover) { hover_ = std::move(hover); }

private:
  void queuePoint(QPointF p);
  float pressure() const { return pen_.value_or(1.0f); }

  ViewportWidget& view_;
  StrokeStabilizer stabilizer_;
  std::optional<core::PickHit> hover_;
  std::optional<float> pen_;
};

} // namespace octaclay::app
