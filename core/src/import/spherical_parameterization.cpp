// The spherical parameterization: a closed genus-0 mesh checked and compacted, then mapped
// coarse to fine (spherical_progressive.cpp) and/or whole (the stages of spherical_stages.cpp),
// keeping the map with fewer flips and lower stretch.
#include "octaclay/core/import/spherical_parameterization.h"

#include "import/spherical_geometry.h"
#include "import/spherical_progressive.h"
#include "import/spherical_stages.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <numeric>
#include <string>

namespace octaclay::core {

namespace {

using detail::Adjacency;
using detail::adjacency;
using detail::balance;
using detail::conformalizedFlow;
using detail::equalizeAreas;
using detail::orientation;
using detail::Points;
using detail::relaxStretch;
using detail::report;
using detail::stretch;
using detail::StretchSummary;
using detail::Tri;
using detail::triangleArea;
using detail::untangle;
using detail::Vec3d;

// The referenced vertices of a mesh renumbered 0 … n−1, in double precision.
struct CompactMesh {
  Points x;
  std::vector<Tri> triangles;
  std::vector<int> original; // compact → mesh index
};

[[noreturn]] void reject(const std::string& what) {
  throw Error(ErrorKind::InvalidInput,
              "cannot parameterize the mesh on the sphere: " + what +
                  "; it must be one closed, manifold, genus-0 surface facing outward (clean it "
                  "up first)");
}

CompactMesh compact(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) reject("it has no triangles");
  const std::size_t nv = mesh.positions.size();
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= nv) reject("a triangle index is out of range");
  const MeshTopology topology = analyzeTopology(mesh);
  if (!topology.closed())
    reject(std::to_string(topology.boundaryEdges) + " edges are on a boundary");
  if (!topology.manifold())
    reject(std::to_string(topology.nonManifoldEdges) + " edges are non-manifold");
  if (topology.degenerateTriangles != 0)
    reject(std::to_string(topology.degenerateTriangles) + " triangles are degenerate");
  if (topology.euler != 2)
    reject("its Euler characteristic is " + std::to_string(topology.euler) + ", not 2");
  if (signedVolume(mesh) <= 0) reject("it faces inward");

  CompactMesh out;
  std::vector<int> index(nv, -1);
  out.triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles) {
    Tri c{};
    for (int k = 0; k < 3; ++k) {
      int& id = index[t[k]];
      if (id < 0) {
        id = static_cast<int>(out.x.size());
        const Vec3f p = mesh.positions[t[k]];
        out.x.emplace_back(p.x, p.y, p.z);
        out.original.push_back(static_cast<int>(t[k]));
      }
      c[k] = id;
    }
    out.triangles.push_back(c);
  }
  // Euler 2 allows a sphere plus tori; insist on one piece.
  std::vector<int> parent(out.x.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto find = [&](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Tri& t : out.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  const int root = find(0);
  for (int v = 0; v < static_cast<int>(out.x.size()); ++v)
    if (find(v) != root) reject("it has more than one connected piece");
  return out;
}

// The whole-mesh pipeline: conformalized flow, untangling, Möbius balancing, area
// equalization, stretch relaxation. Good on small or smooth meshes; the coarse-to-fine path
// uses it for its base. `progress` may be empty.
Points mapDirectly(const Points& x, const std::vector<Tri>& triangles, const Adjacency& rings,
                   const SphericalParameterizationOptions& options,
                   const std::function<bool(float)>& progress) {
  const int n = static_cast<int>(x.size());
  Points flow = x;
  conformalizedFlow(flow, triangles, options.flowSteps, options.flowTimeStep, progress);
  report(progress, 0.5);
  Points s(flow.size());
  for (int v = 0; v < n; ++v)
    s[v] = flow[v].normalized();
  untangle(s, triangles, rings);
  report(progress, 0.55);

  std::vector<double> weights(triangles.size());
  for (std::size_t t = 0; t < weights.size(); ++t)
    weights[t] = triangleArea(x, triangles[t]);
  balance(s, triangles, weights);
  untangle(s, triangles, rings);
  report(progress, 0.6);

  if (options.equalizeSteps > 0) equalizeAreas(s, x, triangles, options.equalizeSteps, progress);
  if (options.relaxSweeps > 0)
    relaxStretch(s, x, triangles, rings, options.relaxSweeps, progress, 0.8, 1.0);
  return s;
}

} // namespace

