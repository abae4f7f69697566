#include "octaclay/core/import/remesh.h"

#include "detail/aabb_tree.h"
#include "detail/parallel_rows.h"
#include "import/spherical_image.h"
#include "measure/move_tolerance.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/vertex_index.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

namespace octaclay::core {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

// A layer's channels at texel t (its fill while uniform).
void layerValue(const Layer& layer, std::size_t t, float* out) {
  const std::size_t ch = static_cast<std::size_t>(layer.channels);
  for (std::size_t c = 0; c < ch; ++c)
    out[c] = layer.uniform() ? layer.fill[c] : layer.texels[t * ch + c];
}

// CIE L*a*b* of an sRGB colour in [0, 1] (D65).
std::array<double, 3> lab(const float* rgb) {
  std::array<double, 3> lin{};
  for (int c = 0; c < 3; ++c) {
    const double v = std::clamp(double(rgb[c]), 0.0, 1.0);
    lin[static_cast<std::size_t>(c)] =
        v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
  }
  const double x = (0.4124 * lin[0] + 0.3576 * lin[1] + 0.1805 * lin[2]) / 0.95047;
  const double y = 0.2126 * lin[0] + 0.7152 * lin[1] + 0.0722 * lin[2];
  const double z = (0.0193 * lin[0] + 0.1192 * lin[1] + 0.9505 * lin[2]) / 1.08883;
  const auto f = [](double t) {
    return t > 216.0 / 24389.0 ? std::cbrt(t) : (24389.0 / 27.0 * t + 16) / 116;
  };
  return {116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))};
}

double deltaE(const float* a, const float* b) {
  const auto p = lab(a), q = lab(b);
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                   (p[2] - q[2]) * (p[2] - q[2]));
}

// Barycentric weights of p (a point of triangle abc) in it.
std::array<double, 3> barycentric(detail::Vec3d p, detail::Vec3d a, detail::Vec3d b,
                                  detail::Vec3d c) {
  const detail::Vec3d e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = dot(e0, e0), d01 = dot(e0, e1), d11 = dot(e1, e1);
  const double d20 = dot(d, e0), d21 = dot(d, e1);
  const double det = d00 * d11 - d01 * d01;
  if (!(det > 0)) return {1, 0, 0};
  const double v = (d11 * d20 - d01 * d21) / det, w = (d00 * d21 - d01 * d20) / det;
  return {1 - v - w, v, w};
}

// The point of the new surface nearest p among the triangles of the new grid cell that `sphere`
// (p's sphere point) falls in and the eight cells around it: the new surface there is the old
// one resampled, so the closest point is near, and its distance is never below the closest
// point's. (An AABB tree over the whole new surface gave the same carried-layer shares, to
// 0.01 %, on bench_remesh's three cases and on remesh_test's stripe, and cost as much as the
// rest of the measure at N = 1024.)
struct NearPoint {
  double distanceSquared = std::numeric_limits<double>::infinity();
  std::array<Sample, 3> corners{};
  std::array<double, 3> weights{};
};

NearPoint nearestOnNewCells(const GeometryImage& to, detail::Vec3d p, Vec3f sphere) {
  const int m = to.size(), half = m / 2;
  const std::array<double, 2> st = octahedralSquarePoint(sphere);
  const int ci = std::clamp(static_cast<int>(std::floor(st[0] * m)), 0, m - 1);
  const int cj = std::clamp(static_cast<int>(std::floor(st[1] * m)), 0, m - 1);
  NearPoint best;
  for (int j = std::max(0, cj - 1); j <= std::min(m - 1, cj + 1); ++j)
    for (int i = std::max(0, ci - 1); i <= std::min(m - 1, ci + 1); ++i) {
      const Sample a{i, j}, b{i + 1, j}, c{i + 1, j + 1}, d{i, j + 1};
      const bool bd = (i < half) == (j < half); // extractMesh's diagonal
      for (const std::array<Sample, 3>& tri : {bd ? std::array{a, b, d} : std::array{a, b, c},
                                               bd ? std::array{b, c, d} : std::array{a, c, d}}) {
        const detail::Vec3d x(to.at(tri[0]).xyz()), y(to.at(tri[1]).xyz()), z(to.at(tri[2]).xyz());
        const detail::Vec3d q = detail::closestPointOnTriangle(p, x, y, z);
        const double e = dot(q - p, q - p);
        if (e < best.distanceSquared) best = {e, tri, barycentric(q, x, y, z)};
      }
    }
  return best;
}

