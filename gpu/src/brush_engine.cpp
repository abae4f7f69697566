#include "octaclay/gpu/brush_engine.h"

#include "shader_sources.h"

#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/material_catalog.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <regex>
#include <sstream>
#include <tuple>

namespace octaclay::gpu {

struct BrushEngine::LoadedBrush {
  BrushManifest manifest;
  std::string body;
  // The body defines brushLayers(): one program writes every layer (keyed as positions).
  bool allLayers = false;
  // Per layer: its passes write the layer's texture in place instead of a scratch copy. Only
  // where nothing reads other texels of that layer: each texel is then read by the fragment
  // that writes it alone (the texture barrier rules).
  std::array<bool, 4> inPlace{};
  bool writesInPlace(core::EditLayer layer) const {
    return inPlace[static_cast<std::size_t>(layer)];
  }
  // Layers the blender mixes the body's (colour, amount) into: written in place, never read.
  bool mixes(core::EditLayer layer) const {
    return std::find(manifest.mix.begin(), manifest.mix.end(), layer) != manifest.mix.end();
  }
  // Whether every layer the brush writes is written in place: its passes may then discard
  // unweighted texels.
  bool allInPlace() const {
    return std::all_of(manifest.writes.begin(), manifest.writes.end(),
                       [this](core::EditLayer l) { return writesInPlace(l); });
  }
  // Whether a pass reads a texel that it also writes (a texture barrier must come first).
  bool readsWhatItWrites() const {
    return std::any_of(manifest.writes.begin(), manifest.writes.end(),
                       [this](core::EditLayer l) { return writesInPlace(l) && !mixes(l); });
  }
  // One per written layer (OCTACLAY_LAYER differs), mask kind (BRUSH_MASK_TEXTURE) and the
  // values of the enum parameters (constants in the source); all but the defaults' variants
  // are compiled on first use.
  std::map<std::tuple<core::EditLayer, bool, std::vector<int>>, Program> programs;
};

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

// Texture units 0-3 and 6 hold the document's layers; the material's four maps start here.
constexpr GLint kMaterialUnit = 7;
constexpr std::size_t kMaterialUnits = 4;

std::string uniformName(const std::string& parameterId) {
  std::string name = "u_" + parameterId;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
}

// The dab's value of each enum parameter (its default where the dab gives none), in manifest
// order, clamped to the options: each set of values is a program of its own.
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

// The brush body starts at line kBodyLine of the assembled source (`#line`), so compiler messages
// about it can name its file and its own line: Mesa prints "0:LINE(COL): …", NVIDIA "0(LINE) : …".
constexpr int kBodyLine = 100001;

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

// Whether the brush body mentions `normal` (b.normal, normalAt) outside comments.
bool readsNormals(const std::string& body) {
  return withoutComments(body).find("normal") != std::string::npos;
}

// Whether the brush body defines `void brushLayers(`: it writes all its layers in one pass.
bool writesAllLayers(const std::string& body) {
  static const std::regex definition(R"(\bvoid\s+brushLayers\s*\()");
  return std::regex_search(withoutComments(body), definition);
}

// Whether code (a body without its comments) names any of these identifiers (whole words:
// u_layer is not u_layerFill).
bool names(const std::string& code, std::initializer_list<const char*> words) {
  return std::any_of(words.begin(), words.end(), [&](const char* w) {
    return std::regex_search(code, std::regex(std::string("\\b") + w + "\\b"));
  });
}

bool needsNormals(const BrushManifest& manifest, const std::string& body) {
  return manifest.area == AreaMode::VolumeNormal || readsNormals(body);
}

// GL 4.5 or ARB_texture_barrier: a pass may read the texel it writes.
bool hasTextureBarrier() {
  return epoxy_gl_version() >= 45 || epoxy_has_gl_extension("GL_ARB_texture_barrier");
}

// allLayers: the body defines brushLayers() and the program writes every layer at once.
// enumValues: the enum parameters' values, in manifest order.
std::string assemble(const BrushManifest& manifest, core::EditLayer layer, bool allLayers,
                     bool maskTexture, bool inPlace, const std::vector<int>& enumValues,
                     const std::string& body) {
  std::string source = "#version 430 core\n#define LAYER_POSITIONS 0\n#define LAYER_DIFFUSE 1\n"
                       "#define LAYER_FEATURE 2\n#define LAYER_MASK 3\n#define LAYER_ALL 4\n";
  if (maskTexture) source += "#define BRUSH_MASK_TEXTURE\n";
  source += std::string("#define OCTACLAY_LAYER ") +
            (allLayers ? "LAYER_ALL" : layerDefine(layer)) + "\n";
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
  if (needsNormals(manifest, body)) source += "#define BRUSH_NEEDS_NORMAL\n";
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
  source += detail::builtInShader("prelude.glsl");
  source += "#line " + std::to_string(kBodyLine) + "\n" + body + "\n#line " +
            std::to_string(2 * kBodyLine) + "\n";
  source += detail::builtInShader("brush_main.glsl");
  return source;
}

GLint location(const Program& program, const char* name) {
  return program.uniform(name);
}

const core::Layer* documentLayer(const core::Document& d, core::EditLayer layer) {
  switch (layer) {
  case core::EditLayer::Diffuse:
    return &d.diffuse;
  case core::EditLayer::Feature:
    return &d.feature;
  case core::EditLayer::Mask:
    return &d.mask;
  case core::EditLayer::Positions:
    break;
  }
  return nullptr;
}

void setUniforms(const Program& program, const BrushManifest& manifest, const GpuDocument& doc,
                 core::EditLayer layer, const Dab& dab) {
  // The layer's base value (what a new document holds): erase modes blend back to it.
  if (const core::Layer* l = documentLayer(doc.document(), layer))
    glUniform4f(location(program, "u_layerFill"), l->fill[0], l->fill[1], l->fill[2], l->fill[3]);
  // brushLayers() brushes: every layer's base value.
  glUniform4f(location(program, "u_diffuseFill"), doc.document().diffuse.fill[0],
              doc.document().diffuse.fill[1], doc.document().diffuse.fill[2],
              doc.document().diffuse.fill[3]);
  glUniform4f(location(program, "u_featureFill"), doc.document().feature.fill[0],
              doc.document().feature.fill[1], doc.document().feature.fill[2], 0.0f);
  glUniform1i(location(program, "u_positions"), 0);
  glUniform1i(location(program, "u_layer"), 1);
  glUniform1i(location(program, "u_diffuseLayer"), 6);
  glUniform1i(location(program, "u_mask"), 2);
  glUniform1f(location(program, "u_maskFill"), doc.document().mask.fill[0]);
  glUniform1i(location(program, "u_size"), doc.size());
  glUniform3f(location(program, "u_centre"), dab.centre.x, dab.centre.y, dab.centre.z);
  glUniform3f(location(program, "u_centreNormal"), dab.centreNormal.x, dab.centreNormal.y,
              dab.centreNormal.z);
  float radius = dab.radius;
  if (manifest.area ==
      AreaMode::Uv) // measured in samples: the same fraction of N as of the diagonal
    radius =
        dab.radius / std::max(1e-20f, doc.bounds().diagonal()) * static_cast<float>(doc.size());
  glUniform1f(location(program, "u_radius"), radius);
  glUniform1f(location(program, "u_strength"), dab.strength);
  glUniform1f(location(program, "u_pressure"), dab.pressure);
  glUniform1f(location(program, "u_normalCosine"),
              std::cos(dab.normalAngleDegrees * std::numbers::pi_v<float> / 180.0f));
  glUniform2i(location(program, "u_centreTexel"), dab.centreTexel.i, dab.centreTexel.j);
  if (!manifest.falloffCurve.empty()) {
    const GLsizei count =
        static_cast<GLsizei>(std::min<std::size_t>(manifest.falloffCurve.size(), 64));
    glUniform1fv(location(program, "u_falloffCurve"), count, manifest.falloffCurve.data());
    glUniform1i(location(program, "u_falloffCurveSize"), count);
  }
  // The projection frame: along the view through the centre, or the centre normal headless.
  const core::Vec3f dir =
      core::normalize(dab.viewDirection ? *dab.viewDirection
                                        : core::Vec3f{-dab.centreNormal.x, -dab.centreNormal.y,
                                                      -dab.centreNormal.z});
  const core::Vec3f helper = std::abs(dir.y) < 0.9f ? core::Vec3f{0, 1, 0} : core::Vec3f{1, 0, 0};
  const core::Vec3f right = core::normalize(core::cross(helper, dir));
  const core::Vec3f up = core::cross(dir, right);
  glUniform3f(location(program, "u_projectionDir"), dir.x, dir.y, dir.z);
  glUniform3f(location(program, "u_projectionRight"), right.x, right.y, right.z);
  glUniform3f(location(program, "u_projectionUp"), up.x, up.y, up.z);
  glUniform1i(location(program, "u_featureLayer"), 3);
  for (const BrushParameter& p : manifest.parameters) {
    const auto given = dab.parameters.find(p.id);
    const std::array<float, 4> v = given != dab.parameters.end() ? given->second : p.defaultValue;
    // Materials are bound by the engine (bindMaterial), enums compiled in (enumValues).
    if (p.type == ParameterType::Material || p.type == ParameterType::Enum) continue;
    const GLint at = location(program, uniformName(p.id).c_str());
    if (p.type == ParameterType::Color)
      glUniform4f(at, v[0], v[1], v[2], v[3]);
    else
      glUniform1f(at, v[0]);
  }
}

void copyRect(const Texture& from, const Texture& to, core::TexelRect r) {
  glCopyImageSubData(from.id(), GL_TEXTURE_2D, 0, r.x, r.y, 0, to.id(), GL_TEXTURE_2D, 0, r.x, r.y,
                     0, r.width, r.height, 1);
}

std::vector<core::TexelRect> regions(const std::vector<core::TexelRect>& rects) {
  std::vector<core::TexelRect> out;
  out.reserve(rects.size());
  for (const core::TexelRect& r : rects)
    out.push_back({r.x, r.y, r.width, r.height});
  return out;
}

} // namespace

