// Based on: Ericson, "Real-Time Collision Detection" (2005), §5.1.5 closest point on a
// triangle and §6 bounding-volume hierarchies (median split, nearer-child-first traversal).
#include "detail/aabb_tree.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <thread>

namespace octaclay::core::detail {

namespace {

constexpr std::size_t leafSize = 4;

Vec3d closestPointOnSegment(Vec3d p, Vec3d a, Vec3d b) {
  const Vec3d ab = b - a;
  const double lengthSquared = dot(ab, ab);
  if (!(lengthSquared > 0)) return a;
  const double t = std::clamp(dot(p - a, ab) / lengthSquared, 0.0, 1.0);
  return a + ab * t;
}

double distanceSquared(Vec3d p, Vec3d q) {
  const Vec3d d = p - q;
  return dot(d, d);
}

// A degenerate triangle is the union of its three edges.
Vec3d closestPointOnEdges(Vec3d p, Vec3d a, Vec3d b, Vec3d c) {
  const std::array<Vec3d, 3> candidates{closestPointOnSegment(p, a, b),
                                        closestPointOnSegment(p, b, c),
                                        closestPointOnSegment(p, c, a)};
  Vec3d best = candidates[0];
  for (const Vec3d& q : candidates)
    if (distanceSquared(p, q) < distanceSquared(p, best)) best = q;
  return best;
}

} // namespace

Vec3d closestPointOnTriangle(Vec3d p, Vec3d a, Vec3d b, Vec3d c) {
  const Vec3d ab = b - a, ac = c - a;
  const Vec3d n = cross(ab, ac);
  if (!(dot(n, n) > 0)) return closestPointOnEdges(p, a, b, c);

  // Voronoi regions of the vertices, then of the edges, else the face (Ericson §5.1.5). The
  // ratio guards only matter when rounding makes a denominator vanish on slivers.
  const Vec3d ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;

  const Vec3d bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;

  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return d1 - d3 > 0 ? a + ab * (d1 / (d1 - d3)) : a;

  const Vec3d cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;

  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return d2 - d6 > 0 ? a + ac * (d2 / (d2 - d6)) : a;

  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const double denominator = (d4 - d3) + (d5 - d6);
    return denominator > 0 ? b + (c - b) * ((d4 - d3) / denominator) : b;
  }

  const double sum = va + vb + vc;
  if (!(sum > 0)) return closestPointOnEdges(p, a, b, c);
  return a + ab * (vb / sum) + ac * (vc / sum);
}

// What the median splits move around: a triangle's box centre and its index (16 bytes, so
// nth_element moves little); its box stays in Bounds, read where a leaf is made. The splits
// depend only on the comparisons of centres, so the tree is the one a wider item would give.
struct AabbTree::BuildItem {
  std::array<float, 3> centroid;
  std::uint32_t id;
};

struct AabbTree::Bounds {
  std::array<float, 3> min, max;
};

void AabbTree::fitLeaf(Node& leaf) const {
  const Vec3f& first = triangles_[leaf.index].a;
  leaf.min[0] = leaf.max[0] = first.x;
  leaf.min[1] = leaf.max[1] = first.y;
  leaf.min[2] = leaf.max[2] = first.z;
  for (std::uint32_t t = leaf.index; t < leaf.index + leaf.count; ++t)
    for (const Vec3f& v : {triangles_[t].a, triangles_[t].b, triangles_[t].c}) {
      const std::array<float, 3> p{v.x, v.y, v.z};
      for (std::size_t c = 0; c < 3; ++c) {
        leaf.min[c] = std::min(leaf.min[c], p[c]);
        leaf.max[c] = std::max(leaf.max[c], p[c]);
      }
    }
}

void AabbTree::unite(Node& parent, const Node& left, const Node& right) {
  for (int c = 0; c < 3; ++c) {
    parent.min[c] = std::min(left.min[c], right.min[c]);
    parent.max[c] = std::max(left.max[c], right.max[c]);
  }
}

// Below this many triangles a subtree is built on the thread that split it.
constexpr std::size_t kParallelSubtree = 1 << 15;

