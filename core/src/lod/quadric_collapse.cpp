#include "lod/quadric_collapse.h"

#include "detail/parallel_rows.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace octaclay::core::detail {
namespace {

// Symmetric 4×4 plane quadric, upper triangle: a² ab ac ad b² bc bd c² cd d².
struct Quadric {
  std::array<double, 10> q{};
  void addPlane(double a, double b, double c, double d, double w) {
    const double p[4] = {a, b, c, d};
    int k = 0;
    for (int i = 0; i < 4; ++i)
      for (int j = i; j < 4; ++j)
        q[k++] += w * p[i] * p[j];
  }
  Quadric& operator+=(const Quadric& o) {
    for (int k = 0; k < 10; ++k)
      q[k] += o.q[k];
    return *this;
  }
  double error(double x, double y, double z) const {
    return q[0] * x * x + 2 * q[1] * x * y + 2 * q[2] * x * z + 2 * q[3] * x + q[4] * y * y +
           2 * q[5] * y * z + 2 * q[6] * y + q[7] * z * z + 2 * q[8] * z + q[9];
  }
};

double errorAt(const Quadric& a, const Quadric& b, Vec3f p) {
  return std::max(0.0, a.error(p.x, p.y, p.z) + b.error(p.x, p.y, p.z));
}

constexpr int kDroppedMantissaBits = 25;
constexpr std::size_t kBuckets = std::size_t(1) << (31 - kDroppedMantissaBits);

// An error's step of a factor 16 (non-negative floats order as their bits).
std::size_t bucketOf(float error) {
  std::uint32_t bits = 0;
  std::memcpy(&bits, &error, sizeof bits);
  return (bits & 0x7fffffffu) >> kDroppedMantissaBits;
}

class Collapser {
public:
  Collapser(const TriangleMesh& mesh, const VertexCollapseOptions& options)
      : options_(options), positions_(mesh.positions), triangles_(mesh.triangles) {
    const std::size_t v = positions_.size(), t = triangles_.size();
    quadrics_.resize(v);
    normals_.resize(t);
    inputAspect_.resize(t);
    deleted_.assign(t, 0);
    origin_.resize(t);
    for (std::size_t k = 0; k < t; ++k)
      origin_[k] = static_cast<std::uint32_t>(k);
    stamp_.assign(v, 0);
    stamp2_.assign(v, 0);
    // Planes weighted by area / mean area: the order is that of area-weighted quadrics, the
    // scale that of unweighted ones (sums of squared distances), which maxError is given in.
    double totalArea = 0;
    for (const auto& tri : triangles_) {
      const Vec3f p0 = positions_[tri[0]];
      totalArea += 0.5 * double(length(cross(positions_[tri[1]] - p0, positions_[tri[2]] - p0)));
    }
    const double areaScale = totalArea > 0 ? double(t) / totalArea : 1.0;
    for (std::size_t k = 0; k < t; ++k) {
      const auto& tri = triangles_[k];
      const Vec3f p0 = positions_[tri[0]];
      const Vec3f n = cross(positions_[tri[1]] - p0, positions_[tri[2]] - p0);
      const double twiceArea = length(n);
      const Vec3f u = normalize(n);
      normals_[k] = u;
      if (options.maxAspectRatio > 0)
        inputAspect_[k] = aspectRatio(positions_[tri[0]], positions_[tri[1]], positions_[tri[2]]);
      if (twiceArea <= 0) continue;
      const double d = -double(dot(u, p0));
      const double weight = options.vertexWeights.empty()
                                ? 1.0
                                : (double(options.vertexWeights[tri[0]]) +
                                   options.vertexWeights[tri[1]] + options.vertexWeights[tri[2]]) /
                                      3;
      Quadric q;
      q.addPlane(u.x, u.y, u.z, d, 0.5 * twiceArea * areaScale * weight);
      for (const std::uint32_t c : tri)
        quadrics_[c] += q;
    }
    if (options.openBoundary) addBoundaryPlanes(areaScale);
    minCos_ = std::cos(double(options.maxNormalTurnDegrees) * M_PI / 180.0);
    if (std::abs(minCos_) < 1e-12) minCos_ = 0; // 90°: cos gives 6e-17, the turn test's sign
    vertexCount_ = 0;
    std::vector<std::uint8_t> used(v, 0);
    for (const auto& tri : triangles_)
      for (const std::uint32_t c : tri)
        used[c] = 1;
    for (const std::uint8_t u : used)
      vertexCount_ += u;
    if (options.maxError > 0) {
      const double bound = options.maxError * boundingBox(mesh).diagonal();
      maxQuadricError_ = bound * bound;
    }
  }

