// Keep detail on a torus or plane (grid_keep_detail.h): Even Out's sweeps over the samples
// around what a stroke changed, checked against the old surface at the same parameter points.
#include "relax/grid_keep_detail.h"

#include "detail/aabb_tree.h"
#include "detail/parallel_rows.h"
#include "document/tile_texels.h"
#include "relax/parameter_field.h"
#include "relax/sample_masks.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace octaclay::core::detail {
namespace {

// Sweeps per lattice level and iteration (Even Out's).
constexpr int kSweepsPerLevel = 100;
// The coarsest lattice's stride: at most this, and a quarter of the margin (the freed region
// then spans eight lattice cells or more across).
constexpr int kMaxStride = 16;
// How far the relaxation may move the surface, as fractions of the diagonal (the ball's).
constexpr double kRmsTolerance = 1e-4;
constexpr double kHausdorffTolerance = 1e-3;
// The check's points: a triangle's at 1/k of its barycentric coordinates, k = 3 for a triangle
// of the surface's usual size and twice its longest edge in median edges for a stretched one (at
// most kMostDivisions): the distances vary along a long facet.
constexpr int kMostDivisions = 10;
// The share of each tolerance the check's points may use: between them a denser measure finds a
// little more (a 1.3 × bound with four points a triangle once).
constexpr double kCheckedShare = 0.8;
// How many times the flow is solved again with the samples where its move cut too deep held.
constexpr int kHoldAttempts = 2;

Sample canonicalSample(const ParameterField& f, int i, int j) {
  const auto [ci, cj] = f.canonicalOf(i, j);
  return {ci, cj};
}

// Marks each lattice sample within `margin` of a marked one along its row (axis 0) or column
// (axis 1): through a torus's period, clamped on a sheet.
void dilate(const ParameterField& f, std::vector<std::uint8_t>& mask, int margin, int axis) {
  const int length = axis == 0 ? f.columns : f.rows, lines = axis == 0 ? f.rows : f.columns;
  const auto at = [&](int line, int k) -> std::uint8_t& {
    return axis == 0 ? mask[f.index(k, line)] : mask[f.index(line, k)];
  };
  std::vector<int> prefix(static_cast<std::size_t>(length) + 1);
  for (int line = 0; line < lines; ++line) {
    for (int k = 0; k < length; ++k)
      prefix[static_cast<std::size_t>(k) + 1] = prefix[static_cast<std::size_t>(k)] + at(line, k);
    const auto count = [&](int a, int b) { // marked in [a, b], 0 <= a, b < length
      return a > b ? 0
                   : prefix[static_cast<std::size_t>(b) + 1] - prefix[static_cast<std::size_t>(a)];
    };
    const int total = count(0, length - 1);
    for (int k = 0; k < length; ++k) {
      int marked = 0;
      if (!f.torus())
        marked = count(std::max(0, k - margin), std::min(length - 1, k + margin));
      else if (2 * margin + 1 >= length)
        marked = total;
      else if (k - margin < 0)
        marked = count(0, k + margin) + count(length + k - margin, length - 1);
      else if (k + margin >= length)
        marked = count(k - margin, length - 1) + count(0, k + margin - length);
      else
        marked = count(k - margin, k + margin);
      at(line, k) = marked > 0 ? 1 : 0;
    }
  }
}

// The full-resolution lattice's samples that may move: within margin of a changed one, pins
// excepted.
std::vector<std::uint8_t> freedSamples(const ParameterField& f,
                                       const std::vector<std::uint8_t>& changed, int margin,
                                       const std::vector<Sample>& pinned) {
  std::vector<std::uint8_t> free(f.offset.size(), 0);
  const int side = f.grid.width + 1;
  for (int j = 0; j <= f.grid.height; ++j)
    for (int i = 0; i <= f.grid.width; ++i)
      if (changed[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) +
                  static_cast<std::size_t>(i)]) {
        const Sample c = canonicalSample(f, i, j);
        free[f.index(c.i, c.j)] = 1;
      }
  dilate(f, free, margin, 0);
  dilate(f, free, margin, 1);
  for (const Sample s : pinned) {
    const Sample c = canonicalSample(f, s.i, s.j);
    free[f.index(c.i, c.j)] = 0;
  }
  return free;
}

