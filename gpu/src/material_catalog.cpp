// Reads and validates material folders (material.json and four maps). Messages follow the brush
// manifests' style, "<file>: <field>: <reason>", so a material author can fix a folder without
// guessing; a broken folder is skipped by the catalog and the others still load.
//
// material.json: "id" (required, [a-z0-9-]+), "name" (required, not empty), "source" and
// "license" (optional strings), "tileSize" (optional, (0, 10]), "heightScale" (optional,
// [0, 10]), "maps" (required: "height", "colour", "specular" and "reflectivity", each a file name
// beside the manifest). Fields starting with "x-" are the author's own and ignored.

#include "octaclay/gpu/material_catalog.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <sstream>

namespace octaclay::gpu {

namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

constexpr const char* kManifestName = "material.json";

constexpr std::array kTopLevelFields{"id",       "name",        "source", "license",
                                     "tileSize", "heightScale", "maps"};
constexpr std::array kMapFields{"height", "colour", "specular", "reflectivity"};

// Map sides: 16 texels keep a tile recognisable, 2048 keeps four float maps per material (64 MiB
// at 2048²) within what the modeller can hold for a handful of materials.
constexpr int kMinMapSide = 16, kMaxMapSide = 2048;
// A tile larger than ten model diagonals, or a relief ten tiles deep, is a typo, not a material.
constexpr double kMaxTileSize = 10.0, kMaxHeightScale = 10.0;

std::string quote(std::string_view s) {
  return json(std::string(s)).dump();
}

std::string formatNumber(double value) {
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string shortDump(const json& value) {
  std::string text = value.dump();
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return text;
}

// What a wrong value was, for "expected …, got …".
std::string describe(const json& value) {
  if (value.is_object()) return "an object";
  if (value.is_array()) return "an array";
  return shortDump(value);
}

std::size_t editDistance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

bool isValidId(std::string_view id) {
  if (id.empty()) return false;
  return std::all_of(id.begin(), id.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
}

bool isPowerOfTwo(int n) {
  return n > 0 && (n & (n - 1)) == 0;
}

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? std::string(value) : std::string();
}

// Tracks the JSON path while nlohmann parses, to name a key that appears twice in one object
// (nlohmann silently keeps the last one, which would hide a copy-paste mistake).
class DuplicateKeyCheck {
public:
  explicit DuplicateKeyCheck(const fs::path& file) : file_(file) {}

  bool operator()(int /*depth*/, json::parse_event_t event, json& parsed) {
    switch (event) {
    case json::parse_event_t::object_start:
      stack_.push_back({true, {}, {}, 0});
      break;
    case json::parse_event_t::array_start:
      stack_.push_back({false, {}, {}, 0});
      break;
    case json::parse_event_t::key: {
      Frame& top = stack_.back();
      top.key = parsed.get<std::string>();
      if (!top.keys.insert(top.key).second)
        throw MaterialLoadError(file_.string() + ": " + path() +
                                ": appears twice in the same object (remove one)");
      break;
    }
    case json::parse_event_t::value:
      advanceArray();
      break;
    case json::parse_event_t::object_end:
    case json::parse_event_t::array_end:
      stack_.pop_back();
      advanceArray();
      break;
    }
    return true;
  }

private:
  struct Frame {
    bool isObject;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  void advanceArray() {
    if (!stack_.empty() && !stack_.back().isObject) ++stack_.back().index;
  }

  std::string path() const {
    std::string out;
    for (const Frame& frame : stack_) {
      if (frame.isObject)
        out += (out.empty() ? "" : ".") + frame.key;
      else
        out += "[" + std::to_string(frame.index) + "]";
    }
    return out;
  }

  fs::path file_;
  std::vector<Frame> stack_;
};

class MaterialParser {
public:
  explicit MaterialParser(const fs::path& folder)
      : folder_(folder), file_(folder / kManifestName) {}

  Material parse() const {
    const json root = readJson();
    if (!root.is_object()) failFile("expected a JSON object { ... }, got " + describe(root));
    rejectUnknownFields(root, "", kTopLevelFields);

    Material material;
    material.folder = folder_;
    material.id = requiredString(root, "id", "id");
    if (!isValidId(material.id))
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
  [[noreturn]] void failFile(const std::string& reason) const {
    throw MaterialLoadError(file_.string() + ": " + reason);
  }
  [[noreturn]] void fail(const std::string& field, const std::string& reason) const {
    throw MaterialLoadError(file_.string() + ": " + field + ": " + reason);
  }

  json readJson() const {
    std::error_code ec;
    const fs::file_status status = fs::status(file_, ec);
    if (!fs::exists(status)) failFile("file not found");
    if (fs::is_directory(status)) failFile("is a folder, not a material manifest");
    std::ifstream in(file_, std::ios::binary);
    if (!in) failFile(std::string("cannot be read (") + std::strerror(errno) + ")");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) failFile("cannot be read (read error)");
    try {
      return json::parse(text.str(), DuplicateKeyCheck(file_));
    } catch (const json::parse_error& e) {
      // nlohmann: "[json.exception.parse_error.101] parse error at line 3, column 5: …".
      std::string detail = e.what();
      const std::string marker = "parse error at ";
      if (const auto at = detail.find(marker); at != std::string::npos)
        detail = detail.substr(at + marker.size());
      failFile("invalid JSON at byte " + std::to_string(e.byte) + ", " + detail);
    }
  }

  template <std::size_t N>
  void rejectUnknownFields(const json& object, const std::string& prefix,
                           const std::array<const char*, N>& known) const {
    for (const auto& [key, value] : object.items()) {
      if (key.starts_with("x-")) continue;
      if (std::find_if(known.begin(), known.end(), [&](const char* k) { return key == k; }) !=
          known.end())
        continue;
      std::string hint;
      for (const char* k : known)
        if (editDistance(key, k) <= 2) {
          hint = " (did you mean " + quote(k) + "?)";
          break;
        }
      if (hint.empty()) hint = " (prefix your own fields with x-)";
      fail(prefix + key, "unknown field" + hint);
    }
  }

  const json& required(const json& object, const char* key, const std::string& field) const {
    if (!object.contains(key)) fail(field, "missing required field");
    return object[key];
  }

  std::string string(const json& value, const std::string& field) const {
    if (!value.is_string()) fail(field, "expected a string, got " + describe(value));
    return value.get<std::string>();
  }
  std::string requiredString(const json& object, const char* key, const std::string& field) const {
    return string(required(object, key, field), field);
  }
  std::optional<std::string> optionalString(const json& object, const char* key,
                                            const std::string& field) const {
    if (!object.contains(key)) return std::nullopt;
    return string(object[key], field);
  }

  double number(const json& value, const std::string& field) const {
    if (!value.is_number()) fail(field, "expected a number, got " + describe(value));
    const double v = value.get<double>();
    if (!std::isfinite(static_cast<float>(v)))
      fail(field, formatNumber(v) + " is too large for a float");
    return v;
  }

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

  fs::path folder_, file_;
};

} // namespace

Material loadMaterial(const fs::path& folder) {
  return MaterialParser(folder).parse();
}

std::vector<fs::path> MaterialCatalog::defaultSearchPath(const fs::path& builtInFolder) {
  std::vector<fs::path> folders{builtInFolder};
  const std::string materialPath = environment("OCTACLAY_MATERIAL_PATH");
  std::size_t start = 0;
  while (start <= materialPath.size()) {
    std::size_t end = materialPath.find(':', start);
    if (end == std::string::npos) end = materialPath.size();
    if (end > start) folders.emplace_back(materialPath.substr(start, end - start));
    start = end + 1;
  }
  // XDG Base Directory spec: a relative XDG_DATA_HOME is invalid and must be ignored.
  const fs::path dataHome = environment("XDG_DATA_HOME");
  if (dataHome.is_absolute())
    folders.push_back(dataHome / "octaclay" / "materials");
  else if (const std::string home = environment("HOME"); !home.empty())
    folders.push_back(fs::path(home) / ".local" / "share" / "octaclay" / "materials");
  return folders;
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
      std::error_code entryEc;
      if (it->is_directory(entryEc) && fs::exists(it->path() / kManifestName, entryEc))
        candidates.push_back(it->path());
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
