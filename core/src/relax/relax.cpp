#include "octaclay/core/relax/relax.h"

#include "detail/aabb_tree.h"
#include "detail/parallel_rows.h"
#include "document/tile_texels.h"
#include "relax/even_out_steps.h"
#include "relax/grid_even_out.h"
#include "relax/grid_keep_detail.h"
#include "relax/offset_field.h"
#include "relax/sample_masks.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/grid_point.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <future>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace {

void checkOptions(const RelaxOptions& options) {
  if (options.iterations < 0 || options.iterations > kMaxRelaxIterations)
    throw Error(ErrorKind::InvalidArgument,
                "iterations " + std::to_string(options.iterations) + " is outside 0 to " +
                    std::to_string(kMaxRelaxIterations) + "; leave it at 0 to choose from N");
}

void checkPositions(const GeometryImage& image) {
  if (const auto problem = positionsProblem(image))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be relaxed");
}

int fineIterations(const RelaxOptions& options) {
  return options.iterations > 0 ? options.iterations : 1;
}

// An edge longer than kStretchedEdge times the surface's median edge is stretched. Samples are
// taken from the surface around it only while its edges stay within a multiple of the median
// (the even-out's, and keep-detail's, whose reservoir is bounded and pinned at its rim): the
// surface they leave keeps its resolution.
constexpr float kStretchedEdge = 2.0f;
constexpr float kCoarseStretchedEdge = 1.5f;
constexpr float kLongEdge = 0.003f;
constexpr float kEvenOutDonorEdge = 3.0f;
constexpr float kKeepDetailDonorEdge = 5.0f;
// How far keep-detail's relaxation may move the surface, as fractions of the bounding-box
// diagonal (the even-out's tolerance).
constexpr double kKeepDetailRms = 1e-4;
constexpr double kKeepDetailHausdorff = 1e-3;
// How many times keep-detail solves again with the samples where its move cut too deep held.
constexpr int kHoldAttempts = 2;

float edgeLength(const GeometryImage& image, int i, int j, int di, int dj) {
  return length(image.at(i + di, j + dj).xyz() - image.at(i, j).xyz());
}

// The median grid edge, from every 8th row and column (a fraction of the work, the same figure
// within a few percent).
float medianEdge(const GeometryImage& image) {
  const int w = image.width(), h = image.height();
  std::vector<float> edges;
  for (int j = 0; j <= h; j += 8)
    for (int i = 0; i < w; ++i)
      edges.push_back(edgeLength(image, i, j, 1, 0));
  for (int i = 0; i <= w; i += 8)
    for (int j = 0; j < h; ++j)
      edges.push_back(edgeLength(image, i, j, 0, 1));
  std::nth_element(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2),
                   edges.end());
  return edges[edges.size() / 2];
}

// The bounding box's diagonal, from every 4th sample.
float diagonal(const GeometryImage& image) {
  Vec3f lo = image.at(0, 0).xyz(), hi = lo;
  for (int j = 0; j <= image.height(); j += 4)
    for (int i = 0; i <= image.width(); i += 4) {
      const Vec3f p = image.at(i, j).xyz();
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return length(hi - lo);
}

// Keep-detail relaxes edges over kStretchedEdge times the median, and at coarse N (long median
// edges) from kCoarseStretchedEdge times: a long edge's facet cuts across the surface the
// relaxation resamples, so it is relaxed before it is longer than kLongEdge of the diagonal.
float stretchedEdgeLimit(const GeometryImage& image, float median) {
  return std::clamp(kLongEdge * diagonal(image), kCoarseStretchedEdge * median,
                    kStretchedEdge * median);
}

// The tiling's half-turn centres, which cannot move without tearing the seam.
bool isSideMidpoint(int n, Sample s) {
  const int h = n / 2;
  return (s.i == h && (s.j == 0 || s.j == n)) || (s.j == h && (s.i == 0 || s.i == n));
}

// The even-out's offsets (the whole model free), solved on document's positions.
detail::OffsetField solveEvenOut(const Document& document, const RelaxOptions& options,
                                 const RelaxProgress& progress) {
  checkOptions(options);
  checkPositions(document.positions);
  detail::OffsetField field(document.size());
  field.freeAll();
  for (Sample s : options.pinned)
    field.pin(s);
  if (!detail::solveOffsets(document.positions, field, fineIterations(options),
                            kEvenOutDonorEdge * medianEdge(document.positions), false, progress))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return field;
}

// Per sample: 1 when one of its grid edges (through the wrap) is over `limit` long.
std::vector<std::uint8_t> stretchedSamples(const GeometryImage& image, double limit) {
  const int n = image.size();
  std::vector<std::uint8_t> out(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f p = image.at(i, j).xyz();
      bool stretched = false;
      for (const Sample d : {Sample{1, 0}, Sample{-1, 0}, Sample{0, 1}, Sample{0, -1}})
        stretched = stretched || length(image.positionWrapped({i + d.i, j + d.j}) - p) > limit;
      out[static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
          static_cast<std::size_t>(i)] = stretched;
    }
  return out;
}

// How many vertices show the stretched part once field (scaled by step) is applied: a vertex
// counts when the grid sample nearest its parameter point is stretched.
std::size_t stretchedShown(const detail::OffsetField& field, double step,
                           const std::vector<std::uint8_t>& stretched) {
  const int n = field.n;
  std::size_t count = 0;
  forEachCanonicalRun(n, [&](int j, int iBegin, int iEnd) {
    for (int i = iBegin; i < iEnd; ++i) {
      const auto& d = field.offset[field.index(i, j)];
      Sample s{i, j};
      if (d[0] != 0.0f || d[1] != 0.0f) {
        const GridPoint p =
            locateGridPoint(n, double(i) + step * double(d[0]), double(j) + step * double(d[1]));
        const auto k = std::max_element(p.weights.begin(), p.weights.end()) - p.weights.begin();
        s = p.corners[static_cast<std::size_t>(k)];
      }
      count += stretched[field.index(s.i, s.j)];
    }
  });
  return count;
}

// The area of the grid's triangles over the cells with a moved corner (offsets[k] != 0), their
// vertices at `positions`: the part of the surface a local relaxation can change; none when no
// cell has one. Summed cell by cell in row order.
std::optional<double> movedCellsArea(int n, const std::vector<Vec3f>& positions,
                                     const detail::OffsetField& field) {
  const auto moved = [&](int i, int j) {
    const auto& d = field.offset[field.index(i, j)];
    return d[0] != 0.0f || d[1] != 0.0f;
  };
  bool any = false;
  double area = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      if (!moved(i, j) && !moved(i + 1, j) && !moved(i, j + 1) && !moved(i + 1, j + 1)) continue;
      any = true;
      for (const auto& tri : cellTriangles(n, i, j)) {
        const Vec3f a = positions[field.index(tri[0].i, tri[0].j)];
        area += 0.5 * double(length(cross(positions[field.index(tri[1].i, tri[1].j)] - a,
                                          positions[field.index(tri[2].i, tri[2].j)] - a)));
      }
    }
  if (!any) return std::nullopt;
  return area;
}

