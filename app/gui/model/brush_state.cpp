#include "brush_state.h"

namespace octaclay::app {

void BrushState::setSettings(const BrushSettings& settings) {
  if (settings == settings_) return;
  settings_ = settings;
  emit changed();
}

void BrushState::setPaintTarget(core::EditLayer layer) {
  if (layer == paintTarget_) return;
  paintTarget_ = layer;
  emit changed();
}

} // namespace octaclay::app
