// Reads and validates brush manifests. Every message starts with the manifest path and names the
// field (as a JSON path: parameters[2].type), so a plugin author can fix it without guessing.

#include "octaclay/gpu/brush_manifest.h"

#include "manifest_json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>
#include <unordered_set>

namespace octaclay::gpu {

namespace {

namespace fs = std::filesystem;
using detail::describe;
using detail::formatNumber;
using detail::isValidId;
using detail::json;
using detail::listChoices;
using detail::quote;
using detail::shortDump;

constexpr std::array kLayerNames{"positions", "diffuse", "feature", "mask"};
constexpr std::array kAreaNames{"uv", "volume", "volume+normal"};
constexpr std::array kFalloffNames{"linear", "smooth", "constant", "curve"};
constexpr std::array kCategoryNames{"sculpt", "paint", "splat"};
constexpr std::array kTypeNames{"float", "int", "bool", "color", "enum", "material"};
constexpr std::array kNeedNames{"normal", "stroke_start"};
constexpr std::array kPassNames{"layers", "reparameterize", "all-layers"};
constexpr std::array kStrokeNames{"spaced", "target", "drag", "anchored"};

constexpr std::array kTopLevelFields{
    "id",      "name",       "version", "api",        "description", "category", "shader",
    "reads",   "writes",     "mix",     "needs",      "area",        "falloff",  "falloffCurve",
    "spacing", "parameters", "pass",    "iterations", "stroke",      "icon"};
constexpr std::array kParameterFields{"id",  "label", "tooltip", "type",   "default",
                                      "min", "max",   "step",    "options"};
// Parameter ids whose uniform would collide with one the host declares (gpu/shaders/prelude.glsl
// and the brush contract in plugins/examples/README.md); keep in step with the prelude.
constexpr std::array kReservedParameterIds{"centre",    "radius", "strength", "pressure",
                                           "positions", "layer",  "mask",     "size"};

constexpr std::size_t kMinCurveSamples = 2, kMaxCurveSamples = 64;
constexpr double kMaxSpacing = 10.0;

class ManifestParser : detail::ManifestReader {
public:
  explicit ManifestParser(const fs::path& file) : ManifestReader(file, "manifest file") {}

  BrushManifest parse() { return parse(readJson()); }
  BrushManifest parseText(std::string_view text) { return parse(parseJson(text)); }

private:
  BrushManifest parse(const json& root) {
    if (!root.is_object()) failFile("expected a JSON object { ... }, got " + describe(root));

    BrushManifest manifest;
    manifest.folder = file().parent_path();
    // api first: a newer manifest may legitimately use fields this build does not know.
    manifest.api = parseApi(root);
    rejectUnknownFields(root, "", kTopLevelFields);

    manifest.id = requiredString(root, "id", "id");
    if (!isValidId(manifest.id, false))
      fail("id",
           quote(manifest.id) + " is not a valid brush id (use lowercase letters, digits and -)");
    manifest.name = requiredString(root, "name", "name");
    if (manifest.name.empty()) fail("name", "must not be empty");
    manifest.version = optionalString(root, "version", "version").value_or("");
    manifest.description = optionalString(root, "description", "description").value_or("");
    if (auto category = optionalString(root, "category", "category"))
      manifest.category = choose<Category>(*category, kCategoryNames, "category", "category");

    manifest.shaderFile = requiredString(root, "shader", "shader");
    checkShader(manifest);
    if (auto icon = optionalString(root, "icon", "icon")) {
      manifest.iconFile = *icon;
      checkIcon(manifest);
    }

    if (const json* reads = root.contains("reads") ? &root["reads"] : nullptr)
      manifest.reads = parseLayers(*reads, "reads");
    manifest.writes = parseLayers(required(root, "writes", "writes"), "writes");
    if (manifest.writes.empty()) fail("writes", "a brush must write at least one layer");
    if (const json* mix = root.contains("mix") ? &root["mix"] : nullptr) parseMix(*mix, manifest);
    if (const json* needs = root.contains("needs") ? &root["needs"] : nullptr)
      manifest.needs = parseNeeds(*needs, manifest.api);
    parsePass(root, manifest);
    parseStroke(root, manifest);

    manifest.area =
        choose<AreaMode>(requiredString(root, "area", "area"), kAreaNames, "area", "area");
    if (auto falloff = optionalString(root, "falloff", "falloff"))
      manifest.falloff = choose<Falloff>(*falloff, kFalloffNames, "falloff", "falloff");
    parseFalloffCurve(root, manifest);

    if (root.contains("spacing")) {
      const double spacing = number(root["spacing"], "spacing");
      if (!(spacing > 0.0 && spacing <= kMaxSpacing))
        fail("spacing", formatNumber(spacing) + " is outside (0, " + formatNumber(kMaxSpacing) +
                            "] (a fraction of the radius)");
      manifest.spacing = static_cast<float>(spacing);
    }

    if (root.contains("parameters")) parseParameters(root["parameters"], manifest);
    return manifest;
  }