// The whole surface's area, straight from the grid (no mesh built).
double surfaceArea(int n, const std::vector<Vec3f>& positions) {
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  const auto at = [&](Sample s) {
    return positions[static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i)];
  };
  double total = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const auto& tri : cellTriangles(n, i, j)) {
        const Vec3f a = at(tri[0]);
        total += 0.5 * double(length(cross(at(tri[1]) - a, at(tri[2]) - a)));
      }
  return total;
}

// What keep-detail's check measures against, the same for every try of one relaxation.
struct SurfaceFigures {
  double diagonal = 0; ///< of the bounding box (every 4th sample)
  double area = 0;     ///< of the whole surface
};

// The positions of `image` resampled at the field's parameter points (what resampleDocument
// writes into the positions), as plain points; `before`: the document's positions as they are.
std::vector<Vec3f> resampledPositions(const Document& document, const std::vector<Vec3f>& before,
                                      const detail::OffsetField& field) {
  const int n = document.size();
  std::vector<Vec3f> out = before;
  detail::parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= n; ++i) {
        const auto& d = field.offset[field.index(i, j)];
        if (d[0] == 0.0f && d[1] == 0.0f) continue;
        float p[4];
        detail::resampleTexel(document, field, EditLayer::Positions, i, j, p);
        out[field.index(i, j)] = {p[0], p[1], p[2]};
      }
  });
  return out;
}

// Keep-detail's surface check: on each side, the mesh's vertices (every k-th, at most
// kCheckVertices) and kCheckAreaPoints area-weighted random points, each with the grid sample it
// stands for (a vertex's own, a random point's nearest corner), and the side's AABB tree; each
// query visits at most kCheckLeaves leaves (compareSurfaces' bound).
constexpr std::size_t kCheckVertices = 20'000, kCheckAreaPoints = 20'000, kCheckChunk = 1024;
constexpr std::uint32_t kCheckLeaves = 256;
// Points whose surface moved by at most this share of the Hausdorff tolerance are not queried
// (nor found far: `far` takes the points beyond the same share).
constexpr double kCheckSkip = 0.5;

// One side's surface for the check: the grid's triangles over some cells (vertices wrapped
// through the seams), its AABB tree, and where each cell's two triangles are in it.
struct CheckSurface {
  TriangleMesh mesh;
  std::vector<std::size_t> samples;       ///< per vertex, its grid sample
  std::vector<std::int32_t> cellTriangle; ///< per cell × 2 (its triangles), mesh index or -1
  std::vector<std::uint32_t> cellOf;      ///< per mesh triangle, cell × 2 + which
  detail::AabbTree tree;
  std::vector<std::uint32_t> leafOf; ///< per mesh triangle, its index in tree.triangles()
};

