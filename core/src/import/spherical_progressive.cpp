#include "import/spherical_progressive.h"

#include "detail/parallel_rows.h"
#include "import/spherical_collapse.h"
#include "import/spherical_stretch.h"

#include <Eigen/Core>
#include <queue>

#include <algorithm>
#include <cstdint>
#include <iterator>

namespace octaclay::core::detail {

namespace {

// The map's state during refinement, with Sander et al.'s local stretch optimization.
class Refiner {
public:
  Refiner(const Points& x, const CollapsibleMesh& mesh, Points& s)
      : x_(x), mesh_(mesh), s_(s), step_(s.size(), std::numeric_limits<double>::infinity()),
        colour_(s.size(), -1) {}

  // v's triangles as seen from v.
  void gatherRing(int v, std::vector<RingFace>& ring) const {
    ring.clear();
    for (int f : mesh_.facesOf(v)) {
      const Tri& t = mesh_.faces()[f];
      const int k = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const int a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      ring.push_back({a, b, x_[v], x_[a], x_[b]});
    }
  }

  // Σ A·(a + c)/2 over v's faces with v at p; infinite when one is flipped.
  double ringEnergy(int v, const Vec3d& p) {
    gatherRing(v, ring_);
    return ringStretchEnergy(s_, ring_, p);
  }

  // One descent step of v; returns the energy decrease. `ring` is the caller's scratch, so
  // that vertices that share no triangle can move on several threads at once.
  double optimize(int v, std::vector<RingFace>& ring) {
    gatherRing(v, ring);
    return descend(s_, v, ring, step_[v]);
  }
  double optimize(int v) { return optimize(v, ring_); }

  // `sweeps` Gauss–Seidel sweeps over `vertices`, each colour class of a greedy colouring (no
  // two vertices of a class share a triangle) moved in parallel.
  void relax(const std::vector<int>& vertices, int sweeps) {
    std::vector<std::vector<int>>& classes = classes_;
    for (auto& c : classes)
      c.clear();
    std::vector<char>& used = usedColours_;
    for (int v : vertices) {
      used.assign(classes.size() + 1, 0);
      for (int f : mesh_.facesOf(v))
        for (int w : mesh_.faces()[f])
          if (w != v && colour_[w] >= 0) used[colour_[w]] = 1;
      const int c = static_cast<int>(std::find(used.begin(), used.end(), 0) - used.begin());
      colour_[v] = c;
      if (c >= static_cast<int>(classes.size())) classes.resize(static_cast<std::size_t>(c) + 1);
      classes[c].push_back(v);
    }
    for (int v : vertices)
      colour_[v] = -1;
    for (int sweep = 0; sweep < sweeps; ++sweep)
      for (const std::vector<int>& c : classes)
        parallelRows(
            static_cast<int>(c.size()),
            [&](int begin, int end) {
              std::vector<RingFace> ring;
              for (int i = begin; i < end; ++i)
                optimize(c[i], ring);
            },
            512);
  }

  // The vertices within `rings` edges of `center`, in breadth-first order.
  void region(int center, int rings, std::vector<int>& out) {
    out.assign(1, center);
    colour_[center] = -2;
    std::size_t begin = 0;
    for (int ring = 0; ring < rings; ++ring) {
      const std::size_t end = out.size();
      for (std::size_t i = begin; i < end; ++i)
        for (int f : mesh_.facesOf(out[i]))
          for (int w : mesh_.faces()[f])
            if (colour_[w] != -2) {
              colour_[w] = -2;
              out.push_back(w);
            }
      begin = end;
    }
    for (int w : out)
      colour_[w] = -1;
  }

  // The largest stretch (a + c)/2 over the triangles of `vertices` against their
  // area-weighted mean; large where a triangle is far more squeezed than its neighbourhood.
  double stretchJump(const std::vector<int>& vertices, const std::vector<int>& centre) {
    double worst = 0, energy = 0, area = 0;
    for (int v : vertices)
      for (int f : mesh_.facesOf(v)) {
        const Tri& t = mesh_.faces()[f];
        const double a = triangleArea(x_, t);
        const double e = stretchEnergy(s_[t[0]], s_[t[1]], s_[t[2]], x_[t[0]], x_[t[1]], x_[t[2]]);
        if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
        energy += e;
        area += a;
      }
    for (int v : centre)
      for (int f : mesh_.facesOf(v)) {
        const Tri& t = mesh_.faces()[f];
        const double a = triangleArea(x_, t);
        const double e = stretchEnergy(s_[t[0]], s_[t[1]], s_[t[2]], x_[t[0]], x_[t[1]], x_[t[2]]);
        if (!std::isfinite(e)) return std::numeric_limits<double>::infinity();
        if (a > 0) worst = std::max(worst, e / a);
      }
    return area > 0 ? worst / (energy / area) : 0;
  }

