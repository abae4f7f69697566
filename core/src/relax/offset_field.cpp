#include "relax/offset_field.h"

#include "detail/parallel_rows.h"

#include "octaclay/core/geometry/grid_point.h"

#include <algorithm>
#include <cmath>

namespace octaclay::core::detail {
namespace {

// Each sweep moves a sample part of the way to where the surface lengths to its two
// neighbours along each grid line would be equal (arc-length equalisation, the two lines'
// moves averaged): samples flow toward long edges, onto what was pulled. (The plain average of
// the neighbours' surface positions would pull samples off a thin limb instead.)
constexpr double kStep = 0.3;     // share of the equalising move taken per sweep (Jacobi)
constexpr double kMaxMove = 0.3;  // lattice steps per sweep
constexpr double kMinArea = 1e-4; // of a cell triangle's rest area: below it counts as folded
constexpr int kCoarsest = 8;      // lattice size the solve starts on
// A coarse lattice's edge is measured along the surface, in kArcParts pieces, on the levels
// whose step is at least N / kArcLevels.
constexpr int kArcParts = 4;
constexpr int kArcLevels = 32;

constexpr std::array<Sample, 4> kNeighbours{{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};

// D(copy) = sign × D(canonical) for identified samples: half-turns negate offsets; the corner
// (N, N) is a translate of (0, 0).
float copySign(int n, Sample copy, Sample canonicalSample) {
  if (copy == canonicalSample) return 1.0f;
  return copy.i == n && copy.j == n ? 1.0f : -1.0f;
}

bool isSideMidpoint(int n, Sample s) {
  const int h = n / 2;
  return (s.i == h && (s.j == 0 || s.j == n)) || (s.j == h && (s.i == 0 || s.i == n));
}

// The held samples of a field (not free, and neither a pin nor a side midpoint: the rim of what
// may move), counted over boxes of the tiled plane.
class HeldSamples {
public:
  explicit HeldSamples(const OffsetField& field)
      : n_(field.n), side_(static_cast<std::size_t>(field.n) + 2), held_(field.free.size()),
        sums_(side_ * side_, 0) {
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i <= n_; ++i)
        held_[field.index(i, j)] = !field.free[field.index(i, j)] && !isSideMidpoint(n_, {i, j});
    for (Sample p : field.pins) {
      std::array<Sample, 4> copies;
      const int k = identifiedSamples(n_, p, copies);
      for (int c = 0; c < k; ++c)
        held_[field.index(copies[static_cast<std::size_t>(c)].i,
                          copies[static_cast<std::size_t>(c)].j)] = 0;
    }
    for (int j = 0; j <= n_; ++j)
      for (int i = 0; i <= n_; ++i)
        sums_[at(i + 1, j + 1)] =
            held_[index(i, j)] + sums_[at(i, j + 1)] + sums_[at(i + 1, j)] - sums_[at(i, j)];
  }

  /// Whether a held sample lies in [i0, i1] × [j0, j1] (positions of the tiled plane).
  bool any(int i0, int j0, int i1, int j1) const {
    if (sums_.back() == 0) return false; // nothing held (the even-out)
    if (i0 >= 0 && j0 >= 0 && i1 <= n_ && j1 <= n_)
      return sums_[at(i1 + 1, j1 + 1)] - sums_[at(i0, j1 + 1)] - sums_[at(i1 + 1, j0)] +
                 sums_[at(i0, j0)] >
             0;
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i)
        if (const Sample w = wrap(n_, {i, j}); held_[index(w.i, w.j)]) return true;
    return false;
  }

private:
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(n_ + 1) +
           static_cast<std::size_t>(i);
  }
  std::size_t at(int i, int j) const {
    return static_cast<std::size_t>(j) * side_ + static_cast<std::size_t>(i);
  }

  int n_;
  std::size_t side_;
  std::vector<std::uint8_t> held_;
  std::vector<std::uint32_t> sums_; // summed-area table of held_, one row and column of zeros first
};

