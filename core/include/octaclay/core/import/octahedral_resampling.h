#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {

/// Where one sample of an octahedral grid lies on a mesh.
struct SampleLocation {
  std::uint32_t triangle = 0;            ///< index into TriangleMesh::triangles
  std::array<float, 3> weights{1, 0, 0}; ///< barycentric, of the triangle's corners 0, 1, 2;
                                         ///< non-negative, summing to 1
};

/// For every sample (i, j) of an n grid, at index j·(n + 1) + i: the triangle of `mesh` whose
/// sphere image under `map` holds octahedralDirection(n, i, j), and the direction's gnomonic
/// barycentric coordinates there (clamped to the triangle): the very locations
/// resampleOctahedral interpolates positions at. Identified samples share one direction but
/// may get different triangles when it lies on an edge. (n + 1)² × 16 bytes.
/// Throws Error(InvalidArgument) as resampleOctahedral does.
std::vector<SampleLocation> locateOctahedralSamples(const TriangleMesh& mesh,
                                                    const SphericalMap& map, int n);

/// The geometry image of size n whose sample (i, j) is the point of `mesh` that `map` sends to
/// octahedralDirection(n, i, j): the sphere triangle holding that direction is found by
/// walking the spherical triangulation, and the mesh's positions are interpolated with the
/// direction's (gnomonic) barycentric coordinates there. Seamed (maxSeamGap == 0). Saliency
/// (w) is 0. Throws Error(InvalidArgument) for an invalid n or a map of the wrong size.
GeometryImage resampleOctahedral(const TriangleMesh& mesh, const SphericalMap& map, int n);

/// A new document holding resampleOctahedral(mesh, map, n). When vertexColours holds one RGBA
/// colour per vertex of `mesh` (components in [0, 1]), they are interpolated the same way into
/// the diffuse layer (seamed: identified samples get their mean); an empty span keeps the
/// default diffuse fill. Throws Error(InvalidArgument) for a colour count other than #V.
Document importToDocument(const TriangleMesh& mesh, const SphericalMap& map, int n,
                          std::span<const Vec4f> vertexColours = {});

/// A new document holding resampleOctahedral(mesh, map, n) whose diffuse layer is `texture`
/// seen through the mesh's texture coordinates: each sample's (u, v) is interpolated from its
/// triangle's corners (cornerUv: one entry per triangle of `mesh`) and the texture read there
/// bilinearly, repeating outside [0, 1], with v pointing up (texel row (1 − v) × height, texel
/// centres at half-integers). Grey is replicated to RGB, a missing alpha is 1. Identified
/// samples (which may fall on both sides of a texture seam) get their mean, so the layer is
/// continuous across the image's border. Throws Error(InvalidArgument) for a cornerUv count
/// other than #T or an empty or inconsistent texture.
Document importToDocument(const TriangleMesh& mesh, const SphericalMap& map, int n,
                          std::span<const CornerUv> cornerUv, const RasterImage& texture);

} // namespace octaclay::core
