#pragma once

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

class BrushState;
class RadiusField;

/// The Brushes dock panel, a view of BrushState: the brush list grouped by category, the brushes
/// that failed to load, and a form for the current brush (radius, strength, falloff, area mode,
/// then one widget per manifest parameter) above the stroke options shared by all brushes
/// (pressure, stabilizer, symmetry, keep detail). Its widgets write into the state and follow
/// it; the state keeps and persists the values. GUI thread.
class BrushPanel : public QWidget {
  Q_OBJECT

public:
  explicit BrushPanel(BrushState& state, QWidget* parent = nullptr);
  ~BrushPanel() override;

  /// The widget editing parameter `id` of the current brush (for tests), or nullptr. Float →
  /// QDoubleSpinBox, Int → QSpinBox, Bool → QCheckBox, Color → ColorButton, Enum → QComboBox.
  QWidget* parameterWidget(const QString& id) const;

private:
  void showBrushes();
  void showCurrentBrush();
  void showValues();
  void rebuildForm();

  BrushState& state_;
  QTreeWidget* brushList_ = nullptr;
  QFrame* errorFrame_ = nullptr;
  QVBoxLayout* errorLayout_ = nullptr;
  QScrollArea* formScroll_ = nullptr;
  QPointer<RadiusField> radiusField_;
  QPointer<QDoubleSpinBox> strengthSpin_;
  QPointer<QComboBox> falloffCombo_, areaCombo_;
  std::map<QString, QPointer<QWidget>> parameterWidgets_;
};

} // namespace octaclay::app