  int parseApi(const json& root) const {
    const int api = integer(required(root, "api", "api"), "api");
    if (api < 1) fail("api", "must be 1 or more, got " + std::to_string(api));
    if (api > kBrushApiVersion)
      fail("api", "needs Octaclay brush API " + std::to_string(api) + ", this Octaclay has " +
                      std::to_string(kBrushApiVersion));
    return api;
  }

  void checkShader(const BrushManifest& manifest) const {
    const std::string& name = manifest.shaderFile;
    if (name.empty() || name == "." || name == ".." ||
        name.find_first_of("/\\") != std::string::npos)
      fail("shader", quote(name) + " must be a file name beside the manifest");
    const fs::path folder = manifest.folder.empty() ? fs::path(".") : manifest.folder;
    std::error_code ec;
    const fs::file_status status = fs::status(folder / name, ec); // a stat: never opens it
    if (!fs::exists(status)) fail("shader", name + " not found in " + folder.string());
    if (!fs::is_regular_file(status))
      fail("shader", name + " in " + folder.string() + " is not a regular file");
  }

  // A relative path to an SVG or PNG inside the brush folder (subfolders allowed); a path or a
  // link that leads out of the folder is refused, so a brush shows only its own files.
  void checkIcon(const BrushManifest& manifest) const {
    const std::string& name = manifest.iconFile;
    const fs::path relative(name);
    const auto leaves = [&] {
      if (name.empty() || relative.is_absolute() || relative.has_root_path() ||
          name.find('\\') != std::string::npos)
        return true;
      for (const fs::path& part : relative)
        if (part == "..") return true;
      return false;
    };
    if (leaves())
      fail("icon", quote(name) + " must be a path inside the brush folder (no .. or leading /)");
    std::string extension = relative.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension != ".svg" && extension != ".png")
      fail("icon", quote(name) + " must be an .svg or .png file");
    const fs::path folder = manifest.folder.empty() ? fs::path(".") : manifest.folder;
    std::error_code ec;
    const fs::file_status status = fs::status(folder / relative, ec); // a stat: never opens it
    if (!fs::exists(status)) fail("icon", name + " not found in " + folder.string());
    if (!fs::is_regular_file(status))
      fail("icon", name + " in " + folder.string() + " is not a regular file");
    const fs::path real = fs::weakly_canonical(folder / relative, ec);
    const fs::path realFolder = fs::weakly_canonical(folder, ec);
    const auto [end, rest] =
        std::mismatch(realFolder.begin(), realFolder.end(), real.begin(), real.end());
    if (ec || end != realFolder.end())
      fail("icon", name + " leads out of " + folder.string() + " (through a link)");
  }

