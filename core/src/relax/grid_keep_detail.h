#pragma once

#include "octaclay/core/relax/relax.h"

namespace octaclay::core::detail {

/// What relaxChangedStep measured of the whole surface before it hands a torus or plane here.
struct KeepDetailFigures {
  float stretchedEdge = 0; ///< an edge longer than this is stretched (stretchedEdgeLimit)
  double diagonal = 0;     ///< the bounding box's, the tolerances' unit
  float medianEdge = 0;    ///< the surface's median grid edge
};

/// relaxChangedStep (relax.h) for a torus or plane document: `changed` holds (W+1)×(H+1)
/// samples. Nothing happens unless a changed sample has a grid edge over figures.stretchedEdge.
/// Then the samples within `margin` samples of a changed one (Chebyshev distance through a
/// torus's periods, clamped at a sheet's edge; pins and a sheet's corners excepted) move in the
/// parameter domain by Even Out's length-squared-weighted sweeps (parameter_field), coarse to
/// fine over the freed samples alone, the others held: samples gather onto what the stroke
/// pulled. Every layer is resampled there on the old surface; every other sample of every layer
/// keeps its bits. The move is kept only within the relaxation's tolerance (0.01 % RMS, 0.1 %
/// Hausdorff of the diagonal, of which the check may use 80 %: its points are a sample of each
/// triangle), measured both ways over every cell with a moved corner by exact closest points
/// (each triangle's points at thirds of its barycentric coordinates, finer on a stretched
/// facet), and only when no moved cell gets an edge longer than the longest it had. The full
/// move is tried, then 1/2, 1/4 and 1/8 of it; where the full move cuts too deep the corners of
/// the cells it cut are held and the flow solved again (twice at most), and the try that moves
/// the samples farthest wins; else nothing moves. Returns the change as an undo step over the
/// image's W+1 × H+1 tiles.
EditStep gridRelaxChangedStep(const Document& document, const std::vector<std::uint8_t>& changed,
                              int margin, std::string label, const RelaxOptions& options,
                              const KeepDetailFigures& figures);

} // namespace octaclay::core::detail
