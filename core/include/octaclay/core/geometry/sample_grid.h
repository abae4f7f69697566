#pragma once

#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/topology.h"

#include <array>

namespace octaclay::core {

/// The shape of an image's vertex-centred grid: its topology and its width W and height H in
/// cells, so (W+1)×(H+1) samples. Every topology stores the last column and row: the
/// octahedral ball folds them onto the first half of its sides, the torus identifies them with
/// the first column and row (so a texture read, a subsampled level and a tile see every cell
/// without a modulo, as on the ball), the plane's are its boundary.
struct SampleGrid {
  Topology topology = Topology::Octahedral;
  int width = 0, height = 0;
  friend bool operator==(const SampleGrid&, const SampleGrid&) = default;
};

/// Smallest side of a torus image: below 4 cells a ring's edges join the same two vertices twice.
inline constexpr int kMinTorusSize = 4;

/// True when W and H are valid sizes (powers of two, 2 … 8192) for the topology: square for
/// the octahedral ball, both at least kMinTorusSize for a torus.
bool isValidGrid(const SampleGrid& grid);
/// Throws Error(InvalidArgument) naming the sizes and topology unless isValidGrid.
void requireValidGrid(const SampleGrid& grid);

/// The grid sample that integer position s stands for: the octahedral fold, the torus's period
/// (W, H) (canonical samples i < W, j < H), the plane's clamp onto its boundary.
Sample wrap(const SampleGrid& grid, Sample s);

/// The grid samples that are the same vertex as s (inside the grid), s included: 1, 2 or 4.
int identifiedSamples(const SampleGrid& grid, Sample s, std::array<Sample, 4>& out);

/// The two triangles of cell (i, j), counter-clockwise in (i, j). The torus and plane split
/// every cell along its anti-diagonal (i, j+1)–(i+1, j); the ball as cellTriangles(n, …).
std::array<std::array<Sample, 3>, 2> cellTriangles(const SampleGrid& grid, int i, int j);

/// Triangles incident to position s, counter-clockwise, each rotated so s comes first; the
/// plane's only those of cells inside it (fewer on its boundary). Unwrapped positions.
int incidentTriangles(const SampleGrid& grid, Sample s, std::array<std::array<Sample, 3>, 6>& out);

/// The number of distinct vertices of the grid subsampled to M_w × M_h cells: M²+2 for the ball,
/// M_w·M_h for the torus, (M_w+1)(M_h+1) for the plane.
long long vertexCount(Topology topology, int cellsWide, int cellsHigh);

} // namespace octaclay::core
