// The spherical parameterization of a geometry image's own surface (Mesh ▸ Remesh,
// `octaclay-cli remesh`), coarse to fine along the image's grid rather than by simplification.
#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <functional>

namespace octaclay::core::detail {

struct ImageParameterizationOptions {
  /// The grid the whole-mesh parameterization runs on: the image sampled every N/coarseSize
  /// samples (coarseSize² · 2 triangles). Images smaller than twice this size are
  /// parameterized whole (parameterizeOnSphere on `mesh`). 64 rather than 128: the levels of
  /// 128 and 256 relaxed from it give a limb as large a share (0.87 of its fair share against
  /// 0.7 wanted) at half the time, which the whole-mesh map of 128² + 2 vertices spent.
  int coarseSize = 64;
  /// Sweeps of local stretch relaxation at each finer level (relaxStretchWhereMoving: after
  /// the first, only where vertices still move).
  int sweepsPerLevel = 4;
  /// Levels finer than this are only refined from the one below and untangled: their
  /// relaxation moves a creature's parts' shares by under 1 % and cost most of the time at
  /// N = 1024.
  int relaxUpToSize = 256;
  /// Sweeps of the descent on the largest stretch (relaxStretchPower, power 2: the tips of thin
  /// parts) on the level of size finishSize (the full resolution when N is smaller): serial,
  /// so kept to a level of 2·256² triangles.
  int finishSweeps = 6;
  int finishSize = 256;
};

/// The map onto the unit sphere of `mesh`, the image's full-resolution surface (extractMesh
/// with its vertex numbering; its triangles as validateGenus0Mesh turned them). The image
/// sampled every N/coarseSize samples (extractMesh's exact subsampling: the coarse vertices
/// are full-resolution samples) is parameterized whole (parameterizeOnSphere, its default
/// pipeline); each level of
/// twice the size takes its new vertices from the level below, linearly inside the coarse
/// triangle of the grid that holds them (the grid's triangulation nests: a coarse triangle is
/// a union of fine ones), and is relaxed (relaxStretch) and untangled. Where the coarse grid
/// cannot be parameterized (degenerate triangles where samples coincide), the whole mesh is.
/// progress as parameterizeOnSphere's; throws Cancelled when it asks to stop.
SphericalMap parameterizeImageOnSphere(const GeometryImage& image, const TriangleMesh& mesh,
                                       const std::function<bool(float)>& progress = {},
                                       const ImageParameterizationOptions& options = {});

} // namespace octaclay::core::detail
