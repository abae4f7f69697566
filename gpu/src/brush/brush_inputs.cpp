#include "brush_inputs.h"

#include "brush_program.h"
#include "texture_units.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

namespace octaclay::gpu::detail {
namespace {

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

// The dab's radius as the pass sees it: object units, or for a uv brush samples (the same
// fraction of them as of the diagonal).
float passRadius(const BrushManifest& manifest, const GpuDocument& doc, const Dab& dab) {
  if (manifest.area != AreaMode::Uv) return dab.radius;
  return dab.radius / std::max(1e-20f, doc.bounds().diagonal()) * doc.samplesAcross();
}

float normalCosine(const Dab& dab) {
  return std::cos(dab.normalAngleDegrees * std::numbers::pi_v<float> / 180.0f);
}

// The projection frame (direction, right, up): along the view through the centre, or the centre
// normal headless.
std::array<core::Vec3f, 3> projectionFrame(const Dab& dab) {
  const core::Vec3f dir =
      core::normalize(dab.viewDirection ? *dab.viewDirection
                                        : core::Vec3f{-dab.centreNormal.x, -dab.centreNormal.y,
                                                      -dab.centreNormal.z});
  const core::Vec3f helper = std::abs(dir.y) < 0.9f ? core::Vec3f{0, 1, 0} : core::Vec3f{1, 0, 0};
  const core::Vec3f right = core::normalize(core::cross(helper, dir));
  return {dir, right, core::cross(dir, right)};
}

} // namespace

void uploadBatch(Buffer& buffer, const BrushManifest& manifest, const GpuDocument& doc,
                 std::span<const Dab> dabs) {
  // batchedRectsVertexShader's BatchDab, std430: nine vec4 and an ivec4 (160 bytes a dab), in
  // prelude.glsl's v_dab order.
  struct Record {
    std::array<float, 36> values;
    std::array<std::int32_t, 4> centreTexel;
  };
  static_assert(sizeof(Record) == 160);
  std::vector<Record> records(dabs.size());
  for (std::size_t k = 0; k < dabs.size(); ++k) {
    const Dab& dab = dabs[k];
    const auto [dir, right, up] = projectionFrame(dab);
    std::size_t at = 0;
    for (const core::Vec3f& v : {dab.centre, dab.centreNormal, dab.drag, dab.strokeDelta,
                                 dab.strokeDirection, dir, right, up}) {
      records[k].values[at] = v.x, records[k].values[at + 1] = v.y;
      records[k].values[at + 2] = v.z, records[k].values[at + 3] = 0.0f;
      at += 4;
    }
    records[k].values[32] = passRadius(manifest, doc, dab);
    records[k].values[33] = dab.strength;
    records[k].values[34] = dab.pressure;
    records[k].values[35] = normalCosine(dab);
    records[k].centreTexel = {dab.centreTexel.i, dab.centreTexel.j, 0, 0};
  }
  if (!buffer.id()) buffer = Buffer::create();
  buffer.upload(std::as_bytes(std::span(records)));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffer.id());
}

void setUniforms(const Program& program, const BrushManifest& manifest, const GpuDocument& doc,
                 core::EditLayer layer, const Dab& dab) {
  // The layer's base value (what a new document holds): erase modes blend back to it.
  if (const core::Layer* l = documentLayer(doc.mirror(), layer))
    glUniform4f(location(program, "u_layerFill"), l->fill[0], l->fill[1], l->fill[2], l->fill[3]);
  // brushLayers() brushes: every layer's base value.
  glUniform4f(location(program, "u_diffuseFill"), doc.mirror().diffuse.fill[0],
              doc.mirror().diffuse.fill[1], doc.mirror().diffuse.fill[2],
              doc.mirror().diffuse.fill[3]);
  glUniform4f(location(program, "u_featureFill"), doc.mirror().feature.fill[0],
              doc.mirror().feature.fill[1], doc.mirror().feature.fill[2], 0.0f);
  for (const BrushUnit& unit : kLayerUnits)
    glUniform1i(location(program, unit.sampler), unit.unit);
  glUniform1f(location(program, "u_maskFill"), doc.mirror().mask.fill[0]);
  glUniform1i(location(program, "u_size"), doc.size());
  glUniform2i(location(program, "u_cells"), doc.grid().width, doc.grid().height);
  glUniform1i(location(program, "u_topology"), static_cast<int>(doc.topology()));
  glUniform3f(location(program, "u_centre"), dab.centre.x, dab.centre.y, dab.centre.z);
  glUniform3f(location(program, "u_centreNormal"), dab.centreNormal.x, dab.centreNormal.y,
              dab.centreNormal.z);
  glUniform1f(location(program, "u_radius"), passRadius(manifest, doc, dab));
  glUniform1f(location(program, "u_strength"), dab.strength);
  glUniform1f(location(program, "u_pressure"), dab.pressure);
  glUniform1f(location(program, "u_normalCosine"), normalCosine(dab));
  glUniform2i(location(program, "u_centreTexel"), dab.centreTexel.i, dab.centreTexel.j);
  glUniform3f(location(program, "u_drag"), dab.drag.x, dab.drag.y, dab.drag.z);
  glUniform3f(location(program, "u_strokeDelta"), dab.strokeDelta.x, dab.strokeDelta.y,
              dab.strokeDelta.z);
  glUniform3f(location(program, "u_strokeDirection"), dab.strokeDirection.x, dab.strokeDirection.y,
              dab.strokeDirection.z);
  if (!manifest.falloffCurve.empty()) {
    const GLsizei count =
        static_cast<GLsizei>(std::min<std::size_t>(manifest.falloffCurve.size(), 64));
    glUniform1fv(location(program, "u_falloffCurve"), count, manifest.falloffCurve.data());
    glUniform1i(location(program, "u_falloffCurveSize"), count);
  }
  const auto [dir, right, up] = projectionFrame(dab);
  glUniform3f(location(program, "u_projectionDir"), dir.x, dir.y, dir.z);
  glUniform3f(location(program, "u_projectionRight"), right.x, right.y, right.z);
  glUniform3f(location(program, "u_projectionUp"), up.x, up.y, up.z);
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

void bindLayers(GpuDocument& document, core::EditLayer layer, bool samplesDiffuse,
                bool samplesFeature) {
  kPositionsUnit.bind(document.texture(core::EditLayer::Positions).id());
  kLayerUnit.bind(document.texture(layer).id());
  kMaskUnit.bind(document.texture(core::EditLayer::Mask).id());
  kFeatureUnit.bind(samplesFeature ? document.texture(core::EditLayer::Feature).id() : 0);
  kDiffuseUnit.bind(samplesDiffuse ? document.texture(core::EditLayer::Diffuse).id() : 0);
  glActiveTexture(GL_TEXTURE0);
}

} // namespace octaclay::gpu::detail