AabbTree::AabbTree(const TriangleMesh& mesh, unsigned threads) {
  const std::size_t count = mesh.triangles.size();
  assert(count < noTriangle);
  std::vector<BuildItem> items(count);
  std::vector<Bounds> bounds(count);
  for (std::size_t t = 0; t < count; ++t) {
    const auto& tri = mesh.triangles[t];
    const Vec3f& a = mesh.positions[tri[0]];
    const Vec3f& b = mesh.positions[tri[1]];
    const Vec3f& c = mesh.positions[tri[2]];
    Bounds& box = bounds[t];
    box.min = {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::min({a.z, b.z, c.z})};
    box.max = {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}), std::max({a.z, b.z, c.z})};
    BuildItem& item = items[t];
    for (int k = 0; k < 3; ++k)
      item.centroid[k] = 0.5f * (box.min[k] + box.max[k]);
    item.id = static_cast<std::uint32_t>(t);
  }
  if (count == 0) return;

  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  nodes_.reserve(count);
  build(items, 0, bounds, nodes_, threads);

  triangles_.resize(count);
  ids_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto& tri = mesh.triangles[items[i].id];
    triangles_[i] = {mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]};
    ids_[i] = items[i].id;
  }
}

AabbTree::AabbTree(const TriangleMesh& mesh, std::span<const std::uint32_t> order,
                   std::span<const std::uint32_t> blockStarts) {
  const std::size_t count = order.size(), blocks = blockStarts.size();
  assert(count == mesh.triangles.size() && count < noTriangle);
  assert(count == 0 || (blocks > 0 && blockStarts[0] == 0));
  if (count == 0) return;
  const auto blockEnd = [&](std::size_t b) {
    return b + 1 < blocks ? std::size_t(blockStarts[b + 1]) : count;
  };
  std::vector<BuildItem> items(blocks);
  for (std::size_t b = 0; b < blocks; ++b) {
    assert(blockStarts[b] < blockEnd(b));
    const Vec3f& first = mesh.positions[mesh.triangles[order[blockStarts[b]]][0]];
    std::array<float, 3> low{first.x, first.y, first.z}, high = low;
    for (std::size_t t = blockStarts[b]; t < blockEnd(b); ++t)
      for (const std::uint32_t v : mesh.triangles[order[t]]) {
        const Vec3f& p = mesh.positions[v];
        const std::array<float, 3> q{p.x, p.y, p.z};
        for (std::size_t k = 0; k < 3; ++k) {
          low[k] = std::min(low[k], q[k]);
          high[k] = std::max(high[k], q[k]);
        }
      }
    for (std::size_t k = 0; k < 3; ++k)
      items[b].centroid[k] = 0.5f * (low[k] + high[k]);
    items[b].id = static_cast<std::uint32_t>(b);
  }
  splitAtMedians(items);

  // The triangles block after block in the split order; each block's range kept in its order.
  triangles_.resize(count);
  ids_.resize(count);
  std::vector<std::uint32_t> firstOf(blocks), countOf(blocks);
  std::uint32_t at = 0;
  for (std::size_t p = 0; p < blocks; ++p) {
    const std::size_t b = items[p].id;
    firstOf[p] = at;
    countOf[p] = static_cast<std::uint32_t>(blockEnd(b) - blockStarts[b]);
    for (std::size_t t = blockStarts[b]; t < blockEnd(b); ++t, ++at) {
      const auto& tri = mesh.triangles[order[t]];
      triangles_[at] = {mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]};
      ids_[at] = order[t];
    }
  }
  nodes_.reserve(count / 2);
  // The nodes over the blocks [lo, hi) of the split order, split where splitAtMedians did.
  const auto emit = [&](auto&& self, std::size_t lo, std::size_t hi) -> std::uint32_t {
    if (hi - lo == 1) return buildInOrder(firstOf[lo], countOf[lo]);
    const auto node = static_cast<std::uint32_t>(nodes_.size());
    nodes_.push_back({});
    const std::size_t middle = lo + (hi - lo) / 2;
    self(self, lo, middle);
    Node made{};
    made.index = self(self, middle, hi);
    unite(made, nodes_[node + 1], nodes_[made.index]);
    nodes_[node] = made;
    return node;
  };
  emit(emit, 0, blocks);
}

