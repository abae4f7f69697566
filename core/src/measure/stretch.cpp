// Per-sample spacing and stretch of a geometry image (DESIGN.md, "Stretch"). The stretch of a
// triangle is the largest singular value of its parameterization's Jacobian (Sander, Snyder,
// Gortler & Hoppe, "Texture mapping progressive meshes", 2001: L∞ stretch, Γ), here per one
// sample step rather than per unit of texture space.
#include "octaclay/core/measure/stretch.h"

#include "detail/parallel_rows.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace octaclay::core {
namespace {

struct Vec3d {
  double x = 0, y = 0, z = 0;
};

Vec3d difference(const Vec4f& a, const Vec4f& b) {
  return {double(a.x) - b.x, double(a.y) - b.y, double(a.z) - b.z};
}

double dotD(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// One triangle's area and largest singular value of [du dv], the surface per one sample step
// along i and j. Both are 0 (skipped) when a corner is not finite or the figures overflow.
struct TriangleFigures {
  float area = 0;
  float sigma = 0;
};

TriangleFigures triangleFigures(Vec3d du, Vec3d dv) {
  const double a = dotD(du, du), b = dotD(du, dv), c = dotD(dv, dv);
  const Vec3d n{du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x};
  const double area = 0.5 * std::sqrt(dotD(n, n));
  const double half = 0.5 * (a - c);
  const double sigma = std::sqrt(0.5 * (a + c) + std::sqrt(half * half + b * b));
  if (!std::isfinite(area) || !std::isfinite(sigma) || !(area < 3e38) || !(sigma < 3e38)) return {};
  return {float(area), float(sigma)};
}

// What measure() gathers per texel: a third of the incident triangles' area and their largest
// stretch (both over the whole vertex after fixBorders()), and the surface's total area.
struct VertexFigures {
  int n = 0;
  std::vector<float> area;  // (N+1)², a third of the incident triangles' area
  std::vector<float> sigma; // (N+1)², the largest incident triangle's sigma
  double totalArea = 0;
};

std::size_t texelIndex(int n, int i, int j) {
  return static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
         static_cast<std::size_t>(i);
}

// cellSplit() for a cell inside the grid (0 ≤ i, j < N), without its divisions: the square's
// lower-left and upper-right quadrants are split along the anti-diagonal.
bool antiDiagonal(int n, int i, int j) {
  return (2 * i >= n) == (2 * j >= n);
}

// Cell (i, j)'s triangles; see cellTriangles(). Anti-diagonal split: {a, b, d}, {b, c, d};
// main: {a, b, c}, {a, c, d}, with a = (i, j), b = (i+1, j), c = (i+1, j+1), d = (i, j+1).
std::array<TriangleFigures, 2> cellFigures(const GeometryImage& image, int i, int j) {
  const Vec4f& a = image.at(i, j);
  const Vec4f& b = image.at(i + 1, j);
  const Vec4f& c = image.at(i + 1, j + 1);
  const Vec4f& d = image.at(i, j + 1);
  if (antiDiagonal(image.size(), i, j))
    return {triangleFigures(difference(b, a), difference(d, a)),
            triangleFigures(difference(c, d), difference(c, b))};
  return {triangleFigures(difference(b, a), difference(c, b)),
          triangleFigures(difference(c, d), difference(d, a))};
}

// The surface's area, every cell's triangles measured once (in parallel rows) and handed to
// perCell(i, j, figures) too.
template <class PerCell> double surfaceArea(const GeometryImage& image, PerCell&& perCell) {
  const int n = image.size();
  std::vector<double> rowArea(static_cast<std::size_t>(n), 0.0);
  detail::parallelRows(n, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j) {
      double sum = 0;
      for (int i = 0; i < n; ++i) {
        const auto f = cellFigures(image, i, j);
        perCell(i, j, f);
        sum += double(f[0].area) + double(f[1].area);
      }
      rowArea[static_cast<std::size_t>(j)] = sum;
    }
  });
  double total = 0;
  for (double a : rowArea)
    total += a;
  return total;
}

