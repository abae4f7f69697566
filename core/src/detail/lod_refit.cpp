#include "detail/lod_refit.h"

#include <array>
#include <thread>
#include <vector>

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

struct Accumulator {
  std::vector<float> along; // Σ φ n·r per vertex
  std::vector<float> mass;  // Σ φ per vertex
};

} // namespace

void refitToSurface(const GeometryImage& full, const VertexIndex& index, TriangleMesh& lod,
                    int stride, int iterations) {
  const int n = full.size(), m = index.size(), step = n / m, half = m / 2;
  const std::size_t vertexCount = lod.positions.size();
  const int rows = n / stride + 1;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const std::vector<Vec3f> normals = vertexNormals(lod);
    std::array<Accumulator, 2> acc;
    for (auto& a : acc) {
      a.along.assign(vertexCount, 0);
      a.mass.assign(vertexCount, 0);
    }
    // Two bands (the machine's two threads), each accumulating into its own arrays.
    const auto band = [&](int rowBegin, int rowEnd, Accumulator& out) {
      for (int row = rowBegin; row < rowEnd; ++row) {
        const int y = row * stride;
        const int cj = std::min(y / step, m - 1);
        const float fy = float(y - cj * step) / float(step);
        const Vec4f* texels = &full.at(0, y);
        for (int x = 0; x <= n; x += stride) {
          const int ci = std::min(x / step, m - 1);
          const float fx = float(x - ci * step) / float(step);
          const std::uint32_t a = index.at(ci, cj), b = index.at(ci + 1, cj);
          const std::uint32_t c = index.at(ci + 1, cj + 1), d = index.at(ci, cj + 1);
          std::array<std::uint32_t, 3> v;
          std::array<float, 3> w;
          if ((ci < half) == (cj < half)) { // anti-diagonal split: abd | bcd
            if (fx + fy <= 1) {
              v = {a, b, d};
              w = {1 - fx - fy, fx, fy};
            } else {
              v = {b, c, d};
              w = {1 - fy, fx + fy - 1, 1 - fx};
            }
          } else if (fx >= fy) { // main diagonal: abc | acd
            v = {a, b, c};
            w = {1 - fx, fx - fy, fy};
          } else {
            v = {a, c, d};
            w = {1 - fy, fx, fy - fx};
          }
          const Vec3f surface =
              lod.positions[v[0]] * w[0] + lod.positions[v[1]] * w[1] + lod.positions[v[2]] * w[2];
          const Vec3f r = texels[x].xyz() - surface;
          for (int k = 0; k < 3; ++k) {
            out.along[v[k]] += w[k] * dot(normals[v[k]], r);
            out.mass[v[k]] += w[k];
          }
        }
      }
    };
    const int split = rows / 2;
    if (rows >= 256) {
      std::thread other([&] { band(split, rows, acc[1]); });
      band(0, split, acc[0]);
      other.join();
    } else {
      band(0, rows, acc[0]);
    }
    for (std::size_t v = 0; v < vertexCount; ++v) {
      const float mass = acc[0].mass[v] + acc[1].mass[v];
      if (mass <= 0) continue;
      const float move = (acc[0].along[v] + acc[1].along[v]) / mass;
      lod.positions[v] += normals[v] * move;
    }
  }
}

} // namespace octaclay::core::detail