BrushEngine::BrushEngine()
    : seamProgram_("gpu/shaders/seam.glsl", rectsVertexShader(),
                   "#version 430 core\n" + detail::builtInShader("seam.glsl")),
      nearestMaps_(Sampler::repeating(false)), bilinearMaps_(Sampler::repeating(true)) {}

BrushEngine::~BrushEngine() = default;

void BrushEngine::load(const BrushManifest& manifest, const std::string& shaderSource) {
  auto brush = std::make_unique<LoadedBrush>();
  brush->manifest = manifest;
  brush->body = shaderSource;
  brush->allLayers = writesAllLayers(shaderSource);
  if (hasTextureBarrier()) {
    const std::string code = withoutComments(shaderSource);
    // Other texels are read through the neighbour helpers, the prelude's normals, or a layer's
    // sampler named by the body. A brushLayers() pass binds u_layer to the positions.
    const bool all = brush->allLayers;
    const auto readsOthers = [&](const char* sampler) {
      return all ? names(code, {sampler}) : names(code, {"fetchLayer", "u_layer", sampler});
    };
    brush->inPlace[0] =
        !needsNormals(manifest, shaderSource) &&
        !names(code, {"fetchPositions", "normalAt", "u_positions", "fetchLayer", "u_layer"});
    brush->inPlace[1] = !readsOthers("u_diffuseLayer");
    brush->inPlace[2] = !readsOthers("u_featureLayer");
    brush->inPlace[3] = !all && !readsOthers("u_mask") && !names(code, {"maskAt"});
  }
  if (!manifest.mix.empty()) {
    const std::string file = manifest.shaderPath().string();
    if (!brush->allLayers)
      throw GlError("brush " + manifest.id + ": " + file +
                    ": \"mix\" needs a brushLayers() body (brush() returns the layer's value)");
    const std::string code = withoutComments(shaderSource);
    for (core::EditLayer layer : manifest.mix) {
      const char* sampler = layer == core::EditLayer::Diffuse ? "u_diffuseLayer" : "u_featureLayer";
      if (names(code, {sampler}))
        throw GlError("brush " + manifest.id + ": " + file + ": it mixes " +
                      std::string(toManifestName(layer)) + " (\"mix\"), so it cannot read " +
                      sampler + ": the blender writes that layer during the pass");
      brush->inPlace[static_cast<std::size_t>(layer)] = true; // the blender reads the target
    }
  }
  if (brush->allLayers && std::find(manifest.writes.begin(), manifest.writes.end(),
                                    core::EditLayer::Mask) != manifest.writes.end())
    throw GlError("brush " + manifest.id + ": " + manifest.shaderPath().string() +
                  ": brushLayers() writes positions, diffuse and feature; a brush that writes "
                  "the mask defines brush() instead");
  for (core::EditLayer layer : manifest.writes)
    program(*brush, layer, false, enumValues(manifest, {}));
  brushes_[manifest.id] = std::move(brush); // only now: a failed reload keeps the old version
}

