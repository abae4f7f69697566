#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <array>
#include <map>
#include <string>

namespace octaclay::app {

/// What pen pressure scales while stroking.
enum class PressureTarget { None, Radius, Strength };

/// What the brush radius is measured in. View: pixels of the view, turned into object units at
/// the depth of the point a stroke begins on (Blender's default: the brush looks the same size
/// at every zoom). Scene: a fraction of the model's bounding-box diagonal (the same size on the
/// model at every zoom).
enum class RadiusUnit { View, Scene };

/// The brush the user has chosen and how: what the Brushes panel edits and the viewport uses.
struct BrushSettings {
  std::string brushId;
  float radius = 0.05f; ///< fraction of the model's bounding-box diagonal, (0, 1]
  /// Which radius the viewport strokes with: radiusPixels (View, turned into
  /// StrokeStart::objectRadius at the press) or radius (Scene). SculptSession itself reads only
  /// radius, unless its StrokeStart gives objectRadius; octaclay-cli strokes with radius.
  RadiusUnit radiusUnit = RadiusUnit::Scene;
  float radiusPixels = 30.0f;                             ///< logical pixels of the view, [1, 1000]
  float strength = 0.5f;                                  ///< fraction of the radius, [0, 1]
  gpu::Falloff falloff = gpu::Falloff::Smooth;            ///< starts as the manifest's
  gpu::AreaMode area = gpu::AreaMode::Volume;             ///< starts as the manifest's
  std::map<std::string, std::array<float, 4>> parameters; ///< manifest parameter id → value
  PressureTarget pressureTarget = PressureTarget::Strength;
  float stabilizer = 0.0f; ///< lazy-mouse strength in [0, 1]; 0 follows the cursor exactly
  unsigned symmetry = 0;   ///< gpu::SymmetryAxis bits
  /// Sculpt strokes relax what they stretched (SculptSession::keepDetail).
  bool keepDetail = true;

  bool operator==(const BrushSettings&) const = default;
};

} // namespace octaclay::app