  CollapsedMesh run() {
    std::size_t alive = triangles_.size();
    const std::size_t target = options_.targetTriangles;
    std::vector<float> errors;
    std::size_t boost = 1; // widens the threshold after a pass that found nothing legal
    for (int pass = 0; pass < 100 && alive > target && alive > 4; ++pass) {
      compact();
      rebuildRefs();
      // Error of each corner's outgoing edge (corner k → k+1) collapsed the cheaper legal way,
      // on every hardware thread (each triangle's entries are its own).
      edgeError_.assign(triangles_.size() * 3, std::numeric_limits<float>::infinity());
      edgeTo_.assign(triangles_.size() * 3, 0);
      const int bands = static_cast<int>((triangles_.size() + 4095) / 4096);
      parallelRows(
          bands,
          [&](int bandBegin, int bandEnd) {
            const std::size_t end = std::min(triangles_.size(), std::size_t(bandEnd) * 4096);
            for (std::size_t t = std::size_t(bandBegin) * 4096; t < end; ++t) {
              for (int k = 0; k < 3; ++k) {
                const std::uint32_t a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
                if (a > b) continue; // each edge once, from the triangle that has it as a < b
                std::uint32_t from = 0, to = 0;
                const double best = cheapestDirection(a, b, from, to);
                if (maxQuadricError_ > 0 && best > maxQuadricError_) continue;
                edgeError_[3 * t + k] = float(best);
                edgeTo_[3 * t + k] = to == b;
              }
            }
          },
          4);
      errors.clear();
      for (const float e : edgeError_)
        if (std::isfinite(e)) errors.push_back(e);
      if (errors.empty()) break;
      // Candidates: the cheapest 3× as many edges as collapses are still wanted (about half
      // are blocked by collapses next to them), taken cheapest first.
      const std::size_t wanted = (alive - std::max<std::size_t>(target, 4) + 1) / 2;
      const std::size_t k =
          std::min(errors.size() - 1, 3 * std::max<std::size_t>(wanted, 1) * boost - 1);
      std::nth_element(errors.begin(), errors.begin() + std::ptrdiff_t(k), errors.end());
      const float threshold = errors[k];
      // Cheapest first by error rounded to a factor of 16 (the float's exponent less its two
      // lowest bits), in mesh order within each step: nearly the same order, but neighbouring
      // collapses come together, which keeps the mesh in cache (2x faster on 2N² triangles).
      // A counting sort: the rounded errors take at most 64 values (4x faster than std::sort).
      std::array<std::uint32_t, kBuckets + 1> bucketStart{};
      for (std::size_t e = 0; e < edgeError_.size(); ++e)
        if (edgeError_[e] <= threshold) ++bucketStart[bucketOf(edgeError_[e]) + 1];
      for (std::size_t b = 0; b < kBuckets; ++b)
        bucketStart[b + 1] += bucketStart[b];
      candidates_.resize(bucketStart[kBuckets]);
      for (std::size_t e = 0; e < edgeError_.size(); ++e)
        if (edgeError_[e] <= threshold)
          candidates_[bucketStart[bucketOf(edgeError_[e])]++] = static_cast<std::uint32_t>(e);
      touched_.assign(positions_.size(), 0);

      std::size_t collapsedThisPass = 0;
      for (const std::uint32_t edge : candidates_) {
        if (alive <= target || alive <= 4) break;
        const std::size_t t = edge / 3;
        if (deleted_[t]) continue;
        const std::uint32_t a = triangles_[t][edge % 3];
        const std::uint32_t b = triangles_[t][(edge % 3 + 1) % 3];
        std::uint32_t from = edgeTo_[edge] ? a : b, to = edgeTo_[edge] ? b : a;
        // Earlier collapses of this pass may have changed the edge or its quadrics (they
        // touched an end): recompute. An open mesh waits for the next pass: where a flat sheet
        // makes every collapse cost the same, one pass would otherwise run chains of collapses
        // into one vertex along its outline (a disc's side gone into one edge).
        if ((touched_[a] || touched_[b]) &&
            (options_.openBoundary || !(cheapestDirection(a, b, from, to) <= threshold)))
          continue;
        if (vertexCount_ <= 4 || !legal(from, to)) continue;
        alive -= collapse(from, to);
        touched_[to] = 1;
        ++collapsedThisPass;
      }
      if (collapsedThisPass == 0 && k + 1 >= errors.size()) break;
      boost = collapsedThisPass == 0 ? boost * 4 : 1;
    }
    return result();
  }

private:
  // Each boundary edge (no triangle runs it the other way) adds to its ends the plane through
  // it that stands on its triangle, weighted far above the faces' (Garland and Heckbert's
  // boundary constraint): a flat sheet's outline then costs what its bends cost, instead of
  // nothing, and keeps its shape (a disc's circle).
  void addBoundaryPlanes(double areaScale) {
    constexpr double kBoundaryWeight = 100;
    std::vector<std::uint64_t> halfEdges;
    halfEdges.reserve(triangles_.size() * 3);
    const auto key = [](std::uint32_t a, std::uint32_t b) { return std::uint64_t(a) << 32 | b; };
    for (const auto& tri : triangles_)
      for (int k = 0; k < 3; ++k)
        halfEdges.push_back(key(tri[k], tri[(k + 1) % 3]));
    std::sort(halfEdges.begin(), halfEdges.end());
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles_[t][k], b = triangles_[t][(k + 1) % 3];
        if (std::binary_search(halfEdges.begin(), halfEdges.end(), key(b, a))) continue;
        const Vec3f edge = positions_[b] - positions_[a];
        const Vec3f u = normalize(cross(edge, normals_[t]));
        if (!(length(u) > 0)) continue;
        const double d = -double(dot(u, positions_[a]));
        Quadric q;
        q.addPlane(u.x, u.y, u.z, d, kBoundaryWeight * double(dot(edge, edge)) * areaScale);
        quadrics_[a] += q;
        quadrics_[b] += q;
      }
  }