const Program& BrushEngine::program(LoadedBrush& brush, core::EditLayer layer, bool maskTexture,
                                    const std::vector<int>& enums) {
  const auto key =
      std::tuple{brush.allLayers ? core::EditLayer::Positions : layer, maskTexture, enums};
  const auto found = brush.programs.find(key);
  if (found != brush.programs.end()) return found->second;
  const std::string file = brush.manifest.shaderPath().string();
  try {
    return brush.programs
        .emplace(key,
                 Program(file, rectsVertexShader(),
                         assemble(brush.manifest, layer, brush.allLayers, maskTexture,
                                  brush.allLayers ? brush.allInPlace() : brush.writesInPlace(layer),
                                  enums, brush.body)))
        .first->second;
  } catch (const GlError& e) {
    throw GlError("brush " + brush.manifest.id + ": " + brushLog(e.what(), file));
  }
}

void BrushEngine::setMaterials(const MaterialCatalog& catalog) {
  materials_.clear();
  for (const Material& m : catalog.materials()) {
    GpuMaterial g;
    g.id = m.id;
    g.tileSize = m.tileSize;
    g.heightScale = m.heightScale;
    // RGBA8 (the maps are 8-bit images), mipmapped, then one view per level: a dab samples the
    // one level its footprint needs, wrapped and filtered by the sampler bindMaterial binds. A
    // per-texel mip choice (trilinear) would cost a software rasterizer more than the dab.
    auto upload = [](int width, int height, const std::vector<float>& rgba) {
      int levels = 1;
      while ((std::max(width, height) >> levels) > 0)
        ++levels;
      Texture t = Texture::withLevels(width, height, TextureFormat::Rgba8, levels);
      t.upload({0, 0, width, height}, rgba);
      glBindTexture(GL_TEXTURE_2D, t.id());
      glGenerateMipmap(GL_TEXTURE_2D);
      std::vector<Texture> views;
      for (int level = 0; level < levels; ++level) {
        GLuint id = 0;
        glGenTextures(1, &id);
        // A view shares t's storage and keeps it alive after t is deleted on return.
        glTextureView(id, GL_TEXTURE_2D, t.id(), GL_RGBA8, static_cast<GLuint>(level), 1, 0, 1);
        views.push_back(Texture::wrap(id, std::max(1, width >> level), std::max(1, height >> level),
                                      TextureFormat::Rgba8));
      }
      glBindTexture(GL_TEXTURE_2D, 0);
      return views;
    };
    g.mapSize = m.colour.width;
    g.colour = upload(m.colour.width, m.colour.height, m.colour.pixels);
    // Height, specular and reflectivity in one texture: one sample instead of three per texel.
    std::vector<float> surface;
    surface.reserve(m.height.pixels.size() * 4);
    for (std::size_t k = 0; k < m.height.pixels.size(); ++k)
      surface.insert(surface.end(),
                     {m.height.pixels[k], m.specular.pixels[k], m.reflectivity.pixels[k], 1.0f});
    g.surface = upload(m.height.width, m.height.height, surface);
    materials_.push_back(std::move(g));
  }
  checkGlError("uploading materials");
}

