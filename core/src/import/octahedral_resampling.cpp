// Based on: Praun & Hoppe, "Spherical parametrization and remeshing" (SIGGRAPH 2003), §5:
// resampling a spherical parameterization on the octahedral domain; point location by a
// visibility walk (Devillers, Pion & Teillaud, "Walking in a triangulation", 2002).
#include "octaclay/core/import/octahedral_resampling.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::core {

namespace {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};

double orientation(const Vec3d& a, const Vec3d& b, const Vec3d& c) {
  return a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) +
         a.z * (b.x * c.y - b.y * c.x);
}

// The sphere triangulation with, for each triangle t and edge k (corner k → corner k+1), the
// triangle across that edge.
struct SphereTriangulation {
  std::vector<Vec3d> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<int, 3>> across;
};

SphereTriangulation triangulation(const TriangleMesh& mesh, const SphericalMap& map) {
  if (map.sphere.size() != mesh.positions.size())
    throw Error(ErrorKind::InvalidArgument,
                "the spherical map has " + std::to_string(map.sphere.size()) +
                    " points but the mesh has " + std::to_string(mesh.positions.size()) +
                    " vertices");
  if (mesh.triangles.empty())
    throw Error(ErrorKind::InvalidArgument, "cannot resample a mesh without triangles");
  SphereTriangulation out;
  out.points.reserve(map.sphere.size());
  for (const Vec3f& p : map.sphere)
    out.points.push_back({p.x, p.y, p.z});
  out.triangles = mesh.triangles;
  for (const auto& t : out.triangles)
    for (std::uint32_t v : t)
      if (v >= out.points.size())
        throw Error(ErrorKind::InvalidArgument, "a triangle index is out of range");
  // Half-edges sorted by (from, to); the triangle across (a → b) owns (b → a).
  struct HalfEdge {
    std::uint32_t from, to;
    int triangle;
  };
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(out.triangles.size() * 3);
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      halfEdges.push_back(
          {out.triangles[t][k], out.triangles[t][(k + 1) % 3], static_cast<int>(t)});
  const auto less = [](const HalfEdge& a, const HalfEdge& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  };
  std::sort(halfEdges.begin(), halfEdges.end(), less);
  out.across.assign(out.triangles.size(), {-1, -1, -1});
  for (std::size_t t = 0; t < out.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const HalfEdge key{out.triangles[t][(k + 1) % 3], out.triangles[t][k], 0};
      const auto it = std::lower_bound(halfEdges.begin(), halfEdges.end(), key, less);
      if (it != halfEdges.end() && it->from == key.from && it->to == key.to)
        out.across[t][k] = it->triangle;
    }
  return out;
}

struct Location {
  int triangle = 0;
  std::array<double, 3> weights{1, 0, 0};
};

// Gnomonic barycentric coordinates of direction d in triangle t: those of the point where the
// ray along d meets the triangle's plane, so they agree along a shared edge from either side.
// Negative weights are clamped (d slightly outside, from a fallback).
Location weightsIn(const SphereTriangulation& mesh, int t, const Vec3d& d) {
  const auto& f = mesh.triangles[t];
  const Vec3d &a = mesh.points[f[0]], &b = mesh.points[f[1]], &c = mesh.points[f[2]];
  std::array<double, 3> w{std::max(0.0, orientation(b, c, d)), std::max(0.0, orientation(c, a, d)),
                          std::max(0.0, orientation(a, b, d))};
  const double sum = w[0] + w[1] + w[2];
  if (sum > 0)
    for (double& x : w)
      x /= sum;
  else
    w = {1.0 / 3, 1.0 / 3, 1.0 / 3};
  return {t, w};
}

// The smallest of the three edge orientations of d against triangle t (≥ 0 inside).
double insideness(const SphereTriangulation& mesh, int t, const Vec3d& d) {
  const auto& f = mesh.triangles[t];
  const Vec3d &a = mesh.points[f[0]], &b = mesh.points[f[1]], &c = mesh.points[f[2]];
  const double facing = d.x * (a.x + b.x + c.x) + d.y * (a.y + b.y + c.y) + d.z * (a.z + b.z + c.z);
  if (facing <= 0) return -std::numeric_limits<double>::infinity();
  return std::min({orientation(a, b, d), orientation(b, c, d), orientation(c, a, d)});
}

