#include "brush_variants.h"

#include "octaclay/core/error.h"

namespace octaclay::app {
namespace {

std::string variantKey(const gpu::BrushManifest& m) {
  std::string key{gpu::toManifestName(m.area)};
  key += '|';
  key += gpu::toManifestName(m.falloff);
  for (core::EditLayer l : m.writes) {
    key += '|';
    key += gpu::toManifestName(l);
  }
  return key;
}

} // namespace

gpu::BrushManifest BrushVariants::prepare(gpu::BrushEngine& engine,
                                          const gpu::BrushCatalog& catalog, const std::string& id,
                                          const BrushSettings& settings,
                                          core::EditLayer paintTarget) {
  const gpu::BrushManifest* base = catalog.find(id);
  if (!base || !engine.has(id))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      "The brush \"" + id + "\" is not loaded (see the Brushes panel for errors)");
  gpu::BrushManifest variant = *base;
  if (id == settings.brushId) {
    variant.area = settings.area;
    variant.falloff = settings.falloff;
    if (variant.falloff == gpu::Falloff::Curve && variant.falloffCurve.empty())
      variant.falloff = gpu::Falloff::Smooth;
  }
  // The Layers dock's paint target redirects colour paint (a brush writing only diffuse);
  // brushes made for another layer (mask, specular, reflectivity) keep theirs.
  if (variant.category == gpu::Category::Paint &&
      variant.writes == std::vector<core::EditLayer>{core::EditLayer::Diffuse})
    variant.writes = {paintTarget};
  const std::string key = variantKey(variant);
  auto found = loaded_.find(id);
  if (found == loaded_.end() ? key != variantKey(*base) : found->second != key) {
    engine.load(variant, gpu::BrushCatalog::shaderSource(*base));
    loaded_[id] = key;
  }
  return variant;
}

void BrushVariants::forget(const std::vector<std::string>& ids) {
  for (const std::string& id : ids)
    loaded_.erase(id);
}

} // namespace octaclay::app
