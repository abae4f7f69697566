#include "mesh_parts.h"

#include <map>
#include <numeric>
#include <tuple>

namespace octaclay::core::detail {

TriangleMesh weldExactly(const TriangleMesh& mesh) {
  TriangleMesh out;
  std::map<std::tuple<float, float, float>, std::uint32_t> seen;
  std::vector<std::uint32_t> remap(mesh.positions.size());
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const Vec3f p = mesh.positions[k];
    const auto [it, inserted] =
        seen.emplace(std::make_tuple(p.x, p.y, p.z), std::uint32_t(out.positions.size()));
    if (inserted) out.positions.push_back(p);
    remap[k] = it->second;
  }
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
  return out;
}

std::vector<TriangleMesh> splitConnectedParts(const TriangleMesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  const auto root = [&](std::uint32_t v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const auto& t : mesh.triangles)
    for (int c = 1; c < 3; ++c) {
      const std::uint32_t a = root(t[0]), b = root(t[c]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  std::vector<std::uint32_t> partOfRoot(mesh.positions.size(), UINT32_MAX);
  std::vector<std::uint32_t> localIndex(mesh.positions.size(), UINT32_MAX);
  std::vector<TriangleMesh> parts;
  for (const auto& t : mesh.triangles) {
    const std::uint32_t r = root(t[0]);
    if (partOfRoot[r] == UINT32_MAX) {
      partOfRoot[r] = static_cast<std::uint32_t>(parts.size());
      parts.emplace_back();
    }
    TriangleMesh& part = parts[partOfRoot[r]];
    std::array<std::uint32_t, 3> local{};
    for (int c = 0; c < 3; ++c) {
      if (localIndex[t[c]] == UINT32_MAX) {
        localIndex[t[c]] = static_cast<std::uint32_t>(part.positions.size());
        part.positions.push_back(mesh.positions[t[c]]);
      }
      local[c] = localIndex[t[c]];
    }
    part.triangles.push_back(local);
  }
  return parts;
}

} // namespace octaclay::core::detail
