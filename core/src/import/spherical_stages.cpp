// Based on: Kazhdan, Solomon & Ben-Chen, "Can mean-curvature flow be modified to be
// non-singular?" (SGP 2012) for the conformalized mean curvature flow and the Möbius
// balancing; Sander, Snyder, Gortler & Hoppe, "Texture mapping progressive meshes"
// (SIGGRAPH 2001) for the stretch metric; the area-equalizing relaxation follows the
// density-diffusion idea of Choi & Rycroft, "Density-equalizing maps for simply connected
// open surfaces" (SIAM J. Imaging Sci. 2018), taken as a Poisson step on the sphere.
#include "import/spherical_stages.h"

#include <Eigen/Geometry>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <cmath>
#include <numeric>

namespace octaclay::core::detail {

namespace {

using SpMat = Eigen::SparseMatrix<double>;

constexpr double kFourPi = 4.0 * M_PI;

// The cotangent Laplacian (negative semi-definite; rows sum to zero). Cotangents of nearly
// degenerate corners are clamped so that one sliver cannot dominate the system.
SpMat cotanLaplacian(const Points& x, const std::vector<Tri>& triangles) {
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(triangles.size() * 12);
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k) {
      const int i = t[(k + 1) % 3], j = t[(k + 2) % 3];
      const Vec3d u = x[i] - x[t[k]], v = x[j] - x[t[k]];
      const double s = u.cross(v).norm();
      const double cot = s > 0 ? std::clamp(u.dot(v) / s, -1e3, 1e3) : 0.0;
      const double w = 0.5 * cot;
      entries.emplace_back(i, j, w);
      entries.emplace_back(j, i, w);
      entries.emplace_back(i, i, -w);
      entries.emplace_back(j, j, -w);
    }
  SpMat l(static_cast<Eigen::Index>(x.size()), static_cast<Eigen::Index>(x.size()));
  l.setFromTriplets(entries.begin(), entries.end());
  return l;
}

// Lumped (barycentric) vertex areas.
Eigen::VectorXd vertexAreas(const Points& x, const std::vector<Tri>& triangles) {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(x.size()));
  for (const Tri& t : triangles) {
    const double third = triangleArea(x, t) / 3.0;
    for (int v : t)
      a[v] += third;
  }
  return a;
}

// Moves the area-weighted centroid to the origin and scales the total area to 4π.
void normalizeSurface(Points& x, const std::vector<Tri>& triangles) {
  double area = 0;
  Vec3d centroid = Vec3d::Zero();
  for (const Tri& t : triangles) {
    const double a = triangleArea(x, t);
    area += a;
    centroid += a * (x[t[0]] + x[t[1]] + x[t[2]]) / 3.0;
  }
  centroid /= area;
  const double scale = std::sqrt(kFourPi / area);
  for (Vec3d& p : x)
    p = (p - centroid) * scale;
}

int countFlipped(const Points& s, const std::vector<Tri>& triangles) {
  int count = 0;
  for (const Tri& t : triangles)
    count += flipped(s, t) ? 1 : 0;
  return count;
}

// trial = s moved by tau·velocity (on the sphere), except that vertices of triangles the move
// would flip take half their step, up to twelve times; the caller rejects a trial that still
// flips. `scale` is per-vertex scratch.
void moveWithoutFlips(const Points& s, const std::vector<Vec3d>& velocity, double tau,
                      const std::vector<Tri>& triangles, std::vector<double>& scale,
                      Points& trial) {
  const std::size_t n = s.size();
  scale.assign(n, tau);
  for (std::size_t v = 0; v < n; ++v)
    trial[v] = (s[v] + tau * velocity[v]).normalized();
  std::vector<int> shrink;
  for (int round = 0; round < 12; ++round) {
    shrink.clear();
    for (const Tri& t : triangles)
      if (flipped(trial, t))
        for (int v : t)
          shrink.push_back(v);
    if (shrink.empty()) return;
    std::sort(shrink.begin(), shrink.end());
    shrink.erase(std::unique(shrink.begin(), shrink.end()), shrink.end());
    for (int v : shrink) {
      scale[v] *= 0.5;
      trial[v] = (s[v] + scale[v] * velocity[v]).normalized();
    }
  }
}

} // namespace

