#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// A 3-vector of doubles for exact-enough distance arithmetic on float positions.
struct Vec3d {
  double x = 0, y = 0, z = 0;

  Vec3d() = default;
  constexpr Vec3d(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}
  explicit constexpr Vec3d(Vec3f v) : x(v.x), y(v.y), z(v.z) {}

  friend Vec3d operator+(Vec3d a, Vec3d b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
  friend Vec3d operator-(Vec3d a, Vec3d b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
  friend Vec3d operator*(Vec3d a, double s) { return {a.x * s, a.y * s, a.z * s}; }
  friend Vec3d operator*(double s, Vec3d a) { return a * s; }
  friend bool operator==(Vec3d a, Vec3d b) = default;
};

inline double dot(Vec3d a, Vec3d b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3d cross(Vec3d a, Vec3d b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The point of triangle abc (edges and interior) closest to p. Degenerate triangles (a
/// segment or a point) are handled as the union of their edges.
Vec3d closestPointOnTriangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c);

/// A binary bounding-volume hierarchy over a mesh's triangles that answers exact
/// closest-point queries. Median split on the longest centroid axis, at most 4 triangles a
/// leaf, nodes in one depth-first array. Const queries only, so any number of threads may query
/// it at once (refit() excepted).
class AabbTree {
public:
  /// A triangle's corners, copied out of the mesh in leaf order.
  struct Triangle {
    Vec3f a, b, c;
  };

  static constexpr std::uint32_t noTriangle = std::numeric_limits<std::uint32_t>::max();

  /// Result of closest(): squared distance and the index into triangles() that attains it.
  struct Hit {
    double distanceSquared = std::numeric_limits<double>::infinity();
    std::uint32_t triangle = noTriangle;
    /// The search stopped at its leaf budget: distanceSquared is an upper bound, not exact.
    bool bounded = false;
    std::uint32_t leaves = 0; ///< leaves visited: the query's work
  };

  /// Builds the tree over all of mesh's triangles in O(T log T), the subtrees of its first
  /// splits on up to `threads` threads (0: one per hardware thread); the tree is the same
  /// whatever the count. Precondition: every index is below mesh.positions.size() and the
  /// referenced positions are finite (compareSurfaces checks this and throws before building).
  explicit AabbTree(const TriangleMesh& mesh, unsigned threads = 0);

  /// Builds the tree over the mesh's triangles taken in `order` (every triangle index once), cut
  /// into blocks where `blockStarts` says (ascending, the first 0): the median splits above over
  /// the blocks' boxes, and inside a block its range of the order split at the middle, in
  /// O(T + B log B) on one thread. For a geometry image's cells in tiles, each tile's cells in
  /// Z order, the blocks are quadtrees of the grid and the tree is built in a fraction of the
  /// time with about as quick queries (as exact; a whole image's cells in Z order as one block
  /// would make loose boxes where a sheet folds: twice the leaves per query on a ridge).
  AabbTree(const TriangleMesh& mesh, std::span<const std::uint32_t> order,
           std::span<const std::uint32_t> blockStarts);

  /// The closest point of the mesh to p, by branch and bound (nearer child first, subtrees
  /// pruned by squared box distance). `hint`, an index into triangles() or noTriangle, seeds
  /// the bound: pass the previous query's triangle when queries are spatially coherent.
  /// An empty tree returns a Hit with infinite distance. maxLeaves bounds the work: after that
  /// many leaves the best so far is returned with `bounded` set (on a self-intersecting tangle
  /// every box overlaps every query and an exact search visits the whole tree).
  Hit closest(Vec3d p, std::uint32_t hint = noTriangle,
              std::uint32_t maxLeaves = std::numeric_limits<std::uint32_t>::max()) const;

  /// Moves the tree onto mesh: the mesh it was built from (the same triangles, in the same
  /// order) with its positions changed. The splits stay and every box is made tight again in
  /// O(T), about a tenth of a build: for a surface whose samples slid a little (keep detail's
  /// check), queries stay about as fast as on a rebuilt tree. Not while another thread queries.
  void refit(const TriangleMesh& mesh);

  /// The triangles in leaf order (consecutive triangles are close in space).
  std::span<const Triangle> triangles() const { return triangles_; }
  /// For each entry of triangles(), its index in the mesh's triangle list.
  std::span<const std::uint32_t> triangleIds() const { return ids_; }

private:
  // Interior nodes have count 0, their left child right after them and `index` the right
  // child; leaves hold triangles()[index, index + count).
  struct Node {
    float min[3];
    std::uint32_t count;
    float max[3];
    std::uint32_t index;
  };
  struct BuildItem;
  struct Bounds;

  /// Appends to `nodes` the subtree over items (triangles()[first, first + items.size())),
  /// its right subtrees built on new threads while `threads` > 1.
  static void build(std::span<BuildItem> items, std::uint32_t first, std::span<const Bounds> bounds,
                    std::vector<Node>& nodes, unsigned threads);
  /// Appends to nodes_ the subtree over triangles()[first, first + count), split at the middle;
  /// returns its root's index.
  std::uint32_t buildInOrder(std::uint32_t first, std::uint32_t count);
  /// Makes a leaf's box its triangles' (leaf.index and leaf.count set).
  void fitLeaf(Node& leaf) const;
  /// Makes parent's box the union of its children's.
  static void unite(Node& parent, const Node& left, const Node& right);
  /// Splits items at the median centroid along the axis where the centroids spread most (the
  /// first half below it); returns where the second half starts.
  static std::size_t splitAtMedian(std::span<BuildItem> items);
  /// Orders items by the median splits of build(), recursively, and nothing more.
  static void splitAtMedians(std::span<BuildItem> items);
  double triangleDistanceSquared(Vec3d p, std::uint32_t triangle) const;

  std::vector<Node> nodes_;
  std::vector<Triangle> triangles_;
  std::vector<std::uint32_t> ids_;
};

} // namespace octaclay::core::detail
