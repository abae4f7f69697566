#pragma once

// Exports that carry the painted layers, so other tools show the model as painted: a textured
// OBJ (with its MTL and PNG maps) and a binary glTF (.glb) with embedded textures.
//
// Both sample the image every `step` samples: grid vertex (i, j) of the (M+1)² grid
// (M = N/step) is image sample (i·step, j·step), and its texture coordinate is the centre of
// texel (i·step, j·step) of the maps, which keep the full (N+1)² resolution of the layers
// (texel (x, y) = layer sample (x, y), top row first). Samples that the octahedral seams
// identify are one surface vertex with several texture coordinates: that is what lets one image
// texture the closed surface. The OBJ writes each surface vertex once (M² + 2 `v`, extractMesh's
// vertices in its order) and splits only its `vt`, so it reads back closed; the GLB, whose
// vertices carry one texture coordinate each, keeps the seam samples as separate vertices with
// equal positions and normals. Triangles follow extractMesh's split and orientation, so the
// surface is the one extractMesh describes.

#include "octaclay/core/document/document.h"

#include <filesystem>
#include <vector>

namespace octaclay::core {

/// The files writeTexturedObj writes for objPath `dir/stem.obj`: the OBJ, `dir/stem.mtl`, and
/// the maps `dir/stem_diffuse.png` (RGBA, diffuse), `dir/stem_specular.png` (grey, feature G),
/// `dir/stem_reflectivity.png` (grey, feature B), `dir/stem_height.png` (grey, feature R), in
/// that order of the returned vector: OBJ first.
std::vector<std::filesystem::path> texturedObjFiles(const std::filesystem::path& objPath);

/// Writes the document's surface sampled every `step` samples as a textured OBJ: M² + 2 `v` and
/// `vn` records (extractMesh's vertices, in its order), (M+1)² `vt` records, grid vertex
/// (i, j) at index j·(M+1) + i (vt = ((x+0.5)/(N+1), 1−(y+0.5)/(N+1)) for image sample (x, y),
/// OBJ's v axis pointing up), 2M² faces `f a/ta/a b/tb/b c/tc/c` (extractMesh's triangles,
/// counter-clockwise seen from outside), and `mtllib`/`usemtl` naming one material whose MTL (`Kd 1
/// 1 1`, `map_Kd`, `Ks 1 1 1`, `map_Ks`, `Ns`, `map_refl`, `bump`) references the PNG maps of
/// texturedObjFiles(objPath), each (N+1)² pixels; an unpainted layer gives a uniform map. The
/// files are written as one set (atomic_output.h): on failure the previous OBJ, MTL and maps
/// all stay as they were. Positions are taken from each sample's canonical sample.
/// Throws Error(InvalidArgument) when step is not a power of two with N/step ≥ 2 or a layer's
/// texel count disagrees with N, Error(Io) when a file cannot be written.
void writeTexturedObj(const Document& doc, int step, const std::filesystem::path& objPath);

/// Writes the document's surface sampled every `step` samples as a binary glTF 2.0 file: one
/// mesh of one triangle primitive with POSITION, NORMAL (unit, from the full-resolution
/// positions), TEXCOORD_0 ((x+0.5)/(N+1), (y+0.5)/(N+1)) for image sample (x, y), glTF's v
/// axis pointing down) and uint32 indices, the same (M+1)² vertices and 2M² triangles as
/// writeTexturedObj; one pbrMetallicRoughness material whose baseColorTexture is the diffuse
/// layer (RGBA PNG) and whose metallicRoughnessTexture (RGB PNG, both factors 1) holds
/// roughness = 1 − specular (feature G) in G and metallic = reflectivity (feature B) in B.
/// Both PNGs, (N+1)² pixels, are embedded in the .glb's binary chunk. Written atomically.
/// Positions are object space as in the document (no axis conversion to glTF's +Y up).
/// Throws Error(InvalidArgument) for a bad step, a layer that disagrees with N, or a result
/// over glTF's 4 GiB binary limit (use a larger step), Error(Io) when it cannot be written.
void writeGlb(const Document& doc, int step, const std::filesystem::path& glbPath);

class OutputSet;

/// writeTexturedObj's and writeGlb's files staged into `set` (atomic_output.h), committed with
/// the caller's others.
void stageTexturedObj(const Document& doc, int step, const std::filesystem::path& objPath,
                      OutputSet& set);
void stageGlb(const Document& doc, int step, const std::filesystem::path& glbPath, OutputSet& set);

} // namespace octaclay::core
