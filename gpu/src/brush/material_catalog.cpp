// Reads and validates material folders (material.json and four maps). Messages follow the brush
// manifests' style, "<file>: <field>: <reason>", so a material author can fix a folder without
// guessing; a broken folder is skipped by the catalog and the others still load.
//
// material.json: "id" (required, [a-z0-9-]+), "name" (required, not empty), "source" and
// "license" (optional strings), "tileSize" (optional, (0, 10]), "heightScale" (optional,
// [0, 10]), "maps" (required: "height", "colour", "specular" and "reflectivity", each a file name
// beside the manifest). Fields starting with "x-" are the author's own and ignored.

#include "octaclay/gpu/material_catalog.h"

#include "manifest_json.h"

#include "octaclay/core/error.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace octaclay::gpu {

namespace {

namespace fs = std::filesystem;
using detail::describe;
using detail::formatNumber;
using detail::isValidId;
using detail::json;
using detail::quote;

constexpr const char* kManifestName = "material.json";

constexpr std::array kTopLevelFields{"id",       "name",        "source", "license",
                                     "tileSize", "heightScale", "maps"};
constexpr std::array kMapFields{"height", "colour", "specular", "reflectivity"};

// Map sides: 16 texels keep a tile recognisable, 2048 keeps four float maps per material (64 MiB
// at 2048²) within what the modeller can hold for a handful of materials.
constexpr int kMinMapSide = 16, kMaxMapSide = 2048;
// A tile larger than ten model diagonals, or a relief ten tiles deep, is a typo, not a material.
constexpr double kMaxTileSize = 10.0, kMaxHeightScale = 10.0;

bool isPowerOfTwo(int n) {
  return n > 0 && (n & (n - 1)) == 0;
}

class MaterialParser : detail::ManifestReader {
public:
  explicit MaterialParser(const fs::path& folder)
      : ManifestReader(folder / kManifestName, "material manifest"), folder_(folder) {}

  Material parse() const {
    const json root = readJson();
    if (!root.is_object()) failFile("expected a JSON object { ... }, got " + describe(root));
    rejectUnknownFields(root, "", kTopLevelFields);

    Material material;
    material.folder = folder_;
    material.id = requiredString(root, "id", "id");
    if (!isValidId(material.id, false))
      fail("id", quote(material.id) +
                     " is not a valid material id (use lowercase letters, digits and -)");
    material.name = requiredString(root, "name", "name");
    if (material.name.empty()) fail("name", "must not be empty");
    material.source = optionalString(root, "source", "source").value_or("");
    material.license = optionalString(root, "license", "license").value_or("");

    if (root.contains("tileSize")) {
      const double tileSize = number(root["tileSize"], "tileSize");
      if (!(tileSize > 0.0 && tileSize <= kMaxTileSize))
        fail("tileSize", formatNumber(tileSize) + " is outside (0, " + formatNumber(kMaxTileSize) +
                             "] (a fraction of the model's bounding-box diagonal)");
      material.tileSize = static_cast<float>(tileSize);
    }
    if (root.contains("heightScale")) {
      const double heightScale = number(root["heightScale"], "heightScale");
      if (!(heightScale >= 0.0 && heightScale <= kMaxHeightScale))
        fail("heightScale", formatNumber(heightScale) + " is outside [0, " +
                                formatNumber(kMaxHeightScale) + "] (a fraction of tileSize)");
      material.heightScale = static_cast<float>(heightScale);
    }

    const json& maps = required(root, "maps", "maps");
    if (!maps.is_object())
      fail("maps", "expected an object of map files, got " + describe(maps) +
                       " (use {\"height\": \"height.png\", ...})");
    rejectUnknownFields(maps, "maps.", kMapFields);
    // The channel counts are what the brush samples: a grey height, specular and reflectivity,
    // an RGBA colour whose alpha is coverage.
    material.height = readMap(maps, "height", 1);
    material.colour = readMap(maps, "colour", 4);
    material.specular = readMap(maps, "specular", 1);
    material.reflectivity = readMap(maps, "reflectivity", 1);

    checkSize(material.height, "maps.height");
    for (const auto& [image, field] : {std::pair{&material.colour, "maps.colour"},
                                       std::pair{&material.specular, "maps.specular"},
                                       std::pair{&material.reflectivity, "maps.reflectivity"}})
      if (image->width != material.height.width || image->height != material.height.height)
        fail(field, std::to_string(image->width) + "x" + std::to_string(image->height) +
                        " differs from maps.height's " + std::to_string(material.height.width) +
                        "x" + std::to_string(material.height.height) +
                        " (all four maps must have the same size)");
    return material;
  }

private:
  core::RasterImage readMap(const json& maps, const char* key, int channels) const {
    const std::string field = std::string("maps.") + key;
    const std::string name = requiredString(maps, key, field);
    // A file name, not a path: a material folder is self-contained and can be copied as a whole.
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/\\") != std::string::npos)
      fail(field, quote(name) + " must be a file name beside the manifest");
    const fs::path mapFile = folder_ / name;
    std::error_code ec;
    if (!fs::is_regular_file(mapFile, ec)) fail(field, name + " not found in " + folder_.string());
    try {
      return core::readImage(mapFile, channels);
    } catch (const core::Error& e) {
      fail(field, e.what()); // core's message starts with the map's path
    }
  }