// Conformalized mean curvature flow: the stiffness stays that of the input, the mass matrix
// follows the flow, so the surface rounds out without developing the neck pinches of plain
// mean curvature flow. Returns after `steps` or once the surface is round to 0.1 %.
void conformalizedFlow(Points& x, const std::vector<Tri>& triangles, int steps, double delta,
                       const std::function<bool(float)>& progress) {
  const auto n = static_cast<Eigen::Index>(x.size());
  normalizeSurface(x, triangles);
  const SpMat l0 = cotanLaplacian(x, triangles);
  SpMat system = -delta * l0;
  system.makeCompressed();
  Eigen::SimplicialLDLT<SpMat> solver;
  solver.analyzePattern(system);
  Eigen::MatrixXd positions(n, 3), rhs(n, 3);
  for (int step = 0; step < steps; ++step) {
    report(progress, 0.5 * step / steps);
    const Eigen::VectorXd mass = vertexAreas(x, triangles);
    system = -delta * l0;
    for (Eigen::Index v = 0; v < n; ++v)
      system.coeffRef(v, v) += mass[v];
    solver.factorize(system);
    if (solver.info() != Eigen::Success) break;
    for (Eigen::Index v = 0; v < n; ++v)
      rhs.row(v) = mass[v] * x[v].transpose();
    positions = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !positions.allFinite()) break;
    for (Eigen::Index v = 0; v < n; ++v)
      x[v] = positions.row(v).transpose();
    normalizeSurface(x, triangles);
    double sum = 0, sum2 = 0;
    for (const Vec3d& p : x) {
      const double r = p.norm();
      sum += r;
      sum2 += r * r;
    }
    const double mean = sum / static_cast<double>(n);
    const double deviation = std::sqrt(std::max(0.0, sum2 / static_cast<double>(n) - mean * mean));
    if (deviation < 1e-3 * mean) break;
  }
}

// Relaxes the neighbourhoods of flipped triangles towards the spherical Tutte embedding
// (each vertex at the normalized mean of its neighbours), growing the neighbourhoods while
// flips remain. Returns the number of flipped triangles left.
int untangle(Points& s, const std::vector<Tri>& triangles, const Adjacency& a) {
  const int n = static_cast<int>(s.size());
  std::vector<char> active(static_cast<std::size_t>(n));
  for (int round = 0; round < 60; ++round) {
    std::fill(active.begin(), active.end(), 0);
    int flips = 0;
    for (const Tri& t : triangles)
      if (flipped(s, t)) {
        ++flips;
        for (int v : t)
          active[v] = 1;
      }
    if (flips == 0) return 0;
    for (int ring = 0; ring < 1 + round / 4; ++ring) {
      std::vector<char> grown = active;
      for (int v = 0; v < n; ++v)
        if (active[v])
          for (int k = a.start[v]; k < a.start[v + 1]; ++k)
            grown[a.adj[k]] = 1;
      active.swap(grown);
    }
    std::vector<int> region;
    for (int v = 0; v < n; ++v)
      if (active[v]) region.push_back(v);
    for (int iteration = 0; iteration < 20; ++iteration)
      for (int v : region) {
        Vec3d sum = Vec3d::Zero();
        for (int k = a.start[v]; k < a.start[v + 1]; ++k)
          sum += s[a.adj[k]];
        if (sum.norm() > 1e-12) s[v] = sum.normalized();
      }
  }
  return countFlipped(s, triangles);
}