std::size_t AabbTree::splitAtMedian(std::span<BuildItem> items) {
  // Along the axis where the centroids spread most; boxes are then the union of the children's,
  // so each level reads only the centroids.
  std::array<float, 3> low = items[0].centroid, high = items[0].centroid;
  for (const BuildItem& item : items)
    for (std::size_t k = 0; k < 3; ++k) {
      low[k] = std::min(low[k], item.centroid[k]);
      high[k] = std::max(high[k], item.centroid[k]);
    }
  std::size_t axis = 0;
  for (std::size_t k = 1; k < 3; ++k)
    if (high[k] - low[k] > high[axis] - low[axis]) axis = k;
  const std::size_t middle = items.size() / 2;
  std::nth_element(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(middle), items.end(),
                   [axis](const BuildItem& l, const BuildItem& r) {
                     return l.centroid[axis] < r.centroid[axis];
                   });
  return middle;
}

void AabbTree::splitAtMedians(std::span<BuildItem> items) {
  if (items.size() <= 1) return;
  const std::size_t middle = splitAtMedian(items);
  splitAtMedians(items.first(middle));
  splitAtMedians(items.subspan(middle));
}

std::uint32_t AabbTree::buildInOrder(std::uint32_t first, std::uint32_t count) {
  const auto node = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back({});
  Node made{};
  if (count <= leafSize) {
    made.count = count;
    made.index = first;
    fitLeaf(made);
  } else {
    const std::uint32_t half = count / 2;
    buildInOrder(first, half);
    made.index = buildInOrder(first + half, count - half);
    unite(made, nodes_[node + 1], nodes_[made.index]);
  }
  nodes_[node] = made;
  return node;
}

void AabbTree::refit(const TriangleMesh& mesh) {
  for (std::size_t i = 0; i < triangles_.size(); ++i) {
    const auto& tri = mesh.triangles[ids_[i]];
    triangles_[i] = {mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]};
  }
  // Children come after their parent in the array: from the last node back, each box is its
  // triangles' (a leaf) or its two children's.
  for (std::size_t k = nodes_.size(); k-- > 0;) {
    Node& node = nodes_[k];
    if (node.count > 0)
      fitLeaf(node);
    else
      unite(node, nodes_[k + 1], nodes_[node.index]);
  }
}

void AabbTree::build(std::span<BuildItem> items, std::uint32_t first,
                     std::span<const Bounds> bounds, std::vector<Node>& nodes, unsigned threads) {
  const std::size_t node = nodes.size();
  nodes.push_back({});

  if (items.size() <= leafSize) {
    const Bounds& b0 = bounds[items[0].id];
    Node leaf{{b0.min[0], b0.min[1], b0.min[2]},
              static_cast<std::uint32_t>(items.size()),
              {b0.max[0], b0.max[1], b0.max[2]},
              first};
    for (const BuildItem& item : items) {
      const Bounds& b = bounds[item.id];
      for (int k = 0; k < 3; ++k) {
        leaf.min[k] = std::min(leaf.min[k], b.min[k]);
        leaf.max[k] = std::max(leaf.max[k], b.max[k]);
      }
    }
    nodes[node] = leaf;
    return;
  }

  const std::size_t middle = splitAtMedian(items);
  const std::span<BuildItem> leftItems = items.first(middle), rightItems = items.subspan(middle);
  const std::uint32_t rightFirst = first + static_cast<std::uint32_t>(middle);
  std::size_t right = 0;
  if (threads > 1 && items.size() >= kParallelSubtree) {
    // The right subtree on its own thread into its own array, appended after the left one
    // with its child links moved by where it lands: the same array as one thread builds.
    std::vector<Node> rightNodes;
    rightNodes.reserve(rightItems.size());
    std::thread worker(
        [&] { build(rightItems, rightFirst, bounds, rightNodes, threads - threads / 2); });
    build(leftItems, first, bounds, nodes, threads / 2);
    worker.join();
    right = nodes.size();
    for (Node& n : rightNodes)
      if (n.count == 0) n.index += static_cast<std::uint32_t>(right);
    nodes.insert(nodes.end(), rightNodes.begin(), rightNodes.end());
  } else {
    build(leftItems, first, bounds, nodes, 1);
    right = nodes.size();
    build(rightItems, rightFirst, bounds, nodes, 1);
  }

  Node parent{};
  unite(parent, nodes[node + 1], nodes[right]);
  parent.index = static_cast<std::uint32_t>(right);
  nodes[node] = parent;
}

