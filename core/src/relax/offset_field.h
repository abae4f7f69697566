#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/relax/relax.h"

#include <array>
#include <cstdint>
#include <vector>

namespace octaclay::core::detail {

/// How far each sample moves in the image's parameter domain, in sample units: sample (i, j)
/// will show the old surface at (i, j) + offset. Identified border samples hold offsets that
/// are images of one another under the tiling's half-turns, so they stay one vertex.
struct OffsetField {
  int n = 0;
  std::vector<std::array<float, 2>> offset; ///< (N+1)², row-major
  std::vector<std::uint8_t> free;           ///< 1 where the sample may move
  std::vector<Sample> pins;                 ///< the samples pin() was given

  explicit OffsetField(int size);
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
           static_cast<std::size_t>(i);
  }
  /// Frees every sample except the four side midpoints (the tiling's half-turn centres, which
  /// cannot move without tearing the seam).
  void freeAll();
  /// Frees the samples strictly inside rect (which may reach out of the image: its samples
  /// there are those of the tiling, wrapped into it) and the samples identified with them.
  void freeInside(TexelRect rect);
  /// Pins sample s and the samples identified with it; the coarse levels of solveOffsets keep
  /// the offset interpolated at s zero too, so that the pin tears nothing when they are refined.
  void pin(Sample s);
};

/// Moves the free samples toward where the surface of `image` is stretched, coarse to fine,
/// keeping every cell unfolded and growing no grid edge beyond edgeCap (object units) by taking
/// samples away. coarseArcs: the coarse lattices (step ≥ N/32) measure their edges along the
/// surface, not as chords that step over a limb pulled out between their samples (what a
/// local relaxation needs to find a thin limb; the even-out does as well without, at 2/3 the
/// time). Returns false when progress cancelled.
bool solveOffsets(const GeometryImage& image, OffsetField& field, int fineIterations,
                  double edgeCap, bool coarseArcs, const RelaxProgress& progress);

/// Texel (i, j) of layer after resampling at the field's parameter points, editLayerChannels
/// floats into out: a sample that did not move keeps its value; identified samples get the
/// same bits (their canonical sample's point).
void resampleTexel(const Document& from, const OffsetField& field, EditLayer layer, int i, int j,
                   float* out);

/// Writes into `to` (a copy of `from`) every layer resampled at the field's parameter points
/// (resampleTexel for each moved sample): samples that did not move keep their texels bit for
/// bit; identified samples stay bit-equal.
void resampleDocument(const Document& from, const OffsetField& field, Document& to);

} // namespace octaclay::core::detail
