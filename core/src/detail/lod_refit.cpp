#include "detail/lod_refit.h"

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

// The samples on the stride lattice that each triangle's corner coordinates enclose. A sample
// on an edge shared by two triangles may be taken by both: the fit is a mean, that is harmless.
std::vector<Covered> rasterize(int n, const std::vector<std::array<Vec2f, 3>>& cornerUv,
                               std::size_t begin, std::size_t end, int stride) {
  std::vector<Covered> covered;
  const double share = double(end - begin) / double(std::max<std::size_t>(1, cornerUv.size()));
  covered.reserve(std::size_t(share * double(n / stride + 1) * double(n / stride + 1)) +
                  (end - begin));
  const float scale = float(n);
  for (std::size_t t = begin; t < end; ++t) {
    const auto& c = cornerUv[t];
    const float x0 = c[0].x * scale, y0 = c[0].y * scale;
    const float x1 = c[1].x * scale, y1 = c[1].y * scale;
    const float x2 = c[2].x * scale, y2 = c[2].y * scale;
    const float area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (!(area > 0)) continue;
    const float inv = 1 / area, eps = -1e-4f;
    const auto lattice = [&](float v, bool up) {
      const int k = up ? int(std::floor(v / float(stride))) : int(std::ceil(v / float(stride)));
      return std::clamp(k * stride, 0, n);
    };
    const int xBegin = lattice(std::min({x0, x1, x2}), false);
    const int xEnd = lattice(std::max({x0, x1, x2}), true);
    const int yBegin = lattice(std::min({y0, y1, y2}), false);
    const int yEnd = lattice(std::max({y0, y1, y2}), true);
    for (int y = yBegin; y <= yEnd; y += stride)
      for (int x = xBegin; x <= xEnd; x += stride) {
        const float px = float(x), py = float(y);
        const float w1 = ((px - x0) * (y2 - y0) - (x2 - x0) * (py - y0)) * inv;
        const float w2 = ((x1 - x0) * (py - y0) - (px - x0) * (y1 - y0)) * inv;
        if (w1 < eps || w2 < eps || 1 - w1 - w2 < eps) continue;
        covered.push_back(
            {static_cast<std::uint32_t>(y * (n + 1) + x), static_cast<std::uint32_t>(t), w1, w2});
      }
  }
  return covered;
}

struct Accumulator {
  std::vector<float> along; // Σ φ n·r per vertex
  std::vector<float> mass;  // Σ φ per vertex
};

} // namespace

void refitToSurface(const GeometryImage& full, const std::vector<std::array<Vec2f, 3>>& cornerUv,
                    TriangleMesh& lod, int stride, int iterations) {
  // Rasterized in two halves of the triangles on two threads when there is enough work.
  std::vector<Covered> covered;
  if (cornerUv.size() >= 4096) {
    const std::size_t half = cornerUv.size() / 2;
    std::vector<Covered> second;
    std::thread other(
        [&] { second = rasterize(full.size(), cornerUv, half, cornerUv.size(), stride); });
    covered = rasterize(full.size(), cornerUv, 0, half, stride);
    other.join();
    covered.insert(covered.end(), second.begin(), second.end());
  } else {
    covered = rasterize(full.size(), cornerUv, 0, cornerUv.size(), stride);
  }
  const std::span<const Vec4f> texels = full.texels();
  const std::size_t vertexCount = lod.positions.size();
  std::array<Accumulator, 2> acc;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const std::vector<Vec3f> normals = vertexNormals(lod);
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
      if (mass <= 0) continue;
      lod.positions[v] += normals[v] * ((acc[0].along[v] + acc[1].along[v]) / mass);
    }
  }
}

} // namespace octaclay::core::detail