  // example: the layer the message's hint shows.
  std::vector<core::EditLayer> parseLayers(const json& value, const std::string& field,
                                           std::string_view example = kLayerNames[0]) const {
    if (!value.is_array())
      fail(field, "expected an array of layers, got " + describe(value) + " (use [\"" +
                      std::string(example) + "\"])");
    std::vector<core::EditLayer> layers;
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::string item = field + "[" + std::to_string(k) + "]";
      const core::EditLayer layer =
          choose<core::EditLayer>(string(value[k], item), kLayerNames, item, "layer");
      if (std::find(layers.begin(), layers.end(), layer) != layers.end())
        fail(item, quote(toManifestName(layer)) + " is listed twice");
      layers.push_back(layer);
    }
    return layers;
  }

  std::vector<BrushNeed> parseNeeds(const json& value, int api) const {
    if (!value.is_array())
      fail("needs", "expected an array, got " + describe(value) + " (use [\"normal\"])");
    std::vector<BrushNeed> needs;
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::string item = "needs[" + std::to_string(k) + "]";
      const BrushNeed need = choose<BrushNeed>(string(value[k], item), kNeedNames, item, "need");
      if (std::find(needs.begin(), needs.end(), need) != needs.end())
        fail(item, quote(toManifestName(need)) + " is listed twice");
      if (need == BrushNeed::StrokeStart && api < 3)
        fail(item,
             "\"stroke_start\" needs \"api\": 3 (it came with brush API 3), the manifest says " +
                 std::to_string(api));
      needs.push_back(need);
    }
    return needs;
  }

  // "pass" and "iterations" (API 2). After writes and mix: a reparameterize pass moves every
  // layer's samples, so it writes all four and mixes none.
  void parsePass(const json& root, BrushManifest& manifest) const {
    if (auto pass = optionalString(root, "pass", "pass")) {
      if (manifest.api < 2)
        fail("pass", "needs \"api\": 2 (pass kinds came with brush API 2), the manifest says " +
                         std::to_string(manifest.api));
      manifest.pass = choose<PassKind>(*pass, kPassNames, "pass", "pass");
      if (manifest.pass == PassKind::AllLayers && manifest.api < 4)
        fail("pass", "\"all-layers\" needs \"api\": 4 (it came with brush API 4), the manifest "
                     "says " +
                         std::to_string(manifest.api));
    }
    if (manifest.pass == PassKind::AllLayers &&
        std::find(manifest.writes.begin(), manifest.writes.end(), core::EditLayer::Mask) !=
            manifest.writes.end())
      fail("writes", "an \"all-layers\" pass (brushLayers()) writes positions, diffuse and "
                     "feature; a brush that writes the mask uses \"pass\": \"layers\" (brush())");
    if (!manifest.mix.empty() && manifest.api >= 4 && manifest.pass != PassKind::AllLayers)
      fail("mix", "needs \"pass\": \"all-layers\" (a brushLayers() body hands the colour back)");
    const bool reparameterize = manifest.pass == PassKind::Reparameterize;
    if (root.contains("iterations")) {
      if (!reparameterize) fail("iterations", "only used when \"pass\" is \"reparameterize\"");
      const int iterations = integer(root["iterations"], "iterations");
      if (iterations < 1 || iterations > kMaxIterations)
        fail("iterations", std::to_string(iterations) + " is outside [1, " +
                               std::to_string(kMaxIterations) + "]");
      manifest.iterations = iterations;
    }
    if (!reparameterize) return;
    for (std::string_view layer : kLayerNames)
      if (std::find_if(manifest.writes.begin(), manifest.writes.end(), [&](core::EditLayer l) {
            return toManifestName(l) == layer;
          }) == manifest.writes.end())
        fail("writes", "a \"reparameterize\" pass resamples every layer, so it writes all four: "
                       "[\"positions\", \"diffuse\", \"feature\", \"mask\"] (\"" +
                           std::string(layer) + "\" is missing)");
    if (!manifest.mix.empty())
      fail("mix", "a \"reparameterize\" pass resamples its layers and mixes none");
  }

  // "stroke" (API 3): how the stroke's dabs fall. After "pass": a reparameterize stroke resamples
  // from its start already and is spaced.
  void parseStroke(const json& root, BrushManifest& manifest) const {
    const auto stroke = optionalString(root, "stroke", "stroke");
    if (!stroke) return;
    if (manifest.api < 3)
      fail("stroke", "needs \"api\": 3 (stroke kinds came with brush API 3), the manifest says " +
                         std::to_string(manifest.api));
    manifest.stroke = choose<StrokeKind>(*stroke, kStrokeNames, "stroke", "stroke kind");
    if (manifest.stroke != StrokeKind::Spaced && manifest.pass == PassKind::Reparameterize)
      fail("stroke", "a \"reparameterize\" pass makes spaced strokes only");
  }

  void parseMix(const json& value, BrushManifest& manifest) const {
    manifest.mix = parseLayers(value, "mix", "diffuse");
    for (std::size_t k = 0; k < manifest.mix.size(); ++k) {
      const core::EditLayer layer = manifest.mix[k];
      const std::string item = "mix[" + std::to_string(k) + "]";
      if (layer != core::EditLayer::Diffuse && layer != core::EditLayer::Feature)
        fail(item, quote(toManifestName(layer)) + " cannot be mixed (only \"diffuse\" and "
                                                  "\"feature\" can)");
      if (std::find(manifest.writes.begin(), manifest.writes.end(), layer) == manifest.writes.end())
        fail(item, quote(toManifestName(layer)) + " is not in \"writes\"");
    }
  }

  void parseFalloffCurve(const json& root, BrushManifest& manifest) const {
    const bool isCurve = manifest.falloff == Falloff::Curve;
    if (!root.contains("falloffCurve")) {
      if (isCurve) fail("falloffCurve", "missing required field (\"falloff\" is \"curve\")");
      return;
    }
    if (!isCurve) fail("falloffCurve", "only used when \"falloff\" is \"curve\"");
    const json& curve = root["falloffCurve"];
    if (!curve.is_array()) fail("falloffCurve", "expected an array, got " + describe(curve));
    if (curve.size() < kMinCurveSamples || curve.size() > kMaxCurveSamples)
      fail("falloffCurve", "needs " + std::to_string(kMinCurveSamples) + " to " +
                               std::to_string(kMaxCurveSamples) + " values, got " +
                               std::to_string(curve.size()));
    for (std::size_t k = 0; k < curve.size(); ++k) {
      const std::string item = "falloffCurve[" + std::to_string(k) + "]";
      const double v = number(curve[k], item);
      if (v < 0.0 || v > 1.0) fail(item, formatNumber(v) + " is outside [0, 1]");
      manifest.falloffCurve.push_back(static_cast<float>(v));
    }
  }

  void parseParameters(const json& value, BrushManifest& manifest) const {
    if (!value.is_array()) fail("parameters", "expected an array, got " + describe(value));
    std::unordered_map<std::string, std::size_t> indexOf; // linear in the parameter count
    manifest.parameters.reserve(value.size());
    for (std::size_t k = 0; k < value.size(); ++k) {
      const std::string field = "parameters[" + std::to_string(k) + "]";
      BrushParameter parameter = parseParameter(value[k], field);
      if (const auto [at, added] = indexOf.emplace(parameter.id, k); !added)
        fail(field + ".id", quote(parameter.id) + " is already used by parameters[" +
                                std::to_string(at->second) + "]");
      manifest.parameters.push_back(std::move(parameter));
    }
  }

  BrushParameter parseParameter(const json& p, const std::string& field) const {
    if (!p.is_object()) fail(field, "expected an object, got " + describe(p));
    rejectUnknownFields(p, field + ".", kParameterFields);

    BrushParameter out;
    out.id = string(required(p, "id", field + ".id"), field + ".id");
    if (!isValidId(out.id, true))
      fail(field + ".id", quote(out.id) + " is not a valid parameter id (use lowercase letters " +
                              "and digits, words joined by single -)");
    for (const char* reserved : kReservedParameterIds)
      if (out.id == reserved)
        fail(field + ".id", quote(out.id) + " is taken by the host's uniform u_" + out.id);
    out.label = optionalString(p, "label", field + ".label").value_or(out.id);
    out.tooltip = optionalString(p, "tooltip", field + ".tooltip").value_or("");
    const std::string typeField = field + ".type";
    const std::string typeName = string(required(p, "type", typeField), typeField);
    out.type = choose<ParameterType>(typeName, kTypeNames, typeField, "type");

    const auto notUsed = [&](const char* key, const char* usedBy) {
      if (p.contains(key))
        fail(field + "." + key,
             "not used by a " + typeName + " parameter (only " + std::string(usedBy) + ")");
    };
    switch (out.type) {
    case ParameterType::Float:
    case ParameterType::Int:
      notUsed("options", "enum");
      parseRange(p, field, out);
      break;
    case ParameterType::Bool:
      for (const char* key : {"min", "max", "step"})
        notUsed(key, "float and int");
      notUsed("options", "enum");
      out.min = 0.0f;
      out.max = 1.0f;
      out.step = 1.0f;
      if (p.contains("default")) {
        const json& d = p["default"];
        if (!d.is_boolean()) fail(field + ".default", "expected true or false, got " + describe(d));
        out.defaultValue[0] = d.get<bool>() ? 1.0f : 0.0f;
      }
      break;
    case ParameterType::Color:
      for (const char* key : {"min", "max", "step"})
        notUsed(key, "float and int");
      notUsed("options", "enum");
      out.min = 0.0f;
      out.max = 1.0f;
      out.step = 1.0f / 255.0f;
      out.defaultValue = {1.0f, 1.0f, 1.0f, 1.0f};
      if (p.contains("default")) {
        const json& d = p["default"];
        const auto isUnit = [](const json& c) {
          return c.is_number() && c.get<double>() >= 0.0 && c.get<double>() <= 1.0;
        };
        if (!d.is_array() || d.size() != 4 || !std::all_of(d.begin(), d.end(), isUnit))
          fail(field + ".default",
               "expected 4 numbers in [0, 1] (red, green, blue, alpha), got " + shortDump(d));
        for (std::size_t c = 0; c < 4; ++c)
          out.defaultValue[c] = d[c].get<float>();
      }
      break;
    case ParameterType::Enum:
      for (const char* key : {"min", "max", "step"})
        notUsed(key, "float and int");
      parseOptions(p, field, out);
      break;
    case ParameterType::Material: {
      // The choices are the materials installed at run time, not the manifest's to list.
      for (const char* key : {"min", "max", "step"})
        notUsed(key, "float and int");
      notUsed("options", "enum");
      const std::string defaultField = field + ".default";
      const std::string id = string(required(p, "default", defaultField), defaultField);
      if (!isValidId(id, true))
        fail(defaultField, quote(id) + " is not a material id (lowercase letters, digits, -)");
      out.options = {id};
      out.min = 0.0f;
      out.max = 0.0f;
      out.step = 1.0f;
      break;
    }
    }
    return out;
  }

  void parseRange(const json& p, const std::string& field, BrushParameter& out) const {
    const bool isInt = out.type == ParameterType::Int;
    const auto read = [&](const char* key, double fallback) {
      if (!p.contains(key)) return fallback;
      const std::string f = field + "." + key;
      return isInt ? static_cast<double>(integer(p[key], f)) : number(p[key], f);
    };
    const double min = read("min", 0.0);
    const double max = read("max", isInt ? 100.0 : 1.0);
    if (min > max)
      fail(field + (p.contains("min") ? ".min" : ".max"),
           "min " + formatNumber(min) + " is greater than max " + formatNumber(max));
    const double step = read("step", isInt ? 1.0 : (max > min ? (max - min) / 100.0 : 0.01));
    if (!(static_cast<float>(step) > 0.0f))
      fail(field + ".step", "must be greater than 0, got " + formatNumber(step));
    const double value = read("default", std::clamp(0.0, min, max));
    if (value < min || value > max)
      fail(field + ".default", formatNumber(value) + " is outside [" + formatNumber(min) + ", " +
                                   formatNumber(max) + "]");
    out.min = static_cast<float>(min);
    out.max = static_cast<float>(max);
    out.step = static_cast<float>(step);
    out.defaultValue[0] = static_cast<float>(value);
  }

  void parseOptions(const json& p, const std::string& field, BrushParameter& out) const {
    const std::string optionsField = field + ".options";
    const json& options = required(p, "options", optionsField);
    if (!options.is_array() || options.empty())
      fail(optionsField, "expected a non-empty array of strings, got " + describe(options));
    std::unordered_set<std::string> seen;
    for (std::size_t k = 0; k < options.size(); ++k) {
      const std::string item = optionsField + "[" + std::to_string(k) + "]";
      std::string option = string(options[k], item);
      if (option.empty()) fail(item, "must not be empty");
      if (!seen.insert(option).second) fail(item, quote(option) + " is listed twice");
      out.options.push_back(std::move(option));
    }
    out.min = 0.0f;
    out.max = static_cast<float>(out.options.size() - 1);
    out.step = 1.0f;
    if (p.contains("default")) {
      const std::string defaultField = field + ".default";
      const std::string value = string(p["default"], defaultField);
      const auto it = std::find(out.options.begin(), out.options.end(), value);
      if (it == out.options.end()) {
        std::string list;
        for (const std::string& option : out.options)
          list += (list.empty() ? "" : ", ") + quote(option);
        fail(defaultField, quote(value) + " is not one of the options (" + list + ")");
      }
      out.defaultValue[0] = static_cast<float>(it - out.options.begin());
    }
  }
};

} // namespace

