#include "octaclay/core/geometry/triangle_mesh.h"

#include <algorithm>
#include <limits>

namespace octaclay::core {

void BoundingBox::extend(Vec3f p) {
  if (empty()) {
    min = max = p;
    return;
  }
  min = {std::min(min.x, p.x), std::min(min.y, p.y), std::min(min.z, p.z)};
  max = {std::max(max.x, p.x), std::max(max.y, p.y), std::max(max.z, p.z)};
}

BoundingBox boundingBox(const TriangleMesh& mesh) {
  BoundingBox box;
  for (const Vec3f& p : mesh.positions)
    box.extend(p);
  return box;
}

double signedVolume(const TriangleMesh& mesh) {
  double volume = 0;
  for (const auto& t : mesh.triangles) {
    const Vec3f a = mesh.positions[t[0]], b = mesh.positions[t[1]], c = mesh.positions[t[2]];
    // det[a b c] / 6, in double: float cancellation would swamp thin shells.
    volume += (double(a.x) * (double(b.y) * c.z - double(b.z) * c.y) -
               double(a.y) * (double(b.x) * c.z - double(b.z) * c.x) +
               double(a.z) * (double(b.x) * c.y - double(b.y) * c.x));
  }
  return volume / 6.0;
}

MeshTopology analyzeTopology(const TriangleMesh& mesh) {
  MeshTopology topo;
  topo.triangles = mesh.triangles.size();

  std::vector<bool> used(mesh.positions.size(), false);
  // Each half-edge as (min << 32 | max, reversed), so equal edges sort next to each other.
  std::vector<std::pair<std::uint64_t, bool>> halfEdges;
  halfEdges.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      used[t[k]] = true;
      const std::uint64_t a = t[k], b = t[(k + 1) % 3];
      const std::uint64_t key = (std::min(a, b) << 32) | std::max(a, b);
      halfEdges.emplace_back(key, a > b);
    }
    const Vec3f p = mesh.positions[t[0]], q = mesh.positions[t[1]], r = mesh.positions[t[2]];
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || length(cross(q - p, r - p)) == 0.0f)
      ++topo.degenerateTriangles;
  }
  std::sort(halfEdges.begin(), halfEdges.end());

  for (std::size_t k = 0; k < halfEdges.size();) {
    std::size_t end = k + 1;
    while (end < halfEdges.size() && halfEdges[end].first == halfEdges[k].first)
      ++end;
    const std::size_t count = end - k;
    ++topo.edges;
    if (count == 1)
      ++topo.boundaryEdges;
    else if (count > 2 || halfEdges[k].second == halfEdges[k + 1].second)
      ++topo.nonManifoldEdges;
    k = end;
  }
  topo.vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), true));
  topo.unusedVertices = mesh.positions.size() - topo.vertices;
  topo.euler = static_cast<long long>(topo.vertices) - static_cast<long long>(topo.edges) +
               static_cast<long long>(topo.triangles);
  return topo;
}

double aspectRatio(Vec3f a, Vec3f b, Vec3f c) {
  const double twiceArea = length(cross(b - a, c - a));
  const double longest =
      std::max({double(dot(b - a, b - a)), double(dot(c - b, c - b)), double(dot(a - c, a - c))});
  return twiceArea > 0 ? longest / twiceArea : std::numeric_limits<double>::infinity();
}

} // namespace octaclay::core
