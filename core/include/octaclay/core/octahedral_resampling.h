#pragma once

#include "octaclay/core/document.h"
#include "octaclay/core/geometry_image.h"
#include "octaclay/core/spherical_parameterization.h"
#include "octaclay/core/surface_distance.h"
#include "octaclay/core/triangle_mesh.h"

#include <array>
#include <span>

namespace octaclay::core {

/// The point (s, t) ∈ [0, 1]² of the octahedral square whose direction is `direction` (any
/// non-zero vector): the inverse of octahedralDirection, so that sample (i, j) of an N grid
/// has (s, t) = (i / N, j / N). Directions on a fold of the square (z < 0 with x = 0 or
/// y = 0) have two or four such points; one of them is returned.
std::array<double, 2> octahedralSquarePoint(Vec3f direction);

/// The geometry image of size n whose sample (i, j) is the point of `mesh` that `map` sends to
/// octahedralDirection(n, i, j): the sphere triangle holding that direction is found by
/// walking the spherical triangulation, and the mesh's positions are interpolated with the
/// direction's (gnomonic) barycentric coordinates there. Seamed (maxSeamGap == 0). Saliency
/// (w) is 0. Throws Error(InvalidArgument) for an invalid n or a map of the wrong size.
GeometryImage resampleOctahedral(const TriangleMesh& mesh, const SphericalMap& map, int n);

/// A new document holding resampleOctahedral(mesh, map, n). When vertexColours holds one RGBA
/// colour per vertex of `mesh` (components in [0, 1]), they are interpolated the same way into
/// the diffuse layer; an empty span keeps the default diffuse fill.
Document importToDocument(const TriangleMesh& mesh, const SphericalMap& map, int n,
                          std::span<const Vec4f> vertexColours = {});

/// How faithful an import is.
struct ImportQuality {
  int flipped = 0;          ///< of the spherical map
  float stretchL2 = 0;      ///< of the spherical map (SphericalMap)
  float stretchLinf = 0;    ///< of the spherical map
  SurfaceDistance distance; ///< mesh against the image's extracted mesh (fractions of diagonal)
};

/// Measures map and image against `mesh` (extractMesh(image) at full resolution).
ImportQuality measureImport(const TriangleMesh& mesh, const SphericalMap& map,
                            const GeometryImage& image, const SurfaceDistanceOptions& options = {});

} // namespace octaclay::core
