#pragma once

#include "brush_settings.h"
#include "brush_value_store.h"

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/gpu/brush_manifest.h"

#include <QObject>
#include <QString>
#include <QStringList>

#include <array>
#include <string>
#include <vector>

namespace octaclay::app {

/// The brush as the user set it: the brushes there are, the current one and every brush's
/// values (remembered while switching and persisted by BrushValueStore), the stroke options all
/// brushes share, and where colour paint goes. The Brushes dock, the tool bar, the header, the
/// canvas's F-adjust and [ / ] edit it and follow it; the viewport (its ring) and the modeller's
/// strokes read settings(). Setters clamp, store, persist and emit changed() only when a value
/// differs. GUI thread.
class BrushState : public QObject {
  Q_OBJECT
public:
  /// Loads the radius unit and the stroke options the user saved.
  explicit BrushState(QObject* parent = nullptr);

  /// Replaces the brushes and the load errors shown beside them. Each brush's values come from
  /// what this state remembers, else from QSettings, else from the manifest, fitted to the
  /// manifest. The current brush stays if it still exists, else "push" if present, else the
  /// first in display order. Emits brushesChanged, then brushSelected and changed.
  void setBrushes(std::vector<gpu::BrushManifest> brushes, std::vector<std::string> errors);
  const std::vector<gpu::BrushManifest>& brushes() const { return brushes_; }
  QStringList errors() const;
  const std::vector<std::string>& errorTexts() const { return errors_; }
  /// The installed materials' ids, in the engine's order: a material parameter's value is an
  /// index into them. Emits brushesChanged when they differ.
  void setMaterials(QStringList ids);
  const QStringList& materials() const { return store_.materials(); }
  /// The brush ids in display order: category (Sculpt, Paint, Splat), then the order given; a
  /// duplicate id only once.
  QStringList brushIds() const;

  QString currentBrushId() const { return currentId_; }
  /// The current brush's manifest, or nullptr when none is loaded.
  const gpu::BrushManifest* currentBrush() const;
  /// Makes brush id current (brushSelected and changed when it was not). False, changing
  /// nothing, when no brush has this id.
  bool selectBrush(const QString& id);

  /// The current brush's values (defaults while no brush is loaded).
  const BrushValues& values() const;
  /// Fraction of the model's bounding-box diagonal, clamped to [kMinRadius, kMaxRadius].
  void setRadius(float fractionOfDiagonal);
  float radius() const { return values().radius; }
  /// Logical pixels of the view, clamped to [kMinRadiusPixels, kMaxRadiusPixels].
  void setRadiusPixels(float pixels);
  float radiusPixels() const { return values().radiusPixels; }
  /// What the radius is measured in, for every brush; persisted.
  void setRadiusUnit(RadiusUnit unit);
  RadiusUnit radiusUnit() const { return options_.radiusUnit; }
  /// The radius in the current unit: what the header, F and [ / ] change.
  void setRadiusInUnit(float value);
  float radiusInUnit() const;
  /// Clamped to [0, 1].
  void setStrength(float strength);
  float strength() const { return values().strength; }
  void setFalloff(gpu::Falloff falloff);
  void setArea(gpu::AreaMode area);
  /// A manifest parameter of the current brush (ignored for an id it does not declare).
  void setParameter(const std::string& id, std::array<float, 4> value);

  /// The stroke options every brush shares; persisted.
  void setPressureTarget(PressureTarget target);
  /// Lazy-mouse strength, clamped to [0, 1] and kept in whole percent.
  void setStabilizer(float amount);
  /// gpu::SymmetryAxis bits (X = 1, Y = 2, Z = 4); other bits are ignored.
  void setSymmetry(unsigned axes);
  /// Whether sculpt strokes relax what they stretched.
  void setKeepDetail(bool on);

  /// The current brush and all its values, plus the stroke options: what a stroke begins with.
  BrushSettings settings() const;

  /// The layer paint-category brushes write (diffuse, feature or mask).
  core::EditLayer paintTarget() const { return paintTarget_; }
  void setPaintTarget(core::EditLayer layer);

signals:
  /// The brushes, their errors or the materials were replaced: lists and forms rebuild.
  void brushesChanged();
  /// Another brush became current: its form rebuilds.
  void brushSelected();
  /// Anything in settings() or paintTarget() may have changed.
  void changed();

private:
  BrushValues& currentValues();
  // Persists the current brush's values and emits changed().
  void valuesEdited();
  void optionsEdited();

  std::vector<gpu::BrushManifest> brushes_;
  std::vector<std::string> errors_;
  BrushValueStore store_;
  QString currentId_;
  BrushValues noBrush_;   // what values() gives while no brush is loaded
  BrushSettings options_; // only the radius unit and the stroke options are used
  core::EditLayer paintTarget_ = core::EditLayer::Diffuse;
};

} // namespace octaclay::app