// Möbius balancing: inversions of the ball move the surface-area-weighted centroid of the
// sphere points to the origin, so no region of the surface is squeezed to one side.
void balance(Points& s, const std::vector<Tri>& triangles, const std::vector<double>& weights) {
  for (int iteration = 0; iteration < 200; ++iteration) {
    Vec3d centroid = Vec3d::Zero();
    double total = 0;
    for (std::size_t t = 0; t < triangles.size(); ++t) {
      const Tri& f = triangles[t];
      centroid += weights[t] * (s[f[0]] + s[f[1]] + s[f[2]]).normalized();
      total += weights[t];
    }
    centroid /= total;
    if (centroid.norm() < 1e-5) return;
    Vec3d c = 0.5 * centroid;
    if (c.norm() > 0.9) c *= 0.9 / c.norm();
    const double c2 = c.squaredNorm();
    for (Vec3d& p : s) {
      const Vec3d d = p - c;
      p = ((1 - c2) * d / d.squaredNorm() - c).normalized();
    }
  }
}

StretchSummary stretch(const Points& s, const Points& x, const std::vector<Tri>& triangles) {
  double surfaceArea = 0, sphereArea = 0, weighted = 0, maxSquare = 0;
  StretchSummary out;
  for (const Tri& t : triangles) {
    const TriangleStretch ts =
        triangleStretch(s[t[0]], s[t[1]], s[t[2]], x[t[0]], x[t[1]], x[t[2]]);
    if (std::isnan(ts.meanSquare)) {
      ++out.flipped;
      continue;
    }
    const double area = triangleArea(x, t);
    surfaceArea += area;
    sphereArea += triangleArea(s, t);
    weighted += area * ts.meanSquare;
    maxSquare = std::max(maxSquare, ts.maxSquare);
  }
  if (surfaceArea <= 0 || sphereArea <= 0) return out;
  // Scaling the sphere by k = √(surface / sphere area) divides the Jacobian by k.
  const double k2 = surfaceArea / sphereArea;
  out.l2 = std::sqrt(weighted / surfaceArea / k2);
  out.linf = std::sqrt(maxSquare / k2);
  return out;
}