// The lattice of every stride-th sample: free where its full-resolution sample is.
std::vector<std::uint8_t> freeAtStride(const ParameterField& fine, const ParameterField& lattice,
                                       const std::vector<std::uint8_t>& free) {
  std::vector<std::uint8_t> out(lattice.offset.size(), 0);
  for (int j = 0; j < lattice.rows; ++j)
    for (int i = 0; i < lattice.columns; ++i)
      out[lattice.index(i, j)] = free[fine.index(i * lattice.stride, j * lattice.stride)];
  return out;
}

// The freed samples' offsets, coarse to fine from a lattice of every stride-th sample: each
// level gets (stride)² times the finest level's sweeps (up to 64 times; a level then costs about
// what the finest does), so samples travel across the freed region.
ParameterField solveFreed(const GeometryImage& image, const std::vector<std::uint8_t>& free,
                          int margin, int sweeps) {
  const SampleGrid& grid = image.grid();
  const int least = grid.topology == Topology::Torus ? kMinTorusSize : 2;
  int stride = 1;
  while (2 * stride <= kMaxStride && 4 * (2 * stride) <= margin &&
         std::min(grid.width, grid.height) / (2 * stride) >= least)
    stride *= 2;
  const ParameterField full = emptyField(grid, 1);
  ParameterField field = emptyField(grid, stride);
  field.free = freeAtStride(full, field, free);
  for (;;) {
    sweepLevel(image, field, sweeps * field.stride, {});
    if (field.stride == 1) return field;
    field = finer(field);
    field.free = freeAtStride(full, field, free);
    for (std::size_t k = 0; k < field.offset.size(); ++k)
      if (!field.free[k]) field.offset[k] = {};
  }
}

struct Moved {
  double rms = 0, hausdorff = 0;        // fractions of the diagonal
  float longestOld = 0, longestNew = 0; // the moved cells' longest edge before and after
};

float longestEdge(const TriangleMesh& mesh, std::size_t triangles) {
  float longest = 0;
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k)
      longest = std::max(longest, length(mesh.positions[tri[std::size_t(k)]] -
                                         mesh.positions[tri[std::size_t((k + 1) % 3)]]));
  }
  return longest;
}

using Cells = std::vector<std::array<int, 2>>;

// The two triangles of each cell, split along its anti-diagonal as the grid's, with the corner
// positions corner(i, j) gives.
template <class Corner> TriangleMesh cellTriangles(const Cells& cells, Corner&& corner) {
  TriangleMesh mesh;
  mesh.positions.reserve(cells.size() * 4);
  mesh.triangles.reserve(cells.size() * 2);
  for (const auto& [i, j] : cells) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const auto& [a, b] : {std::array{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}})
      mesh.positions.push_back(corner(a, b));
    mesh.triangles.push_back({base, base + 1, base + 3});
    mesh.triangles.push_back({base + 1, base + 2, base + 3});
  }
  return mesh;
}

void append(TriangleMesh& to, const TriangleMesh& from) {
  const auto base = static_cast<std::uint32_t>(to.positions.size());
  to.positions.insert(to.positions.end(), from.positions.begin(), from.positions.end());
  for (const auto& t : from.triangles)
    to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

// The cells within two cells of a moved one, the moved ones excepted: where the old surface's
// closest points to the moved cells lie, and what the new surface shares with the old there.
Cells ringAround(const ParameterField& f, const Cells& moved) {
  std::vector<std::uint8_t> mark(
      static_cast<std::size_t>(f.cellsWide) * static_cast<std::size_t>(f.cellsHigh), 0);
  const auto at = [&](int i, int j) -> std::uint8_t& {
    return mark[static_cast<std::size_t>(j) * static_cast<std::size_t>(f.cellsWide) +
                static_cast<std::size_t>(i)];
  };
  for (const auto& [i, j] : moved)
    at(i, j) = 2;
  for (const auto& [i, j] : moved)
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) {
        int a = i + di, b = j + dj;
        if (f.torus()) {
          a = (a + f.cellsWide) % f.cellsWide;
          b = (b + f.cellsHigh) % f.cellsHigh;
        } else if (a < 0 || b < 0 || a >= f.cellsWide || b >= f.cellsHigh) {
          continue;
        }
        if (at(a, b) == 0) at(a, b) = 1;
      }
  Cells ring;
  for (int j = 0; j < f.cellsHigh; ++j)
    for (int i = 0; i < f.cellsWide; ++i)
      if (at(i, j) == 1) ring.push_back({i, j});
  return ring;
}