std::string_view toManifestName(core::EditLayer layer) {
  return kLayerNames[static_cast<std::size_t>(layer)];
}
std::string_view toManifestName(AreaMode area) {
  return kAreaNames[static_cast<std::size_t>(area)];
}
std::string_view toManifestName(Falloff falloff) {
  return kFalloffNames[static_cast<std::size_t>(falloff)];
}
std::string_view toManifestName(Category category) {
  return kCategoryNames[static_cast<std::size_t>(category)];
}
std::string_view toManifestName(ParameterType type) {
  return kTypeNames[static_cast<std::size_t>(type)];
}
std::string_view toManifestName(BrushNeed need) {
  return kNeedNames[static_cast<std::size_t>(need)];
}
std::string_view toManifestName(PassKind pass) {
  return kPassNames[static_cast<std::size_t>(pass)];
}
std::string_view toManifestName(StrokeKind stroke) {
  return kStrokeNames[static_cast<std::size_t>(stroke)];
}

bool BrushManifest::readsLayer(core::EditLayer layer) const {
  return std::find(reads.begin(), reads.end(), layer) != reads.end();
}

bool BrushManifest::needsNormal() const {
  return area == AreaMode::VolumeNormal ||
         std::find(needs.begin(), needs.end(), BrushNeed::Normal) != needs.end();
}

bool BrushManifest::needsStrokeStart() const {
  return stroke == StrokeKind::Anchored ||
         std::find(needs.begin(), needs.end(), BrushNeed::StrokeStart) != needs.end();
}

const BrushParameter* BrushManifest::parameter(std::string_view parameterId) const {
  for (const BrushParameter& p : parameters)
    if (p.id == parameterId) return &p;
  return nullptr;
}

BrushManifest parseBrushManifest(const std::filesystem::path& manifestFile) {
  try {
    return ManifestParser(manifestFile).parse();
  } catch (const detail::ManifestError& e) {
    throw BrushLoadError(e.what());
  }
}

BrushManifest parseBrushManifestText(std::string_view text,
                                     const std::filesystem::path& manifestFile) {
  try {
    return ManifestParser(manifestFile).parseText(text);
  } catch (const detail::ManifestError& e) {
    throw BrushLoadError(e.what());
  }
}

} // namespace octaclay::gpu