VertexFigures measureVertices(const GeometryImage& image) {
  const int n = image.size();
  VertexFigures out;
  out.n = n;
  if (n < 2) return out;
  const std::size_t cells = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  // Every triangle of the mesh is one triangle of a cell inside the grid: measure each once.
  std::vector<std::array<TriangleFigures, 2>> figures(cells);
  out.totalArea = surfaceArea(image, [&](int i, int j, const std::array<TriangleFigures, 2>& f) {
    figures[static_cast<std::size_t>(j) * static_cast<std::size_t>(n) +
            static_cast<std::size_t>(i)] = f;
  });

  // Gather per texel from the (up to) four cells inside the grid around it. Which of a cell's
  // triangles hold a corner: a and c are in both triangles of a main-diagonal cell, b and d in
  // both of an anti-diagonal one, and otherwise in one (see cellFigures).
  const std::size_t texels = image.texelCount();
  out.area.assign(texels, 0.0f);
  out.sigma.assign(texels, 0.0f);
  detail::parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= n; ++i) {
        float area = 0, sigma = 0;
        const auto take = [&](int ci, int cj, bool first, bool second) {
          if (ci < 0 || cj < 0 || ci >= n || cj >= n) return;
          const auto& f = figures[static_cast<std::size_t>(cj) * static_cast<std::size_t>(n) +
                                  static_cast<std::size_t>(ci)];
          if (first) {
            area += f[0].area;
            sigma = std::max(sigma, f[0].sigma);
          }
          if (second) {
            area += f[1].area;
            sigma = std::max(sigma, f[1].sigma);
          }
        };
        const auto anti = [&](int ci, int cj) {
          return ci >= 0 && cj >= 0 && ci < n && cj < n && antiDiagonal(n, ci, cj);
        };
        const bool ac = anti(i - 1, j - 1), ad = anti(i, j - 1), ab = anti(i - 1, j),
                   aa = anti(i, j);
        take(i - 1, j - 1, !ac, true); // texel is the cell's corner c
        take(i, j - 1, ad, true);      // corner d
        take(i - 1, j, true, ab);      // corner b
        take(i, j, true, !aa);         // corner a
        out.area[texelIndex(n, i, j)] = area / 3.0f;
        out.sigma[texelIndex(n, i, j)] = sigma;
      }
  });

  // Identified border samples are one vertex: each copy holds part of its ring.
  const auto unite = [&](Sample s) {
    if (!(canonical(n, s) == s)) return;
    std::array<Sample, 4> copies;
    const int count = identifiedSamples(n, s, copies);
    float area = 0, sigma = 0;
    for (int k = 0; k < count; ++k) {
      area += out.area[texelIndex(n, copies[k].i, copies[k].j)];
      sigma = std::max(sigma, out.sigma[texelIndex(n, copies[k].i, copies[k].j)]);
    }
    for (int k = 0; k < count; ++k) {
      out.area[texelIndex(n, copies[k].i, copies[k].j)] = area;
      out.sigma[texelIndex(n, copies[k].i, copies[k].j)] = sigma;
    }
  };
  for (int k = 0; k <= n; ++k) {
    unite({k, 0});
    unite({k, n});
  }
  for (int k = 1; k < n; ++k) { // the corners were united above, and only once
    unite({0, k});
    unite({n, k});
  }
  return out;
}

double vertexCount(int n) {
  return double(n) * double(n) + 2.0;
}

