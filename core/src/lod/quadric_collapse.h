#pragma once

#include "octaclay/core/lod/vertex_collapse.h"

namespace octaclay::core::detail {

/// The same contract as collapseVertices (closed manifold input; target, error bound, normal
/// turn against the input triangle, aspect ratio, texture folds, veto; link condition, never
/// below a tetrahedron), computed without OpenMesh on flat arrays, in passes: each pass
/// computes every edge's quadric error (Garland–Heckbert, planes weighted by area / mean area, the
/// edge collapsed into the endpoint that costs less), takes the cheapest three times as many edges
/// as collapses are still wanted, sorts them and collapses them in that order, recomputing
/// each one's error when it comes up (earlier collapses change it) and skipping it when it has
/// grown past the pass's threshold or a check refuses it. Two or three passes reach the target
/// on LOD meshes. Input is not checked.
CollapsedMesh quadricCollapse(const TriangleMesh& mesh, const VertexCollapseOptions& options);

} // namespace octaclay::core::detail
