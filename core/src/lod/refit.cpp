#include "lod/refit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <thread>

namespace octaclay::core::detail {
namespace {

std::vector<Vec3f> vertexNormals(const TriangleMesh& mesh) {
  std::vector<Vec3f> normals(mesh.positions.size());
  for (const auto& t : mesh.triangles) {
    const Vec3f p = mesh.positions[t[0]];
    const Vec3f n = cross(mesh.positions[t[1]] - p, mesh.positions[t[2]] - p);
    for (const std::uint32_t v : t)
      normals[v] += n;
  }
  for (Vec3f& n : normals)
    n = normalize(n);
  return normals;
}

// One full-resolution sample inside one LOD triangle.
struct Covered {
  std::uint32_t texel;    // index into the full image's texels
  std::uint32_t triangle; // index into lod.triangles
  float w1, w2;           // barycentric weights of corners 1 and 2
};

// Whether directed edge d of a counter-clockwise triangle owns the samples on it: of the two
// triangles sharing an edge, which see it in opposite directions, exactly one does.
bool ownsEdge(long long dx, long long dy) {
  return dy > 0 || (dy == 0 && dx < 0);
}

// The samples on the stride lattice that each triangle's corner coordinates enclose, each
// sample in one triangle only: one on a shared edge or corner goes to the triangle whose edge
// owns it (the rasterizer's fill rule), so vertices are not counted once per triangle around
// them. Corner coordinates are whole samples (x / W, y / H), so the edge tests are exact.
void rasterize(int w, int h, const std::vector<std::array<Vec2f, 3>>& cornerUv, std::size_t begin,
               std::size_t end, int stride, std::vector<Covered>& covered) {
  covered.clear(); // the caller reserves: each lattice sample lies in one triangle at most
  const float scaleX = float(w), scaleY = float(h);
  for (std::size_t t = begin; t < end; ++t) {
    const auto& c = cornerUv[t];
    std::array<long long, 3> x{}, y{};
    for (int k = 0; k < 3; ++k) { // whole samples in [0, W]: rounding by truncation is exact
      x[k] = static_cast<long long>(c[k].x * scaleX + 0.5f);
      y[k] = static_cast<long long>(c[k].y * scaleY + 0.5f);
    }
    const long long area = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0]);
    if (area <= 0) continue;
    // Edge k runs from corner k to corner k+1; its function weighs the corner opposite it.
    std::array<bool, 3> owns{};
    for (int k = 0; k < 3; ++k)
      owns[k] = ownsEdge(x[(k + 1) % 3] - x[k], y[(k + 1) % 3] - y[k]);
    const auto edge = [&](int k, long long px, long long py) {
      const int next = (k + 1) % 3;
      return (x[next] - x[k]) * (py - y[k]) - (y[next] - y[k]) * (px - x[k]);
    };
    const auto lattice = [&](long long v, bool up, int limit) {
      const long long k = up ? v / stride : (v + stride - 1) / stride; // v ≥ 0
      return static_cast<int>(std::clamp<long long>(k * stride, 0, limit));
    };
    const int xBegin = lattice(std::min({x[0], x[1], x[2]}), false, w);
    const int xEnd = lattice(std::max({x[0], x[1], x[2]}), true, w);
    const int yBegin = lattice(std::min({y[0], y[1], y[2]}), false, h);
    const int yEnd = lattice(std::max({y[0], y[1], y[2]}), true, h);
    const float inv = 1.0f / float(area);
    for (int py = yBegin; py <= yEnd; py += stride)
      for (int px = xBegin; px <= xEnd; px += stride) {
        const long long e0 = edge(0, px, py), e1 = edge(1, px, py), e2 = edge(2, px, py);
        if (e0 < 0 || e1 < 0 || e2 < 0) continue;
        if ((e0 == 0 && !owns[0]) || (e1 == 0 && !owns[1]) || (e2 == 0 && !owns[2])) continue;
        // e1 (edge 1 → 2) weighs corner 0, e2 corner 1, e0 corner 2.
        covered.push_back({static_cast<std::uint32_t>(py * (w + 1) + px),
                           static_cast<std::uint32_t>(t), float(e2) * inv, float(e0) * inv});
      }
  }
}

// The most memory a thread's sample lists keep between calls (N = 1024 at stride 1 fits).
constexpr std::size_t kKeptBytes = std::size_t(32) << 20;

