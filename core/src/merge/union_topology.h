#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstddef>

namespace octaclay::core::detail {

/// The facts a merge checks of its union's mesh before mapping it onto the sphere.
struct UnionTopology {
  std::size_t pieces = 0;   ///< connected components (through shared vertices)
  MeshTopology topology;    ///< of the whole mesh (its Euler characteristic, boundary, …)
  long long genus() const { ///< of one closed piece: (2 − χ) / 2
    return (2 - topology.euler) / 2;
  }
};

/// Counts the pieces with a union–find over the triangles' corners: O(T α(V)) time, O(V) memory.
UnionTopology analyzeUnion(const TriangleMesh& mesh);

} // namespace octaclay::core::detail