// The q-quantile (0 ≤ q ≤ 1) of values by nearest rank; reorders values. 0 when empty.
double quantile(std::vector<float>& values, double q) {
  if (values.empty()) return 0;
  const auto k = static_cast<std::size_t>(std::llround(q * double(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

} // namespace

double meanSpacing(const GeometryImage& image) {
  const int n = image.size();
  if (n < 2) return 0.0;
  // measureVertices' first pass alone, keeping no per-cell figures (a renderer calls this
  // after strokes).
  const double total = surfaceArea(image, [](int, int, const std::array<TriangleFigures, 2>&) {});
  return std::sqrt(total / vertexCount(n));
}

StretchMap measureStretch(const GeometryImage& image) {
  VertexFigures v = measureVertices(image);
  StretchMap map;
  map.n = image.size();
  if (map.n < 2) return map;
  const double mean = std::sqrt(v.totalArea / vertexCount(map.n));
  const float scale = mean > 0 && std::isfinite(mean) ? float(1.0 / mean) : 0.0f;
  map.spacing = std::move(v.area);
  map.stretch = std::move(v.sigma);
  for (float& s : map.spacing)
    s = std::sqrt(s);
  for (float& s : map.stretch)
    s *= scale;
  return map;
}

StretchSummary summarizeStretch(const GeometryImage& image) {
  StretchSummary summary;
  const int n = image.size();
  if (n < 2) return summary;
  // Row j's edges: N to the right (none from the last column), then N+1 down (none from the
  // last row); a non-finite one is marked -1 and left out.
  const std::size_t perRow = 2 * static_cast<std::size_t>(n) + 1;
  std::vector<float> edges(perRow * static_cast<std::size_t>(n + 1), -1.0f);
  detail::parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j) {
      float* row = edges.data() + perRow * static_cast<std::size_t>(j);
      const auto length = [](const Vec4f& p, const Vec4f& q) {
        const Vec3d d = difference(q, p);
        const double l = std::sqrt(dotD(d, d));
        return std::isfinite(l) && l < 3e38 ? float(l) : -1.0f;
      };
      for (int i = 0; i < n; ++i)
        row[i] = length(image.at(i, j), image.at(i + 1, j));
      if (j < n)
        for (int i = 0; i <= n; ++i)
          row[n + i] = length(image.at(i, j), image.at(i, j + 1));
    }
  });
  edges.erase(std::remove(edges.begin(), edges.end(), -1.0f), edges.end());
  if (!edges.empty()) {
    summary.longestEdge = *std::max_element(edges.begin(), edges.end());
    summary.medianEdge = quantile(edges, 0.5);
    // Everything after the median's place is at least the median: the 99th percentile is
    // the same rank among those.
    const auto median = static_cast<std::ptrdiff_t>(std::llround(0.5 * double(edges.size() - 1)));
    const auto rank = static_cast<std::ptrdiff_t>(std::llround(0.99 * double(edges.size() - 1)));
    std::nth_element(edges.begin() + median, edges.begin() + rank, edges.end());
    const double p99 = edges[static_cast<std::size_t>(rank)];
    if (summary.medianEdge > 0) {
      summary.longestOverMedian = summary.longestEdge / summary.medianEdge;
      summary.p99OverMedian = p99 / summary.medianEdge;
    }
  }

  const VertexFigures v = measureVertices(image);
  summary.meanSpacing = std::sqrt(v.totalArea / vertexCount(n));
  std::vector<float> spacing;
  spacing.reserve(static_cast<std::size_t>(vertexCount(n)));
  forEachCanonicalRun(n, [&](int j, int iBegin, int iEnd) {
    for (int i = iBegin; i < iEnd; ++i)
      spacing.push_back(std::sqrt(v.area[texelIndex(n, i, j)]));
  });
  std::vector<float> sorted = spacing;
  const double medianSpacing = quantile(sorted, 0.5);
  std::size_t over = 0;
  for (float s : spacing)
    if (s > 4.0 * medianSpacing) ++over;
  summary.shareOver4x = spacing.empty() ? 0.0 : double(over) / double(spacing.size());
  return summary;
}

RegionSampling regionSampling(const GeometryImage& image,
                              const std::function<bool(const Vec3f&)>& inside) {
  RegionSampling out;
  const int n = image.size();
  if (n < 2) return out;
  const VertexFigures v = measureVertices(image);
  out.vertices = static_cast<std::size_t>(vertexCount(n));
  double regionArea = 0, restArea = 0;
  std::size_t rest = 0;
  forEachCanonicalRun(n, [&](int j, int iBegin, int iEnd) {
    for (int i = iBegin; i < iEnd; ++i) {
      const Vec3f p = image.at(i, j).xyz();
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
      const double area = v.area[texelIndex(n, i, j)];
      if (inside(p)) {
        ++out.samples;
        regionArea += area;
      } else {
        ++rest;
        restArea += area;
      }
    }
  });
  const double total = regionArea + restArea;
  out.areaShare = total > 0 ? regionArea / total : 0.0;
  out.sampleShare = double(out.samples) / double(out.vertices);
  out.fairShare = out.areaShare > 0 ? out.sampleShare / out.areaShare : 0.0;
  if (out.samples > 0 && rest > 0 && restArea > 0)
    out.spacingRatio = std::sqrt((regionArea / double(out.samples)) / (restArea / double(rest)));
  return out;
}

} // namespace octaclay::core