// One level of the coarse-to-fine solve: the lattice of samples whose indices are multiples of
// step (an octahedral grid of size m = n / step over the same surface), with its own copy of
// their offsets.
class Level {
public:
  Level(const GeometryImage& image, OffsetField& field, const HeldSamples& held, int step,
        double edgeCap, bool coarseArcs)
      : image_(image), field_(field), n_(field.n), step_(step), m_(field.n / step),
        arcParts_(coarseArcs && step >= std::max(2, field.n / kArcLevels)
                      ? std::min(step, kArcParts)
                      : 1),
        cap_(edgeCap * step),
        count_(static_cast<std::size_t>(m_ + 1) * static_cast<std::size_t>(m_ + 1)),
        positions_(count_), offsets_(count_), free_(count_, 0), near_(count_, 0) {
    for (int J = 0; J <= m_; ++J)
      for (int I = 0; I <= m_; ++I) {
        offsets_[lattice(I, J)] = field_.offset[fine(I, J)];
        if (!field_.free[fine(I, J)]) continue;
        // A lattice sample whose cells reach a held sample stays: refining would tear the
        // held sample away from the moved samples around it, and the cells there would fold.
        if (step_ > 1 && held.any(I * step_ - step_ + 1, J * step_ - step_ + 1,
                                  I * step_ + step_ - 1, J * step_ + step_ - 1))
          continue;
        free_[lattice(I, J)] = 1;
        for (int dj = -1; dj <= 1; ++dj)
          for (int di = -1; di <= 1; ++di)
            near_[lattice(wrap(m_, {I + di, J + dj}))] = 1;
      }
    forEachBorderSample([&](Sample s) { // near a free sample on one copy: near on all of them
      std::array<Sample, 4> copies;
      const int k = identifiedSamples(m_, s, copies);
      std::uint8_t any = 0;
      for (int c = 0; c < k; ++c)
        any |= near_[lattice(copies[static_cast<std::size_t>(c)])];
      for (int c = 0; c < k; ++c)
        near_[lattice(copies[static_cast<std::size_t>(c)])] = any;
    });
    for (std::uint8_t f : free_)
      freeCount_ += f;
    for (Sample p : field_.pins)
      addPin(p);
    // The rows of cells that hold a near sample: where sweeps and fold checks look.
    nearRows_ = {m_, 0};
    for (int J = 0; J <= m_; ++J)
      for (int I = 0; I <= m_; ++I)
        if (near_[lattice(I, J)]) {
          nearRows_[0] = std::min(nearRows_[0], std::max(J - 1, 0));
          nearRows_[1] = std::max(nearRows_[1], std::min(J + 1, m_));
          break;
        }
    if (nearRows_[1] < nearRows_[0]) nearRows_ = {0, 0};
  }

  std::size_t freeCount() const { return freeCount_; }
  std::size_t size() const { return count_; }

  void sweep() {
    evaluatePositions();
    // Kept from sweep to sweep: a fresh copy was fresh pages each time (8 MB at N = 1024).
    before_.assign(offsets_.begin(), offsets_.end());
    const std::vector<std::array<float, 2>>& before = before_;
    parallelRows(
        nearRows_[1] - nearRows_[0] + 1,
        [&](int rowBegin, int rowEnd) {
          for (int J = nearRows_[0] + rowBegin; J < nearRows_[0] + rowEnd; ++J)
            for (int I = 0; I <= m_; ++I)
              if (free_[lattice(I, J)] && canonical(m_, {I, J}) == Sample{I, J})
                offsets_[lattice(I, J)] = moved(before, I, J);
        },
        16);
    copyToIdentified();
    holdPins();
    repairFolds(before);
    // Folds put back part of a pin's triangle: the rest of it goes back too.
    while (revertBrokenPins(before))
      repairFolds(before);
  }

  /// Unfolds whatever the offsets brought from the coarser level fold (none should: the
  /// prolongation is linear on their triangles) by putting offsets back to zero.
  void unfoldFromRest() { repairFolds(std::vector<std::array<float, 2>>(count_)); }

  /// Writes the level's offsets back to the field.
  void store() const {
    for (int J = 0; J <= m_; ++J)
      for (int I = 0; I <= m_; ++I)
        field_.offset[fine(I, J)] = offsets_[lattice(I, J)];
  }

private:
  std::size_t lattice(int I, int J) const {
    return static_cast<std::size_t>(J) * static_cast<std::size_t>(m_ + 1) +
           static_cast<std::size_t>(I);
  }
  std::size_t lattice(Sample s) const { return lattice(s.i, s.j); }
  std::size_t fine(int I, int J) const { return field_.index(I * step_, J * step_); }

