#pragma once

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <span>

// What a brush pass reads: the prelude's uniforms and the document's layers on their units.
namespace octaclay::gpu::detail {

/// Sets the prelude's uniforms, the samplers' units and the parameters' uniforms of the used
/// program for a pass writing layer.
void setUniforms(const Program& program, const BrushManifest& manifest, const GpuDocument& doc,
                 core::EditLayer layer, const Dab& dab);

/// Puts the per-dab values of a batch (centre, normal, drag, stroke delta and direction,
/// projection frame, radius as the pass sees it, strength, pressure, normal cosine, centre
/// texel: batchedRectsVertexShader's BatchDab) into buffer and binds it as the batch's storage
/// (binding 1). A batched program takes every other uniform from setUniforms.
void uploadBatch(Buffer& buffer, const BrushManifest& manifest, const GpuDocument& doc,
                 std::span<const Dab> dabs);

/// Binds the document's layers to their units for a pass writing layer; a mixed layer is a
/// target the pass must not sample (a feedback loop): its unit is left empty. Leaves unit 0
/// active.
void bindLayers(GpuDocument& document, core::EditLayer layer, bool mixesDiffuse, bool mixesFeature);

} // namespace octaclay::gpu::detail
