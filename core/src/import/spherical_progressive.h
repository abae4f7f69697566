#pragma once

// Coarse-to-fine spherical parameterization after Praun & Hoppe, "Spherical parametrization and
// remeshing" (SIGGRAPH 2003): the mesh is simplified by half-edge collapses to a small base,
// the base is mapped onto the sphere, and the collapses are undone in reverse order, each
// re-inserted vertex placed inside the kernel of its one-ring on the sphere and the map relaxed
// towards low L2 stretch level by level. No step ever flips a triangle, so the map stays
// bijective, and sphere area follows surface area instead of the conformal factor that
// squeezes long protrusions.

#include "import/spherical_geometry.h"

#include <functional>

namespace octaclay::core::detail {

struct CoarseToFineOptions {
  int baseVertices = 100;   ///< simplify down to about this many vertices
  double levelGrowth = 1.5; ///< relax all vertices each time their number grows this much
  int sweepsPerLevel = 3;   ///< stretch-relaxation sweeps per level
};

/// Maps the closed genus-0 mesh (x, triangles), compact (every vertex referenced) and facing
/// outward, onto the unit sphere. `mapBase` maps the base mesh (positions and triangles,
/// renumbered compactly) bijectively onto the unit sphere. `progress` gets the fraction done in
/// [0, 1] now and then; it may throw to stop. Returns one unit vector per vertex; where the base
/// map leaves no flips (a tetrahedron base never does) and every re-inserted vertex found a
/// valid place, no triangle is flipped, in double or in float.
Points mapCoarseToFine(const Points& x, const std::vector<Tri>& triangles,
                       const CoarseToFineOptions& options,
                       const std::function<Points(const Points&, const std::vector<Tri>&)>& mapBase,
                       const std::function<void(double)>& progress);

/// Relaxes the map s of the mesh (x, triangles) towards a low Σ A·m^power, m each triangle's
/// mean squared stretch (power above 1 targets the largest stretch), by flip-safe local
/// descent sweeps over all vertices until a sweep lowers the energy by less than `tolerance`
/// of it or `maxSweeps` have run. Serial: meant for small meshes.
void relaxStretchPower(Points& s, const Points& x, const std::vector<Tri>& triangles, double power,
                       int maxSweeps, double tolerance = 1e-5);

} // namespace octaclay::core::detail
