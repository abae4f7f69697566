#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/lod/lod.h"

#include <vector>

namespace octaclay::app {

/// Moves an LOD with the surface between regenerations: while a stroke runs, generateLod (its
/// vertex collapse) takes far longer than a frame, so each frame the last LOD's vertices follow
/// the samples they came from — its triangles (and their count, the target) stay, each vertex
/// moves by how far its source sample moved since the LOD was made. A few microseconds per
/// thousand vertices; the next generateLod then replaces it with a freshly chosen one.
class LodFollower {
public:
  LodFollower() = default;
  /// `lod` made by generateLod from `source` (its snapshot of the positions).
  LodFollower(core::LodMesh lod, const core::GeometryImage& source);

  bool empty() const { return lod_.mesh.triangles.empty(); }
  /// The LOD as it was made.
  const core::LodMesh& lod() const { return lod_; }
  /// Each vertex's source sample (from its corners' image coordinates).
  const std::vector<core::Sample>& sources() const { return sources_; }

  /// The LOD with every vertex moved by now(source) − then(source); `now` must have the grid
  /// of the source image (else the LOD is returned as made).
  core::LodMesh follow(const core::GeometryImage& now) const;

private:
  core::LodMesh lod_;
  std::vector<core::Sample> sources_;
  std::vector<core::Vec3f> sourcePositions_; // then(source), per vertex
  core::SampleGrid grid_;                    // the source's: a torus's or plane's W × H
};

} // namespace octaclay::app
