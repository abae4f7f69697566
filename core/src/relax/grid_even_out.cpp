// Even Out for a torus or plane (grid_even_out.h): parameter points relaxed by length-squared
// weights, every layer resampled on the old surface, the result checked as the ball's is.
#include "relax/grid_even_out.h"

#include "detail/parallel_rows.h"
#include "relax/even_out_steps.h"
#include "relax/parameter_field.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/grid_point.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace octaclay::core::detail {
namespace {

// A stretched edge is over twice the median (the ball's kStretchedEdge).
constexpr double kStretchedEdge = 2.0;
// Sweeps per level without an iteration count (solve: coarse to fine).
constexpr int kDefaultSweeps = 100;
// The coarsest level's cells across the image's shorter side.
constexpr int kCoarsestCells = 8;

// The relaxation, coarse to fine: from a lattice of at least kCoarsestCells cells across the
// shorter side (every 64th sample at most), `sweeps` sweeps on each level, each level starting
// from the one before it interpolated: a pulled part's samples travel across the image in a few
// hundred sweeps at any N (300 on the full grid alone moved them ~17 samples at 1024 × 512).
ParameterField solve(const GeometryImage& image, int sweeps, const RelaxProgress& progress) {
  const SampleGrid& grid = image.grid();
  int stride = 1;
  while (stride < 64 && std::min(grid.width, grid.height) / (2 * stride) >= kCoarsestCells)
    stride *= 2;
  int levels = 0;
  for (int s = stride; s >= 1; s /= 2)
    ++levels;
  ParameterField field = emptyField(grid, stride);
  for (int level = 0;; ++level) {
    sweepLevel(image, field, sweeps, [&](int swept) {
      if (progress && !progress(float(level * sweeps + swept) / float(levels * sweeps)))
        throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
    });
    if (field.stride == 1) return field;
    field = finer(field);
  }
}

// The canonical samples with a grid edge over `limit` long.
std::vector<std::uint8_t> stretchedSamples(const GeometryImage& image, double limit,
                                           const ParameterField& shape) {
  std::vector<std::uint8_t> out(shape.offset.size(), 0);
  const SampleGrid& grid = image.grid();
  for (int j = 0; j < grid.height; ++j)
    for (int i = 0; i < grid.width; ++i) {
      const Vec3f p = image.at(i, j).xyz();
      for (const auto& [di, dj] : {std::array{1, 0}, {0, 1}}) {
        if (length(image.at(i + di, j + dj).xyz() - p) <= limit) continue;
        for (const auto& [a, b] : {std::array{i, j}, {i + di, j + dj}}) {
          const int wi = grid.topology == Topology::Torus ? a % grid.width : a;
          const int wj = grid.topology == Topology::Torus ? b % grid.height : b;
          out[shape.index(wi, wj)] = 1;
        }
      }
    }
  return out;
}

// Samples whose point (offsets times step) is nearest a stretched sample of the old grid.
std::size_t stretchedShown(const ParameterField& field, double step,
                           const std::vector<std::uint8_t>& stretched) {
  std::size_t shown = 0;
  for (int j = 0; j < field.rows; ++j)
    for (int i = 0; i < field.columns; ++i) {
      const Offset& d = field.offset[field.index(i, j)];
      int ni = int(std::lround(double(i) + step * d.x)),
          nj = int(std::lround(double(j) + step * d.y));
      if (field.grid.topology == Topology::Torus) {
        ni = ((ni % field.grid.width) + field.grid.width) % field.grid.width;
        nj = ((nj % field.grid.height) + field.grid.height) % field.grid.height;
      } else {
        ni = std::clamp(ni, 0, field.grid.width);
        nj = std::clamp(nj, 0, field.grid.height);
      }
      shown += stretched[field.index(ni, nj)];
    }
  return shown;
}

void checkInput(const Document& document, const RelaxOptions& options) {
  if (options.iterations < 0 || options.iterations > kMaxRelaxIterations)
    throw Error(ErrorKind::InvalidArgument,
                "iterations " + std::to_string(options.iterations) + " is outside 0 to " +
                    std::to_string(kMaxRelaxIterations) + "; leave it at 0 to choose from N");
  if (const auto problem = positionsProblem(document.positions))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be relaxed");
}

// The ball's iterations count its finest level's sweeps (its coarser levels get up to 64 times
// as many); one grid has one level: kDefaultSweeps per iteration, at most 25 times that.
int sweepsFor(const RelaxOptions& options) {
  return kDefaultSweeps * std::clamp(options.iterations, 1, 25);
}

} // namespace

Document gridEvenOutSamples(const Document& document, const RelaxOptions& options,
                            const RelaxProgress& progress) {
  checkInput(document, options);
  return resampled(document, solve(document.positions, sweepsFor(options), progress), 1.0);
}

EvenOutResult gridEvenOut(const Document& document, const RelaxOptions& options,
                          const EvenOutCheckOptions& check, const RelaxProgress& progress) {
  checkInput(document, options);
  const float solveShare = 0.5f;
  const ParameterField field = solve(document.positions, sweepsFor(options), [&](float f) {
    return !progress || progress(solveShare * f);
  });
  SolvedEvenOut solved;
  solved.before = summarizeStretch(document.positions);
  solved.vertices = static_cast<std::size_t>(vertexCount(
      document.positions.topology(), document.positions.width(), document.positions.height()));
  const std::vector<std::uint8_t> stretched =
      stretchedSamples(document.positions, kStretchedEdge * solved.before.medianEdge, field);
  solved.resample = [&](double step) { return resampled(document, field, step); };
  solved.stretchedShown = [&](double step) { return stretchedShown(field, step, stretched); };
  return tryEvenOutSteps(document, solved, check, progress, solveShare);
}

} // namespace octaclay::core::detail
