#pragma once

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <functional>
#include <vector>

namespace octaclay::core {

/// A map of a closed genus-0 mesh onto the unit sphere, one point per vertex of the mesh.
struct SphericalMap {
  /// #V unit vectors, indexed like TriangleMesh::positions. Vertices no triangle references
  /// get (0, 0, 1).
  std::vector<Vec3f> sphere;
  /// Triangles whose sphere image is not positively oriented (det(a, b, c) ≤ 0, computed on
  /// the stored floats); 0 means the map is bijective.
  int flipped = 0;
  /// Sander et al. 2001 stretch of the map sphere → surface (each sphere triangle taken flat),
  /// with the sphere scaled to the surface's area: stretchL2 is the surface-area-weighted L2
  /// norm (1 for an isometry up to scale, larger otherwise), stretchLinf the largest singular
  /// value over all triangles. Flipped triangles are left out of both.
  float stretchL2 = 0;
  float stretchLinf = 0;
};

/// Thrown when the progress callback asks to stop: an Error of kind Cancelled.
class Cancelled : public Error {
public:
  Cancelled() : Error(ErrorKind::Cancelled, "cancelled") {}
};

/// Tunables of parameterizeOnSphere; the defaults suit meshes of up to ~10⁵ vertices.
struct SphericalParameterizationOptions {
  int flowSteps = 24;        ///< conformalized mean-curvature-flow steps at most
  double flowTimeStep = 0.5; ///< per step, for the mesh scaled to the unit sphere's area
  int equalizeSteps = 40;    ///< area-equalizing relaxation steps (0: keep the conformal map)
  int relaxSweeps = 10;      ///< sweeps of local stretch minimization over all vertices
  /// Meshes with more than twice this many vertices are mapped coarse to fine (Praun & Hoppe
  /// 2003): simplified to about this many vertices, the base mapped as a whole, the vertices
  /// put back one by one inside their one-rings. 0: always map the whole mesh at once.
  int baseVertices = 100;
  /// Up to this many vertices the whole-mesh map is computed as well and the one with the lower
  /// L2 stretch kept.
  int compareBelowVertices = 20'000;
};

/// Maps `mesh` bijectively onto the unit sphere with low stretch: conformalized mean curvature
/// flow to a near-conformal sphere, untangling of any flipped triangles, Möbius balancing of
/// the surface's area about the origin, then an area-equalizing relaxation that never flips a
/// triangle. Time is dominated by sparse Cholesky factorizations: about a second for 10⁴
/// vertices.
///
/// Preconditions: `mesh` is closed, edge-manifold, genus 0 (Euler characteristic 2 over its
/// referenced vertices), counter-clockwise seen from outside, without degenerate triangles;
/// unused vertices are allowed. Throws Error(InvalidInput) naming what is wrong when it is not.
/// `progress`, when given, is called now and then with the fraction done in [0, 1]; returning
/// false stops the work and throws Cancelled. Called on the caller's thread.
SphericalMap parameterizeOnSphere(const TriangleMesh& mesh,
                                  const std::function<bool(float)>& progress = {},
                                  const SphericalParameterizationOptions& options = {});

/// Recomputes map.flipped, map.stretchL2 and map.stretchLinf from map.sphere (#V unit vectors).
void measureSphericalMap(const TriangleMesh& mesh, SphericalMap& map);

} // namespace octaclay::core
