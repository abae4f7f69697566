#pragma once

#include <QGroupBox>

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace octaclay::app {

class BrushState;

/// The stroke options shared by every brush, a view of BrushState: what pen pressure scales, the
/// stabilizer (lazy mouse), the symmetry planes and keep detail. Its widgets write into the state
/// and follow it. GUI thread.
class StrokeOptionsBox : public QGroupBox {
  Q_OBJECT
public:
  explicit StrokeOptionsBox(BrushState& state, QWidget* parent = nullptr);

private:
  void showValues();

  BrushState& state_;
  QComboBox* pressureCombo_ = nullptr;
  QSlider* stabilizerSlider_ = nullptr;
  QLabel* stabilizerLabel_ = nullptr;
  std::array<QCheckBox*, 3> symmetryBoxes_{};
  QCheckBox* keepDetailBox_ = nullptr;
};

} // namespace octaclay::app