// Walks from `start` across the edge d lies beyond until d is inside; on a bijective map this
// ends after about √T steps from anywhere, O(1) from a neighbouring sample's triangle. A walk
// that runs too long (a flipped map) falls back to the triangle that best contains d.
Location locate(const SphereTriangulation& mesh, int start, const Vec3d& d) {
  int t = start;
  const int limit = 64 + 8 * static_cast<int>(std::sqrt(double(mesh.triangles.size())));
  unsigned rotate = 0;
  for (int step = 0; step < limit; ++step) {
    const auto& f = mesh.triangles[t];
    const Vec3d* p[3] = {&mesh.points[f[0]], &mesh.points[f[1]], &mesh.points[f[2]]};
    int exit = -1;
    // Starting the edge test at a rotating corner keeps the walk from cycling.
    for (int e = 0; e < 3 && exit < 0; ++e) {
      const int k = static_cast<int>((rotate + static_cast<unsigned>(e)) % 3);
      if (orientation(*p[k], *p[(k + 1) % 3], d) < 0) exit = k;
    }
    ++rotate;
    if (exit < 0) {
      if (insideness(mesh, t, d) >= 0) return weightsIn(mesh, t, d);
      break; // the antipodal triangle: only a broken map gets here
    }
    const int next = mesh.across[t][exit];
    if (next < 0) break;
    t = next;
  }
  int best = 0;
  double bestInside = -std::numeric_limits<double>::infinity();
  for (int u = 0; u < static_cast<int>(mesh.triangles.size()); ++u) {
    const double inside = insideness(mesh, u, d);
    if (inside > bestInside) {
      bestInside = inside;
      best = u;
    }
  }
  return weightsIn(mesh, best, d);
}

// Calls sample(i, j, location) for every sample of an n grid, rows in parallel.
template <class Sample>
void forEachLocation(const SphereTriangulation& mesh, int n, Sample&& sample) {
  detail::parallelRows(
      n + 1,
      [&](int rowBegin, int rowEnd) {
        int t = 0;
        for (int j = rowBegin; j < rowEnd; ++j) {
          int rowStart = t;
          for (int i = 0; i <= n; ++i) {
            const Vec3f dir = octahedralDirection(n, i, j);
            const Location at = locate(mesh, i == 0 ? rowStart : t, {dir.x, dir.y, dir.z});
            t = at.triangle;
            if (i == 0) rowStart = t;
            sample(i, j, at);
          }
          t = rowStart;
        }
      },
      16);
}

// The geometry image of resampleOctahedral; extra(i, j, location) is called for every sample
// too, from several threads (rows in parallel), so that a layer is filled in the same walk.
template <class Extra>
GeometryImage resample(const TriangleMesh& mesh, const SphericalMap& map, int n, Extra&& extra) {
  requireValidSize(n);
  const SphereTriangulation sphere = triangulation(mesh, map);
  GeometryImage image(n);
  forEachLocation(sphere, n, [&](int i, int j, const Location& at) {
    const auto& f = sphere.triangles[at.triangle];
    const Vec3f p = mesh.positions[f[0]] * static_cast<float>(at.weights[0]) +
                    mesh.positions[f[1]] * static_cast<float>(at.weights[1]) +
                    mesh.positions[f[2]] * static_cast<float>(at.weights[2]);
    image.at(i, j) = {p.x, p.y, p.z, 0.0f};
    extra(i, j, at);
  });
  seam(image);
  return image;
}

// Gives each set of identified samples of a layer (N+1)² × channels their mean, as seam()
// does for positions: they share a direction, but one that lies on an edge may have been
// located in either triangle, and a texture seam there gives the two different colours.
void seamLayer(std::vector<float>& texels, int n, int channels) {
  const auto index = [&](Sample s) {
    return (static_cast<std::size_t>(s.j) * static_cast<std::size_t>(n + 1) +
            static_cast<std::size_t>(s.i)) *
           static_cast<std::size_t>(channels);
  };
  std::array<Sample, 4> same;
  const auto visit = [&](Sample s) {
    if (!(canonical(n, s) == s)) return;
    const int count = identifiedSamples(n, s, same);
    if (count < 2) return;
    for (int c = 0; c < channels; ++c) {
      float sum = 0;
      for (int k = 0; k < count; ++k)
        sum += texels[index(same[k]) + c];
      for (int k = 0; k < count; ++k)
        texels[index(same[k]) + c] = sum / static_cast<float>(count);
    }
  };
  // Only border samples are identified with others.
  for (int i = 0; i <= n; ++i) {
    visit({i, 0});
    visit({i, n});
  }
  for (int j = 1; j < n; ++j) {
    visit({0, j});
    visit({n, j});
  }
}

// Texel (x, y) of `texture` as RGBA, whatever its channel count.
Vec4f texel(const RasterImage& texture, int x, int y) {
  const float* p =
      &texture.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(texture.width) +
                       static_cast<std::size_t>(x)) *
                      static_cast<std::size_t>(texture.channels)];
  switch (texture.channels) {
  case 1:
    return {p[0], p[0], p[0], 1.0f};
  case 2:
    return {p[0], p[0], p[0], p[1]};
  case 3:
    return {p[0], p[1], p[2], 1.0f};
  default:
    return {p[0], p[1], p[2], p[3]};
  }
}