// What the check measured on one side: the area-weighted sum of squared distances, the area and
// the farthest squared distance; per cell, its farthest squared distance when noted.
struct SideFigures {
  double squares = 0, weight = 0, worst = 0;
  std::vector<double> far;
};

// An upper bound on the distance from a point of the new surface to the old one, without a
// search: the new triangle over parameter points Pa, Pb, Pc shows the old surface at each, so
// its point with weights (u, v, w) stands for the old surface at the same mix of them (a point
// of the old mesh when that mix lies in one of its cells: `onOld`, cellsWide × cellsHigh). A
// bound within `within` stands for the point's distance (no search); `params` holds the new
// surface's positions' parameter points.
struct ParameterBounds {
  const GeometryImage& image;
  const std::vector<Offset>& params;
  const std::vector<std::uint8_t>& onOld;
  const ParameterField& field;
  double within = 0;
};

// The squared bound at parameter point x for surface point p, or infinity where x lies over no
// cell of the old mesh. A millionth of the point's size more than the distance: the surface
// point is interpolated in float.
double boundAt(const ParameterBounds& bounds, Offset x, Vec3d p) {
  const ParameterField& f = bounds.field;
  int ci = static_cast<int>(std::floor(x.x)), cj = static_cast<int>(std::floor(x.y));
  if (f.torus()) {
    std::tie(ci, cj) = f.canonicalOf(ci, cj); // the field is the full-resolution lattice's
  } else if (x.x < 0 || x.y < 0 || x.x > f.grid.width || x.y > f.grid.height) {
    return std::numeric_limits<double>::infinity();
  } else {
    ci = std::min(ci, f.grid.width - 1), cj = std::min(cj, f.grid.height - 1);
  }
  if (!bounds.onOld[static_cast<std::size_t>(cj) * static_cast<std::size_t>(f.grid.width) +
                    static_cast<std::size_t>(ci)])
    return std::numeric_limits<double>::infinity();
  const Vec3d q(surfaceAt(bounds.image, x));
  const Vec3d d = p - q;
  const double size = std::max(
      {std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(q.x), std::abs(q.y), std::abs(q.z)});
  const double bound = std::sqrt(dot(d, d)) + 1e-6 * size;
  return bound * bound;
}

// An upper bound on the distance from a point of the old surface to the new one, without a
// search: the old point at parameter point x (in a moved cell) is the old surface there, and a
// new triangle whose corners show the old surface at parameter points around x has, at x's
// weights among those points, a point of the new surface. The triangle is looked for among the
// moved cells around where x is shown from (q with q + step × offset(q) = x: two fixed-point
// steps: its cell, then the eight around it; the first triangle over x gives the bound); weights
// a float's rounding outside the triangle are clamped into it, so the point is always on the new
// surface. Infinity where no such triangle is found.
struct ShownBounds {
  const ParameterField& field;
  /// Per lattice cell (cellsWide × cellsHigh), its index among the moved cells, or -1.
  const std::vector<std::int32_t>& movedIndex;
  /// Per new corner (four a moved cell, in cellTriangles' order): the parameter point it shows.
  const std::vector<Offset>& params;
  const TriangleMesh& newSurface; ///< the moved cells' new triangles first
  double step;
};