// Area-equalizing relaxation: the log of the ratio of surface to sphere area per vertex drives
// a Poisson problem on the sphere mesh, −Δφ = log ρ − mean; moving the vertices along −∇φ
// expands the regions the surface has too little room in (to first order it equalizes ρ in one
// step). A step is kept only if it flips nothing and lowers the L2 stretch; otherwise it is
// halved.
void equalizeAreas(Points& s, const Points& x, const std::vector<Tri>& triangles, int steps,
                   const std::function<bool(float)>& progress) {
  const auto n = static_cast<Eigen::Index>(s.size());
  Eigen::VectorXd surfaceAreas = vertexAreas(x, triangles);
  surfaceAreas *= kFourPi / surfaceAreas.sum();
  StretchSummary current = stretch(s, x, triangles);
  if (current.flipped != 0) return;
  Eigen::SimplicialLDLT<SpMat> solver;
  bool analyzed = false;
  double tau = 1.0;
  Points trial(s.size());
  std::vector<Vec3d> velocity(s.size());
  std::vector<double> scale;
  for (int step = 0; step < steps; ++step) {
    report(progress, 0.6 + 0.2 * step / steps);
    Eigen::VectorXd sphereAreas = vertexAreas(s, triangles);
    const double sphereTotal = sphereAreas.sum();
    sphereAreas *= kFourPi / sphereTotal;
    Eigen::VectorXd f(n);
    double mean = 0;
    for (Eigen::Index v = 0; v < n; ++v) {
      f[v] = std::clamp(std::log(surfaceAreas[v] / std::max(sphereAreas[v], 1e-300)), -4.0, 4.0);
      mean += f[v] * sphereAreas[v];
    }
    mean /= kFourPi;
    f.array() -= mean;
    SpMat system = -cotanLaplacian(s, triangles);
    for (Eigen::Index v = 0; v < n; ++v)
      system.coeffRef(v, v) += 1e-6 * sphereAreas[v];
    system.makeCompressed();
    if (!analyzed) {
      solver.analyzePattern(system);
      analyzed = true;
    }
    solver.factorize(system);
    if (solver.info() != Eigen::Success) return;
    const Eigen::VectorXd phi = solver.solve(sphereAreas.cwiseProduct(f));
    if (solver.info() != Eigen::Success || !phi.allFinite()) return;

    std::fill(velocity.begin(), velocity.end(), Vec3d::Zero());
    for (const Tri& t : triangles) {
      const Vec3d normal = (s[t[1]] - s[t[0]]).cross(s[t[2]] - s[t[0]]);
      const double twiceArea = normal.norm();
      if (twiceArea <= 0) continue;
      const Vec3d unit = normal / twiceArea;
      Vec3d gradient = Vec3d::Zero();
      for (int k = 0; k < 3; ++k)
        gradient += phi[t[k]] * unit.cross(s[t[(k + 2) % 3]] - s[t[(k + 1) % 3]]);
      // Area-weighted average over the one-ring: Σ A·g / ΣA, with g = gradient / (2A).
      for (int v : t)
        velocity[v] -= 0.5 * gradient;
    }
    const Eigen::VectorXd ringAreas = vertexAreas(s, triangles) * 3.0;
    for (Eigen::Index v = 0; v < n; ++v) {
      Vec3d& u = velocity[v];
      u /= std::max(ringAreas[v], 1e-300);
      u -= u.dot(s[v]) * s[v];
    }

    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      moveWithoutFlips(s, velocity, tau, triangles, scale, trial);
      const StretchSummary next = stretch(trial, x, triangles);
      if (next.flipped == 0 && next.l2 < current.l2) {
        accepted = true;
        const double gain = current.l2 - next.l2;
        s.swap(trial);
        current = next;
        tau = std::min(1.0, tau * 1.5);
        if (gain < 1e-4 * current.l2) return;
      } else {
        tau *= 0.5;
      }
    }
    if (!accepted) return;
  }
}

Adjacency adjacency(int n, const std::vector<Tri>& triangles) {
  // On a closed manifold each directed edge (a → b) appears once; its start vertex lists b.
  Adjacency a;
  a.start.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k)
      ++a.start[static_cast<std::size_t>(t[k]) + 1];
  for (int v = 0; v < n; ++v)
    a.start[v + 1] += a.start[v];
  a.adj.resize(static_cast<std::size_t>(a.start[n]));
  std::vector<int> fill(a.start.begin(), a.start.end() - 1);
  for (const Tri& t : triangles)
    for (int k = 0; k < 3; ++k)
      a.adj[fill[t[k]]++] = t[(k + 1) % 3];
  return a;
}

