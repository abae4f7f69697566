// The adaptive LOD's triangulation (detail/lod_adaptive.h): errors computed bottom-up over the
// right-triangle hierarchy, then the hierarchy cut where the errors fall below a threshold.
#include "lod/adaptive.h"

#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

namespace octaclay::core::detail {
namespace {

// A triangle of the hierarchy as sample indices j·(N+1)+i: hypotenuse a–b, right angle at c,
// counter-clockwise in the image. Its children are (c, a, m) and (b, c, m), m = (a + b) / 2.
struct HierarchyTriangle {
  std::uint32_t a, b, c, m;
};

// Per level, from the roots down, the triangles whose hypotenuse has a midpoint sample, and the
// midpoints on the image border (identified with samples across a seam). The same for every
// image of size N: built once per N.
struct Hierarchy {
  std::vector<std::vector<HierarchyTriangle>> levels;
  std::vector<std::vector<std::uint32_t>> borderMidpoints;
  std::vector<std::uint32_t> canonicalOf; ///< per sample, its canonical sample's index
  /// The canonical samples but the octahedron's six vertices: those a threshold keeps or drops.
  std::vector<std::uint32_t> optional;
  /// Each level sorted by midpoint, so that the two triangles sharing one are neighbours and
  /// the level splits between threads without two writing one sample.
  bool sortedByMidpoint = false;
};

// Sample (i, j) of an image with `side` samples a row as its index j·side + i, and back.
std::uint32_t indexOf(int side, Sample s) {
  return static_cast<std::uint32_t>(s.j * side + s.i);
}
Sample sampleOf(int side, std::uint32_t index) {
  return {int(index) % side, int(index) / side};
}

std::array<HierarchyTriangle, 8> roots(int n) {
  const int side = n + 1, h = n / 2;
  const auto at = [side](int i, int j) { return indexOf(side, {i, j}); };
  std::array<HierarchyTriangle, 8> out{};
  int k = 0;
  for (const int qx : {0, 1})
    for (const int qy : {0, 1}) {
      const int px = qx * n, qyj = qy * n;
      // Upper face (P, Q, C) and lower face (Q, P, K) of quadrant (qx, qy).
      const std::array<std::array<int, 6>, 2> faces{
          {{px, h, h, qyj, h, h}, {h, qyj, px, h, px, qyj}}};
      for (const auto& f : faces) {
        int ax = f[0], ay = f[1], bx = f[2], by = f[3];
        const int cx = f[4], cy = f[5];
        if ((bx - ax) * (cy - ay) - (by - ay) * (cx - ax) < 0) {
          std::swap(ax, bx);
          std::swap(ay, by);
        }
        out[k++] = {at(ax, ay), at(bx, by), at(cx, cy), at((ax + bx) / 2, (ay + by) / 2)};
      }
    }
  return out;
}

Hierarchy buildHierarchy(int n, bool sortByMidpoint) {
  const int side = n + 1;
  Hierarchy h;
  const auto root = roots(n);
  std::vector<HierarchyTriangle> level(root.begin(), root.end());
  while (!level.empty()) {
    std::vector<HierarchyTriangle> next;
    std::vector<std::uint32_t> border;
    for (const HierarchyTriangle& t : level) {
      const Sample m = sampleOf(side, t.m);
      if (m.i == 0 || m.j == 0 || m.i == n || m.j == n) border.push_back(t.m);
      for (const auto& [a, b, c] : {std::array{t.c, t.a, t.m}, std::array{t.b, t.c, t.m}}) {
        const Sample sa = sampleOf(side, a), sb = sampleOf(side, b);
        if ((sa.i + sb.i) % 2 != 0 || (sa.j + sb.j) % 2 != 0) continue; // a leaf: half a cell
        next.push_back({a, b, c, static_cast<std::uint32_t>((a + b) / 2)});
      }
    }
    if (sortByMidpoint)
      std::sort(level.begin(), level.end(),
                [](const HierarchyTriangle& x, const HierarchyTriangle& y) { return x.m < y.m; });
    h.levels.push_back(std::move(level));
    h.borderMidpoints.push_back(std::move(border));
    level = std::move(next);
  }
  h.canonicalOf.resize(static_cast<std::size_t>(side) * side);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      h.canonicalOf[indexOf(side, {i, j})] = indexOf(side, canonical(n, {i, j}));
    }
  std::vector<std::uint32_t> octahedron;
  for (const HierarchyTriangle& r : root)
    for (const std::uint32_t v : {r.a, r.b, r.c})
      octahedron.push_back(h.canonicalOf[v]);
  for (std::uint32_t k = 0; k < h.canonicalOf.size(); ++k)
    if (h.canonicalOf[k] == k &&
        std::find(octahedron.begin(), octahedron.end(), k) == octahedron.end())
      h.optional.push_back(k);
  h.sortedByMidpoint = sortByMidpoint;
  return h;
}

// Kept for N ≤ 1024 (about 2N² triangles of 16 bytes: 37 MB at N = 1024), where the live LOD
// asks for it again and again; built for each call above that (0.6 GB at N = 4096).
std::shared_ptr<const Hierarchy> hierarchy(int n) {
  constexpr int kLargestKept = 1024;
  if (n > kLargestKept) return std::make_shared<const Hierarchy>(buildHierarchy(n, false));
  static std::mutex lock;
  static std::map<int, std::shared_ptr<const Hierarchy>> built;
  const std::lock_guard guard(lock);
  auto& kept = built[n];
  if (!kept) kept = std::make_shared<const Hierarchy>(buildHierarchy(n, true));
  return kept;
}

// How far m lies from the plane of (a, b, c) (from the chord's midpoint where the triangle is
// degenerate); weighted, times √(2 · area): what leaving m out adds to the squared distance
// integrated over the triangle scales as distance² · area, so large triangles split first.
float splitError(Vec3f a, Vec3f b, Vec3f c, Vec3f m, bool weighted) {
  const Vec3f normal = cross(b - a, c - a);
  const float area2 = dot(normal, normal); // (2 · area)²
  if (area2 > 1e-30f)
    return std::abs(dot(m - a, normal)) /
           (weighted ? std::sqrt(std::sqrt(area2)) : std::sqrt(area2));
  const float chord = length(m - (a + b) * 0.5f);
  return weighted ? chord * length(b - a) * 0.70710678f : chord;
}

float above(float e) {
  return std::nextafter(e, std::numeric_limits<float>::infinity());
}

std::vector<float> sampleErrors(const GeometryImage& image, const Hierarchy& h, bool weighted) {
  const int n = image.size(), side = n + 1;
  const auto texels = image.texels();
  std::vector<float> error(texels.size(), 0.0f);
  std::array<Sample, 4> same;
  for (std::size_t l = h.levels.size(); l-- > 0;) {
    const bool children = l + 1 < h.levels.size();
    const std::vector<HierarchyTriangle>& level = h.levels[l];
    const auto part = [&](std::size_t begin, std::size_t end) {
      for (std::size_t k = begin; k < end; ++k) {
        const HierarchyTriangle& t = level[k];
        float e = splitError(texels[t.a].xyz(), texels[t.b].xyz(), texels[t.c].xyz(),
                             texels[t.m].xyz(), weighted);
        // Strictly above its children's: a threshold between equal errors then never keeps a
        // sample without the samples its split depends on.
        if (children)
          e = std::max({e, above(error[(t.c + t.a) / 2]), above(error[(t.b + t.c) / 2])});
        error[t.m] = std::max(error[t.m], e);
      }
    };
    std::size_t split = level.size() / 2;
    if (h.sortedByMidpoint && level.size() >= 32768) {
      while (split < level.size() && level[split].m == level[split - 1].m)
        ++split;
      std::thread other(part, split, level.size());
      part(0, split);
      other.join();
    } else {
      part(0, level.size());
    }
    // Identified samples are one vertex: each copy carries the largest of their errors, so the
    // triangles on both sides of a seam split together.
    for (const std::uint32_t m : h.borderMidpoints[l]) {
      const int count = identifiedSamples(n, sampleOf(side, m), same);
      float e = 0;
      for (int k = 0; k < count; ++k)
        e = std::max(e, error[indexOf(side, same[k])]);
      for (int k = 0; k < count; ++k)
        error[indexOf(side, same[k])] = e;
    }
  }
  return error;
}

// The (rank + 1)-th largest of error[k] over k in samples and how many are larger: a radix
// select on the bits of the (non-negative) floats, which order like the floats.
std::pair<float, std::size_t> largestBut(const std::vector<float>& error,
                                         const std::vector<std::uint32_t>& samples,
                                         std::size_t rank) {
  const auto bits = [&](std::uint32_t k) { return std::bit_cast<std::uint32_t>(error[k]); };
  std::vector<std::uint32_t> histogram(1u << 16, 0);
  for (const std::uint32_t k : samples)
    ++histogram[bits(k) >> 16];
  std::size_t larger = 0;
  auto bin = static_cast<std::uint32_t>(histogram.size() - 1);
  while (larger + histogram[bin] <= rank)
    larger += histogram[bin--];
  std::vector<float> inBin;
  inBin.reserve(histogram[bin]);
  for (const std::uint32_t k : samples)
    if (bits(k) >> 16 == bin) inBin.push_back(error[k]);
  const std::size_t within = rank - larger;
  std::nth_element(inBin.begin(), inBin.begin() + static_cast<std::ptrdiff_t>(within), inBin.end(),
                   std::greater<float>());
  const float value = inBin[within];
  larger += static_cast<std::size_t>(
      std::count_if(inBin.begin(), inBin.end(), [value](float e) { return e > value; }));
  return {value, larger};
}

} // namespace