double shownBoundAt(const ShownBounds& b, Offset x, Vec3d p) {
  const ParameterField& f = b.field;
  Offset q = x;
  for (int k = 0; k < 2; ++k) {
    int ri = static_cast<int>(std::lround(q.x)), rj = static_cast<int>(std::lround(q.y));
    if (!f.torus()) ri = std::clamp(ri, 0, f.cellsWide), rj = std::clamp(rj, 0, f.cellsHigh);
    const Offset at = f.point(ri, rj);
    q = {x.x - b.step * (at.x - double(ri)), x.y - b.step * (at.y - double(rj))};
  }
  const int qi = static_cast<int>(std::floor(q.x)), qj = static_cast<int>(std::floor(q.y));
  // q's cell first, then the eight around it; the first triangle over x gives the bound.
  static constexpr std::array<std::array<int, 2>, 9> kAround{
      {{0, 0}, {-1, 0}, {1, 0}, {0, -1}, {0, 1}, {-1, -1}, {1, -1}, {-1, 1}, {1, 1}}};
  for (const auto& [di, dj] : kAround) {
    {
      int ca = qi + di, cb = qj + dj;
      if (f.torus()) {
        std::tie(ca, cb) = f.canonicalOf(ca, cb);
      } else if (ca < 0 || cb < 0 || ca >= f.cellsWide || cb >= f.cellsHigh) {
        continue;
      }
      const std::int32_t c =
          b.movedIndex[static_cast<std::size_t>(cb) * static_cast<std::size_t>(f.cellsWide) +
                       static_cast<std::size_t>(ca)];
      if (c < 0) continue;
      // x in the canonical cell's frame (a torus's periods apart).
      const Offset y{x.x - double(qi + di - ca), x.y - double(qj + dj - cb)};
      const std::size_t base = 4 * static_cast<std::size_t>(c);
      for (const std::array<std::size_t, 3>& t :
           {std::array<std::size_t, 3>{0, 1, 3}, std::array<std::size_t, 3>{1, 2, 3}}) {
        const Offset &pa = b.params[base + t[0]], &pb = b.params[base + t[1]],
                     &pc = b.params[base + t[2]];
        const double e0x = pb.x - pa.x, e0y = pb.y - pa.y, e1x = pc.x - pa.x, e1y = pc.y - pa.y;
        const double det = e0x * e1y - e1x * e0y;
        if (!(std::abs(det) > 0)) continue;
        const double rx = y.x - pa.x, ry = y.y - pa.y;
        std::array<double, 3> w{0, (rx * e1y - e1x * ry) / det, (e0x * ry - rx * e0y) / det};
        w[0] = 1 - w[1] - w[2];
        if (!(std::min({w[0], w[1], w[2]}) > -1e-6)) continue; // not the triangle over x
        double sum = 0;
        for (double& v : w)
          sum += (v = std::max(v, 0.0));
        Vec3d n(0, 0, 0);
        for (std::size_t k = 0; k < 3; ++k)
          n = n + Vec3d(b.newSurface.positions[base + t[k]]) * (w[k] / sum);
        const Vec3d d = p - n;
        const double size = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), std::abs(n.x),
                                      std::abs(n.y), std::abs(n.z)});
        // A billionth of the size more: the search measures the same triangle in another order.
        const double bound = std::sqrt(dot(d, d)) + 1e-9 * size;
        return bound * bound;
      }
    }
  }
  return std::numeric_limits<double>::infinity();
}

// The parameter point of a triangle's point with weights u, v, w out of d over corners at
// parameter points pa, pb, pc (farthestFrom's check points).
Offset mixOf(const Offset& pa, const Offset& pb, const Offset& pc, int u, int v, int w, int d) {
  return {(double(u) * pa.x + double(v) * pb.x + double(w) * pc.x) * (1.0 / d),
          (double(u) * pa.y + double(v) * pb.y + double(w) * pc.y) * (1.0 / d)};
}

// Adds to `side` the distances from the check points of the `checked` cells' two triangles of
// `from` (triangles 2c and 2c + 1; with or without their corners) to the surface `to`. Stops
// early once a point lies farther than giveUpAt (squared) unless per-cell figures are noted.
// With `bound` (given the point's triangle in `from`, its weights u, v, w out of d and the
// point: an upper bound on its squared distance to `to`, or infinity), a point whose bound is
// within `within` takes it and is not searched: every figure over that is a search's.
using PointBound = std::function<double(const std::array<std::uint32_t, 3>& triangle, int u, int v,
                                        int w, int d, Vec3d p)>;
