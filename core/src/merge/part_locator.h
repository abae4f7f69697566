#pragma once

#include "detail/aabb_tree.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// A merge's part as its surface is searched: its document and its full-resolution surface
/// placed in world space (extractMesh(document.positions) moved by the part's transform, so
/// vertex v is VertexIndex(N).canonicalSamples()[v]).
struct PlacedSurface {
  const Document* document = nullptr;
  TriangleMesh mesh;
};

/// Which placed part is nearest a point, and where on it: an AABB tree per part. Immutable after
/// construction; any number of threads may query it, each with its own Cursor.
class PartLocator {
public:
  /// Builds every part's tree: O(T log T) for T triangles in all. The parts must outlive it.
  explicit PartLocator(std::span<const PlacedSurface> parts);

  /// What a thread carries from one query to the next: spatially coherent queries (a row of
  /// texels, a mesh's vertices in order) start from the last answer.
  struct Cursor {
    std::vector<std::uint32_t> hints;
    std::size_t winner = 0;
  };
  Cursor cursor() const {
    return {std::vector<std::uint32_t>(parts_.size(), AabbTree::noTriangle), 0};
  }

  struct Found {
    std::size_t part = 0;
    std::uint32_t triangle = 0; ///< into parts[part].mesh.triangles
    Vec3d point;                ///< the closest point on it
  };
  /// The closest point of the nearest part (ties: the lower index after the cursor's winner).
  /// The cursor's winner is searched first; another part only where its bounding box is nearer
  /// than the best so far.
  Found nearest(Vec3d p, Cursor& cursor) const;

  /// Whether a part other than `except` comes within `bound` of p (only parts whose bounding
  /// box does are searched).
  bool otherWithin(Vec3d p, std::size_t except, double bound, Cursor& cursor) const;

  std::size_t size() const { return parts_.size(); }
  const PlacedSurface& part(std::size_t k) const { return *parts_[k].surface; }

private:
  struct Part {
    const PlacedSurface* surface;
    std::unique_ptr<AabbTree> tree;
    BoundingBox box;
  };
  std::vector<Part> parts_;
};

} // namespace octaclay::core::detail