// How well the new document keeps the old one's painted layers: each old sample's value
// against the new surface's value at the point nearest the old sample, weighted by its area.
void measureCarried(const Document& from, const Document& to, const SphericalMap& map,
                    RemeshResult& out) {
  struct Entry {
    const Layer* before;
    const Layer* after;
    CarriedLayer* result;
    bool colour;
  };
  std::vector<Entry> layers;
  if (!from.diffuse.uniform()) layers.push_back({&from.diffuse, &to.diffuse, &out.diffuse, true});
  if (!from.feature.uniform()) layers.push_back({&from.feature, &to.feature, &out.feature, false});
  if (from.hasMask && !from.mask.uniform())
    layers.push_back({&from.mask, &to.mask, &out.mask, false});
  if (layers.empty()) return;
  const VertexIndex oldIndex(from.size());
  const std::vector<Sample> oldSamples = oldIndex.canonicalSamples();
  const StretchMap spacing = measureStretch(from.positions);
  const std::size_t oldSide = static_cast<std::size_t>(from.size() + 1);
  const std::size_t newSide = static_cast<std::size_t>(to.size() + 1);
  struct Sums {
    double area = 0, error = 0, within = 0, max = 0, painted = 0, paintedWithin = 0;
  };
  std::vector<Sums> sums(layers.size());
  const int count = static_cast<int>(oldSamples.size());
  std::mutex lock;
  detail::parallelRows(count, [&](int begin, int end) {
    std::vector<Sums> local(layers.size());
    std::array<float, 4> was{}, now{}, corner{};
    for (int v = begin; v < end; ++v) {
      const Sample s = oldSamples[static_cast<std::size_t>(v)];
      const std::size_t t = static_cast<std::size_t>(s.j) * oldSide + static_cast<std::size_t>(s.i);
      const double area = double(spacing.spacing[t]) * double(spacing.spacing[t]);
      if (!(area > 0)) continue;
      const detail::Vec3d p(from.positions.at(s).xyz());
      const NearPoint near =
          nearestOnNewCells(to.positions, p, map.sphere[static_cast<std::size_t>(v)]);
      const std::array<Sample, 3>& corners = near.corners;
      const std::array<double, 3>& w = near.weights;
      for (std::size_t l = 0; l < layers.size(); ++l) {
        const Layer& before = *layers[l].before;
        const Layer& after = *layers[l].after;
        const std::size_t ch = static_cast<std::size_t>(before.channels);
        layerValue(before, t, was.data());
        now.fill(0);
        for (std::size_t k = 0; k < 3; ++k) {
          const Sample q = corners[k];
          layerValue(after, static_cast<std::size_t>(q.j) * newSide + static_cast<std::size_t>(q.i),
                     corner.data());
          for (std::size_t cc = 0; cc < ch; ++cc)
            now[cc] += static_cast<float>(w[k]) * corner[cc];
        }
        double e = 0;
        if (layers[l].colour)
          e = deltaE(was.data(), now.data());
        else
          for (std::size_t cc = 0; cc < ch; ++cc)
            e = std::max(e, double(std::abs(was[cc] - now[cc])));
        Sums& sum = local[l];
        sum.area += area;
        sum.error += area * e;
        sum.within += e <= (layers[l].colour ? 5.0 : 0.02) ? area : 0;
        sum.max = std::max(sum.max, e);
        bool painted = false;
        for (std::size_t cc = 0; cc < ch; ++cc)
          painted = painted || std::abs(was[cc] - before.fill[cc]) > 1e-3f;
        if (painted) {
          sum.painted += area;
          sum.paintedWithin += e <= (layers[l].colour ? 5.0 : 0.02) ? area : 0;
        }
      }
    }
    const std::lock_guard<std::mutex> guard(lock);
    for (std::size_t l = 0; l < layers.size(); ++l) {
      sums[l].area += local[l].area;
      sums[l].error += local[l].error;
      sums[l].within += local[l].within;
      sums[l].max = std::max(sums[l].max, local[l].max);
      sums[l].painted += local[l].painted;
      sums[l].paintedWithin += local[l].paintedWithin;
    }
  });
  for (std::size_t l = 0; l < layers.size(); ++l) {
    CarriedLayer& r = *layers[l].result;
    r.painted = true;
    r.meanError = sums[l].area > 0 ? sums[l].error / sums[l].area : 0;
    r.shareWithin = sums[l].area > 0 ? sums[l].within / sums[l].area : 1;
    r.maxError = sums[l].max;
    r.paintedShareWithin = sums[l].painted > 0 ? sums[l].paintedWithin / sums[l].painted : 1;
    r.paintedArea = sums[l].area > 0 ? sums[l].painted / sums[l].area : 0;
  }
}