  // A pin between this lattice's samples (on a coarse level) holds the offset interpolated at
  // it over its lattice triangle at zero: were the corners to move freely, refining would leave
  // the pinned sample behind them, and the cells around it would fold.
  struct Pin {
    std::array<std::size_t, 3> corners;
    std::array<double, 3> weights;
    std::array<bool, 3> movable;
    // The corner's canonical sample and the sign its offset is copied with (border samples
    // move with their copies).
    std::array<std::size_t, 3> canonicals;
    std::array<float, 3> signs;
  };

  void addPin(Sample p) {
    if (p.i % step_ == 0 && p.j % step_ == 0) return; // a lattice sample: not free here
    const int I = std::min(p.i / step_, m_ - 1), J = std::min(p.j / step_, m_ - 1);
    const double fx = double(p.i) / step_ - I, fy = double(p.j) / step_ - J;
    const std::array<Sample, 4> c{{{I, J}, {I + 1, J}, {I + 1, J + 1}, {I, J + 1}}};
    std::array<Sample, 3> tri;
    std::array<double, 3> w;
    if ((I >= m_ / 2) == (J >= m_ / 2)) { // the anti-diagonal split, as foldedCorners
      if (fx + fy <= 1)
        tri = {c[0], c[1], c[3]}, w = {1 - fx - fy, fx, fy};
      else
        tri = {c[1], c[2], c[3]}, w = {1 - fy, fx + fy - 1, 1 - fx};
    } else {
      if (fx >= fy)
        tri = {c[0], c[1], c[2]}, w = {1 - fx, fx - fy, fy};
      else
        tri = {c[0], c[2], c[3]}, w = {1 - fy, fx, fy - fx};
    }
    Pin pin{};
    bool any = false;
    for (std::size_t k = 0; k < 3; ++k) {
      const Sample v = tri[k], canon = canonical(m_, v);
      pin.corners[k] = lattice(v);
      pin.weights[k] = w[k];
      pin.movable[k] = free_[lattice(v)] != 0;
      pin.canonicals[k] = lattice(canon);
      pin.signs[k] = copySign(m_, v, canon);
      any = any || (pin.movable[k] && w[k] > 0);
    }
    if (any) pins_.push_back(pin);
  }

