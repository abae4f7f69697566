#pragma once

#include "brush_settings.h"

#include "octaclay/gpu/brush_manifest.h"

#include <QString>
#include <QStringList>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace octaclay::app {

/// Radius limits, as a fraction of the model's bounding-box diagonal.
inline constexpr float kMinRadius = 0.001f, kMaxRadius = 1.0f;
/// The view radius's limits and a brush's until the user sets one (RadiusUnit::View), in
/// logical pixels: near the scene default's 5 % of the diagonal on a model the view frames
/// (a sphere in a 1000 × 700 window: 26 px).
inline constexpr float kMinRadiusPixels = 1.0f, kMaxRadiusPixels = 1000.0f,
                       kDefaultRadiusPixels = 30.0f;
/// A sculpt brush's strength until the user sets one: a first stroke, one pass, moves the surface
/// about a quarter of the radius, like a thumb on clay (0.5 dug trenches and raised horns
/// when a newcomer went back and forth).
inline constexpr float kDefaultSculptStrength = 0.25f;
/// A dragging brush's strength (Grab, Snake Hook: anchored and drag strokes) until the user sets
/// one: the surface follows the pointer all the way. At a quarter Snake Hook's 200 px drag
/// pulled a 30 px hook; these brushes apply their strength once per stroke or per dab with no
/// build-up, so less is a lag behind the pointer, not a gentler touch.
inline constexpr float kDefaultDragStrength = 1.0f;

/// value clamped to [lo, hi]; fallback if it is not finite.
float clampFinite(float value, float lo, float hi, float fallback);

/// What the user set for one brush; survives switching brushes.
struct BrushValues {
  float radius = 0.05f;                      ///< RadiusUnit::Scene's
  float radiusPixels = kDefaultRadiusPixels; ///< RadiusUnit::View's
  float strength = 0.5f; ///< paint and splats; sculpt brushes start at kDefaultSculptStrength,
                         ///< dragging ones at kDefaultDragStrength
  gpu::Falloff falloff = gpu::Falloff::Smooth;
  gpu::AreaMode area = gpu::AreaMode::Volume;
  std::map<std::string, std::array<float, 4>> parameters; ///< manifest parameter id → value
};

/// Each brush's values: remembered while the brushes are replaced, persisted with the
/// default-constructed QSettings in group "brushes/<id>" (keys radius, radiusPixels, strength,
/// falloff, area, and parameters/<parameter id>; enum options and materials by name); the
/// radius unit all brushes share in key "brushes/radiusUnit". GUI thread.
class BrushValueStore {
public:
  /// The installed materials' ids, in the engine's order: a material value is an index into
  /// them.
  const QStringList& materials() const { return materials_; }
  void setMaterials(QStringList ids) { materials_ = std::move(ids); }

  /// Keeps values for exactly these brushes: each one's from what the store remembers, else
  /// from QSettings, else from the manifest, then fitted to the manifest (unknown parameters
  /// dropped, values clamped to their ranges). For a duplicate id the first brush wins.
  void setBrushes(const std::vector<gpu::BrushManifest>& brushes);
  /// The values of brush id, or nullptr if the store has none.
  BrushValues* find(const QString& id);
  const BrushValues* find(const QString& id) const;
  /// Persists brush's values (nothing if the store has none).
  void save(const gpu::BrushManifest& brush) const;

  /// The radius unit as stored ("view" or "scene"); without one, View for a new user and Scene
  /// for one whose brushes already have stored values (their radii keep the size they had).
  static RadiusUnit loadRadiusUnit();
  static void saveRadiusUnit(RadiusUnit unit);
  /// The stroke options every brush shares (pressure target, stabilizer, symmetry, keep detail)
  /// as stored in group "brushPanel", written over settings' (what is not stored stays).
  static void loadStrokeOptions(BrushSettings& settings);
  static void saveStrokeOptions(const BrushSettings& settings);

private:
  BrushValues defaults(const gpu::BrushManifest& brush) const;
  BrushValues load(const gpu::BrushManifest& brush) const;

  std::map<QString, BrushValues> values_;
  QStringList materials_;
};

} // namespace octaclay::app