struct Accumulator {
  std::vector<float> along; // Σ φ n·r per vertex
  std::vector<float> mass;  // Σ φ per vertex
};

} // namespace

void refitToSurface(const GeometryImage& full, const std::vector<std::array<Vec2f, 3>>& cornerUv,
                    TriangleMesh& lod, int stride, int iterations, float maxTurnDegrees) {
  // Rasterized in two halves of the triangles on two threads when there is enough work. The
  // lists keep their memory from call to call up to kKeptBytes (the live LOD refits again and
  // again): fresh pages cost about as much as the rasterizing.
  thread_local std::array<std::vector<Covered>, 2> lists;
  std::vector<Covered>& covered = lists[0];
  std::vector<Covered>& second = lists[1]; // a name the other thread reaches through the capture
  const int width = full.width(), height = full.height();
  const std::size_t lattice = std::size_t(width / stride + 1) *
                              std::size_t(height / stride + 1); // every sample in one triangle
  covered.reserve(lattice);                                     // both halves
  if (cornerUv.size() >= 4096) {
    second.reserve(lattice / 2); // about its share; grows once if it covers more
    const std::size_t half = cornerUv.size() / 2;
    std::thread other(
        [&] { rasterize(width, height, cornerUv, half, cornerUv.size(), stride, second); });
    rasterize(width, height, cornerUv, 0, half, stride, covered);
    other.join();
    covered.insert(covered.end(), second.begin(), second.end());
  } else {
    rasterize(width, height, cornerUv, 0, cornerUv.size(), stride, covered);
  }
  const std::span<const Vec4f> texels = full.texels();
  const std::size_t vertexCount = lod.positions.size();
  std::array<Accumulator, 2> acc;
  // The steps move vertices by a fraction of the sample spacing: their normals barely turn, so
  // the first step's serve them all.
  const std::vector<Vec3f> normals = vertexNormals(lod);
  // Vertices on a sharp crease (a triangle around them turned more than maxTurnDegrees from
  // their averaged normal) stay where they are.
  std::vector<std::uint8_t> pinned(vertexCount, 0);
  if (maxTurnDegrees > 0) {
    const float minCos = std::cos(maxTurnDegrees * float(M_PI) / 180.0f);
    for (const auto& t : lod.triangles) {
      const Vec3f p = lod.positions[t[0]];
      const Vec3f n = normalize(cross(lod.positions[t[1]] - p, lod.positions[t[2]] - p));
      for (const std::uint32_t v : t)
        if (dot(n, normals[v]) < minCos) pinned[v] = 1;
    }
  }
  for (int iteration = 0; iteration < iterations; ++iteration) {
    for (auto& a : acc) {
      a.along.assign(vertexCount, 0);
      a.mass.assign(vertexCount, 0);
    }
    const auto part = [&](std::size_t begin, std::size_t end, Accumulator& out) {
      for (std::size_t k = begin; k < end; ++k) {
        const Covered& s = covered[k];
        const auto& t = lod.triangles[s.triangle];
        const float w0 = 1 - s.w1 - s.w2;
        const Vec3f surface =
            lod.positions[t[0]] * w0 + lod.positions[t[1]] * s.w1 + lod.positions[t[2]] * s.w2;
        const Vec3f r = texels[s.texel].xyz() - surface;
        const float w[3] = {w0, s.w1, s.w2};
        for (int c = 0; c < 3; ++c) {
          out.along[t[c]] += w[c] * dot(normals[t[c]], r);
          out.mass[t[c]] += w[c];
        }
      }
    };
    const std::size_t split = covered.size() / 2;
    if (covered.size() >= 32768) {
      std::thread other([&] { part(split, covered.size(), acc[1]); });
      part(0, split, acc[0]);
      other.join();
    } else {
      part(0, covered.size(), acc[0]);
    }
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const float mass = acc[0].mass[v] + acc[1].mass[v];
      if (mass <= 0 || pinned[v]) continue;
      lod.positions[v] += normals[v] * ((acc[0].along[v] + acc[1].along[v]) / mass);
    }
  }
  for (std::vector<Covered>& list : lists)
    if (list.capacity() * sizeof(Covered) > kKeptBytes) std::vector<Covered>().swap(list);
}

} // namespace octaclay::core::detail
