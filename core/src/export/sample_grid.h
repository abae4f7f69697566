#pragma once

// The full-resolution export's vertices: the image's samples every `step` samples, unwelded
// (DESIGN.md, "The geometry image"), with extractMesh's triangles.

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// The exported vertices: sample (i, j) of the (M+1)² grid is image sample (i·step, j·step),
/// numbered j·(M+1) + i. Positions and normals come from the canonical sample so identified
/// vertices are bit-equal in the file even before seaming.
struct SampleGrid {
  int n = 0, m = 0, step = 1;
  std::vector<Vec3f> positions, normals;

  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>((m + 1) * (m + 1)); }
  // Texture coordinates of vertex (i, j): the centre of texel (i·step, j·step), u to the right
  // and v down the image (glTF's convention; OBJ's is 1 − v).
  float u(int i) const { return (static_cast<float>(i * step) + 0.5f) / static_cast<float>(n + 1); }
  float v(int j) const { return (static_cast<float>(j * step) + 0.5f) / static_cast<float>(n + 1); }
};

/// The grid of `doc` every `step` samples. Throws Error(InvalidArgument) when step is not a
/// power of two with N/step ≥ 2 or a layer's texel count disagrees with N.
SampleGrid makeGrid(const Document& doc, int step);

/// Throws Error(InvalidArgument) unless layer is uniform or holds (N+1)² texels of its channels.
void requireLayer(const Layer& layer, int n);

/// The vertices' texture coordinates, in glTF's convention (v down) or OBJ's (vUp).
std::vector<Vec2f> gridTexcoords(const SampleGrid& grid, bool vUp);

/// The 2M² triangles, counter-clockwise seen from outside, split as extractMesh splits them.
std::vector<std::array<std::uint32_t, 3>> gridTriangles(int m);

} // namespace octaclay::core::detail
