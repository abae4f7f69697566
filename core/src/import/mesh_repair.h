// The repairs of validation: closing small holes and carrying texture coordinates through the
// cleanup that turned, dropped and added faces.
#pragma once

#include "import/mesh_topology.h"

#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/mesh_validation.h"

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace octaclay::core::detail {

// Closes every hole whose loop is simple and at most maxEdges long; returns how many.
// A new centre vertex gets the mean colour of its loop when `colours` is not empty.
std::size_t fillHoles(TriangleMesh& mesh, std::vector<Vec4f>& colours,
                      std::vector<std::pair<std::uint32_t, std::uint32_t>> edges,
                      std::size_t maxEdges);

// Texture coordinates of each triangle, found again after the cleanup by matching vertices:
// `source` names the triangle of `before` each one came from (kNone for hole fills), whose
// corners are a permutation of its own.
std::vector<CornerUv> followCorners(const std::vector<Tri>& tris, const std::vector<Tri>& before,
                                    const std::vector<CornerUv>& cornerUv,
                                    const std::vector<std::uint32_t>& source,
                                    std::size_t vertexCount);

} // namespace octaclay::core::detail