namespace {

// relaxStretch and relaxStretchWhereMoving: with `adaptive`, after the first sweep only the
// vertices that moved by at least 1 % of their shortest ring edge, and their neighbours, are
// visited again, and the sweeps stop when none did.
void relaxStretchSweeps(Points& s, const Points& x, const std::vector<Tri>& triangles,
                        const Adjacency& rings, int sweeps, bool adaptive,
                        const std::function<bool(float)>& progress, double progressBegin,
                        double progressEnd) {
  const int n = static_cast<int>(s.size());
  // Triangles around each vertex, in compressed rows like the rings.
  std::vector<int> start(static_cast<std::size_t>(n) + 1, 0), around(triangles.size() * 3);
  for (const Tri& t : triangles)
    for (int v : t)
      ++start[v + 1];
  for (int v = 0; v < n; ++v)
    start[v + 1] += start[v];
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    for (int v : triangles[t])
      around[fill[v]++] = t;
  std::vector<double> surfaceArea(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    surfaceArea[t] = triangleArea(x, triangles[t]);

  const auto ringEnergy = [&](int v, const Vec3d& p) {
    const Vec3d saved = s[v];
    s[v] = p;
    double e = 0;
    for (int k = start[v]; k < start[v + 1] && std::isfinite(e); ++k) {
      const Tri& t = triangles[around[k]];
      const TriangleStretch ts =
          triangleStretch(s[t[0]], s[t[1]], s[t[2]], x[t[0]], x[t[1]], x[t[2]]);
      e = std::isnan(ts.meanSquare) ? std::numeric_limits<double>::infinity()
                                    : e + surfaceArea[around[k]] * ts.meanSquare;
    }
    s[v] = saved;
    return e;
  };
  // One descent step of vertex v; returns the step taken over its shortest ring edge (0: none).
  const auto move = [&](int v) {
    const Vec3d p = s[v];
    double shortest = std::numeric_limits<double>::infinity();
    for (int k = rings.start[v]; k < rings.start[v + 1]; ++k)
      shortest = std::min(shortest, (s[rings.adj[k]] - p).norm());
    if (!(shortest > 0)) return 0.0;
    const Vec3d e1 =
        (std::abs(p.x()) < 0.9 ? Vec3d::UnitX() : Vec3d::UnitY()).cross(p).normalized();
    const Vec3d e2 = p.cross(e1);
    const double h = 1e-3 * shortest;
    const double e0 = ringEnergy(v, p);
    const Vec3d gradient =
        (ringEnergy(v, (p + h * e1).normalized()) - ringEnergy(v, (p - h * e1).normalized())) * e1 +
        (ringEnergy(v, (p + h * e2).normalized()) - ringEnergy(v, (p - h * e2).normalized())) * e2;
    const double norm = gradient.norm();
    if (!(norm > 0) || !std::isfinite(norm)) return 0.0;
    const Vec3d direction = -gradient / norm;
    for (double step = 0.5 * shortest; step > 1e-4 * shortest; step *= 0.5) {
      const Vec3d q = (p + step * direction).normalized();
      if (ringEnergy(v, q) < e0) {
        s[v] = q;
        return step / shortest;
      }
    }
    return 0.0;
  };
  constexpr double kMovedEnough = 0.01;
  std::vector<int> visit(static_cast<std::size_t>(n));
  for (int v = 0; v < n; ++v)
    visit[v] = v;
  std::vector<char> next(adaptive ? static_cast<std::size_t>(n) : 0, 0);
  for (int sweep = 0; sweep < sweeps && !visit.empty(); ++sweep) {
    report(progress, progressBegin + (progressEnd - progressBegin) * sweep / sweeps);
    for (int v : visit)
      if (const double moved = move(v); adaptive && moved >= kMovedEnough) {
        next[v] = 1;
        for (int k = rings.start[v]; k < rings.start[v + 1]; ++k)
          next[rings.adj[k]] = 1;
      }
    if (!adaptive) continue;
    visit.clear();
    for (int v = 0; v < n; ++v)
      if (next[v]) visit.push_back(v), next[v] = 0;
  }
}

} // namespace

// Sander et al.'s local optimization: each vertex in turn moves on the sphere down the
// (finite-difference) gradient of its one-ring's L2 stretch, Σ A'·(a + c)/2, with a halving
// line search. The energy is infinite for a flipped triangle, so no move flips one.
void relaxStretch(Points& s, const Points& x, const std::vector<Tri>& triangles,
                  const Adjacency& rings, int sweeps, const std::function<bool(float)>& progress,
                  double progressBegin, double progressEnd) {
  relaxStretchSweeps(s, x, triangles, rings, sweeps, false, progress, progressBegin, progressEnd);
}

void relaxStretchWhereMoving(Points& s, const Points& x, const std::vector<Tri>& triangles,
                             const Adjacency& rings, int maxSweeps,
                             const std::function<bool(float)>& progress, double progressBegin,
                             double progressEnd) {
  relaxStretchSweeps(s, x, triangles, rings, maxSweeps, true, progress, progressBegin, progressEnd);
}

} // namespace octaclay::core::detail
