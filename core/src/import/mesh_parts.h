#pragma once

// A mesh's connected parts: triangles joined through shared vertices (STL's corners welded by
// exact position first), so that a file of several closed lumps can become several objects.

#include "octaclay/core/geometry/triangle_mesh.h"

#include <vector>

namespace octaclay::core::detail {

/// Welds vertices at exactly the same position (STL's corners), keeping the first.
TriangleMesh weldExactly(const TriangleMesh& mesh);

/// The mesh's parts, each its triangles (in file order) with its used vertices renumbered in
/// first-use order; parts in the order of their first triangle. Unused vertices belong to no
/// part. O(V + F α) time, O(V + F) memory.
std::vector<TriangleMesh> splitConnectedParts(const TriangleMesh& mesh);

} // namespace octaclay::core::detail