  // Places the re-inserted vertex u (whose collapse went into v) inside the kernel of its
  // one-ring: the lowest-energy valid point among the ring's spherical centroid and points on
  // the bisector of the wedge that u's faces took from v, at shrinking distances from v (close
  // enough to v always works: the two thin triangles u–v–a and v–u–b are positive on the
  // bisector even when the wedge is reflex, and u's other faces look like v's did before).
  // Returns false if nothing worked.
  bool place(int u, int v) {
    const Vec3d p = s_[v];
    Vec3d centroid = Vec3d::Zero();
    double reach = 0;
    std::vector<std::pair<int, int>>& next = scratch_;
    next.clear();
    for (int f : mesh_.facesOf(u)) {
      const Tri& t = mesh_.faces()[f];
      for (int k = 0; k < 3; ++k)
        if (t[k] == u) next.emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
      for (int w : t)
        if (w != u) {
          centroid += s_[w];
          reach = std::max(reach, (s_[w] - p).norm());
        }
    }
    const auto after = [&](int w) {
      for (const auto& [from, to] : next)
        if (from == w) return to;
      return -1;
    };
    double best = std::numeric_limits<double>::infinity();
    Vec3d bestPoint = p;
    if (centroid.norm() > 1e-12) {
      const Vec3d q = centroid.normalized();
      const double e = ringEnergy(u, q);
      if (e < best) {
        best = e;
        bestPoint = q;
      }
    }
    // The centroid of the ring's kernel: the ring polygon clipped by the half-plane of each of
    // its edges, in the gnomonic projection about the ring's centroid (straight lines there are
    // great circles).
    if (centroid.norm() > 1e-12) {
      const Vec3d c = centroid.normalized();
      const Vec3d c1 =
          (std::abs(c.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).cross(c).normalized();
      const Vec3d c2 = c.cross(c1);
      std::vector<Eigen::Vector2d>& polygon = scratchPolygon_;
      polygon.clear();
      bool visible = true;
      int w = v;
      for (int k = 0; k < 64 && w >= 0; ++k) {
        const double h = s_[w].dot(c);
        if (h < 0.02) visible = false;
        polygon.emplace_back(s_[w].dot(c1) / h, s_[w].dot(c2) / h);
        w = after(w);
        if (w == v) break;
      }
      if (visible && polygon.size() >= 3) {
        std::vector<Eigen::Vector2d> kernel = polygon, clipped;
        for (std::size_t e = 0; e < polygon.size() && kernel.size() >= 3; ++e) {
          const Eigen::Vector2d pa = polygon[e], pb = polygon[(e + 1) % polygon.size()];
          const auto side = [&](const Eigen::Vector2d& q) {
            const Eigen::Vector2d d = pb - pa, r = q - pa;
            return d.x() * r.y() - d.y() * r.x();
          };
          clipped.clear();
          for (std::size_t i = 0; i < kernel.size(); ++i) {
            const Eigen::Vector2d& q0 = kernel[i];
            const Eigen::Vector2d& q1 = kernel[(i + 1) % kernel.size()];
            const double d0 = side(q0), d1 = side(q1);
            if (d0 >= 0) clipped.push_back(q0);
            if ((d0 >= 0) != (d1 >= 0)) clipped.push_back(q0 + d0 / (d0 - d1) * (q1 - q0));
          }
          kernel.swap(clipped);
        }
        double area = 0;
        Eigen::Vector2d middle = Eigen::Vector2d::Zero();
        for (std::size_t i = 0; i < kernel.size(); ++i) {
          const Eigen::Vector2d& q0 = kernel[i];
          const Eigen::Vector2d& q1 = kernel[(i + 1) % kernel.size()];
          const double cross = q0.x() * q1.y() - q0.y() * q1.x();
          area += cross;
          middle += cross * (q0 + q1);
        }
        if (kernel.size() >= 3 && area > 0) {
          middle /= 3.0 * area;
          const Vec3d q = (c + middle.x() * c1 + middle.y() * c2).normalized();
          const double e = ringEnergy(u, q);
          if (e < best) {
            best = e;
            bestPoint = q;
          }
        }
      }
    }
    // The wedge from a = after(v) counter-clockwise to b, seen from outside in v's tangent plane.
    const Vec3d e1 =
        (std::abs(p.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).cross(p).normalized();
    const Vec3d e2 = p.cross(e1);
    const auto angle = [&](int w) {
      const Vec3d d = s_[w] - p;
      return std::atan2(d.dot(e2), d.dot(e1));
    };
    const int a = after(v);
    double wedge = 0;
    int steps = 0;
    for (int w = a; w != v && w >= 0 && steps < 64; ++steps) {
      const int z = after(w);
      if (z == v || z < 0) break;
      double turn = angle(z) - angle(w);
      while (turn < 0)
        turn += 2 * M_PI;
      while (turn >= 2 * M_PI)
        turn -= 2 * M_PI;
      wedge += turn;
      w = z;
    }
    if (a >= 0) {
      const double theta = angle(a) + 0.5 * wedge;
      const Vec3d direction = std::cos(theta) * e1 + std::sin(theta) * e2;
      for (double distance = reach; distance > 1e-12 * reach; distance *= 0.5) {
        const Vec3d q = (p + distance * direction).normalized();
        const double e = ringEnergy(u, q);
        if (e < best) {
          best = e;
          bestPoint = q;
        } else if (std::isfinite(best)) {
          break; // past the best point on the way in
        }
      }
    }
    s_[u] = bestPoint;
    // Often better: u and v both re-placed by a Tutte embedding (uniform weights) inside the
    // fixed boundary of their joint star, computed in the gnomonic projection about v, where
    // straight lines are great circles.
    const Vec3d savedV = s_[v];
    const double current = edgeStarEnergy(u, v);
    Vec3d sumU = Vec3d::Zero(), sumV = Vec3d::Zero();
    bool visible = true;
    const auto project = [&](int w) {
      const double h = s_[w].dot(p);
      if (h < 0.05) visible = false;
      return Vec3d(s_[w] / h - p);
    };
    std::vector<int>& around = scratchRing_;
    mesh_.neighbours(u, around);
    const double degreeU = static_cast<double>(around.size());
    for (int w : around)
      if (w != v) sumU += project(w);
    mesh_.neighbours(v, around);
    const double degreeV = static_cast<double>(around.size());
    for (int w : around)
      if (w != u) sumV += project(w);
    if (visible) {
      const double det = degreeU * degreeV - 1;
      const Vec3d tu = (degreeV * sumU + sumV) / det, tv = (degreeU * sumV + sumU) / det;
      s_[u] = (p + tu).normalized();
      s_[v] = (p + tv).normalized();
      if (edgeStarEnergy(u, v) < current) return true;
    }
    s_[u] = bestPoint;
    s_[v] = savedV;
    return std::isfinite(best);
  }

  // The energy of all faces around u or v.
  double edgeStarEnergy(int u, int v) {
    double e = ringEnergy(u, s_[u]) + ringEnergy(v, s_[v]);
    for (int f : mesh_.facesOf(u)) {
      const Tri& t = mesh_.faces()[f];
      if (t[0] != v && t[1] != v && t[2] != v) continue;
      e -= stretchEnergy(s_[t[0]], s_[t[1]], s_[t[2]], x_[t[0]], x_[t[1]], x_[t[2]]);
    }
    return std::isfinite(e) ? e : std::numeric_limits<double>::infinity();
  }

private:
  const Points& x_;
  const CollapsibleMesh& mesh_;
  Points& s_;
  std::vector<double> step_;
  std::vector<int> colour_;
  std::vector<std::vector<int>> classes_;
  std::vector<char> usedColours_;
  std::vector<RingFace> ring_;
  std::vector<std::pair<int, int>> scratch_;
  std::vector<int> scratchRing_;
  std::vector<Eigen::Vector2d> scratchPolygon_;
};

} // namespace

Points mapCoarseToFine(const Points& x, const std::vector<Tri>& triangles,
                       const CoarseToFineOptions& options,
                       const std::function<Points(const Points&, const std::vector<Tri>&)>& mapBase,
                       const std::function<void(double)>& progress) {
  const int n = static_cast<int>(x.size());
  CollapsibleMesh mesh(n, triangles);
  std::vector<Collapse> collapses =
      simplify(mesh, x, std::max(4, options.baseVertices), [&](double f) { progress(0.2 * f); });
  progress(0.2);

  // The base, renumbered compactly, onto the sphere: a tetrahedron onto a regular one, anything
  // larger by `mapBase`. Returns whether no base triangle is flipped.
  Points s(x.size(), Vec3d::UnitZ());
  std::vector<int> original;
  const auto mapBaseMesh = [&] {
    std::vector<int> compact(static_cast<std::size_t>(n), -1);
    original.clear();
    Points baseX;
    for (int v = 0; v < n; ++v)
      if (mesh.present(v)) {
        compact[v] = static_cast<int>(original.size());
        original.push_back(v);
        baseX.push_back(x[v]);
      }
    std::vector<Tri> baseTriangles = mesh.aliveFaces();
    for (Tri& t : baseTriangles)
      for (int& w : t)
        w = compact[w];
    Points baseSphere;
    if (baseX.size() == 4) {
      const double third = 1 / std::sqrt(3.0);
      baseSphere = {Vec3d(1, 1, 1) * third, Vec3d(1, -1, -1) * third, Vec3d(-1, 1, -1) * third,
                    Vec3d(-1, -1, 1) * third};
      if (flipped(baseSphere, baseTriangles.front()))
        for (Vec3d& p : baseSphere)
          p.x() = -p.x();
    } else {
      baseSphere = mapBase(baseX, baseTriangles);
    }
    bool valid = true;
    for (const Tri& t : baseTriangles)
      valid = valid && !flipped(baseSphere, t);
    for (std::size_t i = 0; i < original.size(); ++i)
      s[original[i]] = baseSphere[i];
    return valid;
  };
  // Where the whole-mesh map cannot embed the base (long thin parts that conformal flow
  // squeezes to nothing), the mesh is simplified on towards a tetrahedron, which needs no map
  // at all; the refinement then inserts every vertex into a valid ring.
  if (!mapBaseMesh() && mesh.aliveFaces().size() > 4) {
    std::vector<Collapse> more = simplify(mesh, x, 4, [](double) {});
    collapses.insert(collapses.end(), std::make_move_iterator(more.begin()),
                     std::make_move_iterator(more.end()));
    mapBaseMesh();
  }
  progress(0.35);

  Refiner refiner(x, mesh, s);
  std::vector<int> present = original;
  refiner.relax(present, options.sweepsPerLevel);
  double nextLevel = static_cast<double>(present.size()) * options.levelGrowth;
  std::vector<int> ring, area;
  std::size_t sinceReport = 0;
  for (std::size_t i = collapses.size(); i-- > 0;) {
    const Collapse& c = collapses[i];
    mesh.undo(c);
    refiner.place(c.u, c.v);
    present.push_back(c.u);
    // The new vertex and its ring settle at once; the level's sweeps do the rest.
    for (int iteration = 0; iteration < 6; ++iteration)
      if (!(refiner.optimize(c.u) > 0)) break;
    mesh.neighbours(c.u, ring);
    for (int w : ring)
      refiner.optimize(w);
    refiner.optimize(c.u);
    // Where the new vertex is still squeezed far more than its surroundings, its
    // neighbourhood is relaxed as a whole, growing while that does not suffice.
    for (int rings = 2; rings <= 4; ++rings) {
      refiner.region(c.u, rings + 1, area);
      if (refiner.stretchJump(area, {c.u, c.v}) <= 8) break;
      refiner.region(c.u, rings, area);
      for (int sweep = 0; sweep < 4 * rings; ++sweep)
        for (int w : area)
          refiner.optimize(w);
    }
    if (static_cast<double>(present.size()) >= nextLevel || i == 0) {
      refiner.relax(present, options.sweepsPerLevel);
      nextLevel = static_cast<double>(present.size()) * options.levelGrowth;
    }
    if (++sinceReport == 1024 || i == 0) {
      sinceReport = 0;
      progress(0.35 +
               0.65 * (1.0 - double(i) / double(std::max<std::size_t>(1, collapses.size()))));
    }
  }
  progress(1.0);
  return s;
}

void relaxStretchPower(Points& s, const Points& x, const std::vector<Tri>& triangles, double power,
                       int maxSweeps, double tolerance) {
  const int n = static_cast<int>(s.size());
  std::vector<std::vector<RingFace>> rings(static_cast<std::size_t>(n));
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int v = t[k], a = t[(k + 1) % 3], b = t[(k + 2) % 3];
      rings[v].push_back({a, b, x[v], x[a], x[b]});
    }
  double total = 0;
  for (int v = 0; v < n; ++v)
    total += ringStretchEnergy(s, rings[v], s[v], nullptr, power) / 3;
  if (!std::isfinite(total) || !(total > 0)) return;
  std::vector<double> step(static_cast<std::size_t>(n), std::numeric_limits<double>::infinity());
  for (int sweep = 0; sweep < maxSweeps; ++sweep) {
    // Each move changes only the moved vertex's triangles, so the ring decreases add up to the
    // decrease of the whole energy.
    double decrease = 0;
    for (int v = 0; v < n; ++v)
      decrease += descend(s, v, rings[v], step[v], power);
    total -= decrease;
    if (!(decrease > tolerance * total)) break;
  }
}

} // namespace octaclay::core::detail