int BrushEngine::materialIndex(std::string_view id) const {
  for (std::size_t k = 0; k < materials_.size(); ++k)
    if (materials_[k].id == id) return static_cast<int>(k);
  return -1;
}

std::vector<std::string> BrushEngine::materialIds() const {
  std::vector<std::string> ids;
  for (const GpuMaterial& m : materials_)
    ids.push_back(m.id);
  return ids;
}

void BrushEngine::bindMaterial(const Program& program, const BrushManifest& manifest,
                               const GpuDocument& document, const Dab& dab) const {
  for (const BrushParameter& p : manifest.parameters) {
    if (p.type != ParameterType::Material) continue;
    const auto given = dab.parameters.find(p.id);
    int index = given != dab.parameters.end() ? static_cast<int>(given->second[0])
                                              : materialIndex(p.options.front());
    if (index < 0 || index >= static_cast<int>(materials_.size()))
      throw GlError("brush " + manifest.id + ": no material " +
                    (given != dab.parameters.end() ? "#" + std::to_string(index)
                                                   : "'" + p.options.front() + "'") +
                    " is loaded (see resources/materials)");
    const GpuMaterial& m = materials_[static_cast<std::size_t>(index)];
    const float diagonal = std::max(document.bounds().diagonal(), 1e-20f);
    const float tileSize = m.tileSize * diagonal;
    // uv projection measures in samples: the same fraction of N as of the diagonal.
    const float tileSamples = m.tileSize * static_cast<float>(document.size());
    glUniform1f(program.uniform("u_tileSize"), tileSize);
    glUniform1f(program.uniform("u_tileSamples"), tileSamples);
    glUniform1f(program.uniform("u_heightScale"), m.heightScale * tileSize);
    // One mip level for the dab per projection, from the sample spacing at its centre: the
    // maps' texels one sample spans (a per-texel level would cost a position fetch and a log per
    // texel). The brush samples the projection it needs.
    const core::GeometryImage& image = document.document().positions;
    const core::Sample c = dab.centreTexel;
    const core::Sample next{c.i < document.size() ? c.i + 1 : c.i - 1, c.j};
    const float spacing = core::length(image.at(next).xyz() - image.at(c).xyz());
    struct Level {
      std::size_t index;
      bool bilinear;
    };
    // Where a map texel spans more than about 1.4 samples (magnified past level 0) the maps are
    // read bilinearly; elsewhere the chosen level's texels are about a sample wide and the
    // nearest one is read: a bilinear sample costs a software rasterizer as much as the rest of
    // a splat's texel.
    const auto level = [&](float tilesPerSample) {
      const float lod = std::log2(std::max(tilesPerSample * float(m.mapSize), 1e-6f));
      return Level{static_cast<std::size_t>(
                       std::clamp(std::lround(lod), 0L, static_cast<long>(m.colour.size()) - 1)),
                   lod < -0.5f};
    };
    const Level projected = level(spacing / tileSize), uv = level(1.0f / tileSamples);
    const std::array<std::tuple<const char*, const Texture*, bool>, kMaterialUnits> maps{
        {{"u_materialColour", &m.colour[projected.index], projected.bilinear},
         {"u_materialSurface", &m.surface[projected.index], projected.bilinear},
         {"u_materialColourUv", &m.colour[uv.index], uv.bilinear},
         {"u_materialSurfaceUv", &m.surface[uv.index], uv.bilinear}}};
    for (std::size_t k = 0; k < maps.size(); ++k) {
      const auto& [name, texture, bilinear] = maps[k];
      const GLint unit = kMaterialUnit + static_cast<GLint>(k);
      glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
      glBindTexture(GL_TEXTURE_2D, texture->id());
      // The filter belongs to the unit (both projections may read one level's texture).
      glBindSampler(static_cast<GLuint>(unit), bilinear ? bilinearMaps_.id() : nearestMaps_.id());
      glUniform1i(program.uniform(name), unit);
    }
    glActiveTexture(GL_TEXTURE0);
    // The bound maps hold one level each: older brushes' textureLod(…, u_materialLod) still works.
    glUniform1f(program.uniform("u_materialLod"), 0.0f);
    glUniform1f(program.uniform("u_materialLodUv"), 0.0f);
    return;
  }
}

