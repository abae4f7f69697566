// Normal maps baked from the full-resolution image (thesis 4.1: "the original geometry image is
// used to calculate the object space normals rather than the face normals from the reduced
// mesh"), and their tangent-space form relative to the LOD's own frame.

#include "detail/parallel_rows.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/lod/lod_vertices.h"
#include "octaclay/core/lod/normal_map.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace octaclay::core {
namespace {

constexpr int kMaxResolution = 8192;

// The full mesh's interpolated vertex normal at sample coordinates (s, t) in [0, W] × [0, H]:
// the barycentric blend over the full-resolution triangle holding the point, split as
// extractMesh splits its cell (a torus's or plane's cells all along the anti-diagonal).
class FullNormals {
public:
  explicit FullNormals(const GeometryImage& image)
      : width_(image.width()), height_(image.height()),
        octahedral_(image.topology() == Topology::Octahedral), normals_(image.texelCount()) {
    const int side = image.side();
    detail::parallelRows(image.rows(), [&](int j0, int j1) {
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < side; ++i) {
          const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(side) +
                                static_cast<std::size_t>(i);
          normals_[k] = vertexNormal(image, {i, j});
          // A degenerate neighbourhood has no normal: take the direction from the origin.
          if (length(normals_[k]) == 0) normals_[k] = normalize(image.at(i, j).xyz());
        }
    });
  }

  Vec3f at(float s, float t) const {
    const int i = std::clamp(static_cast<int>(std::floor(s)), 0, width_ - 1);
    const int j = std::clamp(static_cast<int>(std::floor(t)), 0, height_ - 1);
    const float fx = std::clamp(s - static_cast<float>(i), 0.0f, 1.0f);
    const float fy = std::clamp(t - static_cast<float>(j), 0.0f, 1.0f);
    const Vec3f a = normal(i, j), b = normal(i + 1, j), c = normal(i + 1, j + 1),
                d = normal(i, j + 1);
    Vec3f blend;
    if (!octahedral_ || cellSplit(width_, i, j) == CellSplit::AntiDiagonal) {
      // Triangles (a, b, d) and (b, c, d), split along b–d.
      blend = fx + fy <= 1 ? a * (1 - fx - fy) + b * fx + d * fy
                           : b * (1 - fy) + c * (fx + fy - 1) + d * (1 - fx);
    } else {
      // Triangles (a, b, c) and (a, c, d), split along a–c.
      blend =
          fx >= fy ? a * (1 - fx) + b * (fx - fy) + c * fy : a * (1 - fy) + c * fx + d * (fy - fx);
    }
    const Vec3f unit = normalize(blend);
    return length(unit) > 0 ? unit : Vec3f{0, 0, 1};
  }

private:
  Vec3f normal(int i, int j) const {
    return normals_[static_cast<std::size_t>(j) * static_cast<std::size_t>(width_ + 1) +
                    static_cast<std::size_t>(i)];
  }
  int width_, height_;
  bool octahedral_;
  std::vector<Vec3f> normals_;
};

float texelToImage(int x, int resolution) {
  return (static_cast<float>(x) + 0.5f) / static_cast<float>(resolution);
}

// Barycentric coordinates of point p in the triangle of texel-space corners q.
std::array<float, 3> barycentric(const std::array<Vec2f, 3>& q, Vec2f p) {
  const float det = (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
  if (det == 0) return {1.0f / 3, 1.0f / 3, 1.0f / 3};
  const float b1 = ((p.x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (p.y - q[0].y)) / det;
  const float b2 = ((q[1].x - q[0].x) * (p.y - q[0].y) - (p.x - q[0].x) * (q[1].y - q[0].y)) / det;
  return {1 - b1 - b2, b1, b2};
}

// For each texel, the LOD triangle whose image-space footprint holds its centre. Texels that no
// triangle covers (rounding at shared edges, or a fold after vertex collapse) take the triangle
// of a covered neighbour, whose barycentrics are then clamped.
std::vector<int> rasterizeTriangles(const LodVertices& vertices, int resolution) {
  const float r = static_cast<float>(resolution);
  std::vector<int> owner(
      static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution), -1);
  constexpr float kEdge = -1e-5f; // texel centres on a shared edge belong to both
  // Triangles folded over in the image (an LOD vertex whose source sample crossed its
  // neighbour's) overlap unfolded ones; those keep the texels, as they are the majority there.
  for (const bool folded : {false, true})
    for (std::size_t t = 0; t < vertices.triangles.size(); ++t) {
      std::array<Vec2f, 3> q;
      for (int c = 0; c < 3; ++c) {
        const Vec2f uv = vertices.uvs[vertices.triangles[t][static_cast<std::size_t>(c)]];
        q[static_cast<std::size_t>(c)] = {uv.x * r, uv.y * r};
      }
      const float area =
          (q[1].x - q[0].x) * (q[2].y - q[0].y) - (q[2].x - q[0].x) * (q[1].y - q[0].y);
      if ((area <= 0) != folded) continue;
      const auto [xMin, xMax] = std::minmax({q[0].x, q[1].x, q[2].x});
      const auto [yMin, yMax] = std::minmax({q[0].y, q[1].y, q[2].y});
      const int x0 = std::max(0, static_cast<int>(std::floor(xMin - 0.5f)));
      const int x1 = std::min(resolution - 1, static_cast<int>(std::ceil(xMax - 0.5f)));
      const int y0 = std::max(0, static_cast<int>(std::floor(yMin - 0.5f)));
      const int y1 = std::min(resolution - 1, static_cast<int>(std::ceil(yMax - 0.5f)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          int& o = owner[static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution) +
                         static_cast<std::size_t>(x)];
          if (o >= 0) continue;
          const auto b =
              barycentric(q, {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f});
          if (b[0] >= kEdge && b[1] >= kEdge && b[2] >= kEdge) o = static_cast<int>(t);
        }
    }
  // Dilation: each pass gives uncovered texels a covered 4-neighbour's triangle.
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<int> next = owner;
    for (int y = 0; y < resolution; ++y)
      for (int x = 0; x < resolution; ++x) {
        const std::size_t k = static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution) +
                              static_cast<std::size_t>(x);
        if (owner[k] >= 0) continue;
        const std::size_t row = static_cast<std::size_t>(resolution);
        if (x > 0 && owner[k - 1] >= 0)
          next[k] = owner[k - 1];
        else if (x + 1 < resolution && owner[k + 1] >= 0)
          next[k] = owner[k + 1];
        else if (y > 0 && owner[k - row] >= 0)
          next[k] = owner[k - row];
        else if (y + 1 < resolution && owner[k + row] >= 0)
          next[k] = owner[k + row];
        changed = changed || next[k] >= 0;
      }
    owner.swap(next);
  }
  return owner;
}