// Sharp tips and creases of the old surface that the new samples step over: an old vertex
// farther than `tolerance` (object units) from the new surface near it (the four triangles of
// either diagonal of the new grid cell its sphere point falls in: an upper bound of its
// distance) hands its own location to a corner of that cell, so the new surface passes through
// it. Worst first, a few passes (a snapped sample changes its neighbours' distances). A sample
// moves only while the four cells around it stay convex in the grid's parameter domain (the
// samples' sphere points seen as grid coordinates), so no triangle of the new grid folds over,
// and makes no edge longer than 1.3 times the longest the new grid had; samples on the image's
// border move only when no neighbour has moved. Returns how many samples moved.
int snapToFeatures(const TriangleMesh& mesh, const SphericalMap& map, const GeometryImage& old,
                   int m, double tolerance, std::vector<SampleLocation>& where) {
  const std::size_t side = static_cast<std::size_t>(m + 1);
  const std::vector<Sample> oldSamples = VertexIndex(old.size()).canonicalSamples();
  const auto index = [side](Sample q) {
    return static_cast<std::size_t>(q.j) * side + static_cast<std::size_t>(q.i);
  };
  const auto positionAt = [&](int i, int j) {
    const SampleLocation& at = where[index(canonical(m, {i, j}))];
    const auto& tri = mesh.triangles[at.triangle];
    detail::Vec3d p;
    for (std::size_t k = 0; k < 3; ++k)
      p = p + detail::Vec3d(mesh.positions[tri[k]]) * double(at.weights[k]);
    return p;
  };
  // Each moved sample's place in grid coordinates (an interior sample's own i, j otherwise).
  std::vector<std::array<double, 2>> place(side * side);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i)
      place[index({i, j})] = {double(i), double(j)};
  std::vector<std::uint8_t> moved(side * side, 0);
  // Each old vertex's place as a corner of one of its triangles.
  std::vector<SampleLocation> corner(mesh.positions.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) {
      SampleLocation& at = corner[mesh.triangles[t][k]];
      at.triangle = static_cast<std::uint32_t>(t);
      at.weights = {0, 0, 0};
      at.weights[k] = 1;
    }
  struct Candidate {
    double distance;
    std::uint32_t vertex;
    double u, w; // grid coordinates of its sphere point
  };
  const auto measure = [&](std::uint32_t v, Candidate& c) {
    const std::array<double, 2> st = octahedralSquarePoint(map.sphere[v]);
    c.vertex = v;
    c.u = st[0] * m;
    c.w = st[1] * m;
    const int i0 = std::clamp(static_cast<int>(std::floor(c.u)), 0, m - 1);
    const int j0 = std::clamp(static_cast<int>(std::floor(c.w)), 0, m - 1);
    const detail::Vec3d a = positionAt(i0, j0), b = positionAt(i0 + 1, j0),
                        cc = positionAt(i0 + 1, j0 + 1), d = positionAt(i0, j0 + 1);
    const detail::Vec3d x(old.at(oldSamples[v]).xyz());
    const auto distance = [&](detail::Vec3d p, detail::Vec3d q, detail::Vec3d r) {
      const detail::Vec3d e = x - detail::closestPointOnTriangle(x, p, q, r);
      return dot(e, e);
    };
    c.distance = std::sqrt(
        std::min({distance(a, b, d), distance(b, cc, d), distance(a, b, cc), distance(a, cc, d)}));
    return c.distance > tolerance;
  };
  // Whether the interior sample (i, j) may move to p: its four cells stay strictly convex.
  const auto keepsCellsConvex = [&](int i, int j, std::array<double, 2> p) {
    const auto at = [&](int di, int dj) {
      return di == 0 && dj == 0 ? p : place[index({i + di, j + dj})];
    };
    for (const auto& [ci, cj] : {std::pair{-1, -1}, {0, -1}, {0, 0}, {-1, 0}}) {
      const std::array<std::array<double, 2>, 4> q{at(ci, cj), at(ci + 1, cj), at(ci + 1, cj + 1),
                                                   at(ci, cj + 1)};
      for (int k = 0; k < 4; ++k) {
        const auto &o = q[k], &e = q[(k + 1) % 4], &f = q[(k + 3) % 4];
        const double cross = (e[0] - o[0]) * (f[1] - o[1]) - (e[1] - o[1]) * (f[0] - o[0]);
        if (!(cross > 1e-3)) return false;
      }
    }
    return true;
  };
  // The grid's edges: right, up and the diagonal extractMesh splits cell (i, j) along.
  const int half = m / 2;
  const auto diagonalOf = [half](int i, int j) {
    return (i < half) == (j < half) ? std::array<Sample, 2>{Sample{i + 1, j}, {i, j + 1}}
                                    : std::array<Sample, 2>{Sample{i, j}, {i + 1, j + 1}};
  };
  const auto squared = [](detail::Vec3d a, detail::Vec3d b) { return dot(a - b, a - b); };
  // No move may make an edge much longer than the longest the new grid has without any: the
  // worst stretch stays about where the parameterization put it.
  double longest = 0;
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const detail::Vec3d p = positionAt(i, j);
      const auto d = diagonalOf(i, j);
      longest =
          std::max({longest, squared(p, positionAt(i + 1, j)), squared(p, positionAt(i, j + 1)),
                    squared(positionAt(d[0].i, d[0].j), positionAt(d[1].i, d[1].j))});
    }
  // 1.3 times that: the snake-hook limb's tip needs its sample moved onto it (Hausdorff 0.18 %
  // against 0.55 % at 1.2 times), and the worst stretch grows by less than the factor (7.2 from
  // 5.9 times the median edge there).
  longest *= 1.3 * 1.3;
  const auto keepsEdgesShort = [&](Sample q, detail::Vec3d x) {
    // The axis neighbours and the diagonal ones of the four cells around; on the border all
    // eight (through the tiling).
    const bool border = q.i <= 0 || q.j <= 0 || q.i >= m || q.j >= m;
    for (int dj = -1; dj <= 1; ++dj)
      for (int di = -1; di <= 1; ++di) {
        if (di == 0 && dj == 0) continue;
        if (!border && di != 0 && dj != 0) {
          const auto d = diagonalOf(q.i + std::min(di, 0), q.j + std::min(dj, 0));
          const Sample other{q.i + di, q.j + dj};
          if (!((d[0] == q && d[1] == other) || (d[1] == q && d[0] == other))) continue;
        }
        const Sample r = wrap(m, {q.i + di, q.j + dj});
        if (squared(x, positionAt(r.i, r.j)) > longest) return false;
      }
    return true;
  };
  const auto tryMove = [&](const Candidate& c) {
    // The corners of its cell, nearest first.
    const int i0 = std::clamp(static_cast<int>(std::floor(c.u)), 0, m - 1);
    const int j0 = std::clamp(static_cast<int>(std::floor(c.w)), 0, m - 1);
    std::array<Sample, 4> corners{Sample{i0, j0}, {i0 + 1, j0}, {i0 + 1, j0 + 1}, {i0, j0 + 1}};
    const auto far = [&](Sample q) { return std::hypot(q.i - c.u, q.j - c.w); };
    std::sort(corners.begin(), corners.end(), [&](Sample a, Sample b) { return far(a) < far(b); });
    const detail::Vec3d x(old.at(oldSamples[c.vertex]).xyz());
    for (const Sample q : corners) {
      const Sample k = canonical(m, q);
      if (moved[index(k)] || !keepsEdgesShort(q, x)) continue;
      const bool border = q.i <= 1 || q.j <= 1 || q.i >= m - 1 || q.j >= m - 1;
      if (border) {
        // Only the nearest corner, and only with no moved neighbour (folds make the
        // neighbourhood's coordinates ambiguous).
        if (far(q) > 0.5) return false;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            if (moved[index(canonical(m, wrap(m, {q.i + di, q.j + dj})))]) return false;
      } else if (!keepsCellsConvex(q.i, q.j, {c.u, c.w})) {
        continue;
      } else {
        place[index(q)] = {c.u, c.w};
      }
      moved[index(k)] = 1;
      where[index(k)] = corner[c.vertex];
      return true;
    }
    return false;
  };

  std::vector<Candidate> candidates;
  std::mutex lock;
  detail::parallelRows(
      static_cast<int>(oldSamples.size()),
      [&](int begin, int end) {
        std::vector<Candidate> local;
        Candidate c{};
        for (int v = begin; v < end; ++v)
          if (measure(static_cast<std::uint32_t>(v), c)) local.push_back(c);
        const std::lock_guard<std::mutex> guard(lock);
        candidates.insert(candidates.end(), local.begin(), local.end());
      },
      1024);
  int count = 0;
  for (int pass = 0; pass < 3 && !candidates.empty(); ++pass) {
    std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
      return x.distance != y.distance ? x.distance > y.distance : x.vertex < y.vertex;
    });
    std::vector<Candidate> left;
    for (const Candidate& c : candidates)
      if (tryMove(c))
        ++count;
      else
        left.push_back(c);
    // Those left, measured against the surface the moves made.
    candidates.clear();
    for (Candidate& c : left)
      if (measure(c.vertex, c)) candidates.push_back(c);
  }
  return count;
}