void farthestFrom(const TriangleMesh& from, const std::vector<std::size_t>& checked,
                  const AabbTree& to, float medianEdge, bool corners, SideFigures& side,
                  bool noting, double giveUpAt, const PointBound* bound = nullptr,
                  double within = 0) {
  std::mutex merge;
  std::atomic<bool> failed = false;
  detail::parallelRows(
      static_cast<int>(checked.size()),
      [&](int c0, int c1) {
        SideFigures local;
        std::vector<std::pair<std::size_t, double>> farCells;
        std::uint32_t hint = AabbTree::noTriangle;
        for (int k = c0; k < c1 && !(failed && !noting); ++k) {
          const std::size_t c = checked[static_cast<std::size_t>(k)];
          double cellWorst = 0;
          for (const std::size_t t : {2 * c, 2 * c + 1}) {
            const auto& tri = from.triangles[t];
            const Vec3d a(from.positions[tri[0]]), b(from.positions[tri[1]]),
                c3(from.positions[tri[2]]);
            const double area = 0.5 * std::sqrt(dot(cross(b - a, c3 - a), cross(b - a, c3 - a)));
            // The triangle's points at 1/d of its barycentric coordinates: the corners (the new
            // surface's lie on the old one; skipped from that side), the edges' and inside.
            const double longest =
                std::sqrt(std::max({dot(b - a, b - a), dot(c3 - b, c3 - b), dot(a - c3, a - c3)}));
            const int d =
                std::clamp(int(std::ceil(longest / double(medianEdge))) + 2, 3, kMostDivisions);
            int counted = 0;
            double triangleSquares = 0;
            for (int u = 0; u <= d; ++u)
              for (int v = 0; u + v <= d; ++v) {
                const int w = d - u - v;
                if (!corners && (u == d || v == d || w == d)) continue;
                const Vec3d p = (double(u) * a + double(v) * b + double(w) * c3) * (1.0 / d);
                double squared =
                    bound ? (*bound)(tri, u, v, w, d, p) : std::numeric_limits<double>::infinity();
                if (!bound || !(squared <= within * within)) {
                  const AabbTree::Hit hit = to.closest(p, hint);
                  hint = hit.triangle;
                  squared = hit.distanceSquared;
                }
                cellWorst = std::max(cellWorst, squared);
                triangleSquares += squared;
                ++counted;
              }
            local.squares += area * triangleSquares / counted;
            local.weight += area;
          }
          local.worst = std::max(local.worst, cellWorst);
          if (noting) farCells.emplace_back(c, cellWorst);
          // Past the tolerance already: the step fails whatever the rest measures.
          if (local.worst > giveUpAt) failed = true;
        }
        const std::lock_guard lock(merge);
        side.squares += local.squares;
        side.weight += local.weight;
        side.worst = std::max(side.worst, local.worst);
        for (const auto& [c, worst] : farCells)
          side.far[c] = std::max(side.far[c], worst);
      },
      256);
}

// One solve's moved cells with what every step's measure shares: the ring of unmoved cells
// around them and the old surface over both, and the moved cells' longest old edge.
struct MovedRegion {
  Cells cells, ring;
  TriangleMesh oldCells, oldRing;
  float longestOld = 0;
};

MovedRegion movedRegion(const GeometryImage& image, const ParameterField& f, Cells cells) {
  const auto oldCorner = [&](int i, int j) { return image.at(i, j).xyz(); };
  MovedRegion region;
  region.oldCells = cellTriangles(cells, oldCorner);
  region.ring = ringAround(f, cells);
  region.oldRing = cellTriangles(region.ring, oldCorner);
  region.longestOld = longestEdge(region.oldCells, region.oldCells.triangles.size());
  region.cells = std::move(cells);
  return region;
}

