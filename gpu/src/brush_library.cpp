#include "octaclay/gpu/brush_library.h"

#include "octaclay/gpu/gl_error.h"

namespace octaclay::gpu {

BrushLibrary::BrushLibrary(const std::vector<std::filesystem::path>& searchPath) {
  catalog_.scan(searchPath);
  for (const BrushCatalogError& e : catalog_.errors())
    errors_.push_back(e.message);
  for (const BrushManifest& brush : catalog_.brushes()) {
    std::string error;
    if (!compile(brush, error)) errors_.push_back(error);
  }
}

bool BrushLibrary::compile(const BrushManifest& brush, std::string& error) {
  try {
    engine_.load(brush, BrushCatalog::shaderSource(brush));
    return true;
  } catch (const std::exception& e) { // GlError (compile) or BrushLoadError (unreadable shader)
    error = e.what();
    return false;
  }
}

std::vector<const BrushManifest*> BrushLibrary::brushes() const {
  std::vector<const BrushManifest*> usable;
  for (const BrushManifest& brush : catalog_.brushes())
    if (engine_.has(brush.id)) usable.push_back(&brush);
  return usable;
}

BrushLibrary::ReloadReport BrushLibrary::reloadChanged() {
  ReloadReport report;
  for (const std::string& id : catalog_.changedBrushes()) {
    const std::filesystem::path folder = catalog_.find(id)->folder;
    if (!catalog_.reload(id)) {
      for (const BrushCatalogError& e : catalog_.errors())
        if (e.path.parent_path() == folder || e.path == folder) report.failed.push_back(e.message);
      continue;
    }
    std::string error;
    if (compile(*catalog_.find(id), error))
      report.reloaded.push_back(id);
    else
      report.failed.push_back(error);
  }
  return report;
}

} // namespace octaclay::gpu
