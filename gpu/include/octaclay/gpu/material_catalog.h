#pragma once

#include "octaclay/core/document/image_io.h"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace octaclay::gpu {

/// A surface material the splat brush projects (resources/materials/<id>/): four maps of the
/// same size and how large one tile of them is on the model.
struct Material {
  std::string id;              ///< [a-z0-9-]+, the folder's manifest id
  std::string name;            ///< shown in the UI
  std::string source, license; ///< where the maps come from and under which terms
  /// Object-space edge of one tile of the maps, as a fraction of the model's bounding-box
  /// diagonal (the brush radius uses the same unit), > 0.
  float tileSize = 0.05f;
  /// How far height 1 displaces the surface, as a fraction of tileSize, ≥ 0.
  float heightScale = 0.1f;
  core::RasterImage height;       ///< 1 channel, 0.5 = no displacement
  core::RasterImage colour;       ///< 4 channels (RGBA, alpha = coverage)
  core::RasterImage specular;     ///< 1 channel
  core::RasterImage reflectivity; ///< 1 channel
  std::filesystem::path folder;
};

/// A material folder that cannot be used; what() starts with the file at fault.
class MaterialLoadError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Reads folder/material.json and its maps. Throws MaterialLoadError naming the file and field.
Material loadMaterial(const std::filesystem::path& folder);

/// The materials found in a search path of folders, each material a sub-folder holding
/// material.json. A broken material is recorded in errors() and skipped; the others load.
class MaterialCatalog {
public:
  /// builtInFolder (resources/materials), then each folder of $OCTACLAY_MATERIAL_PATH
  /// (':'-separated), then $XDG_DATA_HOME/octaclay/materials (or ~/.local/share/…).
  static std::vector<std::filesystem::path>
  defaultSearchPath(const std::filesystem::path& builtInFolder);

  /// Forgets what was loaded and loads every sub-folder with a material.json, in order; a later
  /// id replaces an earlier one.
  void scan(const std::vector<std::filesystem::path>& folders);
  const std::vector<Material>& materials() const { return materials_; }
  const Material* find(std::string_view id) const;
  /// One message per broken material folder, each starting with the file at fault.
  const std::vector<std::string>& errors() const { return errors_; }

private:
  std::vector<Material> materials_;
  std::vector<std::string> errors_;
};

} // namespace octaclay::gpu
