#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <functional>
#include <span>

namespace octaclay::core::detail {

/// The union of closed meshes (world space, any winding) as a triangle mesh, through OpenVDB:
/// each mesh becomes a narrow-band level set (meshToLevelSet, 3 voxels each side of the
/// surface) at `voxelSize`, the sets are united (csgUnion), and the union's zero set is meshed
/// (volumeToMesh, adaptivity 0: one vertex per voxel the surface crosses), each quad split
/// along its shorter diagonal. The mesh is welded (shared vertices) but not checked: it may
/// have several pieces, any genus. `progress` (fraction of this step; false cancels) is asked
/// between the parts on the caller's thread; returns an empty mesh when it cancelled.
/// Precondition: voxelSize > 0 and finite, the meshes' positions finite.
TriangleMesh voxelUnion(std::span<const TriangleMesh> meshes, double voxelSize,
                        const std::function<bool(float)>& progress);

} // namespace octaclay::core::detail
