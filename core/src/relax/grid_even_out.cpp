// Even Out for a torus or plane (grid_even_out.h): parameter points relaxed by length-squared
// weights, every layer resampled on the old surface, the result checked as the ball's is.
#include "relax/grid_even_out.h"

#include "detail/parallel_rows.h"
#include "relax/even_out_steps.h"

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
// Each sweep moves a sample this fraction of the way to its neighbours' weighted centre. With
// length-squared weights the step to the centre is three times a sample's displacement for the
// grid's alternating mode (neighbours displaced the other way): a fraction over 1/3 makes that
// mode grow; 0.15 damps it by 0.1 a sweep.
constexpr double kSweepStep = 0.15;

struct Offset {
  double x = 0, y = 0;
};

// The canonical samples of a lattice over the grid, every `stride`-th sample (a torus's i < W,
// j < H; all of a plane's), and their offsets in full-resolution samples.
struct ParameterField {
  SampleGrid grid;
  int stride = 1;
  int columns = 0, rows = 0;        // canonical lattice samples
  int cellsWide = 0, cellsHigh = 0; // lattice cells: W / stride, H / stride
  std::vector<Offset> offset;
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(columns) +
           static_cast<std::size_t>(i);
  }
  bool torus() const { return grid.topology == Topology::Torus; }
  // Lattice sample (i, j), for any (i, j) within one period: its canonical one.
  std::pair<int, int> canonicalOf(int i, int j) const {
    if (torus())
      return {((i % cellsWide) + cellsWide) % cellsWide, ((j % cellsHigh) + cellsHigh) % cellsHigh};
    return {std::clamp(i, 0, cellsWide), std::clamp(j, 0, cellsHigh)};
  }
  // Lattice sample (i, j)'s parameter point in full-resolution samples, unwrapped.
  Offset point(int i, int j) const {
    const auto [ci, cj] = canonicalOf(i, j);
    const Offset& d = offset[index(ci, cj)];
    return {double(i * stride) + d.x, double(j * stride) + d.y};
  }
};

ParameterField emptyField(const SampleGrid& grid, int stride) {
  ParameterField f;
  f.grid = grid;
  f.stride = stride;
  f.cellsWide = grid.width / stride;
  f.cellsHigh = grid.height / stride;
  f.columns = f.torus() ? f.cellsWide : f.cellsWide + 1;
  f.rows = f.torus() ? f.cellsHigh : f.cellsHigh + 1;
  f.offset.assign(static_cast<std::size_t>(f.columns) * static_cast<std::size_t>(f.rows), {});
  return f;
}

// The field on the lattice twice as fine: each offset interpolated bilinearly from the coarse
// lattice's (through the torus's periods; a sheet's boundary samples from its boundary's, so
// they stay on it).
ParameterField finer(const ParameterField& coarse) {
  ParameterField fine = emptyField(coarse.grid, coarse.stride / 2);
  for (int j = 0; j < fine.rows; ++j)
    for (int i = 0; i < fine.columns; ++i) {
      const int ci = i / 2, cj = j / 2;
      const double fx = (i % 2) * 0.5, fy = (j % 2) * 0.5;
      const auto at = [&](int a, int b) {
        const auto [wa, wb] = coarse.canonicalOf(a, b);
        return coarse.offset[coarse.index(wa, wb)];
      };
      const Offset p = at(ci, cj), q = at(ci + 1, cj), r = at(ci, cj + 1), t = at(ci + 1, cj + 1);
      Offset& d = fine.offset[fine.index(i, j)];
      d.x = (1 - fy) * ((1 - fx) * p.x + fx * q.x) + fy * ((1 - fx) * r.x + fx * t.x);
      d.y = (1 - fy) * ((1 - fx) * p.y + fx * q.y) + fy * ((1 - fx) * r.y + fx * t.y);
    }
  return fine;
}

Vec3f surfaceAt(const GeometryImage& image, Offset u) {
  return interpolatePosition(image, locateGridPoint(image.grid(), u.x, u.y));
}