bool BrushEngine::has(const std::string& id) const {
  return brushes_.count(id) > 0;
}

std::vector<core::TexelRect> BrushEngine::reach(const GpuDocument& document,
                                                const std::string& brushId, const Dab& dab) const {
  const auto found = brushes_.find(brushId);
  if (found == brushes_.end()) throw GlError("no brush named '" + brushId + "' is loaded");
  const core::TileBounds& bounds = document.bounds();
  const int tiles = bounds.tilesPerSide();
  std::vector<core::TexelRect> rects;
  if (found->second->manifest.area == AreaMode::Uv) {
    // Samples within the radius (in samples) of the centre sample or of one of its images over
    // the tiling (prelude.glsl's uvDistance), so uv brushes continue across seams.
    const float r = dab.radius / std::max(1e-20f, bounds.diagonal()) * float(document.size());
    const float n = float(document.size());
    const float ci = float(dab.centreTexel.i), cj = float(dab.centreTexel.j);
    const std::array<std::array<float, 2>, 9> images{{{ci, cj},
                                                      {-ci, n - cj},
                                                      {2 * n - ci, n - cj},
                                                      {n - ci, -cj},
                                                      {n - ci, 2 * n - cj},
                                                      {ci + n, cj + n},
                                                      {ci - n, cj - n},
                                                      {ci + n, cj - n},
                                                      {ci - n, cj + n}}};
    for (int ty = 0; ty < tiles; ++ty)
      for (int tx = 0; tx < tiles; ++tx) {
        const core::TexelRect t = bounds.tileRect(tx, ty);
        for (const auto& c : images) {
          const float dx = std::max({float(t.x) - c[0], 0.0f, c[0] - float(t.x + t.width - 1)});
          const float dy = std::max({float(t.y) - c[1], 0.0f, c[1] - float(t.y + t.height - 1)});
          if (dx * dx + dy * dy <= r * r) {
            rects.push_back(t);
            break;
          }
        }
      }
    return rects;
  }
  for (int t : bounds.tilesNearSphere(dab.centre, dab.radius))
    rects.push_back(bounds.tileRect(t % tiles, t / tiles));
  return rects;
}