  // The quadric error of collapsing edge (a, b) the cheaper allowed way, that way in from → to;
  // infinity when neither is allowed.
  double cheapestDirection(std::uint32_t a, std::uint32_t b, std::uint32_t& from,
                           std::uint32_t& to) const {
    double best = std::numeric_limits<double>::infinity();
    if (allowed(a, b)) {
      best = errorAt(quadrics_[a], quadrics_[b], positions_[b]);
      from = a;
      to = b;
    }
    if (allowed(b, a)) {
      const double e = errorAt(quadrics_[a], quadrics_[b], positions_[a]);
      if (e < best) {
        best = e;
        from = b;
        to = a;
      }
    }
    return best;
  }

  bool allowed(std::uint32_t from, std::uint32_t to) const {
    return !options_.allowCollapse || options_.allowCollapse(from, to);
  }

  // Drops deleted triangles (keeping each survivor's input index), so that later passes
  // scan only what is left.
  void compact() {
    std::size_t kept = 0;
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      if (deleted_[t]) continue;
      triangles_[kept] = triangles_[t];
      normals_[kept] = normals_[t];
      inputAspect_[kept] = inputAspect_[t];
      origin_[kept] = origin_[t];
      ++kept;
    }
    triangles_.resize(kept);
    normals_.resize(kept);
    inputAspect_.resize(kept);
    origin_.resize(kept);
    deleted_.assign(kept, 0);
  }

  void rebuildRefs() {
    start_.assign(positions_.size(), 0);
    count_.assign(positions_.size(), 0);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      if (!deleted_[t])
        for (const std::uint32_t c : triangles_[t])
          ++count_[c];
    std::uint32_t total = 0;
    for (std::size_t v = 0; v < positions_.size(); ++v) {
      start_[v] = total;
      total += count_[v];
    }
    refs_.resize(total);
    std::vector<std::uint32_t> fill(start_);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      if (!deleted_[t])
        for (const std::uint32_t c : triangles_[t])
          refs_[fill[c]++] = static_cast<std::uint32_t>(t);
  }

  // Triangles around v (its refs less those deleted since they were listed).
  template <class F> void forEachTriangle(std::uint32_t v, F&& f) const {
    for (std::uint32_t r = start_[v]; r < start_[v] + count_[v]; ++r)
      if (!deleted_[refs_[r]]) f(refs_[r]);
  }

  bool legal(std::uint32_t from, std::uint32_t to) {
    // Link condition: from and to share exactly the neighbours opposite their edge: two, or one
    // where the edge lies on an open mesh's boundary (a plane's: one triangle has it).
    ++stampValue_;
    int edgeTriangles = 0;
    forEachTriangle(from, [&](std::uint32_t t) {
      for (const std::uint32_t c : triangles_[t]) {
        stamp_[c] = stampValue_;
        edgeTriangles += c == to;
      }
    });
    int shared = 0;
    forEachTriangle(to, [&](std::uint32_t t) {
      for (const std::uint32_t c : triangles_[t])
        if (c != from && c != to && stamp_[c] == stampValue_ && stamp2_[c] != stampValue_) {
          stamp2_[c] = stampValue_;
          ++shared;
        }
    });
    if (edgeTriangles < 1 || shared != edgeTriangles) return false;

    const Vec3f p1 = positions_[to];
    const double maxAspect = options_.maxAspectRatio;
    bool ok = true;
    forEachTriangle(from, [&](std::uint32_t t) {
      if (!ok) return;
      const auto& tri = triangles_[t];
      if (tri[0] == to || tri[1] == to || tri[2] == to) return; // removed by the collapse
      std::array<Vec3f, 3> p;
      std::array<std::uint32_t, 3> moved = tri;
      int m = 0;
      for (int k = 0; k < 3; ++k) {
        if (tri[k] == from) {
          moved[k] = to;
          m = k;
        }
        p[k] = tri[k] == from ? p1 : positions_[tri[k]];
      }
      const Vec3f n = cross(p[1] - p[0], p[2] - p[0]);
      const double twiceAreaSquared = double(dot(n, n));
      if (!(twiceAreaSquared > 0)) {
        ok = false;
        return;
      }
      // The turn's cosine against minCos_, without square roots where minCos_ is 0 (the
      // collapse method's 90°): this test runs for every triangle around every candidate.
      bool turnsTooFar = false;
      if (options_.normalTurnPerCollapse) {
        std::array<Vec3f, 3> q = p;
        q[m] = positions_[from];
        const Vec3f before = cross(q[1] - q[0], q[2] - q[0]);
        const double cosineTimesAreas = double(dot(n, before));
        turnsTooFar = minCos_ == 0
                          ? cosineTimesAreas < 0
                          : cosineTimesAreas <
                                minCos_ * std::sqrt(twiceAreaSquared * double(dot(before, before)));
      } else {
        turnsTooFar = double(dot(n, normals_[t])) < minCos_ * std::sqrt(twiceAreaSquared);
      }
      if (turnsTooFar) {
        ok = false;
        return;
      }
      if (maxAspect > 0) {
        const double twiceArea = std::sqrt(twiceAreaSquared);
        const auto longest = [](const std::array<Vec3f, 3>& q) {
          return std::max({dot(q[1] - q[0], q[1] - q[0]), dot(q[2] - q[1], q[2] - q[1]),
                           dot(q[0] - q[2], q[0] - q[2])});
        };
        const double l = longest(p);
        const double bound =
            std::max(maxAspect, double(options_.maxAspectGrowth) * inputAspect_[t]);
        if (l > bound * twiceArea) {
          std::array<Vec3f, 3> q = p;
          q[m] = positions_[from];
          const double before = length(cross(q[1] - q[0], q[2] - q[0]));
          if (l * before > double(longest(q)) * twiceArea) {
            ok = false;
            return;
          }
        }
      }
      if (options_.cornerCoordinates) {
        const std::array<Vec2f, 3> c = options_.cornerCoordinates(moved);
        const double uvArea = (double(c[1].x) - c[0].x) * (double(c[2].y) - c[0].y) -
                              (double(c[2].x) - c[0].x) * (double(c[1].y) - c[0].y);
        if (!(uvArea > 0)) ok = false;
      }
    });
    return ok;
  }

  // Returns the triangles it removed: two, one on an open mesh's boundary.
  std::size_t collapse(std::uint32_t from, std::uint32_t to) {
    quadrics_[to] += quadrics_[from];
    std::size_t removed = 0;
    forEachTriangle(from, [&](std::uint32_t t) {
      auto& tri = triangles_[t];
      if (tri[0] == to || tri[1] == to || tri[2] == to) {
        deleted_[t] = 1;
        ++removed;
      }
    });
    // to's triangles: its own and from's survivors, listed anew at the end of refs_.
    const auto begin = static_cast<std::uint32_t>(refs_.size());
    forEachTriangle(to, [&](std::uint32_t t) { refs_.push_back(t); });
    forEachTriangle(from, [&](std::uint32_t t) {
      for (std::uint32_t& c : triangles_[t])
        if (c == from) c = to;
      refs_.push_back(t);
    });
    start_[to] = begin;
    count_[to] = static_cast<std::uint32_t>(refs_.size()) - begin;
    count_[from] = 0;
    --vertexCount_;
    return removed;
  }

  CollapsedMesh result() const {
    CollapsedMesh out;
    std::vector<std::uint32_t> index(positions_.size(), 0);
    std::vector<std::uint8_t> used(positions_.size(), 0);
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      if (!deleted_[t])
        for (const std::uint32_t c : triangles_[t])
          used[c] = 1;
    for (std::size_t v = 0; v < positions_.size(); ++v) {
      if (!used[v]) continue;
      index[v] = static_cast<std::uint32_t>(out.mesh.positions.size());
      out.mesh.positions.push_back(positions_[v]);
      out.inputVertex.push_back(static_cast<std::uint32_t>(v));
    }
    for (std::size_t t = 0; t < triangles_.size(); ++t) {
      if (deleted_[t]) continue;
      const auto& tri = triangles_[t];
      out.mesh.triangles.push_back({index[tri[0]], index[tri[1]], index[tri[2]]});
      out.inputTriangle.push_back(origin_[t]);
    }
    return out;
  }

  const VertexCollapseOptions& options_;
  std::vector<Vec3f> positions_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::vector<Quadric> quadrics_;
  std::vector<Vec3f> normals_;      // of the input triangles
  std::vector<double> inputAspect_; // aspectRatio of the input triangles
  std::vector<std::uint8_t> deleted_;
  std::vector<std::uint32_t> origin_; // input index of each triangle (compact() moves them)
  std::vector<std::uint32_t> stamp_, stamp2_;
  std::uint32_t stampValue_ = 0;
  std::vector<std::uint32_t> start_, count_, refs_;
  std::vector<float> edgeError_;
  std::vector<std::uint32_t> candidates_; // 3 × triangle + corner, cheapest bucket first
  std::vector<std::uint8_t> touched_;     // vertices a collapse of this pass changed
  std::vector<std::uint8_t> edgeTo_;
  double minCos_ = 0.5, maxQuadricError_ = 0;
  std::size_t vertexCount_ = 0;
};

} // namespace

CollapsedMesh quadricCollapse(const TriangleMesh& mesh, const VertexCollapseOptions& options) {
  return Collapser(mesh, options).run();
}

} // namespace octaclay::core::detail