// How far the surface with the field's points (offsets times step) lies from the old one over
// the moved cells, both ways: the new triangles' points against the old surface (the moved cells
// and the ring around them) and the old triangles' points against the new surface (the moved
// cells resampled, the ring as it was). Exact closest points, so each figure is an upper bound.
// farCells, when given, gets the moved cells (their indices) with a point farther than `far`.
// With useBounds, the new surface's points whose ParameterBounds bound (over `onOld`, the old
// mesh's cells) is within half the Hausdorff tolerance take it rather than a search.
Moved measureMoveOnce(const GeometryImage& image, const ParameterField& f, double step,
                      const MovedRegion& region, const AabbTree& oldSurface,
                      const std::vector<std::uint8_t>& onOld, const KeepDetailFigures& figures,
                      bool useBounds, std::vector<std::size_t>* farCells, double far) {
  const float medianEdge = figures.medianEdge;
  const double diagonal = figures.diagonal;
  const Cells& moved = region.cells;
  const TriangleMesh& oldMoved = region.oldCells;
  // Where lattice sample (i, j) shows the old surface at this step.
  const auto shown = [&](int i, int j) {
    const Offset p = f.point(i, j);
    return Offset{double(i) + step * (p.x - double(i)), double(j) + step * (p.y - double(j))};
  };
  const auto newCorner = [&](int i, int j) {
    const Offset p = f.point(i, j);
    if (p.x == double(i) && p.y == double(j)) return image.at(i, j).xyz();
    return surfaceAt(image, shown(i, j));
  };
  TriangleMesh newSurface = cellTriangles(moved, newCorner);
  std::vector<Offset> newParams; // per new corner, in cellTriangles' order
  newParams.reserve(4 * moved.size());
  for (const auto& [i, j] : moved)
    for (const auto& [a, b] : {std::array{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}})
      newParams.push_back(shown(a, b));
  append(newSurface, region.oldRing);
  const float longestOld = region.longestOld,
              longestNew = longestEdge(newSurface, 2 * moved.size());
  // A step that lengthens an edge fails whatever the distances: unless its far cells are asked
  // for, they are not measured.
  if (!farCells && longestNew > longestOld)
    return {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            longestOld, longestNew};
  const double giveUp = kCheckedShare * kHausdorffTolerance * diagonal, giveUpAt = giveUp * giveUp;
  // A cell whose corners all moved by at most half the tolerance lies within its corners'
  // farthest move of the old cell (each point of it is its corners' mix, as the old cell's is),
  // both ways: that bound is its Hausdorff share, its centroids' distances its RMS share. The
  // others are checked by closest points throughout.
  SideFigures sides[2];
  const bool noting = farCells != nullptr;
  for (SideFigures& side : sides)
    side.far.assign(noting ? moved.size() : 0, 0.0);
  std::vector<std::size_t> checked, bounded;
  for (std::size_t c = 0; c < moved.size(); ++c) {
    double cornerMove = 0;
    for (std::size_t k = 4 * c; k < 4 * c + 4; ++k) {
      const Vec3f d = newSurface.positions[k] - oldMoved.positions[k];
      cornerMove = std::max(cornerMove, double(dot(d, d)));
    }
    if (cornerMove > 0.25 * giveUpAt) {
      checked.push_back(c);
      continue;
    }
    bounded.push_back(c);
    for (SideFigures& side : sides)
      side.worst = std::max(side.worst, cornerMove);
  }
  const AabbTree newTree(newSurface);
  // The bounded cells' RMS share: their triangles' centroids, both ways (each way's search from
  // the triangle its last one found: the cells are in order, so near one another).
  std::uint32_t hints[2] = {AabbTree::noTriangle, AabbTree::noTriangle};
  for (const std::size_t c : bounded)
    for (const std::size_t t : {2 * c, 2 * c + 1})
      for (int way = 0; way < 2; ++way) {
        const TriangleMesh& from = way == 0 ? newSurface : oldMoved;
        const auto& tri = from.triangles[t];
        const Vec3d a(from.positions[tri[0]]), b(from.positions[tri[1]]),
            c3(from.positions[tri[2]]);
        const double area = 0.5 * std::sqrt(dot(cross(b - a, c3 - a), cross(b - a, c3 - a)));
        const AabbTree& to = way == 0 ? oldSurface : newTree;
        const AabbTree::Hit hit = to.closest((a + b + c3) * (1.0 / 3), hints[way]);
        hints[way] = hit.triangle;
        sides[way].squares += area * hit.distanceSquared;
        sides[way].weight += area;
      }
  const double within = 0.5 * kHausdorffTolerance * diagonal;
  const ParameterBounds bounds{image, newParams, onOld, f, within};
  const PointBound newToOld = [&](const std::array<std::uint32_t, 3>& tri, int u, int v, int w,
                                  int d, Vec3d p) {
    return boundAt(bounds,
                   mixOf(newParams[tri[0]], newParams[tri[1]], newParams[tri[2]], u, v, w, d), p);
  };
  farthestFrom(newSurface, checked, oldSurface, medianEdge, false, sides[0], noting, giveUpAt,
               useBounds ? &newToOld : nullptr, within);
  if (noting || sides[0].worst <= giveUpAt) {
    // The old side's points by where the new surface shows them (ShownBounds).
    std::vector<std::int32_t> movedIndex(
        static_cast<std::size_t>(f.cellsWide) * static_cast<std::size_t>(f.cellsHigh), -1);
    for (std::size_t c = 0; c < moved.size(); ++c)
      movedIndex[static_cast<std::size_t>(moved[c][1]) * static_cast<std::size_t>(f.cellsWide) +
                 static_cast<std::size_t>(moved[c][0])] = static_cast<std::int32_t>(c);
    const ShownBounds shownBounds{f, movedIndex, newParams, newSurface, step};
    const PointBound oldToNew = [&](const std::array<std::uint32_t, 3>& tri, int u, int v, int w,
                                    int d, Vec3d p) {
      // The old corners' parameter points: their lattice samples (four a moved cell).
      const auto param = [&](std::uint32_t k) {
        const auto& [i, j] = moved[k / 4];
        return Offset{double(i + (k % 4 == 1 || k % 4 == 2)), double(j + (k % 4 >= 2))};
      };
      return shownBoundAt(shownBounds,
                          mixOf(param(tri[0]), param(tri[1]), param(tri[2]), u, v, w, d), p);
    };
    farthestFrom(oldMoved, checked, newTree, medianEdge, true, sides[1], noting, giveUpAt,
                 useBounds ? &oldToNew : nullptr, within);
  }
  if (noting) {
    farCells->clear();
    for (std::size_t c = 0; c < moved.size(); ++c)
      if (std::max(sides[0].far[c], sides[1].far[c]) > far * far) farCells->push_back(c);
  }
  double worst[2] = {sides[0].worst, sides[1].worst},
         squares[2] = {sides[0].squares, sides[1].squares},
         weight[2] = {sides[0].weight, sides[1].weight};
  const auto rms = [&](int k) { return weight[k] > 0 ? std::sqrt(squares[k] / weight[k]) : 0.0; };
  return {std::max(rms(0), rms(1)) / diagonal, std::sqrt(std::max(worst[0], worst[1])) / diagonal,
          longestOld, longestNew};
}

