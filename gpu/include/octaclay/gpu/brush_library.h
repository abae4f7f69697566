#pragma once

#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"

#include <filesystem>
#include <string>
#include <vector>

namespace octaclay::gpu {

/// The brushes a session can use: the catalog of brush folders and their compiled programs.
/// Construct, use and reload on the thread whose GL context is current; a brush whose manifest
/// or GLSL is broken is reported in errors() and skipped, and the others load.
class BrushLibrary {
public:
  explicit BrushLibrary(const std::vector<std::filesystem::path>& searchPath);

  BrushEngine& engine() { return engine_; }
  const BrushCatalog& catalog() const { return catalog_; }
  /// Brushes that parsed and compiled, by id order.
  std::vector<const BrushManifest*> brushes() const;
  /// Every manifest and compile error, each naming its file.
  const std::vector<std::string>& errors() const { return errors_; }

  struct ReloadReport {
    std::vector<std::string> reloaded; ///< recompiled and now in use
    std::vector<std::string> failed;   ///< messages; the previous version stays in use
  };
  /// Polls the brush files (cheap: a few stats) and reloads what changed. Call from a timer.
  ReloadReport reloadChanged();

private:
  bool compile(const BrushManifest& brush, std::string& error);

  BrushCatalog catalog_;
  BrushEngine engine_;
  std::vector<std::string> errors_;
};

} // namespace octaclay::gpu
