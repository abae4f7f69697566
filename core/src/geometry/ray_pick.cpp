// Based on: Möller & Trumbore 1997, "Fast, minimum storage ray/triangle intersection".
#include "octaclay/core/geometry/ray_pick.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace {

// Entry distance of the ray into box, or +inf when it misses (slab test).
float enterBox(const Ray& ray, const BoundingBox& box) {
  float near = 0, far = std::numeric_limits<float>::max();
  const float o[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
  const float d[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
  const float lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
  for (int a = 0; a < 3; ++a) {
    if (std::abs(d[a]) < 1e-30f) {
      if (o[a] < lo[a] || o[a] > hi[a]) return std::numeric_limits<float>::infinity();
      continue;
    }
    float t0 = (lo[a] - o[a]) / d[a], t1 = (hi[a] - o[a]) / d[a];
    if (t0 > t1) std::swap(t0, t1);
    near = std::max(near, t0);
    far = std::min(far, t1);
    if (near > far) return std::numeric_limits<float>::infinity();
  }
  return near;
}

// Ray/triangle distance with barycentrics (b1, b2), or nullopt. Edges are widened by a hair so a
// ray through a shared edge or vertex cannot slip between the triangles by rounding.
constexpr float kEdgeTolerance = 1e-6f;

std::optional<std::array<float, 3>> hitTriangle(const Ray& ray, Vec3f a, Vec3f b, Vec3f c) {
  const Vec3f e1 = b - a, e2 = c - a;
  const Vec3f p = cross(ray.direction, e2);
  const float det = dot(e1, p);
  if (std::abs(det) < 1e-20f) return std::nullopt;
  const float inv = 1.0f / det;
  const Vec3f s = ray.origin - a;
  const float b1 = dot(s, p) * inv;
  if (b1 < -kEdgeTolerance || b1 > 1 + kEdgeTolerance) return std::nullopt;
  const Vec3f q = cross(s, e1);
  const float b2 = dot(ray.direction, q) * inv;
  if (b2 < -kEdgeTolerance || b1 + b2 > 1 + kEdgeTolerance) return std::nullopt;
  const float t = dot(e2, q) * inv;
  if (t <= 0) return std::nullopt;
  return std::array<float, 3>{t, b1, b2};
}

} // namespace

Ray cameraRay(const Camera& camera, int width, int height, float px, float py) {
  const Vec3f forward = normalize(camera.target - camera.eye);
  const Vec3f right = normalize(cross(forward, camera.up));
  const Vec3f up = cross(right, forward);
  const float tanHalf = std::tan(camera.fovYDegrees * std::numbers::pi_v<float> / 360.0f);
  const float aspect = static_cast<float>(width) / static_cast<float>(height);
  const float x = (2.0f * (px + 0.5f) / static_cast<float>(width) - 1.0f) * tanHalf * aspect;
  const float y = (1.0f - 2.0f * (py + 0.5f) / static_cast<float>(height)) * tanHalf;
  return {camera.eye, normalize(forward + right * x + up * y)};
}

std::optional<PickHit> pickRay(const GeometryImage& image, const TileBounds& bounds,
                               const Ray& ray) {
  const int tiles = bounds.tilesX();
  std::vector<std::pair<float, int>> order;
  for (int t = 0; t < bounds.tileCount(); ++t) {
    const float enter = enterBox(ray, bounds.box(t));
    if (std::isfinite(enter)) order.emplace_back(enter, t);
  }
  std::sort(order.begin(), order.end());

  std::optional<PickHit> best;
  const SampleGrid& grid = image.grid();
  const int w = grid.width, hgt = grid.height;
  for (const auto& [enter, t] : order) {
    if (best && enter > best->distance) break; // every later tile starts beyond the hit
    const TexelRect r = bounds.tileRect(t % tiles, t / tiles);
    // The tile's samples; cells reach one sample further except on the last row or column.
    for (int j = r.y; j < std::min(r.y + r.height, hgt); ++j)
      for (int i = r.x; i < std::min(r.x + r.width, w); ++i)
        for (const auto& tri : cellTriangles(grid, i, j)) {
          const auto hit = hitTriangle(ray, image.at(tri[0]).xyz(), image.at(tri[1]).xyz(),
                                       image.at(tri[2]).xyz());
          if (!hit || (best && (*hit)[0] >= best->distance)) continue;
          const float b1 = (*hit)[1], b2 = (*hit)[2], b0 = 1 - b1 - b2;
          PickHit h;
          h.distance = (*hit)[0];
          h.position = ray.origin + ray.direction * h.distance;
          const float si = b0 * float(tri[0].i) + b1 * float(tri[1].i) + b2 * float(tri[2].i);
          const float sj = b0 * float(tri[0].j) + b1 * float(tri[1].j) + b2 * float(tri[2].j);
          h.u = si / float(w);
          h.v = sj / float(hgt);
          const float weights[3] = {b0, b1, b2};
          h.sample = tri[static_cast<int>(std::max_element(weights, weights + 3) - weights)];
          best = h;
        }
  }
  return best;
}

} // namespace octaclay::core
