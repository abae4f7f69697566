#include "brush_program.h"

#include "shader_sources.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <regex>
#include <sstream>

namespace octaclay::gpu::detail {
namespace {

const char* layerDefine(core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Positions:
    return "LAYER_POSITIONS";
  case core::EditLayer::Diffuse:
    return "LAYER_DIFFUSE";
  case core::EditLayer::Feature:
    return "LAYER_FEATURE";
  case core::EditLayer::Mask:
    return "LAYER_MASK";
  }
  return "LAYER_POSITIONS";
}

// The brush body starts at line kBodyLine of the assembled source (`#line`), so compiler messages
// about it can name its file and its own line: Mesa prints "0:LINE(COL): …", NVIDIA "0(LINE) : …".
constexpr int kBodyLine = 100001;

constexpr const char* kLayerDefines =
    "#version 430 core\n#define LAYER_POSITIONS 0\n#define LAYER_DIFFUSE 1\n"
    "#define LAYER_FEATURE 2\n#define LAYER_MASK 3\n#define LAYER_ALL 4\n";
const std::string kReparameterizeDefines =
    std::string("#define BRUSH_REPARAMETERIZE\n#define BRUSH_MAX_STEP ") + kMaxOffsetStep + "\n";

// The brush body without its comments.
std::string withoutComments(const std::string& body) {
  std::string code;
  for (std::size_t k = 0; k < body.size(); ++k) {
    if (body.compare(k, 2, "//") == 0) {
      k = body.find('\n', k);
      if (k == std::string::npos) break;
    } else if (body.compare(k, 2, "/*") == 0) {
      k = body.find("*/", k + 2);
      if (k == std::string::npos) break;
      ++k;
      continue;
    }
    code += body[k];
  }
  return code;
}

} // namespace

std::string uniformName(const std::string& parameterId) {
  std::string name = "u_" + parameterId;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

std::vector<int> enumValues(const BrushManifest& manifest,
                            const std::map<std::string, std::array<float, 4>>& given) {
  std::vector<int> values;
  for (const BrushParameter& p : manifest.parameters) {
    if (p.type != ParameterType::Enum) continue;
    const auto found = given.find(p.id);
    const float v = found != given.end() ? found->second[0] : p.defaultValue[0];
    const int last = std::max(0, static_cast<int>(p.options.size()) - 1);
    values.push_back(std::clamp(static_cast<int>(std::lround(v)), 0, last));
  }
  return values;
}

std::string brushLog(const std::string& log, const std::string& file) {
  std::istringstream in(log);
  std::string line, out;
  while (std::getline(in, line)) {
    std::size_t digits = 0;
    while (digits < line.size() && std::isdigit(static_cast<unsigned char>(line[digits])))
      ++digits;
    if (digits > 0 && digits < line.size() && (line[digits] == ':' || line[digits] == '(')) {
      std::size_t start = digits + 1, end = start;
      while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end])))
        ++end;
      const long number = end > start ? std::stol(line.substr(start, end - start)) : 0;
      if (number >= kBodyLine && number < 2 * kBodyLine)
        line = file + ":" + std::to_string(number - kBodyLine + 1) + line.substr(end);
    }
    out += line + "\n";
  }
  return out;
}

bool writesAllLayers(const std::string& body) {
  static const std::regex definition(R"(\bvoid\s+brushLayers\s*\()");
  return std::regex_search(withoutComments(body), definition);
}

bool definesBrushOffset(const std::string& body) {
  static const std::regex definition(R"(\bvec2\s+brushOffset\s*\()");
  return std::regex_search(withoutComments(body), definition);
}

void resolveShaderContract(BrushManifest& manifest, const std::string& body) {
  const std::string file = manifest.shaderPath().string();
  const bool definesLayers = writesAllLayers(body);
  if (manifest.pass == PassKind::Reparameterize) {
    if (!definesBrushOffset(body))
      throw BrushLoadError(file + ": a \"reparameterize\" brush defines vec2 "
                                  "brushOffset(BrushInput b) (the step of each sample in the "
                                  "image, in samples)");
    return;
  }
  // API 1-3 manifests cannot declare it: the body says which pass it is.
  if (manifest.api < 4 && definesLayers) manifest.pass = PassKind::AllLayers;
  if (!manifest.mix.empty() && !definesLayers)
    throw BrushLoadError(
        file + ": \"mix\" needs a brushLayers() body (brush() returns the layer's value)");
  if (manifest.pass == PassKind::AllLayers && !definesLayers)
    throw BrushLoadError(file + ": the manifest's \"pass\" is \"all-layers\", so the shader "
                                "defines void brushLayers(inout vec4 positions, inout vec4 "
                                "diffuse, inout vec4 feature, BrushInput b)");
  if (manifest.pass == PassKind::Layers && definesLayers)
    throw BrushLoadError(file + ": the shader defines brushLayers() but the manifest's \"pass\" "
                                "is \"layers\" (one brush() pass a layer): declare \"pass\": "
                                "\"all-layers\"");
  if (manifest.pass == PassKind::AllLayers &&
      std::find(manifest.writes.begin(), manifest.writes.end(), core::EditLayer::Mask) !=
          manifest.writes.end())
    throw BrushLoadError(file + ": brushLayers() writes positions, diffuse and feature; a brush "
                                "that writes the mask defines brush() instead");
}

