#pragma once

#include "octaclay/core/relax/relax.h"

#include <cstddef>
#include <functional>

namespace octaclay::core::detail {

/// What a solved even-out (the ball's offset field or a torus's or plane's parameter field)
/// gives evenOut's checked tries.
struct SolvedEvenOut {
  std::size_t vertices = 0; ///< the surface's distinct vertices
  StretchSummary before;    ///< summarizeStretch of the document
  /// The document resampled at `step` times the solved move (from the original each time).
  std::function<Document(double step)> resample;
  /// How many samples show the old stretched part at `step` (0: before the move).
  std::function<std::size_t(double step)> stretchedShown;
};

/// evenOut's tries (relax.h) for either solve: each step of check.steps in turn, kept when the
/// longest edge does not grow, the stretched part keeps its samples, one of the two improves by
/// 1 % and the surface moves within the tolerances; else the document unchanged with the first
/// reason. progress gets solveShare … 1 over the tries.
EvenOutResult tryEvenOutSteps(const Document& document, const SolvedEvenOut& solved,
                              const EvenOutCheckOptions& check, const RelaxProgress& progress,
                              float solveShare);

} // namespace octaclay::core::detail