SphericalMap parameterizeOnSphere(const TriangleMesh& mesh,
                                  const std::function<bool(float)>& progress,
                                  const SphericalParameterizationOptions& options) {
  report(progress, 0);
  const CompactMesh input = compact(mesh);
  const int n = static_cast<int>(input.x.size());
  const Adjacency rings = adjacency(n, input.triangles);

  // Coarse to fine for all but small meshes; where the whole-mesh pipeline is affordable too
  // (it wins on some smooth meshes) both run and the lower L2 stretch without flips is kept.
  const bool coarseToFine = options.baseVertices > 0 && n > 2 * options.baseVertices;
  const bool direct = !coarseToFine || n <= options.compareBelowVertices;
  // Where both run they run at once, the whole-mesh map on a worker thread (it reads the mesh
  // only): on two cores the pair takes as long as the slower. The worker reports no progress
  // (progress is called on the caller's thread); it stops when the caller's path ends early.
  std::atomic<bool> stop{false};
  std::future<Points> other;
  const struct StopGuard {
    std::atomic<bool>& stop;
    ~StopGuard() { stop = true; } // before `other`'s destructor waits for the worker
  } guard{stop};
  if (coarseToFine && direct)
    other = std::async(std::launch::async, [&] {
      Points t = mapDirectly(input.x, input.triangles, rings, options,
                             [&](float) { return !stop.load(); });
      untangle(t, input.triangles, rings);
      return t;
    });
  Points s;
  if (coarseToFine) {
    detail::CoarseToFineOptions coarse;
    coarse.baseVertices = options.baseVertices;
    const auto mapBase = [&](const Points& x, const std::vector<Tri>& triangles) {
      return mapDirectly(x, triangles, adjacency(static_cast<int>(x.size()), triangles), options,
                         {});
    };
    s = detail::mapCoarseToFine(input.x, input.triangles, coarse, mapBase,
                                [&](double f) { report(progress, 0.9 * f); });
    if (options.relaxSweeps > 0)
      relaxStretch(s, input.x, input.triangles, rings, options.relaxSweeps, progress, 0.9, 1.0);
    untangle(s, input.triangles, rings);
  }
  if (direct && !coarseToFine) {
    s = mapDirectly(input.x, input.triangles, rings, options, progress);
    untangle(s, input.triangles, rings);
  } else if (direct) {
    Points t = other.get();
    const StretchSummary a = stretch(s, input.x, input.triangles);
    const StretchSummary b = stretch(t, input.x, input.triangles);
    if (b.flipped < a.flipped || (b.flipped == a.flipped && b.l2 < a.l2)) s = std::move(t);
  }
  // Small meshes, where time is cheap, get many more flip-safe descent sweeps on the summed
  // squares of the per-triangle L2 stretch, which weighs the most squeezed triangles (the
  // under-sampled tips of thin parts, which set the resampling's Hausdorff error) more than the
  // L2 energy does. About 2·10⁵ vertex moves in all, at most 100 sweeps.
  if (n <= options.compareBelowVertices && options.relaxSweeps > 0)
    detail::relaxStretchPower(s, input.x, input.triangles, 2.0,
                              std::clamp(200'000 / std::max(1, n), 10, 100));
  untangle(s, input.triangles, rings); // a safety net: the stages above flip nothing
  report(progress, 1);

  SphericalMap map;
  map.sphere.assign(mesh.positions.size(), Vec3f{0, 0, 1});
  const auto store = [&](int v) {
    map.sphere[input.original[v]] = {static_cast<float>(s[v].x()), static_cast<float>(s[v].y()),
                                     static_cast<float>(s[v].z())};
  };
  for (int v = 0; v < n; ++v)
    store(v);
  measureSphericalMap(mesh, map);
  // Last resort for slivers that float rounding still flips: pull their corners to the mean of
  // their neighbours and measure again.
  for (int attempt = 0; attempt < 20 && map.flipped > 0; ++attempt) {
    for (const Tri& t : input.triangles) {
      const Vec3f a = map.sphere[input.original[t[0]]], b = map.sphere[input.original[t[1]]],
                  c = map.sphere[input.original[t[2]]];
      if (orientation({a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}) > 0) continue;
      for (int v : t) {
        Vec3d sum = Vec3d::Zero();
        for (int k = rings.start[v]; k < rings.start[v + 1]; ++k)
          sum += s[rings.adj[k]];
        if (sum.norm() > 1e-12) s[v] = sum.normalized();
        store(v);
      }
    }
    measureSphericalMap(mesh, map);
  }
  return map;
}

void measureSphericalMap(const TriangleMesh& mesh, SphericalMap& map) {
  if (map.sphere.size() != mesh.positions.size())
    throw Error(ErrorKind::InvalidArgument,
                "the spherical map has " + std::to_string(map.sphere.size()) +
                    " points but the mesh has " + std::to_string(mesh.positions.size()) +
                    " vertices");
  Points s(mesh.positions.size()), x(mesh.positions.size());
  for (std::size_t v = 0; v < s.size(); ++v) {
    const Vec3f p = map.sphere[v], q = mesh.positions[v];
    s[v] = {p.x, p.y, p.z};
    x[v] = {q.x, q.y, q.z};
  }
  std::vector<Tri> triangles;
  triangles.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    triangles.push_back({static_cast<int>(t[0]), static_cast<int>(t[1]), static_cast<int>(t[2])});
  const StretchSummary summary = stretch(s, x, triangles);
  map.flipped = summary.flipped;
  map.stretchL2 = static_cast<float>(summary.l2);
  map.stretchLinf = static_cast<float>(summary.linf);
}

} // namespace octaclay::core