std::string assemble(const BrushManifest& manifest, core::EditLayer layer, bool allLayers,
                     bool maskTexture, bool inPlace, const std::vector<int>& enumValues,
                     const std::string& body, bool batched) {
  std::string source = kLayerDefines;
  if (maskTexture) source += "#define BRUSH_MASK_TEXTURE\n";
  if (batched) source += "#define OCTACLAY_BATCH\n";
  // A reparameterize step reads the positions and writes an offset: no layer of its own.
  const bool reparameterize = manifest.pass == PassKind::Reparameterize;
  if (reparameterize) source += kReparameterizeDefines;
  source += std::string("#define OCTACLAY_LAYER ") +
            (allLayers || reparameterize ? "LAYER_ALL" : layerDefine(layer)) + "\n";
  switch (manifest.area) {
  case AreaMode::Uv:
    source += "#define BRUSH_AREA_UV\n";
    break;
  case AreaMode::Volume:
    source += "#define BRUSH_AREA_VOLUME\n";
    break;
  case AreaMode::VolumeNormal:
    source += "#define BRUSH_AREA_VOLUME_NORMAL\n";
    break;
  }
  switch (manifest.falloff) {
  case Falloff::Linear:
    source += "#define BRUSH_FALLOFF_LINEAR\n";
    break;
  case Falloff::Constant:
    source += "#define BRUSH_FALLOFF_CONSTANT\n";
    break;
  case Falloff::Curve:
    source += "#define BRUSH_FALLOFF_CURVE\n";
    break;
  case Falloff::Smooth:
    break;
  }
  // The prelude computes per-sample normals only for brushes that read them.
  if (manifest.needsNormal()) source += "#define BRUSH_NEEDS_NORMAL\n";
  // API 3: the positions at the stroke's start (u_strokeStart), and an anchored dab measured on
  // them.
  if (manifest.needsStrokeStart()) source += "#define BRUSH_STROKE_START\n";
  if (manifest.stroke == StrokeKind::Anchored) source += "#define BRUSH_ANCHORED\n";
  // Every target is the layer itself: an unweighted texel keeps its value unwritten.
  if (inPlace) source += "#define BRUSH_IN_PLACE\n";
  for (core::EditLayer mixed : manifest.mix)
    source += mixed == core::EditLayer::Diffuse ? "#define BRUSH_MIX_DIFFUSE\n"
                                                : "#define BRUSH_MIX_FEATURE\n";
  std::size_t enumIndex = 0;
  for (const BrushParameter& p : manifest.parameters) {
    if (p.type == ParameterType::Material) {
      source += "#define BRUSH_MATERIAL\n";
      continue;
    }
    // A constant, not a uniform: a software rasterizer runs both sides of a branch on a
    // uniform, and a branch on a constant is folded away.
    if (p.type == ParameterType::Enum) {
      source += "const int " + uniformName(p.id) + " = " +
                std::to_string(enumValues.at(enumIndex++)) + ";\n";
      continue;
    }
    const char* type = p.type == ParameterType::Color ? "vec4" : "float";
    source += std::string("uniform ") + type + " " + uniformName(p.id) + ";\n";
  }
  source += builtInShader("prelude.glsl");
  source += "#line " + std::to_string(kBodyLine) + "\n" + body + "\n#line " +
            std::to_string(2 * kBodyLine) + "\n";
  source += builtInShader("brush_main.glsl");
  return source;
}

std::string resampleSource() {
  return kLayerDefines + kReparameterizeDefines + "#define OCTACLAY_LAYER LAYER_ALL\n" +
         builtInShader("prelude.glsl") + builtInShader("resample.glsl");
}

} // namespace octaclay::gpu::detail