// x with normalize(x.x·t + x.y·b + x.z·n) = target, as a unit vector.
Vec3f inFrame(Vec3f t, Vec3f b, Vec3f n, Vec3f target) {
  const float det = dot(t, cross(b, n));
  Vec3f x;
  if (std::abs(det) > 1e-6f)
    x = Vec3f{dot(target, cross(b, n)), dot(t, cross(target, n)), dot(t, cross(b, target))} *
        (1.0f / det);
  else
    x = {dot(target, t), dot(target, b), dot(target, n)};
  const Vec3f unit = normalize(x);
  return length(unit) > 0 ? unit : Vec3f{0, 0, 1};
}

} // namespace

std::string_view normalMapSpaceName(NormalMapSpace space) {
  return space == NormalMapSpace::Tangent ? "tangent" : "object";
}

std::optional<NormalMapSpace> parseNormalMapSpace(std::string_view name) {
  if (name == "object") return NormalMapSpace::Object;
  if (name == "tangent") return NormalMapSpace::Tangent;
  return std::nullopt;
}

NormalMap bakeNormalMap(const GeometryImage& full, const LodMesh& lod, NormalMapSpace space,
                        int resolution) {
  if (resolution < 2 || resolution > kMaxResolution)
    throw Error(ErrorKind::InvalidArgument, "normal map resolution " + std::to_string(resolution) +
                                                " is out of range: use 2 to " +
                                                std::to_string(kMaxResolution));
  requireValidGrid(full.grid());
  NormalMap map;
  map.space = space;
  map.resolution = resolution;
  map.texels.resize(static_cast<std::size_t>(resolution) * static_cast<std::size_t>(resolution));
  const FullNormals normals(full);
  const float across = static_cast<float>(full.width()), down = static_cast<float>(full.height());
  const auto fullNormal = [&](int x, int y) {
    return normals.at(texelToImage(x, resolution) * across, texelToImage(y, resolution) * down);
  };

  if (space == NormalMapSpace::Object) {
    detail::parallelRows(resolution, [&](int y0, int y1) {
      for (int y = y0; y < y1; ++y)
        for (int x = 0; x < resolution; ++x)
          map.texels[static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution) +
                     static_cast<std::size_t>(x)] = fullNormal(x, y);
    });
    return map;
  }

  const LodVertices vertices = lodVertices(lod);
  if (vertices.triangles.empty())
    throw Error(ErrorKind::InvalidArgument, "a tangent-space normal map needs an LOD mesh");
  const std::vector<int> owner = rasterizeTriangles(vertices, resolution);
  const float r = static_cast<float>(resolution);
  detail::parallelRows(resolution, [&](int y0, int y1) {
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < resolution; ++x) {
        const std::size_t k = static_cast<std::size_t>(y) * static_cast<std::size_t>(resolution) +
                              static_cast<std::size_t>(x);
        if (owner[k] < 0) { // no triangle anywhere in the map's square
          map.texels[k] = {0, 0, 1};
          continue;
        }
        const auto& tri = vertices.triangles[static_cast<std::size_t>(owner[k])];
        std::array<Vec2f, 3> q;
        for (int c = 0; c < 3; ++c) {
          const Vec2f uv = vertices.uvs[tri[static_cast<std::size_t>(c)]];
          q[static_cast<std::size_t>(c)] = {uv.x * r, uv.y * r};
        }
        auto b = barycentric(q, {static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f});
        for (float& w : b)
          w = std::max(w, 0.0f);
        const float sum = b[0] + b[1] + b[2];
        Vec3f t{}, bt{}, nn{};
        for (int c = 0; c < 3; ++c) {
          const std::uint32_t v = tri[static_cast<std::size_t>(c)];
          const float w = b[static_cast<std::size_t>(c)] / sum;
          const auto& tg = vertices.tangents[v];
          const Vec3f tangent{tg[0], tg[1], tg[2]};
          t += tangent * w;
          bt += cross(vertices.normals[v], tangent) * (tg[3] * w);
          nn += vertices.normals[v] * w;
        }
        map.texels[k] = inFrame(normalize(t), normalize(bt), normalize(nn), fullNormal(x, y));
      }
  });
  return map;
}

} // namespace octaclay::core