DabResult BrushEngine::dab(GpuDocument& document, const std::string& brushId, const Dab& dab) {
  return this->dab(document, brushId, dab, reach(document, brushId, dab));
}

DabResult BrushEngine::dab(GpuDocument& document, const std::string& brushId, const Dab& dab,
                           std::vector<core::TexelRect> tiles) {
  DabResult result;
  result.tiles = std::move(tiles);
  if (result.tiles.empty()) return result;
  LoadedBrush& brush = *brushes_.at(brushId);
  const bool maskTexture = !document.document().mask.uniform();
  const std::vector<int> enums = enumValues(brush.manifest, dab.parameters);
  const int side = document.size() + 1;
  for (const core::TexelRect& t : result.tiles)
    result.texels += static_cast<std::size_t>(t.width) * t.height;
  result.seams = seamRuns(result.tiles, side);

  const std::vector<core::TexelRect> rects = core::mergeRects(result.tiles);
  const std::vector<core::TexelRect> passRects = regions(rects);
  const std::vector<core::TexelRect> seamRects = regions(result.seams);

  // The material samplers would override the filtering of whatever VTK binds to those units.
  struct MaterialUnitsRelease {
    ~MaterialUnitsRelease() {
      for (std::size_t k = 0; k < kMaterialUnits; ++k)
        glBindSampler(static_cast<GLuint>(kMaterialUnit) + static_cast<GLuint>(k), 0);
    }
  } releaseMaterialUnits;
  // The modeller's context carries VTK's and Qt's state: passes must not blend, test or cull.
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_CULL_FACE);
  glViewport(0, 0, side, side);
  const auto bindInputs = [&](const Program& pass, core::EditLayer layer) {
    pass.use();
    setUniforms(pass, brush.manifest, document, layer, dab);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, document.texture(core::EditLayer::Positions).id());
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, document.texture(layer).id());
    glActiveTexture(GL_TEXTURE2);
    glBindTexture(GL_TEXTURE_2D, document.texture(core::EditLayer::Mask).id());
    // A mixed layer is a target the pass must not sample (a feedback loop): its unit is empty.
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D, brush.mixes(core::EditLayer::Feature)
                                     ? 0
                                     : document.texture(core::EditLayer::Feature).id());
    glActiveTexture(GL_TEXTURE6);
    glBindTexture(GL_TEXTURE_2D, brush.mixes(core::EditLayer::Diffuse)
                                     ? 0
                                     : document.texture(core::EditLayer::Diffuse).id());
    glActiveTexture(GL_TEXTURE0);
    bindMaterial(pass, brush.manifest, document, dab);
  };
  // The layer's scratch holds the pass's result over rects: back into the layer's texture,
  // seamed, and into the mirror.
  const auto finishLayer = [&](core::EditLayer layer) {
    if (brush.writesInPlace(layer)) {
      // The pass wrote the layer's texture itself.
    } else if (rects.size() == 1 && rects[0] == core::TexelRect{0, 0, side, side}) {
      document.swapScratch(layer);
    } else {
      for (const core::TexelRect& r : rects)
        copyRect(document.scratch(layer), document.texture(layer), r);
    }

    if (!result.seams.empty()) {
      // Into the scratch: after a whole-image swap the scratch is the old texture, free to
      // overwrite, and the seam pass reads the layer's texture.
      document.scratch(layer).bindAsTarget();
      seamProgram_.use();
      glUniform1i(seamProgram_.uniform("u_source"), 0);
      glUniform1i(seamProgram_.uniform("u_size"), document.size());
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, document.texture(layer).id());
      rectPass_.draw(seamRects, side, side);
      for (const core::TexelRect& run : result.seams)
        copyRect(document.scratch(layer), document.texture(layer), run);
    }
    checkGlError("brush " + brushId + " pass");

    for (const core::TexelRect& r : rects)
      document.changed(layer, r);
    for (const core::TexelRect& run : result.seams)
      document.changed(layer, run);
  };

  if (brush.allLayers) {
    // One pass writes every layer: each reads all layers as they were before the dab.
    const Program& pass = program(brush, core::EditLayer::Positions, maskTexture, enums);
    const std::array<core::EditLayer, 3> attached{
        core::EditLayer::Positions, core::EditLayer::Diffuse, core::EditLayer::Feature};
    if (!layersTarget_.id())
      layersTarget_ = Framebuffer(document.scratch(core::EditLayer::Positions));
    layersTarget_.bind();
    std::array<GLenum, 3> drawBuffers{};
    for (std::size_t k = 0; k < attached.size(); ++k) {
      const bool written = std::find(brush.manifest.writes.begin(), brush.manifest.writes.end(),
                                     attached[k]) != brush.manifest.writes.end();
      // A layer whose texels the pass reads elsewhere goes to its scratch.
      const Texture& target = brush.writesInPlace(attached[k]) ? document.texture(attached[k])
                                                               : document.scratch(attached[k]);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k),
                             GL_TEXTURE_2D, written ? target.id() : 0, 0);
      drawBuffers[k] = written ? GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k) : GL_NONE;
      if (brush.mixes(attached[k])) { // rgb = mix(rgb, out.rgb, out.a); alpha kept
        const auto buffer = static_cast<GLuint>(k);
        glEnablei(GL_BLEND, buffer);
        glBlendEquationi(buffer, GL_FUNC_ADD);
        glBlendFuncSeparatei(buffer, GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
      }
    }
    glDrawBuffers(static_cast<GLsizei>(drawBuffers.size()), drawBuffers.data());
    // u_layer: the positions (brushInputAt's value is the positions texel).
    bindInputs(pass, core::EditLayer::Positions);
    if (brush.readsWhatItWrites()) glTextureBarrier(); // earlier writes are visible
    rectPass_.draw(passRects, side, side);
    for (core::EditLayer layer : brush.manifest.mix)
      glDisablei(GL_BLEND, static_cast<GLuint>(layer)); // attachment k holds layer k
    // Detached: the framebuffer must not keep a document's textures alive, nor render into a
    // texture that a whole-image swap makes a layer's.
    for (std::size_t k = 0; k < attached.size(); ++k)
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0 + static_cast<GLenum>(k),
                             GL_TEXTURE_2D, 0, 0);
    checkGlError("brush " + brushId + " pass");
    for (core::EditLayer layer : brush.manifest.writes)
      finishLayer(layer);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return result;
  }

  // Positions last: every other layer's pass reads the positions from before the dab.
  // Except for brushes that read the feature layer: their positions pass displaces by the
  // change of it, so it runs while the feature layer still holds the old one.
  std::vector<core::EditLayer> order = brush.manifest.writes;
  const bool readsFeature = std::find(brush.manifest.reads.begin(), brush.manifest.reads.end(),
                                      core::EditLayer::Feature) != brush.manifest.reads.end();
  std::stable_partition(order.begin(), order.end(), [readsFeature](core::EditLayer l) {
    return (l != core::EditLayer::Positions) != readsFeature;
  });
  for (core::EditLayer layer : order) {
    const Program& pass = program(brush, layer, maskTexture, enums);
    const bool inPlace = brush.writesInPlace(layer);
    (inPlace ? document.texture(layer) : document.scratch(layer)).bindAsTarget();
    bindInputs(pass, layer);
    if (inPlace) glTextureBarrier();
    rectPass_.draw(passRects, side, side);
    finishLayer(layer);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  return result;
}