double cross(Offset a, Offset b, Offset c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether any of lattice cell (i, j)'s two parameter triangles (split along its anti-diagonal,
// as the grid's) is folded or flat.
bool cellFolds(const ParameterField& f, int i, int j) {
  const Offset a = f.point(i, j), b = f.point(i + 1, j), c = f.point(i + 1, j + 1),
               d = f.point(i, j + 1);
  return !(cross(a, b, d) > 0) || !(cross(b, c, d) > 0);
}

// `sweeps` Jacobi sweeps of the length-squared-weighted neighbour centre on field's lattice;
// progress(k) after each sweep k.
void sweepLevel(const GeometryImage& image, ParameterField& field, int sweeps,
                const std::function<void(int)>& swept) {
  const bool sheet = !field.torus();
  std::vector<Vec3f> at(field.offset.size());
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    parallelRows(field.rows, [&](int j0, int j1) {
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < field.columns; ++i)
          at[field.index(i, j)] = surfaceAt(image, field.point(i, j));
    });
    ParameterField next = field;
    parallelRows(field.rows, [&](int j0, int j1) {
      for (int j = j0; j < j1; ++j)
        for (int i = 0; i < field.columns; ++i) {
          const bool edgeI = sheet && (i == 0 || i == field.cellsWide);
          const bool edgeJ = sheet && (j == 0 || j == field.cellsHigh);
          if (edgeI && edgeJ) continue; // a sheet's corner stays
          const Offset u = field.point(i, j);
          const Vec3f p = at[field.index(i, j)];
          // Along i from the row's neighbours, along j from the column's: a direction's spacing
          // is evened by its own edges (a torus's ring edges, longer outside than inside, cannot
          // be shortened by moving samples around its tube).
          double s[2] = {0, 0}, total[2] = {0, 0};
          for (const auto& [di, dj] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            const int ni = i + di, nj = j + dj;
            if (sheet && (ni < 0 || nj < 0 || ni > field.cellsWide || nj > field.cellsHigh))
              continue;
            const Offset v = field.point(ni, nj);
            const auto [ci, cj] = field.canonicalOf(ni, nj);
            const Vec3f q = at[field.index(ci, cj)];
            const double w = double(dot(q - p, q - p));
            const int axis = di != 0 ? 0 : 1;
            s[axis] += w * (axis == 0 ? v.x - u.x : v.y - u.y);
            total[axis] += w;
          }
          Offset& d = next.offset[field.index(i, j)];
          // A boundary sample slides along it.
          if (!edgeI && total[0] > 0) d.x += kSweepStep * s[0] / total[0];
          if (!edgeJ && total[1] > 0) d.y += kSweepStep * s[1] / total[1];
        }
    });
    // Where a cell would fold, its corners keep their points (again while undoing one folds a
    // cell beside it).
    for (int pass = 0; pass < 3; ++pass) {
      bool undone = false;
      for (int j = 0; j < field.cellsHigh; ++j)
        for (int i = 0; i < field.cellsWide; ++i)
          if (cellFolds(next, i, j))
            for (const auto& [a, b] : {std::array{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}}) {
              const auto [ci, cj] = field.canonicalOf(a, b);
              Offset& d = next.offset[field.index(ci, cj)];
              const Offset& was = field.offset[field.index(ci, cj)];
              undone = undone || d.x != was.x || d.y != was.y;
              d = was;
            }
      if (!undone) break;
    }
    field = std::move(next);
    if (swept) swept(sweep + 1);
  }
}

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

// Every layer of `document` at the field's points, offsets scaled by `step`.
Document resampled(const Document& document, const ParameterField& field, double step) {
  const GeometryImage& image = document.positions;
  const SampleGrid& grid = image.grid();
  Document out = document;
  const std::size_t side = static_cast<std::size_t>(grid.width + 1);
  const auto layerAt = [&](const Layer& layer, const GridPoint& p, float* value) {
    const std::size_t ch = static_cast<std::size_t>(layer.channels);
    for (std::size_t c = 0; c < ch; ++c) {
      double sum = 0;
      for (std::size_t k = 0; k < 3; ++k) {
        const Sample s = p.corners[k];
        sum += double(p.weights[k]) *
               layer.texels[(static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i)) *
                                ch +
                            c];
      }
      value[c] = float(sum);
    }
  };
  parallelRows(grid.height + 1, [&](int j0, int j1) {
    for (int j = j0; j < j1; ++j)
      for (int i = 0; i <= grid.width; ++i) {
        if (grid.topology == Topology::Torus && (i == grid.width || j == grid.height)) continue;
        const Offset& d = field.offset[field.index(i, j)];
        const GridPoint p = locateGridPoint(grid, double(i) + step * d.x, double(j) + step * d.y);
        const Vec3f q = interpolatePosition(image, p);
        float saliency = 0;
        for (std::size_t k = 0; k < 3; ++k)
          saliency += p.weights[k] * image.at(p.corners[k]).w;
        out.positions.at(i, j) = {q.x, q.y, q.z, saliency};
        const std::size_t t = static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i);
        for (const auto& [from, to] : {std::pair{&document.diffuse, &out.diffuse},
                                       {&document.feature, &out.feature},
                                       {&document.mask, &out.mask}})
          if (!from->uniform())
            layerAt(*from, p, &to->texels[t * static_cast<std::size_t>(from->channels)]);
      }
  });
  if (grid.topology == Topology::Torus) { // column W and row H: column and row 0 again
    for (int j = 0; j <= grid.height; ++j)
      for (int i = 0; i <= grid.width; ++i) {
        if (i < grid.width && j < grid.height) continue;
        const int ci = i % grid.width, cj = j % grid.height;
        out.positions.at(i, j) = out.positions.at(ci, cj);
        for (Layer* l : {&out.diffuse, &out.feature, &out.mask})
          if (!l->uniform()) {
            const std::size_t ch = static_cast<std::size_t>(l->channels);
            std::copy_n(&l->texels[(static_cast<std::size_t>(cj) * side + ci) * ch], ch,
                        &l->texels[(static_cast<std::size_t>(j) * side + i) * ch]);
          }
      }
  }
  return out;
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
