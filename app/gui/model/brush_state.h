#pragma once

#include "brush_settings.h"

#include "octaclay/core/document/edit_layer.h"

#include <QObject>

namespace octaclay::app {

/// The brush as the user set it: the settings the next stroke begins with and where colour paint
/// goes. The Brushes dock, the tool bar, the header and the canvas's F-adjust edit it; the
/// viewport (its ring) and the modeller's strokes read it.
class BrushState : public QObject {
  Q_OBJECT
public:
  explicit BrushState(QObject* parent = nullptr) : QObject(parent) {}

  const BrushSettings& settings() const { return settings_; }
  /// Emits changed() when anything differs.
  void setSettings(const BrushSettings& settings);
  /// The layer paint-category brushes write (diffuse, feature or mask).
  core::EditLayer paintTarget() const { return paintTarget_; }
  void setPaintTarget(core::EditLayer layer);

signals:
  void changed();

private:
  BrushSettings settings_;
  core::EditLayer paintTarget_ = core::EditLayer::Diffuse;
};

} // namespace octaclay::app
