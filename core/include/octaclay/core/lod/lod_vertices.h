#pragma once

// The LOD as a renderer's vertex buffer, with the tangent frame that the tangent-space bake
// (normal_map.h) and the exported files (export/lod_export.h) share.

#include "octaclay/core/geometry/vec.h"
#include "octaclay/core/lod/lod.h"

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::core {

/// The LOD as a renderer's vertex buffer: mesh vertices split where their corners' image
/// coordinates differ (the octahedral seams), so each vertex has one texture coordinate.
///
/// Tangent frame (glTF's convention, what writeLodMesh writes as NORMAL and TANGENT): the
/// normal is the area-weighted average of the LOD's face normals at the welded vertex; the
/// tangent is the area-weighted dP/du of the incident triangles (u = image x, increasing to the
/// right), made orthogonal to the normal; the bitangent is cross(normal, tangent.xyz) · w, with
/// w = ±1 chosen so that it points towards decreasing v (image row 0, "up" in the image: glTF's
/// +Y, OpenGL's and Blender's "Y+" once OBJ's v axis is flipped). The octahedral map keeps
/// orientation, so w is −1 everywhere on a sane LOD. The GLB carries this frame as NORMAL and
/// TANGENT, so a glTF viewer decodes a Tangent map exactly; an OBJ has no tangents and viewers
/// derive their own (MikkTSpace in Blender: the same axes, slightly different averaging), so
/// tangent-space OBJ maps are close but not exact there.
struct LodVertices {
  std::vector<Vec3f> positions, normals;
  std::vector<std::array<float, 4>> tangents; ///< xyz unit tangent, w handedness (±1)
  std::vector<Vec2f> uvs;                     ///< image coordinates: (x / N, y / N)
  std::vector<std::uint32_t> welded;          ///< for each vertex, its index in lod.mesh
  std::vector<std::array<std::uint32_t, 3>> triangles;
};

/// Splits and frames the LOD's vertices. Throws Error(InvalidArgument) when cornerUv and the
/// mesh's triangles disagree in count.
LodVertices lodVertices(const LodMesh& lod);

} // namespace octaclay::core
