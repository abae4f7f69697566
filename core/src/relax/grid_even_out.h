#pragma once

#include "octaclay/core/relax/relax.h"

namespace octaclay::core::detail {

/// evenOut (relax.h) for a torus or plane document. Each sample's parameter point u (its grid
/// position plus an offset, in samples) moves toward the points of its row's and its column's
/// neighbours, each weighted by the square of their edge's length on the surface (Jacobi
/// sweeps: at rest a stretched edge is shorter in the parameter domain, so samples gather where
/// the surface is stretched), coarse to fine: on a lattice of every 2^k-th sample first (8 cells
/// or more across the shorter side, every 64th sample at most), each finer level starting from
/// the coarser one's offsets interpolated. A torus's offsets wrap with its periods, a plane's
/// boundary samples slide along the boundary and its corners stay; a sweep's move that would
/// fold a cell in the parameter domain is undone there. Every layer is then resampled at the
/// new points on the old piecewise-linear surface (locateGridPoint), a torus's column W and row
/// H copied from column and row 0. The result is checked as evenOut checks the ball's (steps 1,
/// ½, ¼, ⅛; the longest edge may not grow, the stretched part may not lose samples, one must
/// improve, the surface may not move beyond the tolerances) with summarizeStretch (its grid
/// figures) for the stretch. Each of options.iterations (0 and 1 alike, at most 25 counted) is 100
/// sweeps a level; options.pinned is not read (the scripted strokes that pin samples are the ball's
/// keep detail).
EvenOutResult gridEvenOut(const Document& document, const RelaxOptions& options,
                          const EvenOutCheckOptions& check, const RelaxProgress& progress);

/// The unchecked even-out of a torus or plane (evenOutSamples): the full step.
Document gridEvenOutSamples(const Document& document, const RelaxOptions& options,
                            const RelaxProgress& progress);

} // namespace octaclay::core::detail