  void checkSize(const core::RasterImage& image, const std::string& field) const {
    const auto side = [&](int n) {
      return isPowerOfTwo(n) && n >= kMinMapSide && n <= kMaxMapSide;
    };
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    // One tileSize is the edge of the tile, so a tile is square.
    if (image.width != image.height) fail(field, size + " is not square");
    if (!side(image.width))
      fail(field, size + " is not a power of two from " + std::to_string(kMinMapSide) + " to " +
                      std::to_string(kMaxMapSide));
  }

  fs::path folder_;
};

} // namespace

Material loadMaterial(const fs::path& folder) {
  try {
    return MaterialParser(folder).parse();
  } catch (const detail::ManifestError& e) {
    throw MaterialLoadError(e.what());
  }
}

std::vector<fs::path> MaterialCatalog::defaultSearchPath(const fs::path& builtInFolder) {
  return detail::pluginSearchPath(builtInFolder, "OCTACLAY_MATERIAL_PATH", "materials");
}

void MaterialCatalog::scan(const std::vector<fs::path>& folders) {
  // Built up aside: folders may name paths held by the materials being replaced.
  std::vector<Material> materials;
  std::vector<std::string> errors;
  for (const fs::path& folder : folders) {
    std::error_code ec;
    if (!fs::exists(folder, ec)) continue; // usually the user folder nobody created: no materials
    std::vector<fs::path> candidates;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
      if (detail::holdsManifest(*it, kManifestName)) candidates.push_back(it->path());
    }
    if (ec) {
      errors.push_back(folder.string() + ": cannot list the material folder (" + ec.message() +
                       ")");
      continue;
    }
    // Directory order differs between file systems; sorted, the same ids win everywhere.
    std::sort(candidates.begin(), candidates.end());
    for (const fs::path& candidate : candidates) {
      try {
        Material material = loadMaterial(candidate);
        const auto same = std::find_if(materials.begin(), materials.end(),
                                       [&](const Material& m) { return m.id == material.id; });
        if (same != materials.end())
          *same = std::move(material);
        else
          materials.push_back(std::move(material));
      } catch (const MaterialLoadError& e) {
        errors.push_back(e.what());
      }
    }
  }
  std::sort(materials.begin(), materials.end(),
            [](const Material& a, const Material& b) { return a.id < b.id; });
  materials_ = std::move(materials);
  errors_ = std::move(errors);
}

const Material* MaterialCatalog::find(std::string_view id) const {
  const auto it =
      std::lower_bound(materials_.begin(), materials_.end(), id,
                       [](const Material& m, std::string_view key) { return m.id < key; });
  return it != materials_.end() && it->id == id ? &*it : nullptr;
}

} // namespace octaclay::gpu
