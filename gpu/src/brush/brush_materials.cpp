// The brush engine's materials: uploaded once as one texture view per mip level, bound to
// their units per dab.
#include "texture_units.h"

#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/material_catalog.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace octaclay::gpu {

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
        // A view shares t's storage and keeps it alive after t is deleted on return; the
        // Texture owns the view.
        glTextureView(id, GL_TEXTURE_2D, t.id(), GL_RGBA8, static_cast<GLuint>(level), 1, 0, 1);
        views.push_back(Texture::adopt(id, std::max(1, width >> level),
                                       std::max(1, height >> level), TextureFormat::Rgba8));
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
    // uv projection measures in samples: the same fraction of them as of the diagonal.
    const float tileSamples = m.tileSize * document.samplesAcross();
    glUniform1f(program.uniform("u_tileSize"), tileSize);
    glUniform1f(program.uniform("u_tileSamples"), tileSamples);
    glUniform1f(program.uniform("u_heightScale"), m.heightScale * tileSize);
    // One mip level for the dab per projection, from the sample spacing at its centre: the
    // maps' texels one sample spans (a per-texel level would cost a position fetch and a log per
    // texel). The brush samples the projection it needs.
    const core::Sample c = dab.centreTexel;
    const core::Sample next{c.i < document.size() ? c.i + 1 : c.i - 1, c.j};
    const core::TexelRect both{std::min(c.i, next.i), c.j, 2, 1};
    document.syncRegion(std::span(&both, 1)); // the rest of the mirror may wait for read-backs
    const core::GeometryImage& image = document.mirror().positions;
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
    // In the order of kMaterialUnits.
    const std::array<std::pair<const Texture*, bool>, detail::kMaterialUnits.size()> maps{
        {{&m.colour[projected.index], projected.bilinear},
         {&m.surface[projected.index], projected.bilinear},
         {&m.colour[uv.index], uv.bilinear},
         {&m.surface[uv.index], uv.bilinear}}};
    for (std::size_t k = 0; k < maps.size(); ++k) {
      const auto& [texture, bilinear] = maps[k];
      const detail::BrushUnit& unit = detail::kMaterialUnits[k];
      unit.bind(texture->id());
      // The filter belongs to the unit (both projections may read one level's texture).
      glBindSampler(static_cast<GLuint>(unit.unit),
                    bilinear ? bilinearMaps_.id() : nearestMaps_.id());
      glUniform1i(program.uniform(unit.sampler), unit.unit);
    }
    glActiveTexture(GL_TEXTURE0);
    // The bound maps hold one level each: older brushes' textureLod(…, u_materialLod) still works.
    glUniform1f(program.uniform("u_materialLod"), 0.0f);
    glUniform1f(program.uniform("u_materialLodUv"), 0.0f);
    return;
  }
}

void BrushEngine::releaseMaterialUnits() {
  for (const detail::BrushUnit& unit : detail::kMaterialUnits)
    glBindSampler(static_cast<GLuint>(unit.unit), 0);
}

} // namespace octaclay::gpu
