#pragma once

#include <vector>

namespace octaclay::app {

/// A point in viewport pixels (x right, y down, like Qt's widget coordinates).
struct Point2 {
  float x = 0.0f;
  float y = 0.0f;
};

/// A "lazy mouse" stroke stabilizer, as in Blender, Krita and ZBrush: the brush hangs on a
/// string of length L behind the cursor. While the cursor stays within L of the brush the
/// brush stays put, so hand tremor never reaches the surface; once the cursor pulls farther, the
/// brush slides along the straight line toward it until it is exactly L away again. The result
/// is a smooth path that lags the cursor by L.
///
/// Plain C++ and single-threaded: the viewport owns one and feeds it from its mouse events.
class StrokeStabilizer {
public:
  /// The string length at strength 1 unless setMaxLengthPixels() says otherwise.
  static constexpr float kDefaultMaxLengthPixels = 60.0f;
  /// The largest gap between two consecutive points moveTo() returns, in pixels.
  static constexpr float kMaxDabSpacingPixels = 2.0f;

  /// strength in [0, 1] (clamped, NaN counts as 0); see setStrength().
  explicit StrokeStabilizer(float strength = 0.0f);

  /// Sets the strength in [0, 1] (clamped, NaN counts as 0). The string length is
  /// L = strength × maxLengthPixels(); 0 makes the brush follow the cursor exactly. Takes effect
  /// on the next moveTo(), also in the middle of a stroke.
  void setStrength(float strength);
  /// The strength in [0, 1].
  float strength() const { return strength_; }

  /// Sets the string length at strength 1, in pixels (≥ 0; negative and NaN count as 0).
  void setMaxLengthPixels(float pixels);
  /// The string length at strength 1, in pixels.
  float maxLengthPixels() const { return maxLength_; }

  /// The current string length L = strength × max length, in pixels.
  float lengthPixels() const { return strength_ * maxLength_; }

  /// Starts a stroke with the brush on the cursor. The caller dabs at the cursor itself: the
  /// first dab of a stroke is where the user pressed.
  void begin(Point2 cursor);

  /// Moves the cursor. Returns where to dab, in order: points along the brush's movement no more
  /// than kMaxDabSpacingPixels apart (so a fast flick leaves no gaps), ending exactly on the
  /// brush's new position. Empty when the brush did not move (the cursor is still within L of
  /// it). With strength 0 the brush is the cursor, so the last point is the cursor exactly.
  /// Called without begin(), it begins the stroke at cursor and returns nothing.
  std::vector<Point2> moveTo(Point2 cursor);

  /// Where the brush is, in pixels: the point the last dab went to.
  Point2 brush() const { return brush_; }

  /// Ends the stroke. Returns no points: like Blender's lazy mouse, the stroke ends where the
  /// brush is, not at the cursor, because catching up would draw the very segment the user
  /// was steering away from. A later moveTo() without begin() starts a new stroke.
  std::vector<Point2> finish();

  /// Whether a stroke is in progress (begin() was called and finish() has not been).
  bool active() const { return active_; }

private:
  float strength_ = 0.0f;
  float maxLength_ = kDefaultMaxLengthPixels;
  Point2 brush_;
  bool active_ = false;
};

} // namespace octaclay::app