AdaptiveTriangulation adaptiveTriangulation(const GeometryImage& image, std::size_t targetTriangles,
                                            double maxError) {
  const int n = image.size(), side = n + 1;
  const std::shared_ptr<const Hierarchy> shared = hierarchy(n);
  const Hierarchy& h = *shared;
  // A distance bound needs plain distances; a triangle target is met best in the L2 sense.
  const std::vector<float> error = sampleErrors(image, h, !(maxError > 0));

  // The octahedron's six vertices are always kept; each other kept vertex adds two triangles.
  // Keep the `extra` samples of largest error: all above the (extra + 1)-th largest and as many
  // of those equal to it as fit (their parents' errors are larger, so any of them may go).
  const std::size_t extra = targetTriangles > 8 ? (targetTriangles + 4) / 2 - 6 : 0;
  float threshold = maxError > 0 ? static_cast<float>(maxError) : -1.0f; // kept: errors above
  std::size_t ties = 0; // samples at the threshold also kept
  if (targetTriangles > 0 && extra < h.optional.size()) {
    const auto [value, larger] = largestBut(error, h.optional, extra);
    if (value > threshold) {
      threshold = value;
      ties = extra - larger;
    }
  }
  std::vector<std::uint8_t> keep(image.texelCount(), 0);
  std::size_t kept = 0;
  for (const std::uint32_t k : h.optional) {
    const float e = error[k];
    const bool tie = e == threshold && ties > 0;
    keep[k] = e > threshold || tie;
    ties -= tie;
    kept += keep[k];
  }

  // Only border samples have another canonical sample (a table look-up costs a cache miss).
  const auto canonicalIndex = [&](Sample s) {
    const std::uint32_t k = indexOf(side, s);
    return s.i == 0 || s.j == 0 || s.i == n || s.j == n ? h.canonicalOf[k] : k;
  };
  // The vertices: the octahedron's six and the kept samples, canonical copies only, numbered in
  // index order (one pass in memory order; the cut below then only reads the numbers).
  const std::vector<HierarchyTriangle>& rootLevel = h.levels.front();
  for (const HierarchyTriangle& r : rootLevel)
    for (const std::uint32_t corner : {r.a, r.b, r.c})
      keep[canonicalIndex(sampleOf(side, corner))] = 1;
  AdaptiveTriangulation out;
  const auto texels = image.texels();
  std::vector<std::uint32_t> vertex(image.texelCount(), UINT32_MAX);
  out.mesh.positions.reserve(6 + kept);
  out.vertexSample.reserve(6 + kept);
  for (std::uint32_t k = 0; k < vertex.size(); ++k)
    if (keep[k]) {
      vertex[k] = static_cast<std::uint32_t>(out.mesh.positions.size());
      out.mesh.positions.push_back(texels[k].xyz());
      out.vertexSample.push_back(sampleOf(side, k));
    }

  // The cut: from each root down to the triangles whose midpoint is dropped. The roots are
  // split between two threads when the mesh is large; each lists its triangles in root order.
  struct Cut {
    std::vector<std::array<std::uint32_t, 3>> triangles;
    std::vector<std::array<Vec2f, 3>> cornerUv;
  };
  const float inv = 1.0f / float(n);
  const auto uv = [inv](Sample s) { return Vec2f{float(s.i) * inv, float(s.j) * inv}; };
  const auto cut = [&](std::size_t firstRoot, std::size_t endRoot, std::size_t expected) {
    Cut c;
    c.triangles.reserve(expected);
    c.cornerUv.reserve(expected);
    std::vector<std::array<Sample, 3>> stack; // hypotenuse a-b, right angle at c
    for (std::size_t r = endRoot; r-- > firstRoot;)
      stack.push_back({sampleOf(side, rootLevel[r].a), sampleOf(side, rootLevel[r].b),
                       sampleOf(side, rootLevel[r].c)});
    while (!stack.empty()) {
      const auto [a, b, corner] = stack.back();
      stack.pop_back();
      // A hypotenuse with a midpoint sample splits there when that sample is kept.
      if (((a.i + b.i) | (a.j + b.j)) % 2 == 0) {
        const Sample m{(a.i + b.i) / 2, (a.j + b.j) / 2};
        if (keep[canonicalIndex(m)]) {
          stack.push_back({b, corner, m});
          stack.push_back({corner, a, m});
          continue;
        }
      }
      c.triangles.push_back(
          {vertex[canonicalIndex(a)], vertex[canonicalIndex(b)], vertex[canonicalIndex(corner)]});
      c.cornerUv.push_back({uv(a), uv(b), uv(corner)});
    }
    return c;
  };
  const std::size_t triangles = 2 * (6 + kept) - 4; // closed genus 0: T = 2V - 4
  if (triangles >= 32768) {
    Cut second;
    std::thread other([&] { second = cut(rootLevel.size() / 2, rootLevel.size(), triangles / 2); });
    Cut first = cut(0, rootLevel.size() / 2, triangles); // becomes the output: room for both
    other.join();
    out.mesh.triangles = std::move(first.triangles);
    out.cornerUv = std::move(first.cornerUv);
    out.mesh.triangles.insert(out.mesh.triangles.end(), second.triangles.begin(),
                              second.triangles.end());
    out.cornerUv.insert(out.cornerUv.end(), second.cornerUv.begin(), second.cornerUv.end());
  } else {
    Cut all = cut(0, rootLevel.size(), triangles);
    out.mesh.triangles = std::move(all.triangles);
    out.cornerUv = std::move(all.cornerUv);
  }
  return out;
}

} // namespace octaclay::core::detail
