// The stages of the whole-mesh spherical parameterization (mapDirectly in
// spherical_parameterization.cpp), each acting on a map s of the mesh (x, triangles): the
// conformalized flow that rounds the surface out, untangling, Möbius balancing, area
// equalization and stretch relaxation, with the stretch measure they are judged by.
#pragma once

#include "import/spherical_geometry.h"

#include "octaclay/core/import/spherical_parameterization.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <vector>

namespace octaclay::core::detail {

// Vertex one-rings in compressed rows: neighbours of v are adj[start[v] … start[v+1]).
struct Adjacency {
  std::vector<int> start, adj;
};

// The one-rings of a closed manifold mesh of n vertices.
Adjacency adjacency(int n, const std::vector<Tri>& triangles);

// Hands `progress` the fraction done; throws Cancelled when it asks to stop.
inline void report(const std::function<bool(float)>& progress, double fraction) {
  if (progress && !progress(static_cast<float>(std::clamp(fraction, 0.0, 1.0)))) throw Cancelled();
}

// Conformalized mean curvature flow: the stiffness stays that of the input, the mass matrix
// follows the flow, so the surface rounds out without developing the neck pinches of plain
// mean curvature flow. Returns after `steps` or once the surface is round to 0.1 %.
void conformalizedFlow(Points& x, const std::vector<Tri>& triangles, int steps, double delta,
                       const std::function<bool(float)>& progress);

// Relaxes the neighbourhoods of flipped triangles towards the spherical Tutte embedding
// (each vertex at the normalized mean of its neighbours), growing the neighbourhoods while
// flips remain. Returns the number of flipped triangles left.
int untangle(Points& s, const std::vector<Tri>& triangles, const Adjacency& a);

// Möbius balancing: inversions of the ball move the surface-area-weighted centroid of the
// sphere points to the origin, so no region of the surface is squeezed to one side.
void balance(Points& s, const std::vector<Tri>& triangles, const std::vector<double>& weights);

struct StretchSummary {
  double l2 = std::numeric_limits<double>::infinity();
  double linf = std::numeric_limits<double>::infinity();
  int flipped = 0;
};

// The L2 and L∞ stretch of the map s of (x, triangles), and how many triangles it flips.
StretchSummary stretch(const Points& s, const Points& x, const std::vector<Tri>& triangles);

// Area-equalizing relaxation: the log of the ratio of surface to sphere area per vertex drives
// a Poisson problem on the sphere mesh, −Δφ = log ρ − mean; moving the vertices along −∇φ
// expands the regions the surface has too little room in (to first order it equalizes ρ in one
// step). A step is kept only if it flips nothing and lowers the L2 stretch; otherwise it is
// halved.
void equalizeAreas(Points& s, const Points& x, const std::vector<Tri>& triangles, int steps,
                   const std::function<bool(float)>& progress);

// Sander et al.'s local optimization: each vertex in turn moves on the sphere down the
// (finite-difference) gradient of its one-ring's L2 stretch, Σ A'·(a + c)/2, with a halving
// line search. The energy is infinite for a flipped triangle, so no move flips one.
void relaxStretch(Points& s, const Points& x, const std::vector<Tri>& triangles,
                  const Adjacency& rings, int sweeps, const std::function<bool(float)>& progress,
                  double progressBegin, double progressEnd);

// relaxStretch that visits again only where it is still moving: after the first sweep, the
// vertices that moved by at least 1 % of their shortest ring edge and their neighbours; it
// stops when none did or after maxSweeps. For a map good almost everywhere (a coarse map
// refined), the work goes where the stretch is.
void relaxStretchWhereMoving(Points& s, const Points& x, const std::vector<Tri>& triangles,
                             const Adjacency& rings, int maxSweeps,
                             const std::function<bool(float)>& progress, double progressBegin,
                             double progressEnd);

} // namespace octaclay::core::detail
