// The simplification half of the coarse-to-fine spherical parameterization
// (spherical_progressive.cpp): a mesh under half-edge collapses, and the quadric-error
// simplification that records them for the refinement to undo.
#pragma once

#include "import/spherical_geometry.h"

#include <functional>
#include <vector>

namespace octaclay::core::detail {

// One half-edge collapse u → v: u disappears into v. `faces` are u's faces before it; the two
// that also hold v die, the others get v in place of u.
struct Collapse {
  int u = 0, v = 0;
  std::vector<int> faces;
};

// A triangle mesh under half-edge collapses and their undoing (in reverse order only).
class CollapsibleMesh {
public:
  CollapsibleMesh(int vertexCount, const std::vector<Tri>& triangles)
      : faces_(triangles), alive_(triangles.size(), 1),
        vertexFaces_(static_cast<std::size_t>(vertexCount)) {
    for (int f = 0; f < static_cast<int>(faces_.size()); ++f)
      for (int w : faces_[f])
        vertexFaces_[w].push_back(f);
  }

  const std::vector<Tri>& faces() const { return faces_; }
  const std::vector<int>& facesOf(int v) const { return vertexFaces_[v]; }
  bool present(int v) const { return !vertexFaces_[v].empty(); }

  // The vertices sharing a face with v, unordered, without repeats.
  void neighbours(int v, std::vector<int>& out) const {
    out.clear();
    for (int f : vertexFaces_[v])
      for (int w : faces_[f])
        if (w != v) out.push_back(w);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  }

  // Whether collapsing u → v keeps a closed manifold genus-0 mesh without tiny valences: the
  // link condition (u and v share exactly the two neighbours opposite their edge) and valence
  // at least 3 (4 for the opposite vertices, which lose one).
  bool topologyAllows(int u, int v, std::vector<int>& nu, std::vector<int>& nv) const {
    int shared = 0;
    std::array<int, 2> opposite{-1, -1};
    for (int f : vertexFaces_[u]) {
      const Tri& t = faces_[f];
      if (t[0] != v && t[1] != v && t[2] != v) continue;
      if (shared == 2) return false;
      for (int w : t)
        if (w != u && w != v) opposite[shared] = w;
      ++shared;
    }
    if (shared != 2) return false;
    if (vertexFaces_[opposite[0]].size() <= 3 || vertexFaces_[opposite[1]].size() <= 3)
      return false;
    if (vertexFaces_[u].size() + vertexFaces_[v].size() < 7) return false;
    neighbours(u, nu);
    neighbours(v, nv);
    std::size_t common = 0;
    for (std::size_t i = 0, j = 0; i < nu.size() && j < nv.size();) {
      if (nu[i] < nv[j]) {
        ++i;
      } else if (nv[j] < nu[i]) {
        ++j;
      } else {
        ++common;
        ++i;
        ++j;
      }
    }
    return common == 2;
  }

  Collapse collapse(int u, int v) {
    Collapse c{u, v, vertexFaces_[u]};
    for (int f : c.faces) {
      Tri& t = faces_[f];
      if (t[0] == v || t[1] == v || t[2] == v) {
        alive_[f] = 0;
        for (int w : t)
          if (w != u) erase(vertexFaces_[w], f);
      } else {
        for (int& w : t)
          if (w == u) w = v;
        vertexFaces_[v].push_back(f);
      }
    }
    vertexFaces_[u].clear();
    return c;
  }

  void undo(const Collapse& c) {
    for (int f : c.faces) {
      Tri& t = faces_[f];
      if (!alive_[f]) {
        alive_[f] = 1;
        for (int w : t)
          if (w != c.u) vertexFaces_[w].push_back(f);
      } else {
        for (int& w : t)
          if (w == c.v) w = c.u;
        erase(vertexFaces_[c.v], f);
      }
      vertexFaces_[c.u].push_back(f);
    }
  }

  std::vector<Tri> aliveFaces() const {
    std::vector<Tri> out;
    for (std::size_t f = 0; f < faces_.size(); ++f)
      if (alive_[f]) out.push_back(faces_[f]);
    return out;
  }

private:
  static void erase(std::vector<int>& list, int value) {
    const auto it = std::find(list.begin(), list.end(), value);
    if (it != list.end()) {
      *it = list.back();
      list.pop_back();
    }
  }

  std::vector<Tri> faces_;
  std::vector<char> alive_;
  std::vector<std::vector<int>> vertexFaces_;
};

// Simplifies by quadric-error half-edge collapses (with an edge-length term so that flat
// regions thin out evenly) to about `target` vertices; collapses that would fold a face over
// by more than ~70° in space are refused.
std::vector<Collapse> simplify(CollapsibleMesh& mesh, const Points& x, int target,
                               const std::function<void(double)>& progress);

} // namespace octaclay::core::detail
