// Shapes and LODs the LOD export tests (core and GL) share.
#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/lod/lod.h"

#include <cmath>

namespace octaclay::core::testing {

/// A unit sphere with bumps a coarse LOD cannot follow: radius 1 + a·sin(f·x)·sin(f·y)·sin(f·z)
/// of the direction, so identified samples are equal (seamed by construction).
inline GeometryImage bumpySphere(int n, float amplitude = 0.04f, float frequency = 9.0f) {
  GeometryImage image(n);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f d = octahedralDirection(n, i, j);
      const float r = 1.0f + amplitude * std::sin(frequency * d.x) * std::sin(frequency * d.y) *
                                 std::sin(frequency * d.z);
      const Vec3f p = d * r;
      image.at(i, j) = {p.x, p.y, p.z, 0};
    }
  return image;
}

/// The plain subsampled grid as an LodMesh (every N/M-th sample, cornerUv from the grid): a
/// reference whose frame and coordinates the tests know exactly.
inline LodMesh gridLod(const GeometryImage& full, int m) {
  const int n = full.size(), step = n / m;
  LodMesh lod;
  lod.mesh = extractMesh(full, step);
  lod.resampledSize = m;
  lod.cornerUv.reserve(lod.mesh.triangles.size());
  const auto uv = [m](int i, int j) {
    return Vec2f{static_cast<float>(i) / static_cast<float>(m),
                 static_cast<float>(j) / static_cast<float>(m)};
  };
  // extractMesh writes two triangles per cell, row-major, split as cellSplit says.
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const Vec2f a = uv(i, j), b = uv(i + 1, j), c = uv(i + 1, j + 1), d = uv(i, j + 1);
      if ((i < m / 2) == (j < m / 2)) {
        lod.cornerUv.push_back({a, b, d});
        lod.cornerUv.push_back({b, c, d});
      } else {
        lod.cornerUv.push_back({a, b, c});
        lod.cornerUv.push_back({a, c, d});
      }
    }
  return lod;
}

} // namespace octaclay::core::testing
