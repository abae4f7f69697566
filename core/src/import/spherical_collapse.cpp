#include "import/spherical_collapse.h"

#include <Eigen/Core>
#include <queue>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace octaclay::core::detail {

namespace {

using Quadric = Eigen::Matrix4d;

} // namespace

std::vector<Collapse> simplify(CollapsibleMesh& mesh, const Points& x, int target,
                               const std::function<void(double)>& progress) {
  const int n = static_cast<int>(x.size());
  std::vector<Quadric> quadrics(static_cast<std::size_t>(n), Quadric::Zero());
  double meanArea = 0;
  for (const Tri& t : mesh.faces()) {
    const Vec3d normal = (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]);
    const double twiceArea = normal.norm();
    meanArea += 0.5 * twiceArea;
    if (twiceArea <= 0) continue;
    const Vec3d unit = normal / twiceArea;
    Eigen::Vector4d plane;
    plane << unit, -unit.dot(x[t[0]]);
    const Quadric q = 0.5 * twiceArea * plane * plane.transpose();
    for (int w : t)
      quadrics[w] += q;
  }
  meanArea /= static_cast<double>(std::max<std::size_t>(1, mesh.faces().size()));

  struct Candidate {
    double cost;
    int u, v;
    std::uint32_t stampU, stampV;
    bool operator<(const Candidate& o) const { return cost > o.cost; }
  };
  std::vector<std::uint32_t> stamp(static_cast<std::size_t>(n), 0);
  std::priority_queue<Candidate> queue;
  const auto push = [&](int u, int v) {
    Eigen::Vector4d p;
    p << x[v], 1.0;
    const double length2 = (x[u] - x[v]).squaredNorm();
    const double cost = p.dot((quadrics[u] + quadrics[v]) * p) + 0.05 * length2 * length2 +
                        1e-3 * meanArea * length2;
    queue.push({cost, u, v, stamp[u], stamp[v]});
  };
  for (const Tri& t : mesh.faces())
    for (int k = 0; k < 3; ++k) {
      push(t[k], t[(k + 1) % 3]);
    }

  std::vector<Collapse> collapses;
  std::vector<int> nu, nv, around;
  int remaining = n;
  const auto foldsOver = [&](int u, int v) {
    for (int f : mesh.facesOf(u)) {
      const Tri& t = mesh.faces()[f];
      if (t[0] == v || t[1] == v || t[2] == v) continue;
      Vec3d p[3], q[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = x[t[k]];
        q[k] = t[k] == u ? x[v] : x[t[k]];
      }
      const Vec3d before = (p[1] - p[0]).cross(p[2] - p[0]);
      const Vec3d after = (q[1] - q[0]).cross(q[2] - q[0]);
      const double a = after.norm(), b = before.norm();
      if (!(a > 1e-12 * b)) return true;
      if (before.dot(after) < 0.35 * a * b) return true;
      // No needles: the new triangle's area against its longest edge squared.
      double longest = 0;
      for (int k = 0; k < 3; ++k)
        longest = std::max(longest, (q[(k + 1) % 3] - q[k]).squaredNorm());
      if (a < 0.02 * longest) return true;
    }
    return false;
  };
  int popped = 0;
  while (remaining > target && !queue.empty()) {
    const Candidate c = queue.top();
    queue.pop();
    if ((++popped & 0xffff) == 0) progress(double(n - remaining) / double(n - target));
    if (!mesh.present(c.u) || !mesh.present(c.v)) continue;
    if (stamp[c.u] != c.stampU || stamp[c.v] != c.stampV) continue;
    if (!mesh.topologyAllows(c.u, c.v, nu, nv) || foldsOver(c.u, c.v)) continue;
    collapses.push_back(mesh.collapse(c.u, c.v));
    --remaining;
    quadrics[c.v] += quadrics[c.u];
    mesh.neighbours(c.v, nv);
    ++stamp[c.v];
    for (int w : nv)
      ++stamp[w];
    for (int w : nv) {
      mesh.neighbours(w, around);
      for (int z : around) {
        push(w, z);
        push(z, w);
      }
    }
  }
  return collapses;
}

} // namespace octaclay::core::detail
