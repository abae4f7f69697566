#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace octaclay::core::detail {

/// The least fair share of the parts, as the octahedral grid will sample them, before and after
/// rotateMapForEvenParts.
struct MapRotationEstimate {
  double before = 0, after = 0;
};

/// Turns a sphere map so that the octahedral grid samples the parts as evenly as it can. The
/// grid's samples are not spread evenly over the sphere: per steradian there are ∝ 1/|d|₁³ of
/// them at direction d (the octahedron's faces, each an equal share of the samples, seen from
/// the centre), 5.2 times as many at the six axes as at the eight face centres; a rotation of
/// the map decides which parts of the surface get the dense directions. Each part's samples
/// are estimated per triangle (its sphere area × that density at its centroid) against its
/// share of the surface area (vertexPart: the part of each vertex of mesh; a triangle belongs
/// to its first corner's part), and of 512 rotations spread over SO(3) (Halton points through
/// Shoemake's uniform quaternions), refined around the best by two rounds of 64 within 12° and
/// 4°, the one whose least part's share is largest is applied. Parts with under 0.1 % of the
/// area are left out of the least. Keeps the map as it is when no rotation does better or when
/// rotating the stored floats would fold a triangle. O(T) per rotation tried.
MapRotationEstimate rotateMapForEvenParts(const TriangleMesh& mesh,
                                          std::span<const std::uint16_t> vertexPart,
                                          std::size_t partCount, SphericalMap& map);

} // namespace octaclay::core::detail