  std::array<double, 2> pinOffset(const Pin& pin) const {
    std::array<double, 2> r{};
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t c = 0; c < 2; ++c)
        r[c] += pin.weights[k] * offsets_[pin.corners[k]][c];
    return r;
  }

  // The smallest change of the movable corners that brings each pin's offset to zero.
  void holdPins() {
    for (const Pin& pin : pins_) {
      const std::array<double, 2> r = pinOffset(pin);
      double ww = 0;
      for (std::size_t k = 0; k < 3; ++k)
        if (pin.movable[k]) ww += pin.weights[k] * pin.weights[k];
      if (!(ww > 0)) continue;
      bool border = false;
      for (std::size_t k = 0; k < 3; ++k)
        if (pin.movable[k]) {
          for (std::size_t c = 0; c < 2; ++c)
            offsets_[pin.canonicals[k]][c] -=
                pin.signs[k] * static_cast<float>(pin.weights[k] * r[c] / ww);
          border = border || onBorder(pin.canonicals[k]);
        }
      // Before the next pin reads a border corner; a pin inside changed no copy's canonical
      // sample (every copy already equals its own, so the pass would write the same values).
      if (border) copyToIdentified();
    }
  }

  bool onBorder(std::size_t at) const {
    const std::size_t side = static_cast<std::size_t>(m_) + 1;
    const std::size_t i = at % side, j = at / side;
    return i == 0 || j == 0 || i + 1 == side || j + 1 == side;
  }

  // Puts back to `before` the corners of each pin that no longer holds; true if any changed.
  bool revertBrokenPins(const std::vector<std::array<float, 2>>& before) {
    bool changed = false;
    for (const Pin& pin : pins_) {
      const std::array<double, 2> r = pinOffset(pin);
      if (std::hypot(r[0], r[1]) <= 1e-3 * step_) continue;
      for (std::size_t k = 0; k < 3; ++k)
        if (offsets_[pin.canonicals[k]] != before[pin.canonicals[k]]) {
          offsets_[pin.canonicals[k]] = before[pin.canonicals[k]];
          changed = true;
        }
      copyToIdentified();
    }
    return changed;
  }

  template <class F> void forEachBorderSample(F&& f) const {
    for (int t = 0; t <= m_; ++t) {
      f(Sample{t, 0});
      f(Sample{t, m_});
      f(Sample{0, t});
      f(Sample{m_, t});
    }
  }

  void evaluatePositions() {
    parallelRows(
        nearRows_[1] - nearRows_[0] + 1,
        [&](int rowBegin, int rowEnd) {
          for (int J = nearRows_[0] + rowBegin; J < nearRows_[0] + rowEnd; ++J)
            for (int I = 0; I <= m_; ++I) {
              if (!near_[lattice(I, J)]) continue;
              const auto& d = offsets_[lattice(I, J)];
              const GridPoint p =
                  locateGridPoint(n_, double(I) * step_ + d[0], double(J) * step_ + d[1]);
              Vec3f x{0, 0, 0};
              for (std::size_t c = 0; c < 3; ++c)
                x = x + image_.at(p.corners[c]).xyz() * p.weights[c];
              positions_[lattice(I, J)] = x;
            }
        },
        16);
  }

  // The surface length between two of this lattice's points (a, b in the tiled plane, at
  // surface points xa, xb) along the parameter segment between them: a coarse lattice's chord
  // would step over whatever was pulled out between its samples.
  double arcLength(double ax, double ay, double bx, double by, Vec3f xa, Vec3f xb) const {
    const int parts = arcParts_;
    if (parts <= 1) return length(xb - xa);
    double sum = 0;
    Vec3f prev = xa;
    for (int p = 1; p < parts; ++p) {
      const double t = double(p) / parts;
      const Vec3f x =
          interpolatePosition(image_, locateGridPoint(n_, ax + t * (bx - ax), ay + t * (by - ay)));
      sum += length(x - prev);
      prev = x;
    }
    return sum + length(xb - prev);
  }

  std::array<float, 2> moved(const std::vector<std::array<float, 2>>& offsets, int I, int J) const {
    const auto& dc = offsets[lattice(I, J)];
    const double pcx = double(I) * step_ + dc[0], pcy = double(J) * step_ + dc[1];
    const Vec3f xc = positions_[lattice(I, J)];
    std::array<double, 4> xs{}, ys{}, lengths{};
    for (std::size_t k = 0; k < 4; ++k) {
      const Sample q{I + kNeighbours[k].i, J + kNeighbours[k].j};
      const OrientedSample w = wrapOriented(m_, q);
      const auto& dk = offsets[lattice(w.sample)];
      const double sign = w.halfTurn ? -1.0 : 1.0; // the neighbour's offset seen from here
      xs[k] = double(q.i) * step_ + sign * dk[0];
      ys[k] = double(q.j) * step_ + sign * dk[1];
      lengths[k] = arcLength(pcx, pcy, xs[k], ys[k], xc, positions_[lattice(w.sample)]);
    }
    double mx = 0, my = 0;
    for (std::size_t a = 0; a < 2; ++a) { // the pairs right/left and up/down
      const std::size_t b = a + 2;
      const double la = lengths[a], lb = lengths[b];
      // Moving a share t of the way to the longer side's neighbour evens the two lengths out
      // when t = (long - short) / (2 long).
      const std::size_t to = la > lb ? a : b;
      const double longer = std::max(la, lb), shorter = std::min(la, lb);
      if (!(longer > 0)) continue;
      // ... but the shorter edge grows no longer than the cap: the surface the samples come
      // from keeps its resolution.
      const double t =
          std::min((longer - shorter) / (2 * longer), std::max(0.0, (cap_ - shorter) / longer));
      mx += t * (xs[to] - pcx);
      my += t * (ys[to] - pcy);
    }
    mx *= kStep, my *= kStep;
    const double move = std::hypot(mx, my), limit = kMaxMove * step_;
    if (!std::isfinite(move)) return dc;
    if (move > limit) mx *= limit / move, my *= limit / move;
    return {static_cast<float>(dc[0] + mx), static_cast<float>(dc[1] + my)};
  }

  void copyToIdentified() {
    forEachBorderSample([&](Sample s) {
      std::array<Sample, 4> copies;
      const int k = identifiedSamples(m_, s, copies);
      const Sample c = canonical(m_, s);
      const auto d = offsets_[lattice(c)];
      for (int i = 0; i < k; ++i) {
        const Sample copy = copies[static_cast<std::size_t>(i)];
        const float sign = copySign(m_, copy, c);
        offsets_[lattice(copy)] = {sign * d[0], sign * d[1]};
      }
    });
  }

  // Folded cell triangles get their moved vertices put back to `fallback` (a fold-free
  // state) until none is left: one pass over every cell, then over the cells around what was
  // put back.
  void repairFolds(const std::vector<std::array<float, 2>>& fallback) {
    std::vector<std::vector<Sample>> bands(static_cast<std::size_t>(m_));
    parallelRows(
        nearRows_[1] - nearRows_[0],
        [&](int rowBegin, int rowEnd) {
          for (int J = nearRows_[0] + rowBegin; J < nearRows_[0] + rowEnd; ++J)
            for (int I = 0; I < m_; ++I)
              if (near_[lattice(I, J)])
                foldedCorners(I, J, fallback, bands[static_cast<std::size_t>(J)]);
        },
        16);
    std::vector<Sample> offenders;
    for (const auto& band : bands)
      offenders.insert(offenders.end(), band.begin(), band.end());
    std::sort(offenders.begin(), offenders.end(),
              [this](Sample a, Sample b) { return lattice(a) < lattice(b); });
    offenders.erase(std::unique(offenders.begin(), offenders.end()), offenders.end());
    while (!offenders.empty()) {
      std::vector<Sample> cells;
      for (Sample v : offenders) {
        std::array<Sample, 4> copies;
        const int k = identifiedSamples(m_, v, copies);
        for (int i = 0; i < k; ++i) {
          const Sample c = copies[static_cast<std::size_t>(i)];
          offsets_[lattice(c)] = fallback[lattice(c)];
          for (int dj = -1; dj <= 0; ++dj)
            for (int di = -1; di <= 0; ++di)
              if (c.i + di >= 0 && c.j + dj >= 0 && c.i + di < m_ && c.j + dj < m_)
                cells.push_back({c.i + di, c.j + dj});
        }
      }
      // A cell or a corner found several times is looked at once (the counts would multiply).
      auto unique = [this](std::vector<Sample>& v) {
        std::sort(v.begin(), v.end(),
                  [this](Sample a, Sample b) { return lattice(a) < lattice(b); });
        v.erase(std::unique(v.begin(), v.end()), v.end());
      };
      unique(cells);
      offenders.clear();
      for (Sample c : cells)
        foldedCorners(c.i, c.j, fallback, offenders);
      unique(offenders);
    }
  }

  // Appends the moved corners of cell (I, J)'s triangles that are folded (or nearly).
  void foldedCorners(int I, int J, const std::vector<std::array<float, 2>>& fallback,
                     std::vector<Sample>& out) const {
    const std::array<Sample, 4> c{{{I, J}, {I + 1, J}, {I + 1, J + 1}, {I, J + 1}}};
    bool moved = false; // a cell none of whose corners moved is as it was: unfolded
    for (Sample v : c)
      moved = moved || offsets_[lattice(v)] != fallback[lattice(v)];
    if (!moved) return;
    // cellTriangles' split: along the anti-diagonal where the column and row halves agree.
    const bool anti = (I >= m_ / 2) == (J >= m_ / 2);
    const std::array<std::array<Sample, 3>, 2> triangles =
        anti ? std::array<std::array<Sample, 3>, 2>{{{c[0], c[1], c[3]}, {c[1], c[2], c[3]}}}
             : std::array<std::array<Sample, 3>, 2>{{{c[0], c[1], c[2]}, {c[0], c[2], c[3]}}};
    const double minArea = kMinArea * 0.5 * double(step_) * double(step_);
    for (const auto& tri : triangles) {
      std::array<std::array<double, 2>, 3> p;
      for (std::size_t v = 0; v < 3; ++v) {
        const auto& d = offsets_[lattice(tri[v])];
        p[v] = {double(tri[v].i) * step_ + d[0], double(tri[v].j) * step_ + d[1]};
      }
      const double area = 0.5 * ((p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) -
                                 (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]));
      if (area >= minArea) continue;
      for (Sample v : tri)
        if (offsets_[lattice(v)] != fallback[lattice(v)]) out.push_back(v);
    }
  }

  const GeometryImage& image_;
  OffsetField& field_;
  int n_, step_, m_;
  int arcParts_; // pieces an edge is measured in (1: the chord)
  double cap_;   // longest a sweep lets an edge of this lattice grow
  std::size_t count_;
  std::vector<Vec3f> positions_;
  std::vector<std::array<float, 2>> offsets_, before_;
  std::vector<std::uint8_t> free_, near_;
  std::vector<Pin> pins_;
  std::array<int, 2> nearRows_{0, 0}; // [first, last) row of cells with a near sample
  std::size_t freeCount_ = 0;
};

