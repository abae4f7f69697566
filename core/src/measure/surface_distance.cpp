// Based on: Cignoni, Rocchini & Scopigno, "Metro: measuring error on simplified surfaces" (1998).
#include "octaclay/core/measure/surface_distance.h"

#include "detail/aabb_tree.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <limits>
#include <random>
#include <span>
#include <string>
#include <thread>
#include <vector>

namespace octaclay::core {

namespace {

using detail::AabbTree;
using detail::Vec3d;

// Queries are handed out in chunks this long; each chunk restarts its warm-start hint, so
// results do not depend on how chunks fall to threads.
constexpr std::size_t chunkSize = 4096;

void validate(const TriangleMesh& mesh, const char* name) {
  if (mesh.triangles.empty())
    throw Error(ErrorKind::InvalidInput,
                std::string("cannot compare surfaces: mesh ") + name + " has no triangles");
  if (mesh.triangles.size() >= AabbTree::noTriangle)
    throw Error(ErrorKind::InvalidInput, std::string("cannot compare surfaces: mesh ") + name +
                                             " has more than 2^32 - 2 triangles");
  const std::size_t vertexCount = mesh.positions.size();
  for (const auto& triangle : mesh.triangles)
    for (const std::uint32_t v : triangle) {
      if (v >= vertexCount)
        throw Error(ErrorKind::InvalidInput, std::string("cannot compare surfaces: mesh ") + name +
                                                 " has a triangle index " + std::to_string(v) +
                                                 " past its " + std::to_string(vertexCount) +
                                                 " positions");
      const Vec3f& p = mesh.positions[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
        throw Error(ErrorKind::InvalidInput, std::string("cannot compare surfaces: mesh ") + name +
                                                 " has a non-finite position at vertex " +
                                                 std::to_string(v));
    }
}

// Diagonal of the box around all positions, in double so that it matches the distances.
double boxDiagonal(const TriangleMesh& mesh) {
  Vec3f low = mesh.positions.front(), high = low;
  for (const Vec3f& p : mesh.positions) {
    low = {std::min(low.x, p.x), std::min(low.y, p.y), std::min(low.z, p.z)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y), std::max(high.z, p.z)};
  }
  const Vec3d extent = Vec3d(high) - Vec3d(low);
  return std::sqrt(dot(extent, extent));
}

// Uniform in [0, 1) from the top 53 bits, the same on every standard library.
double uniform(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

/// The query points of one surface: each referenced vertex once, then `count` independent
/// area-weighted uniform points. Both are in the tree's leaf order, so consecutive queries are
/// close together and the previous answer is a tight starting bound for the next.
std::vector<Vec3d> samplePoints(const TriangleMesh& mesh, const AabbTree& tree, std::size_t count,
                                std::uint64_t seed, std::size_t maxVertices) {
  std::vector<Vec3d> points;
  std::vector<bool> seen(mesh.positions.size(), false);
  for (const std::uint32_t id : tree.triangleIds())
    for (const std::uint32_t v : mesh.triangles[id])
      if (!seen[v]) {
        seen[v] = true;
        points.emplace_back(mesh.positions[v]);
      }
  if (points.size() > maxVertices) { // every k-th, spread over the surface (leaf order)
    const std::size_t stride =
        (points.size() + maxVertices - 1) / std::max<std::size_t>(1, maxVertices);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < points.size(); k += stride)
      points[kept++] = points[k];
    points.resize(kept);
  }

  const std::span<const AabbTree::Triangle> triangles = tree.triangles();
  std::vector<double> cumulativeArea(triangles.size());
  double area = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const Vec3d a(triangles[t].a), b(triangles[t].b), c(triangles[t].c);
    const Vec3d n = cross(b - a, c - a);
    area += 0.5 * std::sqrt(dot(n, n));
    cumulativeArea[t] = area;
  }
  if (!(area > 0) || count == 0) return points;

  // Sorted uniforms come from normalised partial sums of exponential variates, which lets one
  // forward walk over the cumulative areas pick each point's triangle in O(N + T).
  std::mt19937_64 random(seed);
  std::vector<double> spacing(count + 1);
  double total = 0;
  for (double& s : spacing) {
    s = -std::log1p(-uniform(random));
    total += s;
  }
  points.reserve(points.size() + count);
  const double scale = area / total;
  double partial = 0;
  std::size_t t = 0;
  for (std::size_t i = 0; i < count; ++i) {
    partial += spacing[i];
    const double target = partial * scale;
    while (t + 1 < triangles.size() && cumulativeArea[t] <= target)
      ++t;
    double u = uniform(random), v = uniform(random);
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    const Vec3d a(triangles[t].a), b(triangles[t].b), c(triangles[t].c);
    points.push_back(a + (b - a) * u + (c - a) * v);
  }
  return points;
}

struct Side {
  AabbTree tree;
  std::vector<Vec3d> points;
};

Side prepare(const TriangleMesh& mesh, std::size_t count, std::uint64_t seed,
             std::size_t maxVertices) {
  Side side{AabbTree(mesh), {}};
  side.points = samplePoints(mesh, side.tree, count, seed, maxVertices);
  return side;
}

struct Chunk {
  const AabbTree* target;
  std::span<const Vec3d> points;
  std::uint32_t leavesPerQuery;
  double sumSquared = 0;
  double maxSquared = 0;
  std::size_t bounded = 0;
};

void measure(Chunk& chunk) {
  std::uint32_t hint = AabbTree::noTriangle;
  for (const Vec3d& p : chunk.points) {
    const AabbTree::Hit hit = chunk.target->closest(p, hint, chunk.leavesPerQuery);
    hint = hit.triangle;
    chunk.bounded += hit.bounded;
    chunk.sumSquared += hit.distanceSquared;
    chunk.maxSquared = std::max(chunk.maxSquared, hit.distanceSquared);
  }
}

} // namespace