// The surface distance between the old surface and the new one, as compareSurfaces measures it
// (their vertices and random points on each, against the other surface), with two of its parts
// known without a tree query: each new vertex lies on an old triangle (distance 0), and each old
// vertex's distance is taken to the new cells around its sphere point (nearestOnNewCells: never
// below the closest point's, so the figures are never better than the truth). compareSurfaces
// measures the random points. At N = 1024 this halves the measure's time.
SurfaceDistance measureMoved(const TriangleMesh& surface, const GeometryImage& old,
                             const SphericalMap& map, const GeometryImage& resampled,
                             std::size_t samplesPerSurface) {
  const TriangleMesh remeshed = extractMesh(resampled);
  SurfaceDistance d = compareSurfaces(surface, remeshed,
                                      {.samplesPerSurface = samplesPerSurface, .maxVertices = 1});
  const std::vector<Sample> oldSamples = VertexIndex(old.size()).canonicalSamples();
  double sum = 0, worst = 0;
  std::mutex lock;
  detail::parallelRows(
      static_cast<int>(oldSamples.size()),
      [&](int begin, int end) {
        double localSum = 0, localWorst = 0;
        for (int v = begin; v < end; ++v) {
          const NearPoint near =
              nearestOnNewCells(resampled, detail::Vec3d(old.at(oldSamples[std::size_t(v)]).xyz()),
                                map.sphere[static_cast<std::size_t>(v)]);
          localSum += near.distanceSquared;
          localWorst = std::max(localWorst, near.distanceSquared);
        }
        const std::lock_guard<std::mutex> guard(lock);
        sum += localSum;
        worst = std::max(worst, localWorst);
      },
      1024);
  if (!(d.diagonal > 0)) return d;
  const double scale = 1 / (d.diagonal * d.diagonal);
  const std::size_t samples = d.samples + oldSamples.size() + remeshed.positions.size();
  d.rms = std::sqrt((d.rms * d.rms * double(d.samples) + sum * scale) / double(samples));
  d.hausdorff = std::max(d.hausdorff, std::sqrt(worst * scale));
  d.psnr = d.rms > 0 ? 20 * std::log10(1 / d.rms) : std::numeric_limits<double>::infinity();
  d.samples = samples;
  return d;
}

} // namespace

