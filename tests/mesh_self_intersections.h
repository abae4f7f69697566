// Whether a mesh crosses itself where it changed: the check the brush tests (push, and pull at
// the modeller's default strength) run on the surface after a stroke.
#pragma once

#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace octaclay::testing {

// Segment pq crosses triangle abc in its interior (Möller–Trumbore, in double).
inline bool segmentCrossesTriangle(core::Vec3f p, core::Vec3f q, core::Vec3f a, core::Vec3f b,
                                   core::Vec3f c) {
  const auto d3 = [](core::Vec3f v) { return std::array<double, 3>{v.x, v.y, v.z}; };
  const auto sub = [](std::array<double, 3> u, std::array<double, 3> v) {
    return std::array<double, 3>{u[0] - v[0], u[1] - v[1], u[2] - v[2]};
  };
  const auto crossd = [](std::array<double, 3> u, std::array<double, 3> v) {
    return std::array<double, 3>{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                                 u[0] * v[1] - u[1] * v[0]};
  };
  const auto dotd = [](std::array<double, 3> u, std::array<double, 3> v) {
    return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  };
  const auto A = d3(a), e1 = sub(d3(b), A), e2 = sub(d3(c), A), dir = sub(d3(q), d3(p));
  const auto h = crossd(dir, e2);
  const double det = dotd(e1, h);
  if (std::abs(det) < 1e-18) return false;
  const auto s = sub(d3(p), A);
  const double u = dotd(s, h) / det;
  const auto k = crossd(s, e1);
  const double v = dotd(dir, k) / det;
  const double t = dotd(e2, k) / det;
  const double eps = 1e-9;
  return u > eps && v > eps && u + v < 1 - eps && t > eps && t < 1 - eps;
}

// Pairs of triangles sharing no vertex where an edge of one crosses the other, among the
// triangles that touch a changed vertex and every triangle whose box overlaps theirs (found
// through a grid of cells about twice a triangle's mean size).
inline int selfIntersections(const core::TriangleMesh& mesh, const std::vector<bool>& changed) {
  struct Box {
    core::Vec3f lo, hi;
  };
  std::vector<Box> boxes;
  double extent = 0;
  for (const auto& t : mesh.triangles) {
    Box b{mesh.positions[t[0]], mesh.positions[t[0]]};
    for (int k = 1; k < 3; ++k) {
      const core::Vec3f p = mesh.positions[t[k]];
      b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y), std::min(b.lo.z, p.z)};
      b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y), std::max(b.hi.z, p.z)};
    }
    extent += std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
    boxes.push_back(b);
  }
  const float cell = std::max(
      2.0f * static_cast<float>(extent / double(std::max<std::size_t>(1, boxes.size()))), 1e-6f);
  const auto cellsOf = [&](const Box& b, auto&& visit) {
    const auto c = [&](float v) { return static_cast<long long>(std::floor(v / cell)); };
    for (long long x = c(b.lo.x); x <= c(b.hi.x); ++x)
      for (long long y = c(b.lo.y); y <= c(b.hi.y); ++y)
        for (long long z = c(b.lo.z); z <= c(b.hi.z); ++z)
          visit(((x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL)));
  };
  std::unordered_map<long long, std::vector<std::size_t>> grid;
  for (std::size_t o = 0; o < boxes.size(); ++o)
    cellsOf(boxes[o], [&](long long key) { grid[key].push_back(o); });
  std::vector<std::size_t> seenBy(mesh.triangles.size(), SIZE_MAX);
  int crossings = 0;
  for (std::size_t m = 0; m < mesh.triangles.size(); ++m) {
    const auto& tm = mesh.triangles[m];
    if (!changed[tm[0]] && !changed[tm[1]] && !changed[tm[2]]) continue;
    cellsOf(boxes[m], [&](long long key) {
      for (const std::size_t o : grid[key]) {
        if (seenBy[o] == m) continue;
        seenBy[o] = m;
        const auto& to = mesh.triangles[o];
        const Box &bm = boxes[m], &bo = boxes[o];
        if (bm.hi.x < bo.lo.x || bo.hi.x < bm.lo.x || bm.hi.y < bo.lo.y || bo.hi.y < bm.lo.y ||
            bm.hi.z < bo.lo.z || bo.hi.z < bm.lo.z)
          continue;
        bool shared = false;
        for (auto x : tm)
          for (auto y : to)
            shared = shared || x == y;
        if (shared) continue;
        const auto& P = mesh.positions;
        bool crosses = false;
        for (int e = 0; e < 3 && !crosses; ++e) {
          crosses =
              segmentCrossesTriangle(P[tm[e]], P[tm[(e + 1) % 3]], P[to[0]], P[to[1]], P[to[2]]) ||
              segmentCrossesTriangle(P[to[e]], P[to[(e + 1) % 3]], P[tm[0]], P[tm[1]], P[tm[2]]);
        }
        crossings += crosses;
      }
    });
  }
  return crossings;
}

inline std::vector<bool> changedVertices(const core::TriangleMesh& before,
                                         const core::TriangleMesh& after) {
  std::vector<bool> changed(before.positions.size());
  for (std::size_t v = 0; v < changed.size(); ++v)
    changed[v] = !(before.positions[v] == after.positions[v]);
  return changed;
}

// Crossings of the surface after an edit where it changed, both images extracted whole.
inline int selfIntersectionsAfter(const core::GeometryImage& before,
                                  const core::GeometryImage& after) {
  const core::TriangleMesh a = core::extractMesh(before);
  const core::TriangleMesh b = core::extractMesh(after);
  return selfIntersections(b, changedVertices(a, b));
}

} // namespace octaclay::testing
