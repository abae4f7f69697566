#pragma once

// The full-resolution export's vertices: the image's samples every `step` samples, unwelded
// (DESIGN.md, "The geometry image"), with extractMesh's triangles, on every topology.

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/sample_grid.h"
#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// The exported vertices: vertex (i, j) of the (Mw+1)×(Mh+1) grid is image sample (i·step,
/// j·step), numbered j·(Mw+1) + i, with Mw = W/step and Mh = H/step. Positions and normals come
/// from the canonical sample, so identified vertices are bit-equal in the file even before
/// seaming.
struct ExportGrid {
  SampleGrid image; ///< the document's topology and W × H
  int mw = 0, mh = 0, step = 1;
  std::vector<Vec3f> positions, normals;

  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>((mw + 1) * (mh + 1)); }
  // Texture coordinates of vertex (i, j): the centre of texel (i·step, j·step) of the
  // (W+1)×(H+1) maps, u to the right and v down the image (glTF's convention; OBJ's is 1 − v).
  float u(int i) const {
    return (static_cast<float>(i * step) + 0.5f) / static_cast<float>(image.width + 1);
  }
  float v(int j) const {
    return (static_cast<float>(j * step) + 0.5f) / static_cast<float>(image.height + 1);
  }
};

/// The grid of `doc` every `step` samples. Throws Error(InvalidArgument) when step is not a
/// power of two leaving at least the topology's smallest grid (2 cells on the ball and a plane,
/// kMinTorusSize on a torus) or a layer's texel count disagrees with the image.
ExportGrid makeExportGrid(const Document& doc, int step);

/// Throws Error(InvalidArgument) unless layer is uniform or holds (W+1)×(H+1) texels of its
/// channels.
void requireLayer(const Layer& layer, const SampleGrid& image);

/// The vertices' texture coordinates, in glTF's convention (v down) or OBJ's (vUp).
std::vector<Vec2f> gridTexcoords(const ExportGrid& grid, bool vUp);

/// The 2·Mw·Mh triangles, counter-clockwise seen from outside, split as extractMesh splits them.
std::vector<std::array<std::uint32_t, 3>> gridTriangles(const ExportGrid& grid);

/// For each grid vertex, the index of the surface vertex it is in extractMesh(image, step):
/// identified samples (the ball's seams, the torus's last row and column) share one.
std::vector<std::uint32_t> weldedVertices(const ExportGrid& grid, std::uint32_t& weldedCount);

} // namespace octaclay::core::detail