// The surface over the cells marked (non-zero) in `cells` (n × n, row-major).
CheckSurface checkSurface(int n, const std::vector<Vec3f>& positions,
                          const std::vector<std::uint8_t>& cells) {
  TriangleMesh mesh;
  std::vector<std::size_t> samples;
  std::vector<std::int32_t> cellTriangle(2 * cells.size(), -1);
  std::vector<std::uint32_t> cellOf;
  std::vector<std::uint32_t> vertex(positions.size(), ~0u);
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const std::size_t cell =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
      if (!cells[cell]) continue;
      std::size_t which = 0;
      for (const auto& tri : cellTriangles(n, i, j)) {
        std::array<std::uint32_t, 3> t{};
        for (std::size_t v = 0; v < 3; ++v) {
          const std::size_t k =
              static_cast<std::size_t>(tri[v].j) * side + static_cast<std::size_t>(tri[v].i);
          if (vertex[k] == ~0u) {
            vertex[k] = static_cast<std::uint32_t>(mesh.positions.size());
            mesh.positions.push_back(positions[k]);
            samples.push_back(k);
          }
          t[v] = vertex[k];
        }
        cellTriangle[2 * cell + which] = static_cast<std::int32_t>(mesh.triangles.size());
        cellOf.push_back(static_cast<std::uint32_t>(2 * cell + which));
        mesh.triangles.push_back(t);
        ++which;
      }
    }
  // The tree over tiles of 8 × 8 cells, each a quadtree (its cells in Z order): built in a
  // fraction of the time of median splits over every triangle (the old side's tree was 145 of
  // a ridge's 600 ms at N = 1024).
  constexpr int kTile = 8;
  const auto evenBits = [](int z) { // bits 0, 2, 4 of z, packed
    return (z & 1) | ((z >> 1) & 2) | ((z >> 2) & 4);
  };
  std::vector<std::uint32_t> order, blockStarts;
  order.reserve(mesh.triangles.size());
  for (int tj = 0; tj < n; tj += kTile)
    for (int ti = 0; ti < n; ti += kTile) {
      const std::size_t start = order.size();
      for (int z = 0; z < kTile * kTile; ++z) {
        const int i = ti + evenBits(z), j = tj + evenBits(z >> 1);
        if (i >= n || j >= n) continue;
        const std::size_t cell =
            static_cast<std::size_t>(j) * static_cast<std::size_t>(n) + static_cast<std::size_t>(i);
        for (std::size_t which = 0; which < 2; ++which)
          if (const std::int32_t t = cellTriangle[2 * cell + which]; t >= 0)
            order.push_back(static_cast<std::uint32_t>(t));
      }
      if (order.size() > start) blockStarts.push_back(static_cast<std::uint32_t>(start));
    }
  detail::AabbTree tree(mesh, order, blockStarts);
  std::vector<std::uint32_t> leafOf(mesh.triangles.size());
  const auto ids = tree.triangleIds();
  for (std::size_t k = 0; k < ids.size(); ++k)
    leafOf[ids[k]] = static_cast<std::uint32_t>(k);
  return {std::move(mesh),   std::move(samples), std::move(cellTriangle),
          std::move(cellOf), std::move(tree),    std::move(leafOf)};
}

// Puts the samples of `moved`, a copy of the old surface (its mesh, cells and leaves), where
// `after` puts them, and refits its tree rather than building it again (a tenth of the time; the
// moved side of keep detail's check, over the old side's cells: every cell that may move and its
// ring). The copy is made once per relaxation, beside the first solve: made at each try (some
// 70 MB for a ridge at N = 1024, most of it fresh pages) it cost as much as the refit.
void moveSurface(const std::vector<Vec3f>& after, CheckSurface& moved) {
  for (std::size_t v = 0; v < moved.mesh.positions.size(); ++v)
    moved.mesh.positions[v] = after[moved.samples[v]];
  moved.tree.refit(moved.mesh);
}

// The points measured on one side: the vertices (every k-th, at most kCheckVertices) and
// kCheckAreaPoints area-weighted random points of the surface's triangles whose cells are
// marked 2 in `cells`.
struct CheckPoints {
  std::vector<detail::Vec3d> points;
  std::vector<std::size_t>
      samples; ///< the grid sample each stands for (a random point's nearest corner)
  /// Per point, its cell × 2 + which triangle (a vertex: one of its triangles): the same cell's
  /// triangle on the other side is the query's first bound.
  std::vector<std::uint32_t> cellTriangles;
  /// Per point, the samples whose moves bound its distance to the other side: a vertex's own
  /// (three times), a random point's triangle's corners.
  std::vector<std::array<std::size_t, 3>> corners;
  /// Per point, where it lies in the image's parameter domain (sample units).
  std::vector<std::array<float, 2>> params;
  std::size_t vertexPoints = 0; ///< the first points are vertices, the rest random
  double sampledArea = 0;       ///< of the triangles the random points are drawn on
};

