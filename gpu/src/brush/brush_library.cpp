#include "octaclay/gpu/brush_library.h"

#include "octaclay/gpu/gl_error.h"

#include <algorithm>
#include <map>

namespace octaclay::gpu {

BrushLibrary::BrushLibrary(const std::vector<std::filesystem::path>& searchPath) {
  catalog_.scan(searchPath);
  for (const BrushCatalogError& e : catalog_.errors())
    errors_.push_back(e.message);
  for (const BrushManifest& brush : catalog_.brushes()) {
    std::string error;
    if (compile(brush, error))
      usable_.insert(brush.id);
    else
      errors_.push_back(error);
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
    if (usable_.count(brush.id) > 0) usable.push_back(&brush);
  return usable;
}

BrushLibrary::ReloadReport BrushLibrary::reloadChanged() {
  if (catalog_.brushFoldersChanged()) return rescan();
  ReloadReport report;
  for (const std::string& id : catalog_.changedBrushes()) {
    const std::filesystem::path folder = catalog_.find(id)->folder;
    if (!catalog_.reload(id)) {
      for (const BrushCatalogError& e : catalog_.errors())
        if (e.path.parent_path() == folder || e.path == folder) report.failed.push_back(e.message);
      continue;
    }
    std::string error;
    if (compile(*catalog_.find(id), error)) {
      report.reloaded.push_back(id);
      usable_.insert(id);
    } else {
      report.failed.push_back(error);
    }
  }
  return report;
}

BrushLibrary::ReloadReport BrushLibrary::rescan() {
  ReloadReport report;
  // What the catalog held before, so only new or changed brushes are compiled again (a
  // compile per brush would stall the GUI for every plugin dropped in).
  const std::vector<std::string> edited = catalog_.changedBrushes();
  std::map<std::string, std::filesystem::path, std::less<>> before;
  for (const BrushManifest& brush : catalog_.brushes())
    before.emplace(brush.id, brush.folder);
  std::vector<std::string> knownErrors;
  for (const BrushCatalogError& e : catalog_.errors())
    knownErrors.push_back(e.message);

  catalog_.rescan();

  // errors() is rebuilt from this scan; a brush that failed before and is unchanged is tried
  // again (it may have been missing a file) but not reported again.
  std::vector<std::string> errors;
  for (const BrushCatalogError& e : catalog_.errors()) {
    errors.push_back(e.message);
    if (std::find(knownErrors.begin(), knownErrors.end(), e.message) == knownErrors.end())
      report.failed.push_back(e.message);
  }
  for (const auto& [id, folder] : before)
    if (catalog_.find(id) == nullptr) {
      report.removed.push_back(id);
      usable_.erase(id);
    }

  for (const BrushManifest& brush : catalog_.brushes()) {
    const auto old = before.find(brush.id);
    const bool isNew = old == before.end();
    const bool changed =
        !isNew && (old->second != brush.folder ||
                   std::find(edited.begin(), edited.end(), brush.id) != edited.end());
    if (!isNew && !changed && usable_.count(brush.id) > 0) continue;
    std::string error;
    if (compile(brush, error)) {
      usable_.insert(brush.id);
      if (isNew)
        report.added.push_back(brush.id);
      else
        report.reloaded.push_back(brush.id);
    } else {
      errors.push_back(error);
      if (isNew || changed) report.failed.push_back(error);
      // A new brush must not run a stale program left by a removed brush of the same id.
      if (isNew) usable_.erase(brush.id);
    }
  }
  errors_ = std::move(errors);
  return report;
}

} // namespace octaclay::gpu
