#include "import/mesh_repair.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace octaclay::core::detail {

std::size_t fillHoles(TriangleMesh& mesh, std::vector<Vec4f>& colours,
                      std::vector<std::pair<std::uint32_t, std::uint32_t>> edges,
                      std::size_t maxEdges) {
  std::sort(edges.begin(), edges.end());
  auto outgoing = [&](std::uint32_t v) {
    return std::equal_range(edges.begin(), edges.end(), std::pair{v, std::uint32_t(0)},
                            [](const auto& x, const auto& y) { return x.first < y.first; });
  };
  std::vector<char> used(edges.size(), 0);
  std::vector<std::uint32_t> loop;
  std::size_t filled = 0;
  for (std::size_t start = 0; start < edges.size(); ++start) {
    if (used[start]) continue;
    loop.clear();
    bool simple = true;
    std::size_t e = start;
    while (true) {
      used[e] = 1;
      loop.push_back(edges[e].first);
      const std::uint32_t next = edges[e].second;
      if (next == edges[start].first) break;
      // A vertex where two loops touch has a choice of ways on; such loops are left open
      // rather than guessed.
      const auto [lo, hi] = outgoing(next);
      if (hi - lo != 1 || used[static_cast<std::size_t>(lo - edges.begin())]) {
        simple = false;
        break;
      }
      e = static_cast<std::size_t>(lo - edges.begin());
    }
    const auto [lo, hi] = outgoing(edges[start].first);
    if (!simple || hi - lo != 1 || loop.size() > maxEdges) continue;
    if (loop.size() == 3) {
      mesh.triangles.push_back({loop[0], loop[1], loop[2]});
    } else {
      double sum[3] = {0, 0, 0};
      for (const std::uint32_t v : loop) {
        sum[0] += mesh.positions[v].x;
        sum[1] += mesh.positions[v].y;
        sum[2] += mesh.positions[v].z;
      }
      const double n = double(loop.size());
      const auto centre = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.push_back({float(sum[0] / n), float(sum[1] / n), float(sum[2] / n)});
      if (!colours.empty()) {
        double rgba[4] = {0, 0, 0, 0};
        for (const std::uint32_t v : loop) {
          rgba[0] += colours[v].x;
          rgba[1] += colours[v].y;
          rgba[2] += colours[v].z;
          rgba[3] += colours[v].w;
        }
        colours.push_back(
            {float(rgba[0] / n), float(rgba[1] / n), float(rgba[2] / n), float(rgba[3] / n)});
      }
      for (std::size_t k = 0; k < loop.size(); ++k)
        mesh.triangles.push_back({loop[k], loop[(k + 1) % loop.size()], centre});
    }
    ++filled;
  }
  return filled;
}

std::vector<CornerUv> followCorners(const std::vector<Tri>& tris, const std::vector<Tri>& before,
                                    const std::vector<CornerUv>& cornerUv,
                                    const std::vector<std::uint32_t>& source,
                                    std::size_t vertexCount) {
  std::vector<CornerUv> out(tris.size());
  constexpr float kUnknown = std::numeric_limits<float>::quiet_NaN();
  std::vector<std::array<float, 2>> anyUv(vertexCount, {kUnknown, kUnknown});
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (source[t] == kNone) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t v = tris[t][k];
      const Tri& from = before[source[t]];
      const auto j =
          static_cast<std::size_t>(std::find(from.begin(), from.end(), v) - from.begin());
      if (j == 3) continue; // cannot happen: faces are only turned, never rewired
      out[t][k] = cornerUv[source[t]][j];
      anyUv[v] = out[t][k];
    }
  }
  // A filling face spans a hole the texture has no texels for: its loop corners take a
  // coordinate they have on a neighbouring face, a centre vertex the mean of the others.
  for (std::size_t t = 0; t < tris.size(); ++t) {
    if (source[t] != kNone) continue;
    std::array<float, 2> sum{0, 0};
    int known = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      out[t][k] = anyUv[tris[t][k]];
      if (std::isnan(out[t][k][0])) continue;
      sum[0] += out[t][k][0];
      sum[1] += out[t][k][1];
      ++known;
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (std::isnan(out[t][k][0]))
        out[t][k] = known ? std::array<float, 2>{sum[0] / float(known), sum[1] / float(known)}
                          : std::array<float, 2>{0, 0};
  }
  return out;
}

} // namespace octaclay::core::detail
