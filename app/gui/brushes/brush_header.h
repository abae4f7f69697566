#pragma once

#include "brush_settings.h"

#include <QToolBar>

#include <array>

class QAction;
class QLabel;
class QSlider;

namespace octaclay::app {

/// The compact bar above the viewport: the current brush's radius and strength as sliders with
/// their values, and the symmetry toggles X, Y, Z. It shows values and reports the user's edits;
/// the BrushState owns them (brush_bars keeps the two in step). Object names: headerRadius,
/// headerStrength (the sliders), headerSymmetryX/Y/Z (checkable actions). GUI thread.
class BrushHeader : public QToolBar {
  Q_OBJECT
public:
  explicit BrushHeader(QWidget* parent = nullptr);

  /// Shows these values without emitting anything. radius in unit: pixels (View) or a
  /// fraction of the bounding-box diagonal (Scene); strength in [0, 1]; symmetry:
  /// gpu::SymmetryAxis bits.
  void setValues(RadiusUnit unit, float radius, float strength, unsigned symmetry);

  /// The radius slider's scale: position (0 … kRadiusSteps) ↔ radius, logarithmic from
  /// kMinRadius to kMaxRadius (Scene) or kMinRadiusPixels to kMaxRadiusPixels (View) so small
  /// brushes get fine steps.
  static constexpr int kRadiusSteps = 1000;
  static int radiusToPosition(float radius, RadiusUnit unit = RadiusUnit::Scene);
  static float positionToRadius(int position, RadiusUnit unit = RadiusUnit::Scene);

signals:
  /// In the unit shown (setValues).
  void radiusEdited(float radius);
  void strengthEdited(float strength);
  void symmetryEdited(unsigned axes);

private:
  void showLabels(float radius, float strength);

  RadiusUnit unit_ = RadiusUnit::Scene;
  QSlider* radius_ = nullptr;
  QSlider* strength_ = nullptr;
  QLabel* radiusLabel_ = nullptr;
  QLabel* strengthLabel_ = nullptr;
  std::array<QAction*, 3> symmetry_{};
};

} // namespace octaclay::app