CheckPoints checkPoints(int n, const CheckSurface& surface, const std::vector<std::uint8_t>& cells,
                        std::uint64_t seed) {
  const TriangleMesh& mesh = surface.mesh;
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  const auto param = [&](std::size_t k) {
    return std::array<double, 2>{double(k % side), double(k / side)};
  };
  const auto sampled = [&](std::size_t t) { return cells[surface.cellOf[t] / 2] == 2; };
  CheckPoints out;
  const std::size_t count = mesh.positions.size();
  std::vector<std::uint32_t> triangleOf(count, ~0u);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    if (sampled(t))
      for (const std::uint32_t v : mesh.triangles[t])
        triangleOf[v] = static_cast<std::uint32_t>(t);
  std::size_t used = 0;
  for (const std::uint32_t t : triangleOf)
    used += t != ~0u;
  const std::size_t stride = std::max<std::size_t>(1, (used + kCheckVertices - 1) / kCheckVertices);
  for (std::size_t v = 0, u = 0; v < count; ++v) {
    if (triangleOf[v] == ~0u || u++ % stride != 0) continue;
    const std::size_t k = surface.samples[v];
    out.points.emplace_back(mesh.positions[v]);
    out.samples.push_back(k);
    out.cellTriangles.push_back(surface.cellOf[triangleOf[v]]);
    out.corners.push_back({k, k, k});
    const auto at = param(k);
    out.params.push_back({float(at[0]), float(at[1])});
  }
  out.vertexPoints = out.points.size();
  std::vector<double> cumulative(mesh.triangles.size());
  double total = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    if (sampled(t))
      total += 0.5 * double(length(cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                         mesh.positions[tri[2]] - mesh.positions[tri[0]])));
    cumulative[t] = total;
  }
  out.sampledArea = total;
  if (!(total > 0)) return out;
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  // Drawn in the order of the mesh's triangles (sorted), so consecutive queries are near.
  std::vector<double> draws(kCheckAreaPoints);
  for (double& r : draws)
    r = uniform(random) * total;
  std::sort(draws.begin(), draws.end());
  for (const double r : draws) {
    const std::size_t t = std::min<std::size_t>(
        static_cast<std::size_t>(std::upper_bound(cumulative.begin(), cumulative.end(), r) -
                                 cumulative.begin()),
        cumulative.size() - 1);
    double u = uniform(random), v = uniform(random);
    if (u + v > 1) u = 1 - u, v = 1 - v;
    const auto& tri = mesh.triangles[t];
    const detail::Vec3d a(mesh.positions[tri[0]]), b(mesh.positions[tri[1]]),
        c(mesh.positions[tri[2]]);
    out.points.push_back(a + (b - a) * u + (c - a) * v);
    const double w0 = 1 - u - v;
    out.samples.push_back(surface.samples[tri[w0 >= u && w0 >= v ? 0 : u >= v ? 1 : 2]]);
    out.cellTriangles.push_back(surface.cellOf[t]);
    out.corners.push_back(
        {surface.samples[tri[0]], surface.samples[tri[1]], surface.samples[tri[2]]});
    const auto pa = param(surface.samples[tri[0]]), pb = param(surface.samples[tri[1]]),
               pc = param(surface.samples[tri[2]]);
    out.params.push_back({float(pa[0] + (pb[0] - pa[0]) * u + (pc[0] - pa[0]) * v),
                          float(pa[1] + (pb[1] - pa[1]) * u + (pc[1] - pa[1]) * v)});
  }
  return out;
}

// What each point of `from` starts its query on `to` from: the nearest of `to`'s triangles over
// the cell of the point's parameter location there (and the eight cells around it when that
// one is farther than nearEnough, squared), as the search's first bound
// (its index into to.tree's triangles, or noTriangle) and as an upper bound on the nearest
// distance (squared, the same figure to the bit the search would find for that triangle;
// infinity where no such triangle is in `to`). The moved surface shows the old one at
// q + offset(q), so a moved point at q lies near the old surface's q + offset(q), and an old
// point at x near the moved surface's q = x - offset(q) (two fixed-point steps). The same
// cell's triangle was the nearest for 1 query in 200 on a pulled ridge (the samples flowed).
struct QuerySeeds {
  std::vector<std::uint32_t> hints;
  std::vector<double> bounds;
};

QuerySeeds querySeeds(int n, const CheckPoints& from, const CheckSurface& to,
                      const detail::OffsetField& field, bool toMoved, double nearEnough) {
  const auto offsetNear = [&](std::array<double, 2> x) {
    const int i = std::clamp(static_cast<int>(std::lround(x[0])), 0, n);
    const int j = std::clamp(static_cast<int>(std::lround(x[1])), 0, n);
    const auto& d = field.offset[field.index(i, j)];
    return std::array<double, 2>{double(d[0]), double(d[1])};
  };
  QuerySeeds seeds{
      std::vector<std::uint32_t>(from.points.size(), detail::AabbTree::noTriangle),
      std::vector<double>(from.points.size(), std::numeric_limits<double>::infinity())};
  const auto seedOf = [&](std::size_t k) {
    const std::array<double, 2> x{double(from.params[k][0]), double(from.params[k][1])};
    std::array<double, 2> q = x;
    if (toMoved)
      for (int step = 0; step < 2; ++step) {
        const auto d = offsetNear(q);
        q = {x[0] - d[0], x[1] - d[1]};
      }
    else {
      const auto d = offsetNear(x);
      q = {x[0] + d[0], x[1] + d[1]};
    }
    const int ci = std::clamp(static_cast<int>(std::floor(q[0])), 0, n - 1);
    const int cj = std::clamp(static_cast<int>(std::floor(q[1])), 0, n - 1);
    std::int32_t best = -1;
    const auto tryCell = [&](int cx, int cy) {
      for (std::size_t which = 0; which < 2; ++which) {
        const std::int32_t t =
            to.cellTriangle[2 * (static_cast<std::size_t>(cy) * static_cast<std::size_t>(n) +
                                 static_cast<std::size_t>(cx)) +
                            which];
        if (t < 0) continue;
        // The mesh's corners (in cell order, near one another), the tree's figure to the bit.
        const auto& tri = to.mesh.triangles[static_cast<std::size_t>(t)];
        const detail::Vec3d p = from.points[k];
        const detail::Vec3d d =
            p - detail::closestPointOnTriangle(p, detail::Vec3d(to.mesh.positions[tri[0]]),
                                               detail::Vec3d(to.mesh.positions[tri[1]]),
                                               detail::Vec3d(to.mesh.positions[tri[2]]));
        if (const double squared = dot(d, d); squared < seeds.bounds[k]) {
          seeds.bounds[k] = squared;
          best = t;
        }
      }
    };
    // The cell alone where it is near enough (most points), else the eight around it too.
    tryCell(ci, cj);
    if (!(seeds.bounds[k] <= nearEnough))
      for (int cy = std::max(cj - 1, 0); cy <= std::min(cj + 1, n - 1); ++cy)
        for (int cx = std::max(ci - 1, 0); cx <= std::min(ci + 1, n - 1); ++cx)
          if (cx != ci || cy != cj) tryCell(cx, cy);
    if (best < 0) best = to.cellTriangle[from.cellTriangles[k]]; // the point's own cell there
    if (best >= 0) seeds.hints[k] = to.leafOf[static_cast<std::size_t>(best)];
  };
  const int chunks = static_cast<int>((from.points.size() + kCheckChunk - 1) / kCheckChunk);
  detail::parallelRows(
      chunks,
      [&](int first, int last) {
        for (std::size_t k = static_cast<std::size_t>(first) * kCheckChunk;
             k < std::min(from.points.size(), static_cast<std::size_t>(last) * kCheckChunk); ++k)
          seedOf(k);
      },
      4);
  return seeds;
}