// Offsets of the samples between those of a lattice `step` apart, linear on the lattice's
// triangles (the fine grid's triangles lie inside them, so nothing folds).
// Rows in parallel: a pass writes only samples between the lattice's and reads only the
// lattice's.
void prolong(OffsetField& field, int step) {
  const int half = step / 2, n = field.n;
  auto at = [&](int i, int j) { return field.offset[field.index(i, j)]; };
  parallelRows(n / half + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin * half; j < rowEnd * half; j += half)
      for (int i = 0; i <= n; i += half) {
        const bool oddI = i % step != 0, oddJ = j % step != 0;
        if (!oddI && !oddJ) continue;
        std::array<float, 2> d{};
        if (oddI && oddJ) { // on the coarse cell's diagonal: the coarse map stays piecewise linear
          const bool anti =
              cellSplit(n / step, (i - half) / step, (j - half) / step) == CellSplit::AntiDiagonal;
          const auto a = anti ? at(i - half, j + half) : at(i - half, j - half);
          const auto b = anti ? at(i + half, j - half) : at(i + half, j + half);
          for (int c = 0; c < 2; ++c)
            d[c] = 0.5f * (a[c] + b[c]);
        } else if (oddI) {
          for (int c = 0; c < 2; ++c)
            d[c] = 0.5f * (at(i - half, j)[c] + at(i + half, j)[c]);
        } else {
          for (int c = 0; c < 2; ++c)
            d[c] = 0.5f * (at(i, j - half)[c] + at(i, j + half)[c]);
        }
        field.offset[field.index(i, j)] =
            field.free[field.index(i, j)] ? d : std::array<float, 2>{};
      }
  });
}

} // namespace

