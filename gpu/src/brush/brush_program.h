#pragma once

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/gpu/brush_manifest.h"

#include <array>
#include <map>
#include <string>
#include <vector>

// Program assembly: the defines, parameter uniforms, prelude, brush body and main() of a brush
// pass, and the compiler's messages mapped back to the body's own lines.
namespace octaclay::gpu::detail {

/// The uniform of a parameter: u_<id>, '-' replaced by '_'.
std::string uniformName(const std::string& parameterId);

/// The dab's value of each enum parameter (its default where the dab gives none), in manifest
/// order, clamped to the options: each set of values is a program of its own.
std::vector<int> enumValues(const BrushManifest& manifest,
                            const std::map<std::string, std::array<float, 4>>& given);

/// The compiler's log with the body's lines named as file:line.
std::string brushLog(const std::string& log, const std::string& file);

/// Whether the brush body defines `void brushLayers(`: it writes all its layers in one pass.
bool writesAllLayers(const std::string& body);

/// Whether the brush body defines `vec2 brushOffset(`: a reparameterize brush must.
bool definesBrushOffset(const std::string& body);

/// The contract between manifest and shader body, checked when the catalog loads a brush (and
/// again by BrushEngine::load): an "all-layers" pass defines brushLayers(), a "layers" pass does
/// not (for API 1–3, whose manifests cannot say so, a body defining it makes the pass
/// AllLayers), a reparameterize pass defines brushOffset(), "mix" needs brushLayers(), and
/// brushLayers() writes no mask. Throws BrushLoadError starting with the shader's path.
void resolveShaderContract(BrushManifest& manifest, const std::string& body);

/// The longest step, in samples, a reparameterize brush's brushOffset() may take per iteration:
/// below half the smallest height of a grid triangle (1/√8), so a step field folds no cell.
inline constexpr const char* kMaxOffsetStep = "0.35";

/// The fragment source of one pass. allLayers: the body defines brushLayers() and the program
/// writes every layer at once. enumValues: the enum parameters' values, in manifest order.
/// batched: the dab's values come from a batch of dabs, one per rectangle (OCTACLAY_BATCH; the
/// program's vertex shader is batchedRectsVertexShader()).
std::string assemble(const BrushManifest& manifest, core::EditLayer layer, bool allLayers,
                     bool maskTexture, bool inPlace, const std::vector<int>& enumValues,
                     const std::string& body, bool batched = false);

/// The fragment source of the resampling pass after a reparameterize brush's steps
/// (resample.glsl with the prelude).
std::string resampleSource();

} // namespace octaclay::gpu::detail