// Distances from `from`'s points to the surface of `to`: the largest and the sum of squares
// (over chunks summed in order, so the figures do not depend on the thread count); the samples
// of the points farther than `limit` go to `far` when given.
struct CheckSums {
  double maxSquared = 0, sumSquared = 0; ///< sumSquared: over the random points
  std::size_t count = 0;                 ///< random points
};

// Without `far`, the measure stops at the first point farther than `fail` (the try fails: its
// figures are then a lower bound). A point whose corners (CheckPoints::corners) moved by at most
// `skip` (`moves`, per sample, object units) is not queried: the point of the other surface
// with its barycentric weights lies no farther than the farthest corner move, which counts as
// its distance (an upper bound: the figures stay conservative). With seedBounds, so does a
// point's seed bound (QuerySeeds) when it is within `limit`: every figure over `limit` is then
// a search's, and `far` the same as without.
CheckSums measureSide(const CheckPoints& from, const CheckSurface& toSide, const QuerySeeds& seeds,
                      bool seedBounds, double limit, double fail, const std::vector<float>& moves,
                      double skip, std::vector<std::size_t>* far) {
  const detail::AabbTree& to = toSide.tree;
  std::atomic<bool> failed{false};
  const std::size_t n = from.points.size();
  const int chunks = static_cast<int>((n + kCheckChunk - 1) / kCheckChunk);
  std::vector<CheckSums> sums(static_cast<std::size_t>(chunks));
  std::vector<std::vector<std::size_t>> farChunks(static_cast<std::size_t>(chunks));
  detail::parallelRows(
      chunks,
      [&](int begin, int end) {
        for (int c = begin; c < end; ++c) {
          CheckSums& s = sums[static_cast<std::size_t>(c)];
          const std::size_t first = static_cast<std::size_t>(c) * kCheckChunk;
          for (std::size_t k = first; k < std::min(n, first + kCheckChunk); ++k) {
            if (!far && failed.load(std::memory_order_relaxed)) break;
            const auto& at = from.corners[k];
            const double bound = double(std::max({moves[at[0]], moves[at[1]], moves[at[2]]}));
            const bool random = k >= from.vertexPoints;
            if (bound <= skip) {
              s.maxSquared = std::max(s.maxSquared, bound * bound);
              s.sumSquared += random ? bound * bound : 0.0;
              s.count += random;
              continue;
            }
            // With seedBounds, a seed no farther than `limit` stands for the point's distance:
            // never less, and never far.
            if (seedBounds && seeds.bounds[k] <= limit * limit) {
              s.maxSquared = std::max(s.maxSquared, seeds.bounds[k]);
              s.sumSquared += random ? seeds.bounds[k] : 0.0;
              s.count += random;
              continue;
            }
            const detail::AabbTree::Hit hit =
                to.closest(from.points[k], seeds.hints[k], kCheckLeaves);
            if (hit.distanceSquared > fail * fail) failed.store(true, std::memory_order_relaxed);
            s.maxSquared = std::max(s.maxSquared, hit.distanceSquared);
            s.sumSquared += random ? hit.distanceSquared : 0.0;
            s.count += random;
            if (far && hit.distanceSquared > limit * limit)
              farChunks[static_cast<std::size_t>(c)].push_back(from.samples[k]);
          }
        }
      },
      1);
  CheckSums total;
  for (std::size_t c = 0; c < sums.size(); ++c) {
    total.maxSquared = std::max(total.maxSquared, sums[c].maxSquared);
    total.sumSquared += sums[c].sumSquared;
    total.count += sums[c].count;
    if (far) far->insert(far->end(), farChunks[c].begin(), farChunks[c].end());
  }
  return total;
}

