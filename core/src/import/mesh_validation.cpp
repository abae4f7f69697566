// Validation of imported meshes before spherical parameterization.
// Based on: the half-edge view of Botsch, Kobbelt, Pauly, Alliez & Lévy, "Polygon Mesh
// Processing" (2010), ch. 2 (manifoldness as one fan per vertex and at most two faces per edge,
// orientation by propagation across edges) and the Euler–Poincaré formula V − E + F = 2 − 2g
// for one closed orientable component. Edges are found by sorting half-edge keys and fans by
// union-find over face corners, so every step is O(F log F).

#include "octaclay/core/import/mesh_validation.h"

#include "import/mesh_readers.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

using Tri = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

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

std::string counted(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Topology of a mesh whose faces have three distinct corners. Edge "slots" are 3f + k: the edge
// from corner k of face f to corner k + 1.
struct Analysis {
  std::size_t edges = 0;
  std::size_t nonManifoldEdges = 0;
  std::uint32_t exampleA = 0, exampleB = 0; ///< vertices of one non-manifold edge
  std::size_t exampleFaces = 0;
  bool orientable = true;
  std::vector<char> flip; ///< per face: turn it to agree with its component's majority
  std::size_t components = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> holeEdges; ///< (from, to) as a fill
                                                                  ///< triangle must run them
  std::size_t holes = 0;
  std::size_t pinchVertices = 0;
  std::uint32_t firstPinch = 0; ///< lowest-numbered pinch vertex
  std::size_t firstPinchFans = 0;
};

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

// Closes every hole whose loop is simple and at most maxEdges long; returns how many.
// A new centre vertex gets the mean colour of its loop when `colours` is not empty.
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

std::string handles(long long genus) {
  if (genus == 1) return "one handle";
  return std::to_string(genus) + " handles";
}

// Texture coordinates of each triangle, found again after the cleanup by matching vertices:
// `source` names the triangle of `before` each one came from (kNone for hole fills), whose
// corners are a permutation of its own.
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

// Vertex colours and corner texture coordinates as read (either may be empty).
struct Attributes {
  std::vector<Vec4f> vertexColours;
  std::vector<CornerUv> cornerUv;
};

ValidatedMesh validate(TriangleMesh mesh, Attributes attributes, const ValidationOptions& options,
                       const std::string& prefix, bool weld, std::size_t shortFaces) {
  auto refuse = [&](const std::string& what) {
    throw Error(ErrorKind::InvalidInput, prefix + what);
  };
  MeshCleanup cleanup;
  cleanup.degenerateFacesRemoved = shortFaces;
  auto& positions = mesh.positions;
  auto& tris = mesh.triangles;
  const std::size_t inputVertices = positions.size();

  if (tris.empty())
    refuse("no faces: there is no surface to import (only points or lines?) — export the "
           "model as a triangle or polygon mesh");
  if (inputVertices >= kNone) refuse("more than 4 billion vertices");
  std::vector<Vec4f>& colours = attributes.vertexColours;
  if (!colours.empty() && colours.size() != inputVertices)
    refuse(std::to_string(colours.size()) + " vertex colours for " + std::to_string(inputVertices) +
           " vertices");
  if (!attributes.cornerUv.empty() && attributes.cornerUv.size() != tris.size())
    refuse(std::to_string(attributes.cornerUv.size()) + " texture coordinate triples for " +
           std::to_string(tris.size()) + " triangles");
  std::vector<char> used(inputVertices, 0);
  for (std::size_t f = 0; f < tris.size(); ++f)
    for (const std::uint32_t v : tris[f]) {
      if (v >= inputVertices)
        refuse("triangle " + std::to_string(f + 1) + " refers to vertex " +
               std::to_string(std::uint64_t(v) + 1) + ", but there are only " +
               std::to_string(inputVertices) + " vertices — the file is damaged; re-export it");
      used[v] = 1;
    }
  for (std::size_t v = 0; v < inputVertices; ++v) {
    const Vec3f p = positions[v];
    if (used[v] && !(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)))
      refuse("vertex " + std::to_string(v + 1) +
             " has a coordinate that is not a finite number (NaN or infinity) — the file is "
             "damaged; re-export it");
  }

  if (weld) {
    // Sort used vertices by position; every vertex maps to the lowest index at its position,
    // so vertex numbers in later messages are still the file's.
    std::vector<std::uint32_t> order;
    for (std::uint32_t v = 0; v < inputVertices; ++v)
      if (used[v]) order.push_back(v);
    auto less = [&](std::uint32_t a, std::uint32_t b) {
      const Vec3f p = positions[a], q = positions[b];
      if (p.x != q.x) return p.x < q.x;
      if (p.y != q.y) return p.y < q.y;
      if (p.z != q.z) return p.z < q.z;
      return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> remap(inputVertices);
    std::iota(remap.begin(), remap.end(), std::uint32_t(0));
    for (std::size_t i = 1; i < order.size(); ++i)
      if (positions[order[i]] == positions[order[i - 1]]) {
        remap[order[i]] = remap[order[i - 1]];
        ++cleanup.duplicateVerticesWelded;
      }
    for (Tri& t : tris)
      for (std::uint32_t& v : t)
        v = remap[v];
  }

  // Which input triangle each triangle is, so that texture coordinates can follow them.
  const std::vector<Tri> inputTris = attributes.cornerUv.empty() ? std::vector<Tri>() : tris;
  std::vector<std::uint32_t> source(tris.size());
  std::iota(source.begin(), source.end(), std::uint32_t(0));
  auto keepFaces = [&](auto&& keep) {
    std::size_t out = 0;
    for (std::size_t f = 0; f < tris.size(); ++f)
      if (keep(f)) {
        tris[out] = tris[f];
        source[out++] = source[f];
      }
    const std::size_t removed = tris.size() - out;
    tris.resize(out);
    source.resize(out);
    return removed;
  };

  // Faces with a repeated corner bound no area and add an edge twice in opposite directions:
  // dropping them changes no other face's neighbourhood.
  cleanup.degenerateFacesRemoved += keepFaces([&](std::size_t f) {
    const Tri& t = tris[f];
    return !(t[0] == t[1] || t[1] == t[2] || t[0] == t[2]);
  });

  // A face listed twice (in either winding) makes its edges look non-manifold; keep the first.
  {
    std::vector<std::pair<Tri, std::uint32_t>> keys(tris.size());
    for (std::size_t f = 0; f < tris.size(); ++f) {
      Tri key = tris[f];
      std::sort(key.begin(), key.end());
      keys[f] = {key, static_cast<std::uint32_t>(f)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<char> duplicate(tris.size(), 0);
    for (std::size_t i = 1; i < keys.size(); ++i)
      if (keys[i].first == keys[i - 1].first) {
        duplicate[keys[i].second] = 1;
        ++cleanup.duplicateFacesRemoved;
      }
    if (cleanup.duplicateFacesRemoved) keepFaces([&](std::size_t f) { return !duplicate[f]; });
  }
  if (tris.empty())
    refuse("no faces left after removing " +
           counted(cleanup.degenerateFacesRemoved, "degenerate face", "degenerate faces") +
           " — the file has no surface to import");

  Analysis a = analyze(mesh);
  if (a.nonManifoldEdges)
    refuse(counted(a.nonManifoldEdges, "edge", "edges") +
           " shared by more than two faces (non-manifold; e.g. the edge between vertices " +
           std::to_string(a.exampleA + 1) + " and " + std::to_string(a.exampleB + 1) + " has " +
           std::to_string(a.exampleFaces) +
           " faces) — remove the internal walls or fins, or split the parts, in a modelling "
           "tool");
  if (!a.orientable)
    refuse("not orientable: the faces cannot all be turned to one side (a Möbius strip or "
           "Klein bottle) — it has no outside, so it cannot become a geometry image");
  for (std::size_t f = 0; f < tris.size(); ++f)
    if (a.flip[f]) {
      std::swap(tris[f][1], tris[f][2]);
      ++cleanup.facesFlipped;
    }

  if (!a.holeEdges.empty() && options.fillHoles && options.maxHoleEdges >= 3) {
    cleanup.holesFilled =
        fillHoles(mesh, colours, a.holeEdges, static_cast<std::size_t>(options.maxHoleEdges));
    source.resize(tris.size(), kNone);
    if (cleanup.holesFilled) a = analyze(mesh);
  }
  if (!a.holeEdges.empty()) {
    std::string what = "open: " + counted(a.holes, "hole", "holes") + ", " +
                       counted(a.holeEdges.size(), "boundary edge", "boundary edges");
    if (!options.fillHoles)
      what += " — close them first (or try --fill-holes)";
    else
      what += " left after filling " + counted(cleanup.holesFilled, "hole", "holes") +
              " of at most " + std::to_string(options.maxHoleEdges) +
              " edges — close the rest in a modelling tool (or allow larger holes)";
    refuse(what);
  }
  if (a.pinchVertices)
    refuse("vertex " + std::to_string(std::uint64_t(a.firstPinch) + 1) +
           " is a pinch: its faces form " + std::to_string(a.firstPinchFans) +
           " separate fans — split it (or pull the touching parts apart) in a modelling tool" +
           (a.pinchVertices > 1 ? " (" + std::to_string(a.pinchVertices) + " pinch vertices in all)"
                                : std::string()));
  if (a.components > 1)
    refuse(std::to_string(a.components) +
           " components: only one closed surface can become a geometry image — keep the "
           "largest or split the file");

  std::size_t vertexCount = 0;
  {
    std::vector<char> referenced(positions.size(), 0);
    for (const Tri& t : tris)
      for (const std::uint32_t v : t)
        referenced[v] = 1;
    vertexCount = static_cast<std::size_t>(std::count(referenced.begin(), referenced.end(), 1));
  }
  const long long euler = static_cast<long long>(vertexCount) - static_cast<long long>(a.edges) +
                          static_cast<long long>(tris.size());
  if (euler != 2) {
    // One closed orientable component has χ = 2 − 2g, so χ is even and at most 2.
    const long long genus = (2 - euler) / 2;
    refuse("genus " + std::to_string(genus) + ": " + handles(genus) + " (Euler characteristic " +
           std::to_string(euler) +
           "); only genus-0 surfaces become an octahedral geometry image — close the handles in "
           "a modelling tool");
  }

  for (const Tri& t : tris) {
    const Vec3f p = positions[t[0]], q = positions[t[1]], r = positions[t[2]];
    // Exactly zero in double: these are collinear corners, not merely thin faces.
    const double ux = double(q.x) - p.x, uy = double(q.y) - p.y, uz = double(q.z) - p.z;
    const double vx = double(r.x) - p.x, vy = double(r.y) - p.y, vz = double(r.z) - p.z;
    if (uy * vz - uz * vy == 0 && uz * vx - ux * vz == 0 && ux * vy - uy * vx == 0)
      ++cleanup.zeroAreaFacesKept;
  }

  const double volume = signedVolume(mesh);
  if (!(std::abs(volume) > 0) || !std::isfinite(volume))
    refuse("the surface encloses no volume (it is flat or folded onto itself) — it has no "
           "inside to unfold onto a sphere");
  if (volume < 0) {
    for (Tri& t : tris)
      std::swap(t[1], t[2]);
    cleanup.windingReversed = true;
  }

  std::vector<CornerUv> cornerUv;
  if (!attributes.cornerUv.empty())
    cornerUv = followCorners(tris, inputTris, attributes.cornerUv, source, positions.size());

  // Compact: drop every vertex no face refers to, keeping file order.
  std::vector<std::uint32_t> newIndex(positions.size(), kNone);
  for (const Tri& t : tris)
    for (const std::uint32_t v : t)
      newIndex[v] = 0;
  std::uint32_t next = 0;
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (newIndex[v] == 0) {
      newIndex[v] = next;
      if (!colours.empty()) colours[next] = colours[v];
      positions[next++] = positions[v];
    }
  const std::size_t removed = positions.size() - next;
  positions.resize(next);
  if (!colours.empty()) colours.resize(next);
  for (Tri& t : tris)
    for (std::uint32_t& v : t)
      v = newIndex[v];
  cleanup.unusedVerticesRemoved = removed - cleanup.duplicateVerticesWelded;
  ValidatedMesh out;
  out.mesh = std::move(mesh);
  out.cleanup = cleanup;
  out.vertexColours = std::move(colours);
  out.cornerUv = std::move(cornerUv);
  return out;
}

} // namespace

ValidatedMesh loadGenus0Mesh(const fs::path& path, const ValidationOptions& options) {
  detail::RawMesh raw = detail::readRawMesh(path);
  ValidatedMesh out =
      validate(std::move(raw.mesh), {std::move(raw.vertexColours), std::move(raw.cornerUv)},
               options, path.string() + ": ", raw.cornersPerFace, raw.shortFaces);
  out.diffuseTexture = std::move(raw.diffuseTexture);
  out.notes = std::move(raw.notes);
  return out;
}

ValidatedMesh validateGenus0Mesh(TriangleMesh mesh, const ValidationOptions& options) {
  return validate(std::move(mesh), {}, options, std::string(), false, 0);
}

} // namespace octaclay::core
