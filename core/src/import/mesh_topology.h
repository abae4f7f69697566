// The topology checks of validation: edges, manifoldness, orientation, components, holes and
// pinch vertices of a triangle list, in one pass of sorts and union-finds.
#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace octaclay::core::detail {

using Tri = std::array<std::uint32_t, 3>;
inline constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Topology of a mesh whose faces have three distinct corners. Edge "slots" are 3f + k: the edge
// from corner k of face f to corner k + 1.
struct Analysis {
  std::size_t edges = 0;
  std::size_t nonManifoldEdges = 0;
  std::uint32_t exampleA = 0, exampleB = 0; ///< vertices of one non-manifold edge
  std::size_t exampleFaces = 0;
  bool orientable = true;
  std::vector<char> flip; ///< per face: turn it to agree with its component's majority
  std::size_t components = 0;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> holeEdges; ///< (from, to) as a fill
                                                                  ///< triangle must run them
  std::size_t holes = 0;
  std::size_t pinchVertices = 0;
  std::uint32_t firstPinch = 0; ///< lowest-numbered pinch vertex
  std::size_t firstPinchFans = 0;
};

Analysis analyze(const TriangleMesh& mesh);

} // namespace octaclay::core::detail