// Keeps keep-detail's solved move within the relaxation's tolerance: the surface moves by at
// most kKeepDetailRms (RMS) and kKeepDetailHausdorff (Hausdorff) of the bounding-box diagonal,
// measured over the cells that changed (the rest of the surface keeps its bits; the RMS is
// taken over the whole surface's area). Like evenOut, the move is kept, or scaled back (1/2,
// 1/4, 1/8: a move that cuts across a sharp feature, a crease's valley or the coarse facets of
// a limb pulled far in one stroke), or dropped (every offset zero). `old` is the old surface over
// every cell that may move and the ring around them, its tree built once per relaxation; `moved`
// the moved side's surface, kept from try to try (moveSurface). `far`,
// when given, gets the samples whose points the full move takes farther than half the Hausdorff
// tolerance (where it cuts: a pulled limb's tip). Returns the step kept (0: none).
double keepWithinTolerance(const Document& document, const std::vector<Vec3f>& before,
                           const SurfaceFigures& figures, const CheckSurface& old,
                           CheckSurface& moved, detail::OffsetField& field,
                           std::vector<std::size_t>* far = nullptr) {
  // Collecting where the full move cuts: only the full move is tried (the caller holds those
  // samples and solves again rather than scale the move down).
  const std::vector<double> steps =
      far ? std::vector<double>{1.0} : std::vector<double>{1.0, 0.5, 0.25, 0.125};
  const GeometryImage& image = document.positions;
  const int n = image.size();
  const double diag = figures.diagonal, total = figures.area;
  const std::optional<double> moving = movedCellsArea(n, before, field);
  if (!moving) return 0;
  const double movedArea = *moving;
  const double share = total > 0 ? std::min(1.0, movedArea / total) : 1.0;
  const double fail = kKeepDetailHausdorff * diag, limit = 0.5 * fail, skip = kCheckSkip * fail;
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  const detail::OffsetField solved = field;
  for (const double step : steps) {
    for (std::size_t k = 0; k < field.offset.size(); ++k)
      field.offset[k] = {static_cast<float>(step * double(solved.offset[k][0])),
                         static_cast<float>(step * double(solved.offset[k][1]))};
    const std::vector<Vec3f> after = resampledPositions(document, before, field);
    // A sample whose offset is zero keeps its bits: its move is zero.
    std::vector<float> moves(after.size(), 0.0f);
    for (std::size_t k = 0; k < after.size(); ++k)
      if (field.offset[k][0] != 0.0f || field.offset[k][1] != 0.0f)
        moves[k] = length(after[k] - before[k]);
    // Only the cells whose surface moved by more than `skip` are measured (a point of a cell
    // lies within its farthest corner's move of the other surface), against them and the cells
    // around them.
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
    const auto move = [&](int i, int j) {
      return moves[static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)];
    };
    bool any = false;
    double skippedSquares = 0; // the unmeasured moved cells: area × farthest corner move²
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const double farthest =
            double(std::max({move(i, j), move(i + 1, j), move(i, j + 1), move(i + 1, j + 1)}));
        if (farthest > 0 && farthest <= skip)
          for (const auto& tri : cellTriangles(n, i, j)) {
            const Vec3f a = image.at(tri[0]).xyz();
            skippedSquares +=
                farthest * farthest * 0.5 *
                double(length(cross(image.at(tri[1]).xyz() - a, image.at(tri[2]).xyz() - a)));
          }
        if (farthest > skip) {
          for (int dj = -1; dj <= 1; ++dj)
            for (int di = -1; di <= 1; ++di)
              if (i + di >= 0 && j + dj >= 0 && i + di < n && j + dj < n) {
                std::uint8_t& c =
                    cells[static_cast<std::size_t>(j + dj) * static_cast<std::size_t>(n) +
                          static_cast<std::size_t>(i + di)];
                c = std::max<std::uint8_t>(c, di == 0 && dj == 0 ? 2 : 1);
              }
          any = true;
        }
      }
    double hausdorff = skip,
           rms = std::sqrt(skippedSquares / std::max(movedArea, 1e-30)) * std::sqrt(share);
    if (any) {
      // The old side's points are drawn on a thread of their own while the moved side is made.
      std::future<CheckPoints> oldDrawn =
          std::async(std::launch::async, [&] { return checkPoints(n, old, cells, 1); });
      moveSurface(after, moved);
      const CheckPoints newPoints = checkPoints(n, moved, cells, 2);
      const CheckPoints oldPoints = oldDrawn.get();
      std::vector<std::size_t>* cuts = step == 1.0 ? far : nullptr;
      const double nearEnough = 0.0625 * limit * limit; // a quarter of `limit`, squared
      const QuerySeeds seedsOnMoved = querySeeds(n, oldPoints, moved, field, true, nearEnough),
                       seedsOnOld = querySeeds(n, newPoints, old, field, false, nearEnough);
      const std::size_t farBefore = cuts ? cuts->size() : 0;
      // The try's Hausdorff distance and RMS (a Hausdorff distance over `fail` alone when the
      // old side already passes it); with seedBounds, from the seeds' bounds where they suffice.
      const auto measure = [&](bool seedBounds) {
        if (cuts) cuts->resize(farBefore);
        const CheckSums a =
            measureSide(oldPoints, moved, seedsOnMoved, seedBounds, limit, fail, moves, skip, cuts);
        if (!cuts && a.maxSquared > fail * fail)
          return std::pair{std::sqrt(a.maxSquared), std::numeric_limits<double>::infinity()};
        const CheckSums b =
            measureSide(newPoints, old, seedsOnOld, seedBounds, limit, fail, moves, skip, cuts);
        // The RMS over the moved cells' area: the measured cells' mean square by their area,
        // the others' bound by theirs.
        const double measured = std::min(movedArea, oldPoints.sampledArea);
        const double meanSquared =
            (a.sumSquared + b.sumSquared) / double(std::max<std::size_t>(1, a.count + b.count));
        return std::pair{
            std::max(skip, std::sqrt(std::max(a.maxSquared, b.maxSquared))),
            std::sqrt((measured * meanSquared + skippedSquares) / std::max(movedArea, 1e-30)) *
                std::sqrt(share)};
      };
      // The seeds' bounds first (on a ridge at N = 1024, 12 000 of the old side's 39 000 points
      // and 15 of the moved side's are searched, then 6 500 and none): they only raise the
      // figures, so a pass stands, and so does a Hausdorff distance over `fail` (a search's).
      // A try that fails by its RMS alone is measured again by searches throughout: every step
      // is decided as the searches decide it.
      std::tie(hausdorff, rms) = measure(true);
      if (hausdorff <= fail && rms > kKeepDetailRms * diag)
        std::tie(hausdorff, rms) = measure(false);
    }
    if (hausdorff <= fail && rms <= kKeepDetailRms * diag) return step;
  }
  for (auto& d : field.offset)
    d = {0.0f, 0.0f};
  return 0;
}

} // namespace