RemeshResult remeshDocument(const Document& document, const RemeshOptions& options,
                            const std::function<bool(float)>& progress) {
  // It makes an octahedral ball (a torus or plane would first need its own parameterization).
  requireOctahedral(document.positions, "remesh", "this object");
  const int n = document.size();
  const int m = options.size == 0 ? n : options.size;
  requireValidSize(m);
  if (const auto problem = positionsProblem(document.positions))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be remeshed");
  const auto cancelled = [] { return Error(ErrorKind::Cancelled, "remeshing was cancelled"); };
  const auto report = [&](float f) {
    if (progress && !progress(f)) throw cancelled();
  };
  RemeshResult out;
  out.before = summarizeStretch(document.positions);
  report(0);

  // The surface as a mesh, one vertex per canonical sample (VertexIndex's numbering).
  auto start = Clock::now();
  const TriangleMesh surface = extractMesh(document.positions);
  // The grid's mesh is closed, manifold and genus 0 by construction, with no unused vertex and
  // no repeated corner: all validateGenus0Mesh would do is turn an inward-facing one around (at
  // the cost of sorting its 6N² half-edges, a tenth of the time at N = 1024), or refuse one
  // that encloses no volume.
  ValidatedMesh validated;
  validated.mesh = surface;
  const double volume = signedVolume(surface);
  if (!(std::abs(volume) > 0)) {
    out.document = document;
    out.reason = "the surface cannot be parameterized: it encloses no volume";
    return out;
  }
  if (volume < 0)
    for (auto& t : validated.mesh.triangles)
      std::swap(t[1], t[2]);
  SphericalMap map;
  try {
    // From N = 1024 the coarse grid is 128: at 64 a leg of a creature with its samples (keep
    // detail's) sees too few of them, and the map gives it 0.67 of its fair share (0.83 at 128,
    // the floor 0.7), for 1.5 s more at N = 1024.
    detail::ImageParameterizationOptions mapping;
    if (document.size() >= 1024) mapping.coarseSize = 128;
    map = detail::parameterizeImageOnSphere(
        document.positions, validated.mesh,
        [&](float f) { return !progress || progress(0.8f * f); }, mapping);
  } catch (const Error& e) {
    if (e.kind() == ErrorKind::Cancelled) throw cancelled();
    out.document = document;
    out.reason = std::string("the surface cannot be parameterized: ") + e.what();
    return out;
  }
  out.parameterizeMs = msSince(start);
  out.flipped = map.flipped;
  report(0.8f);

  // Every layer at each new sample's point on the old surface.
  start = Clock::now();
  std::vector<SampleLocation> where = locateOctahedralSamples(validated.mesh, map, m);
  const double diagonal = boundingBox(surface).diagonal();
  out.snapped = snapToFeatures(validated.mesh, map, document.positions, m,
                               options.featureTolerance * diagonal, where);
  const std::vector<Sample> oldSamples = VertexIndex(n).canonicalSamples();
  const std::size_t oldSide = static_cast<std::size_t>(n + 1);
  const std::size_t side = static_cast<std::size_t>(m + 1);
  Document result = document;
  result.positions = GeometryImage(m);
  struct Carried {
    const Layer* from;
    Layer* to;
  };
  std::vector<Carried> layers;
  for (Layer* l : {&result.diffuse, &result.feature, &result.mask}) {
    const Layer& from = l == &result.diffuse   ? document.diffuse
                        : l == &result.feature ? document.feature
                                               : document.mask;
    if (from.uniform()) continue;
    l->texels.assign(side * side * static_cast<std::size_t>(from.channels), 0.0f);
    layers.push_back({&from, l});
  }
  const auto oldTexel = [&](std::uint32_t vertex) {
    const Sample s = oldSamples[vertex];
    return static_cast<std::size_t>(s.j) * oldSide + static_cast<std::size_t>(s.i);
  };
  detail::parallelRows(m + 1, [&](int rowBegin, int rowEnd) {
    std::array<float, 4> value{};
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= m; ++i) {
        const Sample c = canonical(m, {i, j});
        const std::size_t t = static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i);
        const SampleLocation& at =
            where[static_cast<std::size_t>(c.j) * side + static_cast<std::size_t>(c.i)];
        const auto& tri = validated.mesh.triangles[at.triangle];
        Vec4f p{0, 0, 0, 0};
        for (std::size_t k = 0; k < 3; ++k) {
          const Vec4f& q = document.positions.texels()[oldTexel(tri[k])];
          const float w = at.weights[k];
          p = {p.x + w * q.x, p.y + w * q.y, p.z + w * q.z, p.w + w * q.w};
        }
        result.positions.at(i, j) = p;
        for (const Carried& l : layers) {
          const std::size_t ch = static_cast<std::size_t>(l.from->channels);
          float* o = &l.to->texels[t * ch];
          std::fill_n(o, ch, 0.0f);
          for (std::size_t k = 0; k < 3; ++k) {
            layerValue(*l.from, oldTexel(tri[k]), value.data());
            for (std::size_t cc = 0; cc < ch; ++cc)
              o[cc] += at.weights[k] * value[cc];
          }
        }
      }
  });
  out.resampleMs = msSince(start);
  report(0.85f);

  start = Clock::now();
  out.after = summarizeStretch(result.positions);
  if (boundingBox(surface).diagonal() > 0)
    out.moved =
        measureMoved(surface, document.positions, map, result.positions, options.samplesPerSurface);
  report(0.95f);
  measureCarried(document, result, map, out);
  out.measureMs = msSince(start);
  report(1);

  const double scale = m < n ? double(n / m) * double(n / m) : 1.0;
  if (map.flipped > 0)
    out.reason = "the surface's spherical map folds " + std::to_string(map.flipped) + " triangles";
  else
    out.reason = detail::surfaceMovedTooFar(out.moved, scale * options.rmsTolerance,
                                            scale * options.hausdorffTolerance);
  if (!out.reason.empty()) {
    out.document = document;
    return out;
  }
  out.document = std::move(result);
  out.changed = true;
  return out;
}

} // namespace octaclay::core