// Runs along the border lines (the rows whole, the columns without their corners). Elsewhere
// identified samples are already equal, and the seaming pass would write them back unchanged.
std::vector<core::TexelRect> seamRuns(const std::vector<core::TexelRect>& tiles, int side) {
  const auto onBorder = [side](const core::TexelRect& t) {
    return t.x == 0 || t.y == 0 || t.x + t.width == side || t.y + t.height == side;
  };
  if (std::none_of(tiles.begin(), tiles.end(), onBorder)) return {}; // most dabs
  const int n = side - 1;
  std::array<std::vector<std::uint8_t>, 4> marked; // bottom, top (by i); left, right (by j)
  for (auto& m : marked)
    m.assign(static_cast<std::size_t>(side), 0);
  const auto mark = [&](std::vector<std::uint8_t>& line, int begin, int end) {
    for (int k = begin; k < end; ++k)
      line[static_cast<std::size_t>(k)] = line[static_cast<std::size_t>(n - k)] = 1;
  };
  for (const core::TexelRect& t : tiles) {
    if (t.y == 0) mark(marked[0], t.x, t.x + t.width);
    if (t.y + t.height == side) mark(marked[1], t.x, t.x + t.width);
    if (t.x == 0) mark(marked[2], t.y, t.y + t.height);
    if (t.x + t.width == side) mark(marked[3], t.y, t.y + t.height);
  }
  const bool corner = marked[0][0] || marked[1][0] || marked[2][0] || marked[3][0];
  for (int k : {0, 1})
    marked[k][0] = marked[k][static_cast<std::size_t>(n)] = corner;
  std::vector<core::TexelRect> runs;
  for (int line = 0; line < 4; ++line) {
    const bool row = line < 2;
    const int begin = row ? 0 : 1, end = row ? side : n; // columns leave the corners to rows
    for (int k = begin; k < end;) {
      if (!marked[static_cast<std::size_t>(line)][static_cast<std::size_t>(k)]) {
        ++k;
        continue;
      }
      int stop = k;
      while (stop < end && marked[static_cast<std::size_t>(line)][static_cast<std::size_t>(stop)])
        ++stop;
      const int at = line % 2 == 0 ? 0 : n;
      runs.push_back(row ? core::TexelRect{k, at, stop - k, 1}
                         : core::TexelRect{at, k, 1, stop - k});
      k = stop;
    }
  }
  return runs;
}

} // namespace octaclay::gpu
