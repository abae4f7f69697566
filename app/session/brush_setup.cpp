#include "brush_setup.h"

#include "data_folders.h"

#include <cstdlib>

namespace octaclay::app {

std::filesystem::path builtInBrushFolder() {
  if (const char* folder = std::getenv("OCTACLAY_BUILTIN_BRUSHES")) return folder;
  return builtInBrushes();
}

gpu::BrushCatalog scanBrushes() {
  gpu::BrushCatalog catalog;
  catalog.scan(gpu::BrushCatalog::defaultSearchPath(builtInBrushFolder()));
  return catalog;
}

std::filesystem::path builtInMaterialFolder() {
  if (const char* folder = std::getenv("OCTACLAY_BUILTIN_MATERIALS")) return folder;
  return resourceFolder() / "materials";
}

gpu::MaterialCatalog scanMaterials() {
  gpu::MaterialCatalog catalog;
  catalog.scan(gpu::MaterialCatalog::defaultSearchPath(builtInMaterialFolder()));
  return catalog;
}

} // namespace octaclay::app