// Bilinear read at (u, v), repeating, v up; texel centres at half-integers.
Vec4f sampleTexture(const RasterImage& texture, float u, float v) {
  const auto fraction = [](float t) {
    const double x = static_cast<double>(t);
    return std::isfinite(x) ? x - std::floor(x) : 0.0;
  };
  const int w = texture.width, h = texture.height;
  const double x = fraction(u) * w - 0.5, y = (1.0 - fraction(v)) * h - 0.5;
  const double x0 = std::floor(x), y0 = std::floor(y);
  const auto fx = static_cast<float>(x - x0), fy = static_cast<float>(y - y0);
  // x0 ∈ [−1, w − 1], so both columns are at most one period away.
  const auto wrap = [](int k, int size) { return k < 0 ? k + size : (k >= size ? k - size : k); };
  const int xa = wrap(static_cast<int>(x0), w), xb = wrap(static_cast<int>(x0) + 1, w);
  const int ya = wrap(static_cast<int>(y0), h), yb = wrap(static_cast<int>(y0) + 1, h);
  const Vec4f a = texel(texture, xa, ya), b = texel(texture, xb, ya);
  const Vec4f c = texel(texture, xa, yb), d = texel(texture, xb, yb);
  const auto mix = [&](float p, float q, float r, float s) {
    return (1 - fy) * ((1 - fx) * p + fx * q) + fy * ((1 - fx) * r + fx * s);
  };
  return {mix(a.x, b.x, c.x, d.x), mix(a.y, b.y, c.y, d.y), mix(a.z, b.z, c.z, d.z),
          mix(a.w, b.w, c.w, d.w)};
}

} // namespace

std::vector<SampleLocation> locateOctahedralSamples(const TriangleMesh& mesh,
                                                    const SphericalMap& map, int n) {
  requireValidSize(n);
  const SphereTriangulation sphere = triangulation(mesh, map);
  const auto side = static_cast<std::size_t>(n + 1);
  std::vector<SampleLocation> out(side * side);
  forEachLocation(sphere, n, [&](int i, int j, const Location& at) {
    out[static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)] = {
        static_cast<std::uint32_t>(at.triangle),
        {static_cast<float>(at.weights[0]), static_cast<float>(at.weights[1]),
         static_cast<float>(at.weights[2])}};
  });
  return out;
}

GeometryImage resampleOctahedral(const TriangleMesh& mesh, const SphericalMap& map, int n) {
  return resample(mesh, map, n, [](int, int, const Location&) {});
}

Document importToDocument(const TriangleMesh& mesh, const SphericalMap& map, int n,
                          std::span<const Vec4f> vertexColours) {
  if (!vertexColours.empty() && vertexColours.size() != mesh.positions.size())
    throw Error(ErrorKind::InvalidArgument, "expected one colour per vertex (" +
                                                std::to_string(mesh.positions.size()) + "), got " +
                                                std::to_string(vertexColours.size()));
  if (vertexColours.empty()) return makeDocument(resampleOctahedral(mesh, map, n));
  requireValidSize(n);
  const auto side = static_cast<std::size_t>(n + 1);
  std::vector<float> texels(side * side * 4, 0.0f);
  Document document = makeDocument(resample(mesh, map, n, [&](int i, int j, const Location& at) {
    const auto& f = mesh.triangles[static_cast<std::size_t>(at.triangle)];
    float* out = &texels[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * 4];
    for (int k = 0; k < 3; ++k) {
      const Vec4f c = vertexColours[f[k]];
      const auto w = static_cast<float>(at.weights[k]);
      out[0] += w * c.x;
      out[1] += w * c.y;
      out[2] += w * c.z;
      out[3] += w * c.w;
    }
  }));
  seamLayer(texels, n, 4);
  document.diffuse.texels = std::move(texels);
  return document;
}

Document importToDocument(const TriangleMesh& mesh, const SphericalMap& map, int n,
                          std::span<const CornerUv> cornerUv, const RasterImage& texture) {
  if (cornerUv.size() != mesh.triangles.size())
    throw Error(ErrorKind::InvalidArgument, "expected texture coordinates for each of the " +
                                                std::to_string(mesh.triangles.size()) +
                                                " triangles, got " +
                                                std::to_string(cornerUv.size()));
  if (texture.width <= 0 || texture.height <= 0 || texture.channels < 1 || texture.channels > 4 ||
      texture.pixels.size() != static_cast<std::size_t>(texture.width) *
                                   static_cast<std::size_t>(texture.height) *
                                   static_cast<std::size_t>(texture.channels))
    throw Error(ErrorKind::InvalidArgument,
                "the texture is empty or its pixels do not match its size (" +
                    std::to_string(texture.width) + " x " + std::to_string(texture.height) + " x " +
                    std::to_string(texture.channels) + ")");
  requireValidSize(n);
  const auto side = static_cast<std::size_t>(n + 1);
  std::vector<float> texels(side * side * 4, 0.0f);
  Document document = makeDocument(resample(mesh, map, n, [&](int i, int j, const Location& at) {
    const CornerUv& uv = cornerUv[static_cast<std::size_t>(at.triangle)];
    float u = 0, v = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const auto w = static_cast<float>(at.weights[k]);
      u += w * uv[k][0];
      v += w * uv[k][1];
    }
    const Vec4f c = sampleTexture(texture, u, v);
    float* out = &texels[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * 4];
    out[0] = c.x;
    out[1] = c.y;
    out[2] = c.z;
    out[3] = c.w;
  }));
  seamLayer(texels, n, 4);
  document.diffuse.texels = std::move(texels);
  return document;
}

} // namespace octaclay::core
