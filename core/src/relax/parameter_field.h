#pragma once

// A torus's or plane's parameter points (each sample's grid position plus an offset, in
// samples) on a lattice of every stride-th sample, and the sweeps that relax them: shared by
// Even Out (grid_even_out) and keep detail (grid_keep_detail) on these topologies.

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/sample_grid.h"

#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace octaclay::core::detail {

struct Offset {
  double x = 0, y = 0;
};

/// The canonical samples of a lattice over the grid, every `stride`-th sample (a torus's i < W,
/// j < H; all of a plane's), their offsets in full-resolution samples, and which may move.
struct ParameterField {
  SampleGrid grid;
  int stride = 1;
  int columns = 0, rows = 0;        ///< canonical lattice samples
  int cellsWide = 0, cellsHigh = 0; ///< lattice cells: W / stride, H / stride
  std::vector<Offset> offset;
  /// Per lattice sample, 1 where it may move; empty: every one may (a sheet's corners never do).
  std::vector<std::uint8_t> free;

  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(i);
  }
  bool torus() const { return grid.topology == Topology::Torus; }
  /// Lattice sample (i, j), for any (i, j) within one period: its canonical one.
  std::pair<int, int> canonicalOf(int i, int j) const;
  /// Lattice sample (i, j)'s parameter point in full-resolution samples, unwrapped.
  Offset point(int i, int j) const;
};

/// The old piecewise-linear surface at parameter point u (in samples, anywhere: wrapped by the
/// topology).
Vec3f surfaceAt(const GeometryImage& image, Offset u);

/// A field of zero offsets, every `stride`-th sample (stride divides W and H).
ParameterField emptyField(const SampleGrid& grid, int stride);

/// The field on the lattice twice as fine: each offset interpolated bilinearly from the coarse
/// lattice's (through the torus's periods; a sheet's boundary samples from its boundary's, so
/// they stay on it). Every fine sample may move.
ParameterField finer(const ParameterField& coarse);

/// `sweeps` Jacobi sweeps of the length-squared-weighted neighbour centre over the field's free
/// samples: each moves a step toward its row's neighbours' weighted centre along i and its
/// column's along j (a sheet's boundary samples slide along it, its corners stay), a move that
/// would fold a cell in the parameter domain undone there. swept(k) after each sweep k.
void sweepLevel(const GeometryImage& image, ParameterField& field, int sweeps,
                const std::function<void(int)>& swept);

/// Every layer of `document` at the full-resolution field's points, offsets scaled by `step`,
/// on the old piecewise-linear surface (locateGridPoint); a torus's column W and row H copied
/// from column and row 0. A sample of zero offset keeps its bits.
Document resampled(const Document& document, const ParameterField& field, double step);

} // namespace octaclay::core::detail