Document evenOutSamples(const Document& document, const RelaxOptions& options,
                        const RelaxProgress& progress) {
  if (document.positions.topology() != Topology::Octahedral)
    return detail::gridEvenOutSamples(document, options, progress);
  const detail::OffsetField field = solveEvenOut(document, options, progress);
  Document result = document; // samples that do not move keep their texels
  detail::resampleDocument(document, field, result);
  if (progress && !progress(1.0f))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return result;
}

EvenOutResult evenOut(const Document& document, const RelaxOptions& options,
                      const EvenOutCheckOptions& check, const RelaxProgress& progress) {
  if (document.positions.topology() != Topology::Octahedral)
    return detail::gridEvenOut(document, options, check, progress);
  // The solve is most of the work at one try; each try's measure is about as much again.
  const float solveShare = 0.5f;
  const detail::OffsetField field = solveEvenOut(
      document, options, [&](float f) { return !progress || progress(solveShare * f); });
  detail::SolvedEvenOut solved;
  solved.before = summarizeStretch(document.positions);
  const int n = document.size();
  solved.vertices = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) + 2;
  const std::vector<std::uint8_t> stretched =
      stretchedSamples(document.positions, kStretchedEdge * solved.before.medianEdge);
  solved.resample = [&](double step) {
    detail::OffsetField scaled = field;
    for (auto& d : scaled.offset)
      d = {static_cast<float>(step * double(d[0])), static_cast<float>(step * double(d[1]))};
    Document result = document;
    detail::resampleDocument(document, scaled, result);
    return result;
  };
  solved.stretchedShown = [&](double step) { return stretchedShown(field, step, stretched); };
  return detail::tryEvenOutSteps(document, solved, check, progress, solveShare);
}

int keepDetailMargin(const GeometryImage& image, double radius) {
  const double median = medianEdge(image);
  const double margin = median > 0 ? std::ceil(kKeepDetailMarginRadii * radius / median) : 0.0;
  // At most the image's whole side: past it the region holds every sample anyway.
  return static_cast<int>(std::clamp(margin, double(kKeepDetailMinMargin),
                                     double(std::max(image.width(), image.height()))));
}

