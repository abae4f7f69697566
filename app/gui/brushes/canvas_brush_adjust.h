#pragma once

#include "octaclay/core/geometry/vec.h"

#include <QObject>
#include <QPointF>
#include <QPointer>
#include <QString>

namespace octaclay::app {

class BrushState;
class ViewportWidget;

/// F / Shift+F on the canvas: begin() at the pointer's last place over the viewport, then moving
/// the pointer sideways changes the current brush's radius (the ring's edge follows the pointer:
/// one pixel is one pixel of radius at the ring's centre) or its strength (kPixelsPerStrength
/// pixels for 0 → 100 %), written to the BrushState as it goes so the ring and the header show
/// it live. A left click (at its release) or Enter confirms; Esc, a right click or another
/// begin() cancels and restores the value it started from. While it runs it watches the whole
/// application's input and lets no click through to the viewport. GUI thread.
class CanvasBrushAdjust : public QObject {
  Q_OBJECT
public:
  enum class Mode { None, Radius, Strength };
  static constexpr double kPixelsPerStrength = 300.0;

  CanvasBrushAdjust(ViewportWidget* viewport, BrushState* state, QObject* parent = nullptr);
  ~CanvasBrushAdjust() override;

  /// Starts adjusting (cancelling one under way). Refused (false) without a current brush or
  /// while a mouse button is held (a stroke, an orbit).
  bool begin(Mode mode);
  void confirm();
  void cancel();
  Mode mode() const { return mode_; }
  /// Where (viewport pixels) the adjustment began: the pointer's place then.
  QPointF origin() const { return origin_; }
  /// The value the adjustment started from (a radius in the state's unit, or a strength).
  float startValue() const { return start_; }
  /// What the adjustment paints over the viewport's frames (logical pixels): its value in a
  /// box beside centre, and a ring of ringPixels (with a disc of strength × ringPixels inside,
  /// strength ≥ 0) where the surface's own ring cannot show the radius.
  struct Marks {
    QPointF centre;
    double ringPixels = 0;
    double strength = -1; ///< < 0: no disc
    bool drawRing = false;
    QString text;
  };
  /// The marks shown now (meaningful while mode() is not None).
  const Marks& marks() const { return marks_; }
  /// Pixels of sideways motion per unit of radius: 1 for a view radius (pixels), else per
  /// fraction of the model's diagonal as measured at begin() at the ring's centre.
  double pixelsPerRadius() const { return pixelsPerRadius_; }

signals:
  /// The adjustment ended: confirmed or cancelled.
  void finished(bool confirmed);

protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

private:
  void moveTo(QPointF viewportPos);
  void end(bool confirm);

  QPointer<ViewportWidget> viewport_;
  QPointer<BrushState> state_;
  Marks marks_;
  Mode mode_ = Mode::None;
  QPointF lastPos_; // the pointer's last place over the viewport
  QPointF origin_;  // where the adjustment began
  float start_ = 0; // the value then
  double pixelsPerRadius_ = 1;
  Qt::MouseButton swallowRelease_ = Qt::NoButton;
};

} // namespace octaclay::app