OffsetField::OffsetField(int size)
    : n(size), offset(static_cast<std::size_t>(size + 1) * static_cast<std::size_t>(size + 1)),
      free(offset.size(), 0) {}

void OffsetField::freeAll() {
  std::fill(free.begin(), free.end(), 1);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (isSideMidpoint(n, {i, j})) free[index(i, j)] = 0;
}

void OffsetField::freeInside(TexelRect rect) {
  for (int j = rect.y + 1; j < rect.y + rect.height - 1; ++j)
    for (int i = rect.x + 1; i < rect.x + rect.width - 1; ++i) {
      const Sample s = wrap(n, {i, j});
      if (isSideMidpoint(n, s)) continue;
      std::array<Sample, 4> copies;
      const int k = identifiedSamples(n, s, copies);
      for (int c = 0; c < k; ++c)
        free[index(copies[static_cast<std::size_t>(c)].i, copies[static_cast<std::size_t>(c)].j)] =
            1;
    }
}

void OffsetField::pin(Sample s) {
  if (s.i < 0 || s.j < 0 || s.i > n || s.j > n) return;
  std::array<Sample, 4> copies;
  const int k = identifiedSamples(n, s, copies);
  for (int c = 0; c < k; ++c)
    free[index(copies[static_cast<std::size_t>(c)].i, copies[static_cast<std::size_t>(c)].j)] = 0;
  pins.push_back(s);
}