// measureMoveOnce with the bounds first: they only raise the figures, so a pass stands, and so
// does a Hausdorff distance over the tolerance (a search's, past half of it); a step failed by
// its RMS alone is measured again by searches throughout, so every step is decided as searches
// decide it (and the far cells are the same).
Moved measureMove(const GeometryImage& image, const ParameterField& f, double step,
                  const MovedRegion& region, const AabbTree& oldSurface,
                  const std::vector<std::uint8_t>& onOld, const KeepDetailFigures& figures,
                  std::vector<std::size_t>* farCells = nullptr, double far = 0) {
  Moved moved =
      measureMoveOnce(image, f, step, region, oldSurface, onOld, figures, true, farCells, far);
  if (moved.hausdorff <= kCheckedShare * kHausdorffTolerance &&
      moved.rms > kCheckedShare * kRmsTolerance && moved.longestNew <= moved.longestOld)
    moved =
        measureMoveOnce(image, f, step, region, oldSurface, onOld, figures, false, farCells, far);
  return moved;
}

// The cells with a corner whose offset is not zero.
Cells movedCells(const ParameterField& f) {
  Cells cells;
  for (int j = 0; j < f.cellsHigh; ++j)
    for (int i = 0; i < f.cellsWide; ++i)
      for (const auto& [a, b] : {std::array{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}) {
        const auto [ca, cb] = f.canonicalOf(a, b);
        const Offset& d = f.offset[f.index(ca, cb)];
        if (d.x != 0 || d.y != 0) {
          cells.push_back({i, j});
          break;
        }
      }
  return cells;
}

// The tiles holding a moved sample or one of its copies (a torus's column W and row H).
std::vector<std::uint8_t> movedTiles(const ParameterField& f, int tilesX, int tilesY) {
  std::vector<std::uint8_t> tiles(
      static_cast<std::size_t>(tilesX) * static_cast<std::size_t>(tilesY), 0);
  const auto mark = [&](int i, int j) {
    tiles[static_cast<std::size_t>(j / EditStepRecorder::kTileSize) *
              static_cast<std::size_t>(tilesX) +
          static_cast<std::size_t>(i / EditStepRecorder::kTileSize)] = 1;
  };
  for (int j = 0; j < f.rows; ++j)
    for (int i = 0; i < f.columns; ++i) {
      const Offset& d = f.offset[f.index(i, j)];
      if (d.x == 0 && d.y == 0) continue;
      mark(i, j);
      if (!f.torus()) continue;
      if (i == 0) mark(f.grid.width, j);
      if (j == 0) mark(i, f.grid.height);
      if (i == 0 && j == 0) mark(f.grid.width, f.grid.height);
    }
  return tiles;
}

} // namespace

