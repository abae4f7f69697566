// Based on: the half-edge view of Botsch, Kobbelt, Pauly, Alliez & Lévy, "Polygon Mesh
// Processing" (2010), ch. 2 (manifoldness as one fan per vertex and at most two faces per edge,
// orientation by propagation across edges). Edges are found by sorting half-edge keys and fans
// by union-find over face corners, so every step is O(F log F).

#include "import/mesh_topology.h"

#include <algorithm>
#include <numeric>

namespace octaclay::core::detail {

namespace {

struct UnionFind {
  std::vector<std::uint32_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) {
    std::iota(parent.begin(), parent.end(), std::uint32_t(0));
  }
  std::uint32_t find(std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]]; // path halving keeps the trees flat
    return x;
  }
  void unite(std::uint32_t a, std::uint32_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

} // namespace

Analysis analyze(const TriangleMesh& mesh) {
  const auto& tris = mesh.triangles;
  const std::size_t faceCount = tris.size();
  Analysis a;

  // Half-edges keyed by their unordered vertex pair, so the faces of one edge sort together.
  struct HalfEdge {
    std::uint64_t key;
    std::uint32_t slot;
    bool operator<(const HalfEdge& o) const {
      return key < o.key || (key == o.key && slot < o.slot);
    }
  };
  std::vector<HalfEdge> halfEdges(faceCount * 3);
  for (std::size_t f = 0; f < faceCount; ++f)
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint64_t u = tris[f][k], v = tris[f][(k + 1) % 3];
      halfEdges[3 * f + k] = {(std::min(u, v) << 32) | std::max(u, v),
                              static_cast<std::uint32_t>(3 * f + k)};
    }
  std::sort(halfEdges.begin(), halfEdges.end());

  auto from = [&](std::uint32_t slot) { return tris[slot / 3][slot % 3]; };
  auto to = [&](std::uint32_t slot) { return tris[slot / 3][(slot % 3 + 1) % 3]; };

  std::vector<std::uint32_t> neighbour(faceCount * 3, kNone); // the other slot on the same edge
  std::vector<std::uint32_t> boundarySlots;
  for (std::size_t i = 0; i < halfEdges.size();) {
    std::size_t end = i + 1;
    while (end < halfEdges.size() && halfEdges[end].key == halfEdges[i].key)
      ++end;
    ++a.edges;
    const std::size_t count = end - i;
    if (count == 1) {
      boundarySlots.push_back(halfEdges[i].slot);
    } else if (count == 2) {
      neighbour[halfEdges[i].slot] = halfEdges[i + 1].slot;
      neighbour[halfEdges[i + 1].slot] = halfEdges[i].slot;
    } else {
      if (a.nonManifoldEdges == 0 || count > a.exampleFaces) {
        a.exampleA = from(halfEdges[i].slot);
        a.exampleB = to(halfEdges[i].slot);
        a.exampleFaces = count;
      }
      ++a.nonManifoldEdges;
    }
    i = end;
  }

  // Orientation and components: a breadth-first walk across two-face edges. Two faces agree
  // when they run their shared edge in opposite directions.
  a.flip.assign(faceCount, 0);
  std::vector<char> seen(faceCount, 0);
  std::vector<std::uint32_t> order;
  order.reserve(faceCount);
  for (std::size_t seed = 0; seed < faceCount; ++seed) {
    if (seen[seed]) continue;
    ++a.components;
    const std::size_t begin = order.size();
    seen[seed] = 1;
    order.push_back(static_cast<std::uint32_t>(seed));
    for (std::size_t q = begin; q < order.size(); ++q) {
      const std::uint32_t f = order[q];
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t other = neighbour[3 * f + k];
        if (other == kNone) continue;
        const std::uint32_t g = other / 3;
        const bool sameDirection = from(3 * f + k) == from(other);
        const char wanted = static_cast<char>(a.flip[f] ^ (sameDirection ? 1 : 0));
        if (!seen[g]) {
          seen[g] = 1;
          a.flip[g] = wanted;
          order.push_back(g);
        } else if (a.flip[g] != wanted) {
          a.orientable = false;
        }
      }
    }
    // Keep the orientation most faces already have; the volume test turns everything later.
    const auto flipped = static_cast<std::size_t>(
        std::count_if(order.begin() + static_cast<std::ptrdiff_t>(begin), order.end(),
                      [&](std::uint32_t f) { return a.flip[f] != 0; }));
    if (2 * flipped > order.size() - begin)
      for (std::size_t q = begin; q < order.size(); ++q)
        a.flip[order[q]] ^= 1;
  }

  // Holes: boundary edges, run the way a filling face would (opposite to their own face, as
  // that face will be once flipped), grouped into loops by shared vertices.
  UnionFind loops(mesh.positions.size());
  for (const std::uint32_t slot : boundarySlots) {
    const bool flipped = a.flip[slot / 3] != 0;
    const std::uint32_t u = from(slot), v = to(slot);
    a.holeEdges.emplace_back(flipped ? u : v, flipped ? v : u);
    loops.unite(u, v);
  }
  std::vector<std::uint32_t> roots;
  for (const auto& [u, v] : a.holeEdges)
    roots.push_back(loops.find(u));
  std::sort(roots.begin(), roots.end());
  a.holes = static_cast<std::size_t>(std::unique(roots.begin(), roots.end()) - roots.begin());

  // Fans: corners 3f + k around one vertex join when their faces share an edge there. A vertex
  // whose corners form more than one group is a pinch.
  UnionFind fans(faceCount * 3);
  for (std::uint32_t slot = 0; slot < neighbour.size(); ++slot) {
    const std::uint32_t other = neighbour[slot];
    if (other == kNone || other < slot) continue;
    const std::uint32_t f = slot / 3, g = other / 3;
    const std::uint32_t fk[2] = {slot, 3 * f + (slot % 3 + 1) % 3};
    const std::uint32_t gk[2] = {other, 3 * g + (other % 3 + 1) % 3};
    for (const std::uint32_t c : fk)
      for (const std::uint32_t d : gk)
        if (tris[c / 3][c % 3] == tris[d / 3][d % 3]) fans.unite(c, d);
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> vertexFans(faceCount * 3);
  for (std::uint32_t c = 0; c < vertexFans.size(); ++c)
    vertexFans[c] = {tris[c / 3][c % 3], fans.find(c)};
  std::sort(vertexFans.begin(), vertexFans.end());
  vertexFans.erase(std::unique(vertexFans.begin(), vertexFans.end()), vertexFans.end());
  for (std::size_t i = 0; i < vertexFans.size();) {
    std::size_t end = i + 1;
    while (end < vertexFans.size() && vertexFans[end].first == vertexFans[i].first)
      ++end;
    if (end - i > 1) {
      if (a.pinchVertices == 0) {
        a.firstPinch = vertexFans[i].first;
        a.firstPinchFans = end - i;
      }
      ++a.pinchVertices;
    }
    i = end;
  }
  return a;
}

} // namespace octaclay::core::detail