bool solveOffsets(const GeometryImage& image, OffsetField& field, int fineIterations,
                  double edgeCap, bool coarseArcs, const RelaxProgress& progress) {
  const int n = field.n;
  std::vector<std::pair<int, int>> plan; // (step, sweeps), coarse to fine
  for (int m = std::min(n, kCoarsest); m <= n; m *= 2)
    plan.emplace_back(n / m, fineIterations * std::max(1, 512 / m)); // coarse sweeps are cheap
  const HeldSamples held(field);
  double total = 0, done = 0;
  for (const auto& [step, sweeps] : plan)
    total += double(sweeps) * double(n / step + 1) * double(n / step + 1);
  for (std::size_t l = 0; l < plan.size(); ++l) {
    const auto [step, sweeps] = plan[l];
    Level level(image, field, held, step, edgeCap, coarseArcs);
    if (l > 0) level.unfoldFromRest();
    if (level.freeCount() > 0)
      for (int s = 0; s < sweeps; ++s) {
        level.sweep();
        done += double(level.size());
        if (progress && !progress(static_cast<float>(done / total))) return false;
      }
    level.store();
    if (step > 1) prolong(field, step);
  }
  return true;
}

void resampleTexel(const Document& from, const OffsetField& field, EditLayer layer, int i, int j,
                   float* out) {
  const int n = field.n;
  const std::size_t side = static_cast<std::size_t>(n + 1);
  auto texel = [&](Sample s, float* value) {
    const std::size_t t = static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i);
    if (layer == EditLayer::Positions) {
      const Vec4f& p = from.positions.at(s);
      value[0] = p.x, value[1] = p.y, value[2] = p.z, value[3] = p.w;
      return;
    }
    const Layer& l = layer == EditLayer::Diffuse   ? from.diffuse
                     : layer == EditLayer::Feature ? from.feature
                                                   : from.mask;
    const std::size_t ch = static_cast<std::size_t>(l.channels);
    for (std::size_t c = 0; c < ch; ++c)
      value[c] = l.uniform() ? l.fill[c] : l.texels[t * ch + c];
  };
  const auto& d = field.offset[field.index(i, j)];
  if (d[0] == 0.0f && d[1] == 0.0f) {
    texel({i, j}, out);
    return;
  }
  const Sample c = canonical(n, {i, j});
  const auto& dc = field.offset[field.index(c.i, c.j)];
  const GridPoint p = locateGridPoint(n, double(c.i) + dc[0], double(c.j) + dc[1]);
  const std::size_t channels = static_cast<std::size_t>(editLayerChannels(layer));
  std::array<float, 4> value{};
  for (std::size_t ch = 0; ch < channels; ++ch)
    out[ch] = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    texel(p.corners[k], value.data());
    for (std::size_t ch = 0; ch < channels; ++ch)
      out[ch] += value[ch] * p.weights[k];
  }
}

void resampleDocument(const Document& from, const OffsetField& field, Document& to) {
  const int n = field.n;
  std::vector<std::pair<EditLayer, float*>> layers{
      {EditLayer::Positions, &to.positions.texels()[0].x}};
  // A uniform layer resamples to its own fill: it stays uniform.
  if (!from.diffuse.uniform()) layers.emplace_back(EditLayer::Diffuse, to.diffuse.texels.data());
  if (!from.feature.uniform()) layers.emplace_back(EditLayer::Feature, to.feature.texels.data());
  if (from.hasMask && !from.mask.uniform())
    layers.emplace_back(EditLayer::Mask, to.mask.texels.data());
  parallelRows(n + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= n; ++i) {
        const std::size_t t = field.index(i, j);
        if (field.offset[t][0] == 0.0f && field.offset[t][1] == 0.0f) continue; // keeps its bits
        for (const auto& [layer, texels] : layers) {
          const std::size_t channels = static_cast<std::size_t>(editLayerChannels(layer));
          resampleTexel(from, field, layer, i, j, texels + t * channels);
        }
      }
  });
}

} // namespace octaclay::core::detail
