#pragma once

#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"

#include <filesystem>
#include <set>
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
  /// Brushes that parsed and compiled, by id order. A removed brush's program may stay in
  /// engine() (it cannot unload one), but it is no longer listed here.
  std::vector<const BrushManifest*> brushes() const;
  /// Every manifest and compile error, each naming its file.
  const std::vector<std::string>& errors() const { return errors_; }

  struct ReloadReport {
    std::vector<std::string> reloaded; ///< recompiled and now in use
    std::vector<std::string> failed;   ///< messages; the previous version stays in use
    std::vector<std::string> added;    ///< ids of brushes new to the search path, now usable
    std::vector<std::string> removed;  ///< ids of brushes no longer found, no longer listed
  };
  /// Polls the brush files (cheap: a listing of each search folder and a few stats per brush)
  /// and reloads what changed. When brush folders appeared or vanished it rescans the search
  /// path: new brushes are compiled (a broken one lands in failed and errors(), the others
  /// stay), changed ones recompiled, unchanged ones keep their programs, and gone ones are
  /// dropped from brushes(). Otherwise it recompiles only the brushes whose files changed,
  /// keeping the previous program of one that fails. Call from a timer on the GL thread.
  ReloadReport reloadChanged();

private:
  bool compile(const BrushManifest& brush, std::string& error);
  ReloadReport rescan();

  BrushCatalog catalog_;
  BrushEngine engine_;
  std::vector<std::string> errors_;
  /// Ids whose program in engine_ belongs to a brush in the catalog: a removed brush's stale
  /// program must not make a broken re-added brush of the same id look usable.
  std::set<std::string, std::less<>> usable_;
};

} // namespace octaclay::gpu
