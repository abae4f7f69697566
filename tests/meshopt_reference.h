#pragma once

// The anchor of issue 24: meshopt_simplify on a full-resolution mesh, as a game developer would
// call it, with the triangles over only the vertices they use (the distance measure samples
// vertices too).

#include "octaclay/core/geometry/triangle_mesh.h"

#include <meshoptimizer.h>

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::testing {

inline core::TriangleMesh meshoptSimplified(const core::TriangleMesh& full, std::size_t triangles) {
  std::vector<unsigned> indices;
  for (const auto& t : full.triangles)
    indices.insert(indices.end(), t.begin(), t.end());
  std::vector<unsigned> out(indices.size());
  out.resize(meshopt_simplify(out.data(), indices.data(), indices.size(), &full.positions[0].x,
                              full.positions.size(), sizeof(core::Vec3f), 3 * triangles, 1.0f, 0,
                              nullptr));
  std::vector<std::uint32_t> remap(full.positions.size(), UINT32_MAX);
  core::TriangleMesh compact;
  for (std::size_t k = 0; k + 2 < out.size(); k += 3) {
    std::array<std::uint32_t, 3> t{};
    for (int c = 0; c < 3; ++c) {
      std::uint32_t& r = remap[out[k + c]];
      if (r == UINT32_MAX) {
        r = static_cast<std::uint32_t>(compact.positions.size());
        compact.positions.push_back(full.positions[out[k + c]]);
      }
      t[c] = r;
    }
    compact.triangles.push_back(t);
  }
  return compact;
}

} // namespace octaclay::testing
