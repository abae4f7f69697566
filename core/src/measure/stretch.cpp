// Per-sample spacing and stretch of a geometry image (DESIGN.md, "Stretch"). The stretch of a
// triangle is the largest singular value of its parameterization's Jacobian (Sander, Snyder,
// Gortler & Hoppe, "Texture mapping progressive meshes", 2001: L∞ stretch, Γ), here per one
// sample step rather than per unit of texture space.
#include "octaclay/core/measure/stretch.h"

#include "detail/float_ranks.h"
#include "detail/parallel_rows.h"
#include "measure/grid_stretch.h"

#include "octaclay/core/document/document_checks.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <span>

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

// triangleFigures(du, dv).area without the stretch's square roots where they cannot reject the
// triangle: σ² ≤ a + c (|b| ≤ √(ac)), so below 1e76 σ is finite and under 3e38.
[[gnu::noinline]] float slowTriangleArea(Vec3d du, Vec3d dv) {
  return triangleFigures(du, dv).area;
}

inline float triangleArea(Vec3d du, Vec3d dv) {
  const double a = dotD(du, du), c = dotD(dv, dv);
  if (!(a + c < 1e76)) [[unlikely]]
    return slowTriangleArea(du, dv);
  const Vec3d n{du.y * dv.z - du.z * dv.y, du.z * dv.x - du.x * dv.z, du.x * dv.y - du.y * dv.x};
  const double area = 0.5 * std::sqrt(dotD(n, n));
  if (!std::isfinite(area) || !(area < 3e38)) return 0;
  return float(area);
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

// cellFigures' two areas alone.
// here and next: rows j and j+1.
std::array<float, 2> cellAreas(const Vec4f* here, const Vec4f* next, int n, int i, int j) {
  const Vec4f& a = here[i];
  const Vec4f& b = here[i + 1];
  const Vec4f& c = next[i + 1];
  const Vec4f& d = next[i];
  if (antiDiagonal(n, i, j))
    return {triangleArea(difference(b, a), difference(d, a)),
            triangleArea(difference(c, d), difference(c, b))};
  return {triangleArea(difference(b, a), difference(c, b)),
          triangleArea(difference(c, d), difference(d, a))};
}

// The row loops of summarizeStretch, in straight lines a compiler turns into vector code (no
// call, no branch per element; the file is built without errno from sqrt, see core's
// CMakeLists). Same figures to the bit as cellAreas() and a grid edge's length (-1 when not
// finite or over a float): a square root of a sum of squares is never negative, so "finite and
// below 3e38" is "below 3e38".

// A triangle's doubled area, squared: |du × dv|².
inline double crossSquared(double ux, double uy, double uz, double vx, double vy, double vz) {
  const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  return nx * nx + ny * ny + nz * nz;
}

inline float areaFromCrossSquared(double q) {
  const double area = 0.5 * std::sqrt(q);
  return float(area < 3e38 ? area : 0.0); // chosen before the conversion, which may not trap
}

// A row of positions as doubles, one array per axis (what vector code loads best). load() tells
// whether every coordinate is finite and below 1e37 in magnitude: then every squared edge of a
// cell is below 12e74 and a + c below 1e76, so no triangle leaves triangleArea's quick path.
struct RowD {
  std::vector<double> x, y, z;
  bool load(const Vec4f* row, int count) {
    x.resize(static_cast<std::size_t>(count));
    y.resize(static_cast<std::size_t>(count));
    z.resize(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
      x[static_cast<std::size_t>(i)] = row[i].x;
      y[static_cast<std::size_t>(i)] = row[i].y;
      z[static_cast<std::size_t>(i)] = row[i].z;
    }
    int large = 0; // a count, not a flag, so this loop is vector code too
    for (int i = 0; i < count; ++i)
      large += int(!(std::fabs(row[i].x) < 1e37f)) | int(!(std::fabs(row[i].y) < 1e37f)) |
               int(!(std::fabs(row[i].z) < 1e37f));
    return large == 0;
  }
};

// Cells [iBegin, iEnd) between rows here and next (loaded small), all of one split, into
// cells[i]. Also built for AVX2, chosen when the processor has it: four doubles a step, the same
// values (AVX2 has no fused multiply-add, and the file is built without contraction).
template <bool AntiDiagonal>
[[gnu::always_inline]] inline void cellAreaRunOf(const RowD& here, const RowD& next, int iBegin,
                                                 int iEnd, std::array<float, 2>* cells) {
  const double *hx = here.x.data(), *hy = here.y.data(), *hz = here.z.data();
  const double *nx = next.x.data(), *ny = next.y.data(), *nz = next.z.data();
  for (int i = iBegin; i < iEnd; ++i) {
    // a = here[i], b = here[i + 1], c = next[i + 1], d = next[i]. Anti-diagonal: {a, b, d}
    // (b - a, d - a), {b, c, d} (c - d, c - b); main: {a, b, c} (b - a, c - b), {a, c, d}
    // (c - d, d - a).
    const double abx = hx[i + 1] - hx[i], aby = hy[i + 1] - hy[i], abz = hz[i + 1] - hz[i];
    const double dcx = nx[i + 1] - nx[i], dcy = ny[i + 1] - ny[i], dcz = nz[i + 1] - nz[i];
    const double adx = nx[i] - hx[i], ady = ny[i] - hy[i], adz = nz[i] - hz[i];
    const double bcx = nx[i + 1] - hx[i + 1], bcy = ny[i + 1] - hy[i + 1],
                 bcz = nz[i + 1] - hz[i + 1];
    double q0, q1;
    if constexpr (AntiDiagonal) {
      q0 = crossSquared(abx, aby, abz, adx, ady, adz);
      q1 = crossSquared(dcx, dcy, dcz, bcx, bcy, bcz);
    } else {
      q0 = crossSquared(abx, aby, abz, bcx, bcy, bcz);
      q1 = crossSquared(dcx, dcy, dcz, adx, ady, adz);
    }
    cells[i][0] = areaFromCrossSquared(q0);
    cells[i][1] = areaFromCrossSquared(q1);
  }
}

__attribute__((target_clones("avx2", "default"))) void
cellAreaRun(bool antiDiagonal, const RowD& here, const RowD& next, int iBegin, int iEnd,
            std::array<float, 2>* cells) {
  if (antiDiagonal)
    cellAreaRunOf<true>(here, next, iBegin, iEnd, cells);
  else
    cellAreaRunOf<false>(here, next, iBegin, iEnd, cells);
}

// The lengths of the edges p[i] → q[i], i in [0, count), into out.
void edgeLengthRun(const Vec4f* p, const Vec4f* q, int count, float* out) {
  for (int i = 0; i < count; ++i) {
    const double dx = double(q[i].x) - p[i].x, dy = double(q[i].y) - p[i].y,
                 dz = double(q[i].z) - p[i].z;
    const double l = std::sqrt(dx * dx + dy * dy + dz * dz);
    out[i] = float(l < 3e38 ? l : -1.0);
  }
}

// Row j's edges as edgeLengthRun makes them, from the rows loaded small (here: row j, next: row
// j + 1): N to the right, then N + 1 down. The same subtractions and sums, so the same floats; four
// doubles a step where the processor has AVX2.
__attribute__((target_clones("avx2", "default"))) void
edgeRowFromDoubles(const RowD& here, const RowD& next, int n, float* out) {
  const double *hx = here.x.data(), *hy = here.y.data(), *hz = here.z.data();
  const double *nx = next.x.data(), *ny = next.y.data(), *nz = next.z.data();
  for (int i = 0; i < n; ++i) {
    const double dx = hx[i + 1] - hx[i], dy = hy[i + 1] - hy[i], dz = hz[i + 1] - hz[i];
    out[i] = float(std::sqrt(dx * dx + dy * dy + dz * dz));
  }
  for (int i = 0; i <= n; ++i) {
    const double dx = nx[i] - hx[i], dy = ny[i] - hy[i], dz = nz[i] - hz[i];
    out[n + i] = float(std::sqrt(dx * dx + dy * dy + dz * dz));
  }
}

// summarizeStretch's vertex areas of an inner row over [iBegin, iEnd) (0 < i < N), where the
// four cells around each vertex keep one split each: ac, ad, ab, aa for the cells up-left,
// up-right, down-left and down-right (whether each is split along the anti-diagonal). The same
// additions in the same order as the per-vertex code.
template <bool AC, bool AD, bool AB, bool AA>
void vertexAreaRunOf(const std::array<float, 2>* above, const std::array<float, 2>* below,
                     int iBegin, int iEnd, float* out) {
  for (int i = iBegin; i < iEnd; ++i) {
    float a = 0;
    if constexpr (!AC) a += above[i - 1][0];
    a += above[i - 1][1];
    if constexpr (AD) a += above[i][0];
    a += above[i][1];
    a += below[i - 1][0];
    if constexpr (AB) a += below[i - 1][1];
    a += below[i][0];
    if constexpr (!AA) a += below[i][1];
    out[i] = a / 3.0f;
  }
}

void vertexAreaRun(bool ac, bool ad, bool ab, bool aa, const std::array<float, 2>* above,
                   const std::array<float, 2>* below, int iBegin, int iEnd, float* out) {
  using Run = void (*)(const std::array<float, 2>*, const std::array<float, 2>*, int, int, float*);
  static constexpr Run runs[16] = {
      vertexAreaRunOf<false, false, false, false>, vertexAreaRunOf<false, false, false, true>,
      vertexAreaRunOf<false, false, true, false>,  vertexAreaRunOf<false, false, true, true>,
      vertexAreaRunOf<false, true, false, false>,  vertexAreaRunOf<false, true, false, true>,
      vertexAreaRunOf<false, true, true, false>,   vertexAreaRunOf<false, true, true, true>,
      vertexAreaRunOf<true, false, false, false>,  vertexAreaRunOf<true, false, false, true>,
      vertexAreaRunOf<true, false, true, false>,   vertexAreaRunOf<true, false, true, true>,
      vertexAreaRunOf<true, true, false, false>,   vertexAreaRunOf<true, true, false, true>,
      vertexAreaRunOf<true, true, true, false>,    vertexAreaRunOf<true, true, true, true>};
  runs[(ac ? 8 : 0) + (ad ? 4 : 0) + (ab ? 2 : 0) + (aa ? 1 : 0)](above, below, iBegin, iEnd, out);
}

// Identified border samples are one vertex: each copy holds part of its ring. Gives every copy
// the sum of their areas (and the largest of their sigmas, when sigma is given).
void uniteIdentified(int n, std::span<float> area, std::vector<float>* sigma) {
  const auto unite = [&](Sample s) {
    if (!(canonical(n, s) == s)) return;
    std::array<Sample, 4> copies;
    const int count = identifiedSamples(n, s, copies);
    float sum = 0, largest = 0;
    for (int k = 0; k < count; ++k) {
      sum += area[texelIndex(n, copies[k].i, copies[k].j)];
      if (sigma) largest = std::max(largest, (*sigma)[texelIndex(n, copies[k].i, copies[k].j)]);
    }
    for (int k = 0; k < count; ++k) {
      area[texelIndex(n, copies[k].i, copies[k].j)] = sum;
      if (sigma) (*sigma)[texelIndex(n, copies[k].i, copies[k].j)] = largest;
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
  // Per-sample figures on the ball's square grid (a torus's or plane's: summarizeStretch).
  requireOctahedral(image, "the per-sample stretch map", "this image");
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

  uniteIdentified(n, out.area, &out.sigma);
  return out;
}

double vertexCount(int n) {
  return double(n) * double(n) + 2.0;
}

// The q-quantile's (0 ≤ q ≤ 1) place among count values, by nearest rank.
std::size_t nearestRank(std::size_t count, double q) {
  return static_cast<std::size_t>(std::llround(q * double(count - 1)));
}

} // namespace

double meanSpacing(const GeometryImage& image) {
  if (image.topology() != Topology::Octahedral) return detail::gridMeanSpacing(image);
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
  if (image.topology() != Topology::Octahedral) return detail::summarizeGridStretch(image);
  StretchSummary summary;
  const int n = image.size();
  if (n < 2) return summary;
  // One pass over the texel rows on every core: the areas of the cells of row j (kept for row
  // j+1) and the vertex areas of row j from the cells above and below it: measureVertices'
  // figures without its per-cell and stretch arrays. Left uninitialized: every value is written
  // below, on the core that first touches its pages (zero-filling them first was 0.8 GB of
  // single-threaded page faults and memset at N = 8192).
  // The edges' ranks are counted in the same pass, row by row (edgesOf), after a sample of the
  // rows guessed their bins; only a bin the guess missed reads the rows again.
  const auto edgesOf = [&](int j, float* row) {
    const Vec4f* here = &image.at(0, j);
    edgeLengthRun(here, here + 1, n, row);
    if (j < n) edgeLengthRun(here, &image.at(0, j + 1), n + 1, row + n);
    return j < n ? 2 * n + 1 : n;
  };
  const auto edgeBlock = [&](int j, auto&& visit) {
    thread_local std::vector<float> row; // each pass's threads make rows one at a time
    row.resize(2 * static_cast<std::size_t>(n) + 1);
    const int count = edgesOf(j, row.data());
    for (int k = 0; k < count; ++k)
      visit(row[static_cast<std::size_t>(k)]);
  };
  const auto edgeRanksAsked = [](std::size_t count) {
    return std::vector<std::size_t>{nearestRank(count, 0.5), nearestRank(count, 0.99)};
  };
  detail::FloatRankSelection edgeSelection(edgeRanksAsked);
  edgeSelection.guess(n + 1, edgeBlock);
  const auto areaValues = std::make_unique_for_overwrite<float[]>(image.texelCount());
  const std::span<float> area(areaValues.get(), image.texelCount());
  std::vector<double> rowArea(static_cast<std::size_t>(n), 0.0);
  detail::parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    std::vector<std::array<float, 2>> above(static_cast<std::size_t>(n)),
        below(static_cast<std::size_t>(n));
    RowD hereD, nextD;
    auto edgeCounts = edgeSelection.counter();
    std::vector<float> edgeRow(2 * static_cast<std::size_t>(n) + 1);
    bool loadedSmall = false; // cellRow's rows were loaded small (hereD, nextD)
    const auto cellRow = [&](int j, std::vector<std::array<float, 2>>& cells) {
      double sum = 0;
      const Vec4f* here = &image.at(0, j);
      const Vec4f* next = &image.at(0, j + 1);
      // Two runs, each of one split (cellSplit: 2i >= n from half on).
      const bool small = hereD.load(here, n + 1) & nextD.load(next, n + 1);
      loadedSmall = small;
      const int half = (n + 1) / 2;
      const bool lower = 2 * j >= n;
      std::array<float, 2>* out = cells.data();
      if (!small) // a huge or non-finite coordinate: cell by cell, as triangleArea decides
        for (int i = 0; i < n; ++i)
          cells[static_cast<std::size_t>(i)] = cellAreas(here, next, n, i, j);
      else if (lower) {
        cellAreaRun(false, hereD, nextD, 0, half, out);
        cellAreaRun(true, hereD, nextD, half, n, out);
      } else {
        cellAreaRun(true, hereD, nextD, 0, half, out);
        cellAreaRun(false, hereD, nextD, half, n, out);
      }
      for (int i = 0; i < n; ++i)
        sum += double(cells[static_cast<std::size_t>(i)][0]) +
               double(cells[static_cast<std::size_t>(i)][1]);
      return sum;
    };
    if (rowBegin > 0) cellRow(rowBegin - 1, above);
    for (int j = rowBegin; j < rowEnd; ++j) {
      if (j < n) rowArea[static_cast<std::size_t>(j)] = cellRow(j, below);
      // Row j's edges from the rows just loaded where they are small (below 1e37: every edge
      // is then finite and below 3e38), else as edgesOf makes them.
      int edges = 2 * n + 1;
      if (j < n && loadedSmall)
        edgeRowFromDoubles(hereD, nextD, n, edgeRow.data());
      else
        edges = edgesOf(j, edgeRow.data());
      for (int k = 0; k < edges; ++k)
        edgeCounts.add(edgeRow[static_cast<std::size_t>(k)]);
      // The take() order of measureVertices, so every vertex area is the same float.
      const auto vertexArea = [&](int i) {
        float a = 0;
        if (j > 0) {
          if (i > 0) {
            const auto& f = above[static_cast<std::size_t>(i - 1)];
            if (!antiDiagonal(n, i - 1, j - 1)) a += f[0];
            a += f[1];
          }
          if (i < n) {
            const auto& f = above[static_cast<std::size_t>(i)];
            if (antiDiagonal(n, i, j - 1)) a += f[0];
            a += f[1];
          }
        }
        if (j < n) {
          if (i > 0) {
            const auto& f = below[static_cast<std::size_t>(i - 1)];
            a += f[0];
            if (antiDiagonal(n, i - 1, j)) a += f[1];
          }
          if (i < n) {
            const auto& f = below[static_cast<std::size_t>(i)];
            a += f[0];
            if (!antiDiagonal(n, i, j)) a += f[1];
          }
        }
        area[texelIndex(n, i, j)] = a / 3.0f;
      };
      float* areaRow = area.data() + texelIndex(n, 0, j);
      if (j == 0 || j == n) {
        for (int i = 0; i <= n; ++i)
          vertexArea(i);
      } else { // inner rows: the ends alone, the runs between them of one split each
        vertexArea(0);
        const int half = (n + 1) / 2;
        for (const auto& [iBegin, iEnd] :
             {std::pair{1, half}, std::pair{half, half + 1}, std::pair{half + 1, n}})
          if (iBegin < iEnd)
            vertexAreaRun(antiDiagonal(n, iBegin - 1, j - 1), antiDiagonal(n, iBegin, j - 1),
                          antiDiagonal(n, iBegin - 1, j), antiDiagonal(n, iBegin, j), above.data(),
                          below.data(), iBegin, std::min(iEnd, n), areaRow);
        vertexArea(n);
      }
      std::swap(above, below);
    }
    edgeSelection.merge(edgeCounts);
  });
  uniteIdentified(n, area, nullptr);

  // Row j's edges: N to the right (none from the last column), then N+1 down (none from the last
  // row); a non-finite one is -1 and left out. Counted in the pass above and made again where a
  // pass needs them rather than kept (134 million floats at N = 8192: 537 MB of fresh pages).
  const detail::FloatRanks edgeRanks = edgeSelection.finish(n + 1, edgeBlock, 16);
  if (edgeRanks.count > 0) {
    summary.longestEdge = edgeRanks.largest;
    summary.medianEdge = edgeRanks.at[0];
    if (summary.medianEdge > 0) {
      summary.longestOverMedian = summary.longestEdge / summary.medianEdge;
      summary.p99OverMedian = edgeRanks.at[1] / summary.medianEdge;
    }
  }

  double total = 0;
  for (double a : rowArea)
    total += a;
  summary.meanSpacing = std::sqrt(total / vertexCount(n));
  // The spacing of every vertex once: its canonical sample's area, the other copies of border
  // vertices marked -1 (left out of the ranks). A spacing is √area as a float, monotone in the
  // area, so the median spacing is the square root of the median area.
  forEachCanonicalRun(n, [&](int j, int iBegin, int iEnd) {
    for (int i = 0; i < iBegin; ++i)
      area[texelIndex(n, i, j)] = -1.0f;
    for (int i = iEnd; i <= n; ++i)
      area[texelIndex(n, i, j)] = -1.0f;
  });
  const detail::FloatRanks areaRanks = detail::selectFloatRanks(
      area, [](std::size_t count) { return std::vector<std::size_t>{nearestRank(count, 0.5)}; });
  const double medianSpacing = areaRanks.count ? double(std::sqrt(areaRanks.at[0])) : 0.0;
  // The least area whose spacing (√area, a float) is over 4 × the median: √ is monotone, so the
  // areas over it are those from it on (found over the floats' bits, whose order is theirs).
  const double threshold = 4.0 * medianSpacing;
  const auto isOver = [threshold](std::uint32_t bits) {
    float a;
    std::memcpy(&a, &bits, 4);
    return double(std::sqrt(a)) > threshold;
  };
  constexpr std::uint32_t kInfinity = 0x7f800000u;
  std::uint32_t below = 0, least = kInfinity; // !isOver(below) (√0 is not over 0 or more)
  if (isOver(least))
    while (least - below > 1) {
      const std::uint32_t mid = below + (least - below) / 2;
      (isOver(mid) ? least : below) = mid;
    }
  float leastOver; // NaN when even √∞ is not over: no area counts
  std::memcpy(&leastOver, &least, 4);
  if (!isOver(least)) leastOver = std::numeric_limits<float>::quiet_NaN();
  std::vector<std::size_t> overPerBand(64, 0);
  const int bands = static_cast<int>(overPerBand.size());
  detail::parallelRows(
      bands,
      [&](int b0, int b1) {
        for (int b = b0; b < b1; ++b) {
          const std::size_t from = area.size() * static_cast<std::size_t>(b) / bands,
                            to = area.size() * static_cast<std::size_t>(b + 1) / bands;
          std::size_t over = 0;
          for (std::size_t k = from; k < to; ++k)
            over += area[k] >= leastOver ? 1 : 0; // -1 (a copy left out) is not
          overPerBand[static_cast<std::size_t>(b)] = over;
        }
      },
      1);
  std::size_t over = 0;
  for (std::size_t c : overPerBand)
    over += c;
  summary.shareOver4x = areaRanks.count ? double(over) / double(areaRanks.count) : 0.0;
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
