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

// A lattice sample as a sweep reads it: its canonical sample's index and its unwrapped grid
// position (i × stride, j × stride); its parameter point is that plus the canonical offset, as
// ParameterField::point gives it.
struct LatticeRef {
  std::size_t index = 0;
  double x = 0, y = 0;
};

LatticeRef latticeRef(const ParameterField& f, int i, int j) {
  const auto [ci, cj] = f.canonicalOf(i, j);
  return {f.index(ci, cj), double(i * f.stride), double(j * f.stride)};
}

Offset pointOf(const ParameterField& f, const LatticeRef& r) {
  const Offset& d = f.offset[r.index];
  return {r.x + d.x, r.y + d.y};
}

double cross(Offset a, Offset b, Offset c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The lattice samples a sweep moves, those whose surface points it reads (the moving ones and
// their four neighbours) and the cells it may fold (those with a moving corner), with the
// canonical samples each looks up found once rather than at every sweep.
struct SweepSet {
  struct Moving {
    LatticeRef self;
    std::array<LatticeRef, 4> neighbours; ///< right, left, up, down: those inside
    int count = 0;
    std::array<int, 4> axes{};         ///< 0 along i, 1 along j
    bool edgeI = false, edgeJ = false; ///< a sheet's boundary sample: slides along it
  };
  std::vector<Moving> moving;
  std::vector<LatticeRef> read;
  std::vector<std::array<LatticeRef, 4>> cells; ///< corners (i, j), (i+1, j), (i+1, j+1), (i, j+1)
};

// Whether any of a lattice cell's two parameter triangles (split along its anti-diagonal, as the
// grid's) is folded or flat.
bool cellFolds(const ParameterField& f, const std::array<LatticeRef, 4>& corners) {
  const Offset a = pointOf(f, corners[0]), b = pointOf(f, corners[1]), c = pointOf(f, corners[2]),
               d = pointOf(f, corners[3]);
  return !(cross(a, b, d) > 0) || !(cross(b, c, d) > 0);
}

SweepSet sweepSet(const ParameterField& f) {
  SweepSet set;
  const bool sheet = !f.torus();
  std::vector<std::uint8_t> read(f.offset.size(), 0), cell(f.offset.size(), 0);
  for (int j = 0; j < f.rows; ++j)
    for (int i = 0; i < f.columns; ++i) {
      const std::size_t k = f.index(i, j);
      const bool corner = sheet && (i == 0 || i == f.cellsWide) && (j == 0 || j == f.cellsHigh);
      if (corner || (!f.free.empty() && !f.free[k])) continue;
      SweepSet::Moving m;
      m.self = latticeRef(f, i, j);
      m.edgeI = sheet && (i == 0 || i == f.cellsWide);
      m.edgeJ = sheet && (j == 0 || j == f.cellsHigh);
      for (const auto& [di, dj] : {std::array{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        const int ni = i + di, nj = j + dj;
        if (sheet && (ni < 0 || nj < 0 || ni > f.cellsWide || nj > f.cellsHigh)) continue;
        m.neighbours[static_cast<std::size_t>(m.count)] = latticeRef(f, ni, nj);
        m.axes[static_cast<std::size_t>(m.count++)] = di != 0 ? 0 : 1;
      }
      set.moving.push_back(m);
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
  const auto columns = static_cast<std::size_t>(f.columns);
  for (std::size_t k = 0; k < read.size(); ++k) {
    const int i = static_cast<int>(k % columns), j = static_cast<int>(k / columns);
    if (read[k]) set.read.push_back(latticeRef(f, i, j));
    if (cell[k])
      set.cells.push_back({latticeRef(f, i, j), latticeRef(f, i + 1, j),
                           latticeRef(f, i + 1, j + 1), latticeRef(f, i, j + 1)});
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
  const SweepSet set = sweepSet(field);
  std::vector<Vec3f> at(field.offset.size());
  // The sweep's result; only the moving samples' offsets ever differ from field's.
  ParameterField next = field;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    parallelRows(
        static_cast<int>(set.read.size()),
        [&](int k0, int k1) {
          for (int k = k0; k < k1; ++k) {
            const LatticeRef& r = set.read[static_cast<std::size_t>(k)];
            at[r.index] = surfaceAt(image, pointOf(field, r));
          }
        },
        kSamplesPerThread);
    parallelRows(
        static_cast<int>(set.moving.size()),
        [&](int k0, int k1) {
          for (int k = k0; k < k1; ++k) {
            const SweepSet::Moving& m = set.moving[static_cast<std::size_t>(k)];
            const Offset u = pointOf(field, m.self);
            const Vec3f p = at[m.self.index];
            // Along i from the row's neighbours, along j from the column's: a direction's spacing
            // is evened by its own edges (a torus's ring edges, longer outside than inside, cannot
            // be shortened by moving samples around its tube).
            double sum[2] = {0, 0}, total[2] = {0, 0};
            for (int e = 0; e < m.count; ++e) {
              const LatticeRef& r = m.neighbours[static_cast<std::size_t>(e)];
              const Offset v = pointOf(field, r);
              const Vec3f q = at[r.index];
              const double w = double(dot(q - p, q - p));
              const int axis = m.axes[static_cast<std::size_t>(e)];
              sum[axis] += w * (axis == 0 ? v.x - u.x : v.y - u.y);
              total[axis] += w;
            }
            Offset& d = next.offset[m.self.index];
            // A boundary sample slides along it.
            if (!m.edgeI && total[0] > 0) d.x += kSweepStep * sum[0] / total[0];
            if (!m.edgeJ && total[1] > 0) d.y += kSweepStep * sum[1] / total[1];
          }
        },
        kSamplesPerThread);
    // Where a cell would fold, its corners keep their points (again while undoing one folds a
    // cell beside it).
    for (int pass = 0; pass < 3; ++pass) {
      bool undone = false;
      for (const auto& corners : set.cells)
        if (cellFolds(next, corners))
          for (const LatticeRef& r : corners) {
            Offset& d = next.offset[r.index];
            const Offset& was = field.offset[r.index];
            undone = undone || d.x != was.x || d.y != was.y;
            d = was;
          }
      if (!undone) break;
    }
    for (const SweepSet::Moving& m : set.moving)
      field.offset[m.self.index] = next.offset[m.self.index];
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