SurfaceDistance compareSurfaces(const TriangleMesh& a, const TriangleMesh& b,
                                const SurfaceDistanceOptions& options) {
  validate(a, "a");
  validate(b, "b");
  SurfaceDistance result;
  result.diagonal = boxDiagonal(a);
  if (!(result.diagonal > 0))
    throw Error(ErrorKind::InvalidInput,
                "cannot compare surfaces: mesh a has a zero-size bounding box, so relative "
                "distances are undefined");

  // The two sides are independent until the queries: build them side by side. Each has its
  // own random stream so the samples do not depend on that order.
  auto futureB = std::async(std::launch::async, prepare, std::cref(b), options.samplesPerSurface,
                            options.seed ^ 0x9e3779b97f4a7c15ULL, options.maxVertices);
  const Side sideA = prepare(a, options.samplesPerSurface, options.seed, options.maxVertices);
  const Side sideB = futureB.get();

  const std::uint32_t leaves = std::max<std::uint32_t>(1, options.leavesPerQuery);
  // The pilot: about 2048 queries spread over both directions say what the whole would cost.
  const std::size_t queries = sideA.points.size() + sideB.points.size();
  const std::size_t pilotStep = std::max<std::size_t>(1, queries / 2048);
  double pilotLeaves = 0;
  std::size_t pilotQueries = 0;
  for (const auto& [from, to] : {std::pair{&sideA, &sideB}, std::pair{&sideB, &sideA}})
    for (std::size_t k = 0; k < from->points.size(); k += pilotStep, ++pilotQueries)
      pilotLeaves += to->tree.closest(from->points[k], AabbTree::noTriangle, leaves).leaves;
  const double estimate =
      pilotQueries ? pilotLeaves / static_cast<double>(pilotQueries) * static_cast<double>(queries)
                   : 0;
  const double budget = std::max<double>(1, static_cast<double>(options.leafBudget));
  result.stride = estimate > budget ? static_cast<std::size_t>(std::ceil(estimate / budget)) : 1;

  // Every stride-th point of each side (all of them when the budget allows).
  std::vector<Vec3d> pickedA, pickedB;
  const auto picked = [&result](const std::vector<Vec3d>& all, std::vector<Vec3d>& keep) {
    if (result.stride == 1) return std::span<const Vec3d>(all);
    for (std::size_t k = 0; k < all.size(); k += result.stride)
      keep.push_back(all[k]);
    return std::span<const Vec3d>(keep);
  };
  const std::span<const Vec3d> fromA = picked(sideA.points, pickedA);
  const std::span<const Vec3d> fromB = picked(sideB.points, pickedB);

  std::vector<Chunk> chunks;
  const auto addChunks = [&chunks, leaves](std::span<const Vec3d> points, const Side& to) {
    for (std::size_t begin = 0; begin < points.size(); begin += chunkSize)
      chunks.push_back(
          {&to.tree, points.subspan(begin, std::min(chunkSize, points.size() - begin)), leaves});
  };
  addChunks(fromA, sideB);
  addChunks(fromB, sideA);

  std::atomic<std::size_t> next{0};
  const auto work = [&chunks, &next] {
    for (std::size_t i; (i = next.fetch_add(1, std::memory_order_relaxed)) < chunks.size();)
      measure(chunks[i]);
  };
  const std::size_t threadCount =
      std::min<std::size_t>(std::max(1u, std::thread::hardware_concurrency()), chunks.size());
  std::vector<std::future<void>> workers;
  for (std::size_t i = 1; i < threadCount; ++i)
    workers.push_back(std::async(std::launch::async, work));
  work();
  for (auto& worker : workers)
    worker.get();

  // Summed in chunk order, so the result is the same for any thread count.
  double sumSquared = 0, maxSquared = 0;
  for (const Chunk& chunk : chunks) {
    sumSquared += chunk.sumSquared;
    maxSquared = std::max(maxSquared, chunk.maxSquared);
    result.boundedQueries += chunk.bounded;
  }
  result.samples = fromA.size() + fromB.size();
  result.rms = std::sqrt(sumSquared / static_cast<double>(result.samples)) / result.diagonal;
  result.hausdorff = std::sqrt(maxSquared) / result.diagonal;
  result.psnr =
      result.rms > 0 ? 20 * std::log10(1 / result.rms) : std::numeric_limits<double>::infinity();
  return result;
}

} // namespace octaclay::core
