#pragma once

#include "brush_settings.h"

#include <QGroupBox>

#include <array>

class QCheckBox;
class QComboBox;
class QLabel;
class QSlider;

namespace octaclay::app {

/// The stroke options shared by every brush: what pen pressure scales, the stabilizer (lazy
/// mouse), the symmetry planes and keep detail. The box owns the values (widgets only show
/// them), loads them from the default-constructed QSettings group "brushPanel" (keys
/// pressureTarget, stabilizer, symmetry, keepDetail) and saves each change there. GUI thread.
class StrokeOptionsBox : public QGroupBox {
  Q_OBJECT
public:
  explicit StrokeOptionsBox(QWidget* parent = nullptr);

  PressureTarget pressureTarget() const { return pressureTarget_; }
  /// Lazy-mouse strength in [0, 1], in whole percent like the slider.
  float stabilizer() const { return static_cast<float>(stabilizerPercent_) / 100.0f; }
  /// gpu::SymmetryAxis bits.
  unsigned symmetry() const { return symmetry_; }
  /// Whether sculpt strokes relax what they stretched (on by default).
  bool keepDetail() const { return keepDetail_; }

  /// Each setter emits changed when the value changes.
  void setPressureTarget(PressureTarget target);
  /// Clamped to [0, 1] and rounded to whole percent.
  void setStabilizer(float amount);
  /// Bits other than X, Y and Z are ignored.
  void setSymmetry(unsigned axes);
  void setKeepDetail(bool on);

signals:
  void changed();

private:
  void load();
  void save() const;

  PressureTarget pressureTarget_ = PressureTarget::Strength;
  int stabilizerPercent_ = 0;
  unsigned symmetry_ = 0;
  bool keepDetail_ = true;

  QComboBox* pressureCombo_ = nullptr;
  QSlider* stabilizerSlider_ = nullptr;
  QLabel* stabilizerLabel_ = nullptr;
  std::array<QCheckBox*, 3> symmetryBoxes_{};
  QCheckBox* keepDetailBox_ = nullptr;
};

} // namespace octaclay::app
