#pragma once

// The one binary glTF writer of the exports (full resolution and LOD): one mesh of one triangle
// primitive, one material, its textures embedded as PNG.

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {
class OutputSet;
}

namespace octaclay::core::detail {

/// The primitive's attributes, one per vertex, and its triangles.
struct GlbMesh {
  std::span<const Vec3f> positions;               ///< POSITION, with its min and max
  std::span<const Vec3f> normals;                 ///< NORMAL
  std::span<const std::array<float, 4>> tangents; ///< TANGENT; empty = none
  std::span<const Vec2f> texcoords;               ///< TEXCOORD_0 (glTF's v axis down)
  std::span<const std::array<std::uint32_t, 3>> triangles;
};

/// An embedded PNG texture; every texture uses one sampler (linear, mipmapped, clamped: the
/// image's border is the octahedral seam, and must not blend with the opposite side).
struct GlbTexture {
  std::string name;
  std::vector<unsigned char> png;
};

/// The material (pbrMetallicRoughness) and the names of the mesh and its node. Texture slots
/// hold an index into the textures, −1 for none.
struct GlbMaterial {
  std::string name, meshName, nodeName;
  double metallicFactor = 1, roughnessFactor = 1;
  int baseColorTexture = -1, metallicRoughnessTexture = -1, normalTexture = -1;
  /// glTF has no object-space normal texture: this one is named in the material's extras
  /// (`octaclay_object_space_normal_texture`) for renderers that know.
  int objectSpaceNormalTexture = -1;
};

/// A node of a scene's .glb: its mesh, its material and where it sits (translation, rotation
/// quaternion x, y, z, w, scale; each empty for the identity, and then not written).
struct GlbNode {
  GlbMesh mesh;
  GlbMaterial material;
  std::vector<double> translation, rotation, scale;
};

/// Stages a .glb of several nodes into `set`: node k has mesh k and material k (named by its
/// material's nodeName, meshName and name), the textures shared by index; buffer views as
/// writeGlbFile's, mesh after mesh, then the textures.
void writeGlbNodes(std::span<const GlbNode> nodes, std::span<const GlbTexture> textures,
                   const std::filesystem::path& path, OutputSet& set);

/// Stages the .glb into `set` (the caller commits): buffer views 4-byte aligned in the order
/// positions, normals, tangents, texture coordinates, indices (uint32), then the textures. Throws
/// Error(Io) when it cannot be written.
void writeGlbFile(const GlbMesh& mesh, std::span<const GlbTexture> textures,
                  const GlbMaterial& material, const std::filesystem::path& path, OutputSet& set);

} // namespace octaclay::core::detail