EditStep gridRelaxChangedStep(const Document& document, const std::vector<std::uint8_t>& changed,
                              int margin, std::string label, const RelaxOptions& options,
                              const KeepDetailFigures& figures) {
  const GeometryImage& image = document.positions;
  const int side = image.side(), rows = image.rows();
  if (changed.size() != static_cast<std::size_t>(side) * static_cast<std::size_t>(rows))
    throw Error(ErrorKind::InvalidArgument,
                "the changed samples must cover the (W+1) × (H+1) image");
  EditStepRecorder recorder(side, rows);
  // Nothing stretched: no sample is freed (what most strokes end with).
  if (!stretchedAt(image, changed, figures.stretchedEdge)) return recorder.finish(std::move(label));
  const ParameterField full = emptyField(image.grid(), 1);
  const std::vector<std::uint8_t> free = freedSamples(full, changed, margin, options.pinned);
  if (std::find(free.begin(), free.end(), 1) == free.end())
    return recorder.finish(std::move(label));
  // Where the full move cuts too deep (the tip of a part pulled far), the corners of the cells
  // it cut are held and the flow solved again, kHoldAttempts times at most; the try that moves
  // the samples farthest (its kept step times its offsets) wins.
  const int sweeps = kSweepsPerLevel * std::clamp(options.iterations, 1, 25);
  std::vector<std::uint8_t> tried = free;
  std::optional<AabbTree> oldSurface;
  std::vector<std::uint8_t> onOld; // its cells, cellsWide × cellsHigh
  ParameterField field;
  double kept = 0, keptTravel = 0;
  for (int attempt = 0; attempt <= kHoldAttempts; ++attempt) {
    ParameterField solved = solveFreed(image, tried, margin, sweeps);
    const MovedRegion region = movedRegion(image, solved, movedCells(solved));
    if (region.cells.empty()) break;
    const Cells& cells = region.cells;
    // The old surface around the first solve's moved cells (every later one moves fewer).
    if (!oldSurface) {
      TriangleMesh around = region.oldCells;
      append(around, region.oldRing);
      oldSurface.emplace(around);
      onOld.assign(
          static_cast<std::size_t>(full.cellsWide) * static_cast<std::size_t>(full.cellsHigh), 0);
      for (const Cells* part : {&region.cells, &region.ring})
        for (const auto& [i, j] : *part)
          onOld[static_cast<std::size_t>(j) * static_cast<std::size_t>(full.cellsWide) +
                static_cast<std::size_t>(i)] = 1;
    }
    std::vector<std::size_t> far;
    double step = 0;
    for (const double s : {1.0, 0.5, 0.25, 0.125}) {
      const Moved moved =
          measureMove(image, solved, s, region, *oldSurface, onOld, figures,
                      s == 1.0 ? &far : nullptr, 0.5 * kHausdorffTolerance * figures.diagonal);
      // Within the tolerance, and no edge longer than the longest it replaces.
      if (moved.rms <= kCheckedShare * kRmsTolerance &&
          moved.hausdorff <= kCheckedShare * kHausdorffTolerance &&
          moved.longestNew <= moved.longestOld) {
        step = s;
        break;
      }
    }
    // The try that moves the samples farthest in all wins (a try whose holds stopped the flow
    // may keep its whole step and move next to nothing).
    double travel = 0;
    for (const Offset& d : solved.offset)
      travel += step * std::hypot(d.x, d.y);
    if (travel > keptTravel) {
      kept = step;
      keptTravel = travel;
      field = std::move(solved);
    }
    if (step == 1.0 || far.empty()) break;
    for (const std::size_t c : far)
      for (int dj = 0; dj <= 1; ++dj)
        for (int di = 0; di <= 1; ++di) {
          const Sample q = canonicalSample(full, cells[c][0] + di, cells[c][1] + dj);
          tried[full.index(q.i, q.j)] = 0;
        }
  }
  if (kept == 0) return recorder.finish(std::move(label));
  const Document after = resampled(document, field, kept);
  const int tilesX = EditStepRecorder::tilesPerSide(side),
            tilesY = EditStepRecorder::tilesPerSide(rows);
  const std::vector<std::uint8_t> tiles = movedTiles(field, tilesX, tilesY);
  for (EditLayer layer :
       {EditLayer::Positions, EditLayer::Diffuse, EditLayer::Feature, EditLayer::Mask}) {
    if (!resamplingChanges(document, layer)) continue;
    for (int ty = 0; ty < tilesY; ++ty)
      for (int tx = 0; tx < tilesX; ++tx) {
        if (!tiles[static_cast<std::size_t>(ty) * static_cast<std::size_t>(tilesX) +
                   static_cast<std::size_t>(tx)])
          continue;
        const TexelRect r = EditStepRecorder::tileRegion(side, rows, tx, ty);
        recorder.addTile(layer, tx, ty, editLayerChannels(layer), tileTexels(document, layer, r),
                         tileTexels(after, layer, r));
      }
  }
  return recorder.finish(std::move(label));
}

} // namespace octaclay::core::detail
