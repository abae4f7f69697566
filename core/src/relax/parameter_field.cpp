// Parameter points of a torus or plane and their length-squared-weighted sweeps
// (parameter_field.h).
#include "relax/parameter_field.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/grid_point.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace octaclay::core::detail {
namespace {

// Each sweep moves a sample this fraction of the way to its neighbours' weighted centre. With
// length-squared weights the step to the centre is three times a sample's displacement for the
// grid's alternating mode (neighbours displaced the other way): a fraction over 1/3 makes that
// mode grow; 0.15 damps it by 0.1 a sweep.
constexpr double kSweepStep = 0.15;
// Fewer samples than this a thread are swept on one (a local relaxation's few hundred).
constexpr int kSamplesPerThread = 2048;

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

// The lattice samples a sweep moves, those whose surface points it reads (the moving ones and
// their four neighbours) and the cells it may fold (those with a moving corner).
struct SweepSet {
  std::vector<std::size_t> moving, read;
  std::vector<std::array<int, 2>> cells;
};

SweepSet sweepSet(const ParameterField& f) {
  SweepSet set;
  const bool sheet = !f.torus();
  std::vector<std::uint8_t> read(f.offset.size(), 0), cell(f.offset.size(), 0);
  for (int j = 0; j < f.rows; ++j)
    for (int i = 0; i < f.columns; ++i) {
      const std::size_t k = f.index(i, j);
      const bool corner = sheet && (i == 0 || i == f.cellsWide) && (j == 0 || j == f.cellsHigh);
      if (corner || (!f.free.empty() && !f.free[k])) continue;
      set.moving.push_back(k);
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if (sheet && (a < 0 || b < 0 || a > f.cellsWide || b > f.cellsHigh)) continue;
          const auto [ca, cb] = f.canonicalOf(a, b);
          read[f.index(ca, cb)] = 1;
          // The cells with (i, j) as a corner: (i - 1 … i, j - 1 … j).
          if (di <= 0 && dj <= 0 && (!sheet || (a < f.cellsWide && b < f.cellsHigh)))
            cell[f.index(ca, cb)] = 1;
        }
    }
  for (std::size_t k = 0; k < read.size(); ++k) {
    if (read[k]) set.read.push_back(k);
    if (cell[k])
      set.cells.push_back({static_cast<int>(k % static_cast<std::size_t>(f.columns)),
                           static_cast<int>(k / static_cast<std::size_t>(f.columns))});
  }
  return set;
}

} // namespace

Vec3f surfaceAt(const GeometryImage& image, Offset u) {
  return interpolatePosition(image, locateGridPoint(image.grid(), u.x, u.y));
}

std::pair<int, int> ParameterField::canonicalOf(int i, int j) const {
  if (torus())
    return {((i % cellsWide) + cellsWide) % cellsWide, ((j % cellsHigh) + cellsHigh) % cellsHigh};
  return {std::clamp(i, 0, cellsWide), std::clamp(j, 0, cellsHigh)};
}

Offset ParameterField::point(int i, int j) const {
  const auto [ci, cj] = canonicalOf(i, j);
  const Offset& d = offset[index(ci, cj)];
  return {double(i * stride) + d.x, double(j * stride) + d.y};
}

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

void sweepLevel(const GeometryImage& image, ParameterField& field, int sweeps,
                const std::function<void(int)>& swept) {
  const bool sheet = !field.torus();
  const SweepSet set = sweepSet(field);
  const auto columns = static_cast<std::size_t>(field.columns);
  std::vector<Vec3f> at(field.offset.size());
  // The sweep's result; only the moving samples' offsets ever differ from field's.
  ParameterField next = field;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    parallelRows(
        static_cast<int>(set.read.size()),
        [&](int k0, int k1) {
          for (int k = k0; k < k1; ++k) {
            const std::size_t s = set.read[static_cast<std::size_t>(k)];
            at[s] = surfaceAt(
                image, field.point(static_cast<int>(s % columns), static_cast<int>(s / columns)));
          }
        },
        kSamplesPerThread);
    parallelRows(
        static_cast<int>(set.moving.size()),
        [&](int k0, int k1) {
          for (int k = k0; k < k1; ++k) {
            const std::size_t s = set.moving[static_cast<std::size_t>(k)];
            const int i = static_cast<int>(s % columns), j = static_cast<int>(s / columns);
            const bool edgeI = sheet && (i == 0 || i == field.cellsWide);
            const bool edgeJ = sheet && (j == 0 || j == field.cellsHigh);
            const Offset u = field.point(i, j);
            const Vec3f p = at[s];
            // Along i from the row's neighbours, along j from the column's: a direction's spacing
            // is evened by its own edges (a torus's ring edges, longer outside than inside, cannot
            // be shortened by moving samples around its tube).
            double sum[2] = {0, 0}, total[2] = {0, 0};
            for (const auto& [di, dj] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
              const int ni = i + di, nj = j + dj;
              if (sheet && (ni < 0 || nj < 0 || ni > field.cellsWide || nj > field.cellsHigh))
                continue;
              const Offset v = field.point(ni, nj);
              const auto [ci, cj] = field.canonicalOf(ni, nj);
              const Vec3f q = at[field.index(ci, cj)];
              const double w = double(dot(q - p, q - p));
              const int axis = di != 0 ? 0 : 1;
              sum[axis] += w * (axis == 0 ? v.x - u.x : v.y - u.y);
              total[axis] += w;
            }
            Offset& d = next.offset[s];
            // A boundary sample slides along it.
            if (!edgeI && total[0] > 0) d.x += kSweepStep * sum[0] / total[0];
            if (!edgeJ && total[1] > 0) d.y += kSweepStep * sum[1] / total[1];
          }
        },
        kSamplesPerThread);
    // Where a cell would fold, its corners keep their points (again while undoing one folds a
    // cell beside it).
    for (int pass = 0; pass < 3; ++pass) {
      bool undone = false;
      for (const auto& [i, j] : set.cells)
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
    for (const std::size_t k : set.moving)
      field.offset[k] = next.offset[k];
    if (swept) swept(sweep + 1);
  }
}

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
        if (d.x == 0 && d.y == 0) continue; // out holds the sample already, bit for bit
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

} // namespace octaclay::core::detail
