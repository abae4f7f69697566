#pragma once

#include "brush_settings.h"
#include "brush_value_store.h"
#include "color_button.h"

#include "octaclay/gpu/brush_manifest.h"

#include <QPointer>
#include <QString>
#include <QWidget>

#include <array>
#include <map>
#include <string>
#include <vector>

class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QFrame;
class QLabel;
class QScrollArea;
class QTreeWidget;
class QTreeWidgetItem;
class QVBoxLayout;

namespace octaclay::app {

class RadiusField;
class StrokeOptionsBox;

/// The Brushes dock panel: the brush list grouped by category, the brushes that failed to load,
/// and a form for the current brush (radius, strength, falloff, area mode, then one widget per
/// manifest parameter) above the stroke options shared by all brushes (pressure, stabilizer,
/// symmetry, keep detail). Each brush's values are remembered while switching and persisted with
/// the default-constructed QSettings in group "brushes/<id>" (keys radius, radiusPixels, strength,
/// falloff, area, and parameters/<parameter id>); the radius unit, shared by all brushes, in
/// key "brushes/radiusUnit" (BrushValueStore::loadRadiusUnit: View for a new user); the stroke
/// options live in group "brushPanel". GUI thread.
class BrushPanel : public QWidget {
  Q_OBJECT

public:
  explicit BrushPanel(QWidget* parent = nullptr);
  ~BrushPanel() override;

  /// Replaces the brush list (grouped by category Sculpt/Paint/Splat in the given order, shown
  /// by name, id as item data) and the load errors (each shown in full in a red list that is
  /// hidden only when there are none). Each brush's values come from what this panel
  /// remembers, else from QSettings, else from the manifest, and are then fitted to the
  /// manifest (unknown parameters dropped, values clamped to their ranges). Keeps the current
  /// brush selected if it still exists, else selects "push" if present, else the first listed.
  /// Rebuilds the form and emits settingsChanged.
  void setBrushes(std::vector<gpu::BrushManifest> brushes, std::vector<std::string> errors);
  /// The installed materials' ids, in the engine's order: a material parameter's value is an
  /// index into them.
  void setMaterials(QStringList ids);

  /// The current brush and all its values, plus the stroke options. brushId is empty when no
  /// brush is loaded.
  BrushSettings settings() const;
  /// Id of the current brush; empty when none.
  QString currentBrushId() const;
  /// The manifest of the current brush, or nullptr.
  const gpu::BrushManifest* currentBrush() const;
  /// Makes the brush with this id current (rebuilding the form, emitting settingsChanged when
  /// it was not already current). Returns false, changing nothing, when no brush has this id.
  bool selectBrush(const QString& id);
  /// Ids of the listed brushes in display order (category, then the order given).
  QStringList brushIds() const;
  /// The error strings shown, in order (the same as given to setBrushes).
  QStringList errors() const;

  /// Radius of the current brush as a fraction of the model's bounding-box diagonal; clamped
  /// to [0.001, 1]. Updates the widget and emits settingsChanged when the value changes.
  void setRadius(float fractionOfDiagonal);
  /// Strength of the current brush, clamped to [0, 1]; emits settingsChanged when it changes.
  void setStrength(float s);
  float radius() const;
  float strength() const;

  /// What the radius is measured in, for every brush: pixels of the view (View) or a fraction
  /// of the diagonal (Scene). Persisted; emits settingsChanged when it changes.
  void setRadiusUnit(RadiusUnit unit);
  RadiusUnit radiusUnit() const { return radiusUnit_; }
  /// The current brush's view radius in logical pixels, clamped to [1, 1000]; emits
  /// settingsChanged when it changes.
  void setRadiusPixels(float pixels);
  float radiusPixels() const { return currentValues().radiusPixels; }
  /// The radius in the current unit: pixels (View) or a fraction of the diagonal (Scene), what
  /// the header, F and [ / ] change.
  void setRadiusInUnit(float value);
  float radiusInUnit() const;

  /// Stroke options shared by all brushes; each emits settingsChanged when the value changes.
  void setPressureTarget(PressureTarget target);
  /// Lazy-mouse strength, clamped to [0, 1] and kept in whole percent like the slider.
  void setStabilizer(float amount);
  /// gpu::SymmetryAxis bits (X = 1, Y = 2, Z = 4); other bits are ignored.
  void setSymmetry(unsigned axes);
  /// Whether sculpt strokes relax what they stretched.
  void setKeepDetail(bool on);

  /// The widget editing parameter `id` of the current brush (for tests), or nullptr. Float →
  /// QDoubleSpinBox, Int → QSpinBox, Bool → QCheckBox, Color → ColorButton, Enum → QComboBox.
  QWidget* parameterWidget(const QString& id) const;

signals:
  /// Anything in settings() may have changed.
  void settingsChanged();

private:
  const gpu::BrushManifest* findBrush(const QString& id) const;
  BrushValues& currentValues();
  const BrushValues& currentValues() const;

  void onCurrentItemChanged(QTreeWidgetItem* item);
  void makeCurrent(const QString& id);
  void rebuildForm();
  // Stores a value the user (or a setter) changed, persists it and emits settingsChanged.
  void valuesEdited();

  std::vector<gpu::BrushManifest> brushes_;
  std::vector<std::string> errors_;
  BrushValueStore store_;
  QString currentId_;
  BrushValues noBrush_; // what radius() and friends use while no brush is loaded

  QTreeWidget* brushList_ = nullptr;
  QFrame* errorFrame_ = nullptr;
  QVBoxLayout* errorLayout_ = nullptr;
  QScrollArea* formScroll_ = nullptr;
  QLabel* descriptionLabel_ = nullptr;
  RadiusUnit radiusUnit_ = RadiusUnit::View;
  QPointer<RadiusField> radiusField_;
  QPointer<QDoubleSpinBox> strengthSpin_;
  std::map<QString, QPointer<QWidget>> parameterWidgets_;
  StrokeOptionsBox* strokeOptions_ = nullptr;
};

} // namespace octaclay::app