double AabbTree::triangleDistanceSquared(Vec3d p, std::uint32_t triangle) const {
  const Triangle& t = triangles_[triangle];
  return distanceSquared(p, closestPointOnTriangle(p, Vec3d(t.a), Vec3d(t.b), Vec3d(t.c)));
}

AabbTree::Hit AabbTree::closest(Vec3d p, std::uint32_t hint, std::uint32_t maxLeaves) const {
  Hit best;
  if (nodes_.empty()) return best;
  if (hint < triangles_.size()) best = {triangleDistanceSquared(p, hint), hint};

  const double point[3] = {p.x, p.y, p.z};
  // The squared distance from p to the box [lo, hi].
  const auto boxDistanceSquared = [&](const float* lo, const float* hi) {
    double sum = 0;
    for (int k = 0; k < 3; ++k) {
      const double below = static_cast<double>(lo[k]) - point[k];
      const double above = point[k] - static_cast<double>(hi[k]);
      const double gap = std::max({below, above, 0.0});
      sum += gap * gap;
    }
    return sum;
  };
  const auto nodeDistanceSquared = [&](const Node& node) {
    return boxDistanceSquared(node.min, node.max);
  };
  const auto cornerBoxDistanceSquared = [&](const Triangle& t) {
    const float lo[3] = {std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}),
                         std::min({t.a.z, t.b.z, t.c.z})};
    const float hi[3] = {std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}),
                         std::max({t.a.z, t.b.z, t.c.z})};
    return boxDistanceSquared(lo, hi);
  };

  // Median splits keep the depth below 32, and each level pushes at most one entry.
  struct Pending {
    std::uint32_t node;
    double distanceSquared;
  };
  std::array<Pending, 64> stack;
  std::size_t pending = 0;
  if (nodeDistanceSquared(nodes_[0]) < best.distanceSquared) stack[pending++] = {0, 0.0};

  std::uint32_t leaves = 0;
  while (pending > 0) {
    const Pending top = stack[--pending];
    if (!(top.distanceSquared < best.distanceSquared)) continue;
    std::uint32_t current = top.node;
    for (;;) {
      const Node& node = nodes_[current];
      if (node.count > 0) {
        for (std::uint32_t t = node.index; t < node.index + node.count; ++t) {
          // The hint was measured first, and a triangle whose corners' box lies no nearer than
          // the best cannot do better: neither changes what is found (only a nearer one does).
          // The box's distance is taken a billionth short, far beyond both figures' rounding.
          if (t == hint ||
              !(cornerBoxDistanceSquared(triangles_[t]) * (1 - 1e-9) < best.distanceSquared))
            continue;
          const double d = triangleDistanceSquared(p, t);
          if (d < best.distanceSquared) best = {d, t};
        }
        if (++leaves >= maxLeaves) {
          best.bounded = pending > 0;
          best.leaves = leaves;
          return best;
        }
        break;
      }
      std::uint32_t nearChild = current + 1, farChild = node.index;
      double nearDistance = nodeDistanceSquared(nodes_[nearChild]);
      double farDistance = nodeDistanceSquared(nodes_[farChild]);
      if (farDistance < nearDistance) {
        std::swap(nearChild, farChild);
        std::swap(nearDistance, farDistance);
      }
      if (!(nearDistance < best.distanceSquared)) break;
      if (farDistance < best.distanceSquared) stack[pending++] = {farChild, farDistance};
      current = nearChild;
    }
  }
  best.leaves = leaves;
  return best;
}

} // namespace octaclay::core::detail
