// Meshes the core tests build themselves.
#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <set>
#include <utility>
#include <vector>

namespace octaclay::core::testing {

/// Boundary edges (in one triangle only) joined into loops: the number of loops.
inline int boundaryLoops(const TriangleMesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++directed[{t[k], t[(k + 1) % 3]}];
  std::map<std::uint32_t, std::uint32_t> next; // boundary half-edge a → b
  for (const auto& [e, count] : directed)
    if (!directed.count({e.second, e.first})) next[e.first] = e.second;
  std::set<std::uint32_t> seen;
  int loops = 0;
  for (const auto& [start, unused] : next) {
    if (seen.count(start)) continue;
    ++loops;
    for (std::uint32_t v = start; !seen.count(v); v = next.at(v))
      seen.insert(v);
  }
  return loops;
}

/// An octahedron split `levels` times into four and projected onto the unit sphere:
/// 8·4^levels triangles, outward, extreme vertices on the axes.
inline TriangleMesh unitSphere(int levels) {
  TriangleMesh mesh;
  mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int level = 0; level < levels; ++level) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t i, std::uint32_t j) {
      const auto key = std::minmax(i, j);
      const auto [it, inserted] =
          midpoints.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) mesh.positions.push_back(normalize(mesh.positions[i] + mesh.positions[j]));
      return it->second;
    };
    std::vector<std::array<std::uint32_t, 3>> finer;
    for (const auto& [a, b, c] : mesh.triangles) {
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({ab, b, bc});
      finer.push_back({ca, bc, c});
      finer.push_back({ab, bc, ca});
    }
    mesh.triangles = std::move(finer);
  }
  return mesh;
}

} // namespace octaclay::core::testing
