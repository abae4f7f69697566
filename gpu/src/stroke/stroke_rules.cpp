#include "octaclay/gpu/stroke_rules.h"

#include "value_text.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <vector>

namespace octaclay::gpu {

// NaN fails every comparison: each check is written so that it must pass, never so that it
// must fail.
void requireFinite(const char* what, float v) {
  if (!std::isfinite(v))
    throw core::Error(core::ErrorKind::InvalidArgument,
                      std::string(what) + " " + detail::valueText(v) + " is not a finite number");
}

void requirePathPoint(core::Vec2f uv) {
  if (!(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1))
    throw core::Error(core::ErrorKind::InvalidArgument, "path point (" + detail::valueText(uv.x) +
                                                            ", " + detail::valueText(uv.y) +
                                                            ") is outside [0, 1]");
}

float dabSpacing(const BrushManifest& brush, float spacing) {
  return std::max(spacing > 0 ? spacing : brush.spacing, kMinDabSpacing);
}

float dabShare(const BrushManifest& brush, float spacing) {
  if (brush.category != Category::Sculpt || brush.stroke != StrokeKind::Spaced) return 1.0f;
  return std::clamp(dabSpacing(brush, spacing), kMinDabSpacing, 1.0f);
}

core::GridPoint surfacePointAt(int n, double x, double y) {
  return core::locateGridPoint(n, std::clamp(x, 0.0, double(n)), std::clamp(y, 0.0, double(n)));
}

core::GridPoint surfacePointAt(const core::SampleGrid& grid, double x, double y) {
  return core::locateGridPoint(grid, std::clamp(x, 0.0, double(grid.width)),
                               std::clamp(y, 0.0, double(grid.height)));
}

core::Vec3f interpolateNormal(const core::GeometryImage& image, const core::GridPoint& p) {
  core::Vec3f sum;
  for (std::size_t k = 0; k < 3; ++k)
    sum += core::gridNormal(image, p.corners[k]) * p.weights[k];
  if (core::length(sum) > 1e-6f) return core::normalize(sum);
  const auto nearest = std::max_element(p.weights.begin(), p.weights.end()) - p.weights.begin();
  return core::gridNormal(image, p.corners[static_cast<std::size_t>(nearest)]);
}

namespace {

// How far from centre a point may lie for every triangle with its corners within that distance
// to pass areaNormal's centroid test, with room to spare for float rounding, among the points of
// box: their centroids lie that close up to a few ulps of the coordinates. Negative: none.
double wellInsideReach(const core::BoundingBox& box, core::Vec3f centre, float radius) {
  double scale = 0;
  for (const float v : {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z, centre.x,
                        centre.y, centre.z})
    scale = std::max(scale, std::abs(double(v)));
  // 1e-6 of the coordinates' size is some 8 ulps of float: the centroid's rounding and the
  // test's own; 1e-5 of the radius covers the rounding of its square.
  return double(radius) * (1 - 1e-5) - 1e-6 * scale;
}

// Whether every point of box lies within wellInsideReach of centre: then every triangle of the
// tile's cells (their corners lie in its box) passes the centroid test, and the test can be
// skipped without changing which triangles count.
bool boxWellInside(const core::BoundingBox& box, core::Vec3f centre, float radius) {
  double far2 = 0;
  const float lo[3] = {box.min.x, box.min.y, box.min.z}, hi[3] = {box.max.x, box.max.y, box.max.z};
  const float c[3] = {centre.x, centre.y, centre.z};
  for (int k = 0; k < 3; ++k) {
    const double reach = std::max(std::abs(double(lo[k]) - c[k]), std::abs(double(hi[k]) - c[k]));
    far2 += reach * reach;
  }
  return std::sqrt(far2) <= wellInsideReach(box, centre, radius);
}

// The sum over the cells [x0, x1) × [y0, y1) of each quad's area vector (c − a) × (d − b), the
// sum of its two triangles' whichever the split. A quad's is a×b + b×c + c×d + d×a around it, so
// the edges inside the block cancel and the sum is that of its border loop: 2 (W + H) terms
// instead of W × H quads (a 32² tile: 128 against 1024). Taken about the block's first corner and
// summed in double, so a block far from the origin loses no more than its cells' own sum does.
core::Vec3f blockAreaVector(const core::GeometryImage& image, int x0, int y0, int x1, int y1) {
  const core::Vec3f origin = image.at(x0, y0).xyz();
  double sx = 0, sy = 0, sz = 0;
  core::Vec3f previous; // the loop's last point, about origin: (x0, y0) itself
  const auto to = [&](int i, int j) {
    const core::Vec3f p = image.at(i, j).xyz() - origin;
    sx += double(previous.y) * p.z - double(previous.z) * p.y;
    sy += double(previous.z) * p.x - double(previous.x) * p.z;
    sz += double(previous.x) * p.y - double(previous.y) * p.x;
    previous = p;
  };
  for (int i = x0 + 1; i <= x1; ++i) // a → b along the first row
    to(i, y0);
  for (int j = y0 + 1; j <= y1; ++j) // up the last column
    to(x1, j);
  for (int i = x1 - 1; i >= x0; --i) // back along the last row
    to(i, y1);
  for (int j = y1 - 1; j >= y0; --j) // down the first column, to where it began
    to(x0, j);
  return {float(sx), float(sy), float(sz)};
}

} // namespace

void syncTiles(const GpuDocument& document, std::span<const int> tiles) {
  const core::TileBounds& bounds = document.bounds();
  std::vector<core::TexelRect> rects;
  rects.reserve(tiles.size());
  for (int t : tiles) // a tile's cells reach the first sample past it
    rects.push_back(bounds.tileRect(t % bounds.tilesX(), t / bounds.tilesX()));
  for (core::TexelRect& r : rects)
    r.width += 1, r.height += 1;
  document.syncRegion(rects);
}

void syncAround(const GpuDocument& document, double x, double y) {
  const int n = document.grid().width, h = document.grid().height;
  const int i = static_cast<int>(std::floor(x)), j = static_cast<int>(std::floor(y));
  const int margin = 3;
  std::vector<core::TexelRect> rects{{i - margin, j - margin, 2 * margin + 2, 2 * margin + 2}};
  if (i <= margin || j <= margin || i >= n - margin || j >= h - margin) {
    // Neighbours across a seam (wrap) lie anywhere along the border: its strips, whole.
    const int w = margin + 1;
    rects.push_back({0, 0, n + 1, w});
    rects.push_back({0, h + 1 - w, n + 1, w});
    rects.push_back({0, 0, w, h + 1});
    rects.push_back({n + 1 - w, 0, w, h + 1});
  }
  document.syncRegion(rects);
}

AreaSum areaSumOnCpu(const GpuDocument& document, std::span<const int> near, core::Vec3f centre,
                     float radius) {
  const core::GeometryImage& image = document.mirror().positions;
  const core::TileBounds& bounds = document.bounds();
  syncTiles(document, near);
  const int n = document.grid().width, h = document.grid().height, half = n / 2;
  // The torus and plane split every cell along its anti-diagonal (core::cellTriangles).
  const bool ball = document.topology() == core::Topology::Octahedral;
  const float r2 = radius * radius;
  core::Vec3f sum;
  int triangles = 0;
  const auto add = [&](core::Vec3f a, core::Vec3f b, core::Vec3f c) {
    const core::Vec3f d = (a + b + c) * (1.0f / 3.0f) - centre;
    if (core::dot(d, d) > r2) return;
    sum += core::cross(b - a, c - a);
    ++triangles;
  };
  // Every dab runs this over the cells its radius covers: rows read in place and the cell's
  // split (core::cellTriangles: anti-diagonal where i and j lie in the same half) inline. A tile
  // well inside the sphere (most of them) adds its cells without the centroid test, as the
  // area vector of its block (blockAreaVector: its border alone).
  std::vector<std::uint8_t> insideRow, insideBelow; // per sample of a rim tile's two rows
  for (int t : near) {
    const core::TexelRect r = bounds.tileRect(t % bounds.tilesX(), t / bounds.tilesX());
    const int iEnd = std::min(r.x + r.width, n), jEnd = std::min(r.y + r.height, h);
    if (iEnd <= r.x || jEnd <= r.y) continue;
    if (boxWellInside(bounds.box(t), centre, radius)) {
      sum += blockAreaVector(image, r.x, r.y, iEnd, jEnd);
      triangles += 2 * (iEnd - r.x) * (jEnd - r.y);
      continue;
    }
    // A tile on the rim: a cell whose four corners lie well inside adds its quad's area vector
    // without the centroid tests (as boxWellInside argues for a tile, per sample).
    const double reach = wellInsideReach(bounds.box(t), centre, radius);
    const double reach2 = reach > 0 ? reach * reach : -1.0;
    const auto markInside = [&](const core::Vec4f* samples, std::vector<std::uint8_t>& inside) {
      inside.resize(static_cast<std::size_t>(iEnd - r.x + 1));
      for (int i = r.x; i <= iEnd; ++i) {
        const double dx = double(samples[i].x) - centre.x, dy = double(samples[i].y) - centre.y,
                     dz = double(samples[i].z) - centre.z;
        inside[static_cast<std::size_t>(i - r.x)] = dx * dx + dy * dy + dz * dz <= reach2;
      }
    };
    markInside(&image.at(0, r.y), insideBelow);
    for (int j = r.y; j < jEnd; ++j) {
      const core::Vec4f* row = &image.at(0, j);
      const core::Vec4f* below = &image.at(0, j + 1);
      const bool lowJ = j < half;
      std::swap(insideRow, insideBelow);
      markInside(below, insideBelow);
      for (int i = r.x; i < iEnd; ++i) {
        const core::Vec3f a = row[i].xyz(), b = row[i + 1].xyz(), c = below[i + 1].xyz(),
                          d = below[i].xyz();
        const std::size_t k = static_cast<std::size_t>(i - r.x);
        if (insideRow[k] & insideRow[k + 1] & insideBelow[k] & insideBelow[k + 1]) {
          sum += core::cross(c - a, d - b);
          triangles += 2;
        } else if (!ball || (i < half) == lowJ) {
          add(a, b, d);
          add(b, c, d);
        } else {
          add(a, b, c);
          add(a, c, d);
        }
      }
    }
  }
  return {sum, triangles};
}

core::Vec3f areaNormal(const GpuDocument& document, core::Vec3f centre, float radius,
                       core::Vec3f fallback) {
  const std::vector<int> near = document.bounds().tilesNearSphere(centre, radius);
  // A GPU reduces it and reads back the quarters' sums, not the texels under the dab; a
  // software rasterizer runs the loop faster on the CPU than as a compute pass.
  const AreaSum area = document.softwareRenderer() ? areaSumOnCpu(document, near, centre, radius)
                                                   : document.areaSum(near, centre, radius);
  const core::Vec3f sum = area.sum;
  const int triangles = area.triangles;
  // Too few triangles to average (samples far apart on a stretched tip): the point normal.
  if (triangles < kAreaNormalTriangles || !(core::length(sum) > 1e-20f)) return fallback;
  return core::normalize(sum);
}

} // namespace octaclay::gpu
