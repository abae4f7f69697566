#pragma once

#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/model_renderer.h"

#include <QString>
#include <QWidget>

#include <array>

class QButtonGroup;
class QCheckBox;
class QComboBox;
class QLabel;
class QRadioButton;

namespace octaclay::app {

/// The Layers dock panel: one row per document layer (Positions, Diffuse, Feature, Mask) with
/// a visibility check box (Diffuse: colour shown; Feature: height/specular shading shown; Mask:
/// tint shown; Positions: always shown, its box disabled), the paint target (which of Diffuse,
/// Feature, Mask the paint-category brushes write; Diffuse by default) and whether the layer
/// is painted or still uniform. Visibility and target persist with the default-constructed
/// QSettings in group "layers" (keys visible/<layer>, paintTarget; layer names as in
/// manifests). GUI thread.
class LayersPanel : public QWidget {
  Q_OBJECT

public:
  explicit LayersPanel(QWidget* parent = nullptr);

  // The layer overloads below would otherwise hide QWidget's own isVisible() and setVisible().
  using QWidget::isVisible;
  using QWidget::setVisible;

  /// Whether the layer is shown; Positions always is.
  bool isVisible(core::EditLayer layer) const;
  /// Shows or hides the layer; emits visibilityChanged when that changes. Positions cannot be
  /// hidden (ignored).
  void setVisible(core::EditLayer layer, bool visible);

  /// The layer paint-category brushes write: Diffuse, Feature or Mask.
  core::EditLayer paintTarget() const;
  /// Makes layer the paint target; emits paintTargetChanged when it changes. Positions is not a
  /// paint target (ignored).
  void setPaintTarget(core::EditLayer layer);

  /// Says whether the layer holds painted data or is still uniform (its fill value).
  void setLayerState(core::EditLayer layer, bool painted);
  /// What setLayerState last said (false, "uniform", until then).
  bool isPainted(core::EditLayer layer) const;
  /// The state line shown for the layer, e.g. "uniform" (for tests).
  QString layerStateText(core::EditLayer layer) const;

  using Preview = gpu::ModelView::Preview;
  /// The shaded model, one layer channel alone, or the saliency or stretch as a heat map.
  Preview preview() const;
  void setPreview(Preview preview);
  /// The preview list's row, in Preview's order (0 the shaded model … 6 saliency, 7 stretch).
  void setPreview(int row);

signals:
  void previewChanged(octaclay::gpu::ModelView::Preview preview);
  void visibilityChanged();
  void paintTargetChanged();

private:
  QComboBox* preview_ = nullptr;
  static constexpr std::size_t kLayerCount = 4;

  void save() const;

  std::array<bool, kLayerCount> visible_{true, true, true, true};
  std::array<bool, kLayerCount> painted_{};
  core::EditLayer paintTarget_ = core::EditLayer::Diffuse;

  std::array<QCheckBox*, kLayerCount> visibleBoxes_{};
  std::array<QRadioButton*, kLayerCount> targetButtons_{}; // none for Positions
  std::array<QLabel*, kLayerCount> stateLabels_{};
  QButtonGroup* targetGroup_ = nullptr;
};

} // namespace octaclay::app
