// evenOut's checked tries, one loop for the ball's and the grid topologies' solves.
#include "relax/even_out_steps.h"

#include "measure/move_tolerance.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <cstdio>
#include <string>
#include <utility>

namespace octaclay::core::detail {
namespace {

std::string times(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3gx", ratio);
  return text;
}

// Why the step's result is not kept (empty: kept), from its stretch and samples.
std::string stretchReason(const StretchSummary& before, const StretchSummary& after,
                          std::size_t stretchedBefore, std::size_t shown) {
  if (after.longestOverMedian > before.longestOverMedian * (1 + 1e-6))
    return "the longest edge would grow from " + times(before.longestOverMedian) + " to " +
           times(after.longestOverMedian) + " the median";
  if (shown < stretchedBefore)
    return "the stretched part would lose samples (" + std::to_string(stretchedBefore) + " -> " +
           std::to_string(shown) + ")";
  if (after.longestOverMedian > 0.99 * before.longestOverMedian &&
      double(shown) < 1.01 * double(stretchedBefore) + 0.5)
    return "the samples are already as even as it can make them (longest edge " +
           times(before.longestOverMedian) + " the median)";
  return {};
}

} // namespace

EvenOutResult tryEvenOutSteps(const Document& document, const SolvedEvenOut& solved,
                              const EvenOutCheckOptions& check, const RelaxProgress& progress,
                              float solveShare) {
  const auto report = [&](float fraction) {
    if (progress && !progress(fraction))
      throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  };
  EvenOutResult out;
  out.before = solved.before;
  out.after = out.before;
  out.vertices = solved.vertices;
  out.stretchedBefore = solved.stretchedShown(0.0);
  out.stretchedAfter = out.stretchedBefore;
  const TriangleMesh surface = extractMesh(document.positions);
  const bool hasScale = boundingBox(surface).diagonal() > 0;
  std::string firstReason;
  for (std::size_t t = 0; t < check.steps.size(); ++t) {
    const double step = check.steps[t];
    if (!(step > 0 && step <= 1))
      throw Error(ErrorKind::InvalidArgument, "an even-out step must be in (0, 1]");
    Document result = solved.resample(step);
    ++out.tries;
    const StretchSummary after = summarizeStretch(result.positions);
    const std::size_t shown = solved.stretchedShown(step);
    std::string reason = stretchReason(out.before, after, out.stretchedBefore, shown);
    if (reason.empty() && hasScale) {
      out.moved = compareSurfaces(surface, extractMesh(result.positions),
                                  {.samplesPerSurface = check.samplesPerSurface});
      reason = surfaceMovedTooFar(out.moved, check.rmsTolerance, check.hausdorffTolerance);
    }
    report(solveShare + (1 - solveShare) * float(t + 1) / float(check.steps.size()));
    if (reason.empty()) {
      out.document = std::move(result);
      out.changed = true;
      out.step = step;
      out.after = after;
      out.stretchedAfter = shown;
      report(1.0f);
      return out;
    }
    if (firstReason.empty()) firstReason = reason;
  }
  out.document = document;
  out.reason = firstReason;
  if (check.steps.size() > 1) out.reason += ", and no smaller step did better";
  report(1.0f);
  return out;
}

} // namespace octaclay::core::detail
