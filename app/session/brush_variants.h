#pragma once

#include "brush_settings.h"

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"

#include <map>
#include <string>
#include <vector>

namespace octaclay::app {

/// The brushes as the user set them: a manifest with the area and falloff the settings chose
/// and the paint target the Layers dock chose, compiled into the engine when that differs from
/// what it holds. Call on the thread whose GL context is current.
class BrushVariants {
public:
  /// The manifest of brush id as settings and paintTarget ask for it (the settings' area and
  /// falloff apply only when id is settings.brushId), compiled if the engine holds another
  /// variant. Throws core::Error(InvalidArgument) if the brush is not in catalog or not
  /// compiled in engine, or what BrushEngine::load throws.
  gpu::BrushManifest prepare(gpu::BrushEngine& engine, const gpu::BrushCatalog& catalog,
                             const std::string& id, const BrushSettings& settings,
                             core::EditLayer paintTarget);
  /// The brushes were recompiled from their files: their compiled variant is the manifest's.
  void forget(const std::vector<std::string>& ids);

private:
  std::map<std::string, std::string> loaded_; // brush id → the variant key compiled
};

} // namespace octaclay::app
