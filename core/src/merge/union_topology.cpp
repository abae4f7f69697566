#include "merge/union_topology.h"

#include <cstdint>
#include <numeric>
#include <vector>

namespace octaclay::core::detail {

UnionTopology analyzeUnion(const TriangleMesh& mesh) {
  UnionTopology out;
  out.topology = analyzeTopology(mesh);
  std::vector<std::uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto find = [&](std::uint32_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  std::vector<bool> used(mesh.positions.size(), false);
  for (const auto& t : mesh.triangles) {
    for (std::uint32_t v : t)
      used[v] = true;
    for (int c = 1; c < 3; ++c) {
      const std::uint32_t a = find(t[0]), b = find(t[std::size_t(c)]);
      if (a != b) parent[a] = b;
    }
  }
  for (std::uint32_t v = 0; v < parent.size(); ++v)
    if (used[v] && find(v) == v) ++out.pieces;
  return out;
}

} // namespace octaclay::core::detail