EditStep relaxChangedStep(const Document& document, const std::vector<std::uint8_t>& changed,
                          int margin, std::string label, const RelaxOptions& options) {
  checkOptions(options);
  if (margin < 0)
    throw Error(ErrorKind::InvalidArgument,
                "a relaxation margin must be 0 or more samples, not " + std::to_string(margin));
  checkPositions(document.positions);
  if (document.positions.topology() != Topology::Octahedral) {
    const float median = medianEdge(document.positions);
    return detail::gridRelaxChangedStep(
        document, changed, margin, std::move(label), options,
        {stretchedEdgeLimit(document.positions, median), diagonal(document.positions), median});
  }
  const int n = document.size(), side = n + 1;
  if (changed.size() != static_cast<std::size_t>(side) * static_cast<std::size_t>(side))
    throw Error(ErrorKind::InvalidArgument, "the changed samples must cover the (N+1)² image");
  const float median = medianEdge(document.positions);
  const float limit = stretchedEdgeLimit(document.positions, median);
  EditStepRecorder recorder(side);
  // Nothing stretched: no sample is freed, and no field is made (what most strokes end with).
  if (!detail::stretchedAt(document.positions, changed, limit))
    return recorder.finish(std::move(label));
  detail::OffsetField field(n);
  const std::vector<std::uint8_t> grown = detail::grownMask(n, changed, margin);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (grown[field.index(i, j)] && !isSideMidpoint(n, {i, j})) field.free[field.index(i, j)] = 1;
  for (Sample s : options.pinned)
    field.pin(s);
  if (std::find(field.free.begin(), field.free.end(), 1) == field.free.end())
    return recorder.finish(std::move(label));
  // Where the full move cuts too deep (the tip of a limb pulled far: its samples are the
  // surface's corners there), those samples and their neighbours are held and the flow solved
  // again around them, up to kHoldAttempts times; the try that keeps the largest step wins.
  const detail::OffsetField unsolved = field;
  detail::OffsetField best = field; // nothing moved
  // The old surface over every cell with a corner that may move, and the ring around them (where
  // a moved point's nearest old point may lie): built once for every try.
  const std::vector<std::uint8_t> region = detail::cellsNearFree(n, unsolved.free);
  // The check's inputs are made on their own thread while the first solve runs (neither reads
  // what the other writes): the positions as points, the surface's figures, the old surface and
  // its copy that each try moves (moveSurface).
  struct CheckInputs {
    std::vector<Vec3f> was;
    SurfaceFigures figures;
    CheckSurface old;
    CheckSurface moved;
  };
  std::future<CheckInputs> madeInputs = std::async(std::launch::async, [&] {
    std::vector<Vec3f> was(document.positions.texels().size());
    for (std::size_t k = 0; k < was.size(); ++k)
      was[k] = document.positions.texels()[k].xyz();
    const SurfaceFigures figures{diagonal(document.positions), surfaceArea(n, was)};
    CheckSurface old = checkSurface(n, was, region);
    CheckSurface moved = old;
    return CheckInputs{std::move(was), figures, std::move(old), std::move(moved)};
  });
  std::optional<CheckInputs> inputs;
  double bestStep = 0;
  std::vector<Sample> held;
  for (int attempt = 0; attempt <= kHoldAttempts; ++attempt) {
    detail::OffsetField tried = unsolved;
    for (Sample s : held)
      tried.pin(s);
    detail::solveOffsets(document.positions, tried, fineIterations(options),
                         kKeepDetailDonorEdge * median, true, {});
    if (!inputs) inputs.emplace(madeInputs.get());
    std::vector<std::size_t> far;
    const double step =
        keepWithinTolerance(document, inputs->was, inputs->figures, inputs->old, inputs->moved,
                            tried, attempt < kHoldAttempts ? &far : nullptr);
    if (step > bestStep) {
      best = std::move(tried);
      bestStep = step;
    }
    if (step == 1.0 || far.empty()) break;
    for (const std::size_t k : far) {
      const int i = static_cast<int>(k % static_cast<std::size_t>(side)),
                j = static_cast<int>(k / static_cast<std::size_t>(side));
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (const Sample q = wrap(n, {i + di, j + dj}); unsolved.free[field.index(q.i, q.j)])
            held.push_back(q);
    }
    std::sort(held.begin(), held.end(),
              [&](Sample a, Sample b) { return field.index(a.i, a.j) < field.index(b.i, b.j); });
    held.erase(std::unique(held.begin(), held.end()), held.end());
  }
  field = std::move(best);
  const int tiles = EditStepRecorder::tilesPerSide(side);
  std::vector<std::uint8_t> moved(static_cast<std::size_t>(tiles) * tiles, 0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto& d = field.offset[field.index(i, j)];
      if (d[0] != 0.0f || d[1] != 0.0f)
        moved[static_cast<std::size_t>(j / EditStepRecorder::kTileSize) * tiles +
              static_cast<std::size_t>(i / EditStepRecorder::kTileSize)] = 1;
    }
  std::vector<std::array<int, 2>> movedTiles;
  for (int ty = 0; ty < tiles; ++ty)
    for (int tx = 0; tx < tiles; ++tx)
      if (moved[static_cast<std::size_t>(ty) * tiles + static_cast<std::size_t>(tx)])
        movedTiles.push_back({tx, ty});
  for (EditLayer layer :
       {EditLayer::Positions, EditLayer::Diffuse, EditLayer::Feature, EditLayer::Mask}) {
    if (!detail::resamplingChanges(document, layer)) continue;
    const std::size_t ch = static_cast<std::size_t>(editLayerChannels(layer));
    // The tiles resampled on every core, then recorded in order.
    std::vector<std::vector<float>> before(movedTiles.size()), after(movedTiles.size());
    detail::parallelRows(
        static_cast<int>(movedTiles.size()),
        [&](int first, int last) {
          for (int t = first; t < last; ++t) {
            const std::size_t k = static_cast<std::size_t>(t);
            const TexelRect r =
                EditStepRecorder::tileRegion(side, movedTiles[k][0], movedTiles[k][1]);
            before[k] = detail::tileTexels(document, layer, r);
            after[k].resize(before[k].size());
            std::size_t o = 0;
            for (int j = r.y; j < r.y + r.height; ++j)
              for (int i = r.x; i < r.x + r.width; ++i, o += ch)
                detail::resampleTexel(document, field, layer, i, j, &after[k][o]);
          }
        },
        1);
    for (std::size_t k = 0; k < movedTiles.size(); ++k)
      recorder.addTile(layer, movedTiles[k][0], movedTiles[k][1], static_cast<int>(ch), before[k],
                       after[k]);
  }
  return recorder.finish(std::move(label));
}

EditStep relaxRegionsStep(const Document& document, const std::vector<TexelRect>& regions,
                          int margin, std::string label, const RelaxOptions& options) {
  const int side = document.positions.side(), rows = document.positions.rows();
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(side) * static_cast<std::size_t>(rows),
                                    0);
  for (const TexelRect& region : regions) {
    const int x0 = std::max(region.x, 0), y0 = std::max(region.y, 0);
    const int x1 = std::min(region.x + region.width, side),
              y1 = std::min(region.y + region.height, rows);
    for (int j = y0; j < y1; ++j)
      for (int i = x0; i < x1; ++i)
        changed[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) +
                static_cast<std::size_t>(i)] = 1;
  }
  return relaxChangedStep(document, changed, margin, std::move(label), options);
}

std::vector<TexelRect> relaxRegions(Document& document, const std::vector<TexelRect>& regions,
                                    int margin, const RelaxOptions& options) {
  const EditStep step = relaxRegionsStep(document, regions, margin, "relax", options);
  const TileApplier apply = applierFor(document);
  std::vector<TexelRect> changed;
  for (const TileChange& t : step.tiles) {
    t.apply(TileState::After, apply);
    if (t.layer == EditLayer::Positions) changed.push_back(t.region);
  }
  return changed;
}

} // namespace octaclay::core
