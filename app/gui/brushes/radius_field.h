#pragma once

#include "brush_settings.h"

#include <QString>
#include <QWidget>

class QComboBox;
class QDoubleSpinBox;

namespace octaclay::app {

/// A radius as the Brushes dock, the header and F show it: "40 px" (RadiusUnit::View) or
/// "5.0 %" of the diagonal (Scene; value a fraction).
QString radiusText(RadiusUnit unit, float value);

/// The Brushes dock's Radius row: a spin box with the radius in its unit (pixels, or percent of
/// the model's bounding-box diagonal) and beside it the unit (object names "radius" and
/// "radiusUnit"). It shows values and reports the user's edits; the panel owns them. GUI thread.
class RadiusField : public QWidget {
  Q_OBJECT
public:
  explicit RadiusField(QWidget* parent = nullptr);

  /// Shows value (pixels, or a fraction of the diagonal) in unit, emitting nothing.
  void setValue(RadiusUnit unit, float value);
  QDoubleSpinBox* spinBox() const { return spin_; }

signals:
  /// The user typed or stepped a radius: pixels, or a fraction of the diagonal.
  void valueEdited(float value);
  void unitChosen(octaclay::app::RadiusUnit unit);

private:
  RadiusUnit unit_ = RadiusUnit::Scene;
  QDoubleSpinBox* spin_ = nullptr;
  QComboBox* unitCombo_ = nullptr;
};

} // namespace octaclay::app
