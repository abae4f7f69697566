#include "octaclay/core/document/resize.h"

#include "detail/parallel_rows.h"
#include "measure/move_tolerance.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/measure/stretch.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace octaclay::core {
namespace {

// The Catmull-Rom kernel (a = -1/2): 1 at 0, 0 at the other integers, support (-2, 2).
double catmullRom(double x) {
  x = std::abs(x);
  if (x < 1) return (1.5 * x - 2.5) * x * x + 1;
  if (x < 2) return ((-0.5 * x + 2.5) * x - 4) * x + 2;
  return 0;
}

// One axis's taps: the old sample offsets from a base position and their weights.
struct Taps {
  int base = 0;
  std::vector<double> weights; // for base, base + 1, …
};

// The taps for new sample k of an m grid (m > n) from an n grid along one axis: Catmull-Rom
// interpolation at k·n/m.
Taps tapsFor(int k, int n, int m) {
  Taps t;
  const int r = m / n;
  const int whole = k / r;
  const double frac = double(k % r) / double(r);
  t.base = whole - 1;
  for (int a = -1; a <= 2; ++a)
    t.weights.push_back(catmullRom(double(a) - frac));
  return t;
}

// The sample that grid sample s is the same vertex as and takes its bits from: the ball's
// canonical one, a torus's (i mod W, j mod H); a plane's samples are all their own.
Sample canonicalIn(const SampleGrid& grid, Sample s) {
  // wrap() takes a torus's column W and row H to 0 and leaves a plane's samples as they are.
  return grid.topology == Topology::Octahedral ? canonical(grid.width, s) : wrap(grid, s);
}

// Gives every identified sample of a (W+1) × (H+1) field of `ch` floats its canonical one's.
void copyIdentified(const SampleGrid& grid, std::size_t ch, float* field) {
  if (grid.topology == Topology::Plane) return;
  const std::size_t side = static_cast<std::size_t>(grid.width + 1);
  for (int j = 0; j <= grid.height; ++j)
    for (int i = 0; i <= grid.width; ++i) {
      const Sample c = canonicalIn(grid, {i, j});
      if (c == Sample{i, j}) continue;
      std::copy_n(
          &field[(static_cast<std::size_t>(c.j) * side + static_cast<std::size_t>(c.i)) * ch], ch,
          &field[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * ch]);
    }
}

// Resamples a field of `channels` floats per sample of the `from` grid, read by value(sample,
// out), onto the finer `to` grid ((W'+1) × (H'+1) × channels floats); clamp: each channel kept
// within the values of the taps that carry weight (no overshoot).
template <class Value>
std::vector<float> resampleField(const SampleGrid& from, const SampleGrid& to, int channels,
                                 bool clamp, const Value& value) {
  const std::size_t side = static_cast<std::size_t>(to.width + 1),
                    ch = static_cast<std::size_t>(channels);
  std::vector<Taps> across, down;
  for (int k = 0; k <= to.width; ++k)
    across.push_back(tapsFor(k, from.width, to.width));
  for (int k = 0; k <= to.height; ++k)
    down.push_back(tapsFor(k, from.height, to.height));
  std::vector<float> out(side * static_cast<std::size_t>(to.height + 1) * ch);
  detail::parallelRows(to.height + 1, [&](int rowBegin, int rowEnd) {
    std::array<float, 4> v{};
    std::array<double, 4> sum{}, lo{}, hi{};
    for (int j = rowBegin; j < rowEnd; ++j) {
      const Taps& ty = down[static_cast<std::size_t>(j)];
      // Only the samples on the grid's canonical positions matter; the rest are copied below.
      for (int i = 0; i <= to.width; ++i) {
        const Taps& tx = across[static_cast<std::size_t>(i)];
        sum.fill(0);
        lo.fill(1e300);
        hi.fill(-1e300);
        for (std::size_t b = 0; b < ty.weights.size(); ++b) {
          if (ty.weights[b] == 0) continue;
          for (std::size_t a = 0; a < tx.weights.size(); ++a) {
            const double w = tx.weights[a] * ty.weights[b];
            if (w == 0) continue;
            value(wrap(from, {tx.base + int(a), ty.base + int(b)}), v.data());
            for (std::size_t c = 0; c < ch; ++c) {
              sum[c] += w * double(v[c]);
              lo[c] = std::min(lo[c], double(v[c]));
              hi[c] = std::max(hi[c], double(v[c]));
            }
          }
        }
        float* o = &out[(static_cast<std::size_t>(j) * side + static_cast<std::size_t>(i)) * ch];
        for (std::size_t c = 0; c < ch; ++c)
          o[c] = static_cast<float>(clamp ? std::clamp(sum[c], lo[c], hi[c]) : sum[c]);
      }
    }
  });
  copyIdentified(to, ch, out.data());
  return out;
}

// Catmull-Rom swings out beside long edges (a stretched limb's 64× the median: 2.5 % of the
// diagonal at its tip). Each new sample's offset from the old surface at its point (linear on
// the old grid's triangles, as extractMesh splits the cells) is cut to a tenth of the old
// median edge, far above the sagitta of a smooth surface's cell (h/8R of h) and far below an
// overshoot beside a long edge. Identified samples get their canonical sample's bits again.
void limitOvershoot(const GeometryImage& from, GeometryImage& to) {
  const bool ball = from.topology() == Topology::Octahedral;
  const int w = from.width(), h = from.height(), r = to.width() / w, half = w / 2;
  const double cap = 0.1 * summarizeStretch(from).medianEdge;
  if (!(cap > 0)) return;
  detail::parallelRows(to.height() + 1, [&](int rowBegin, int rowEnd) {
    for (int j = rowBegin; j < rowEnd; ++j)
      for (int i = 0; i <= to.width(); ++i) {
        const int ci = std::min(i / r, w - 1), cj = std::min(j / r, h - 1);
        const double u = double(i - ci * r) / r, v = double(j - cj * r) / r;
        const Vec3f a = from.at(ci, cj).xyz(), b = from.at(ci + 1, cj).xyz(),
                    c = from.at(ci + 1, cj + 1).xyz(), d = from.at(ci, cj + 1).xyz();
        Vec3f p;
        // A torus's or plane's cells all split along the anti-diagonal.
        if (!ball || (ci < half) == (cj < half)) // triangles abd and bcd
          p = u + v <= 1 ? a + (b - a) * float(u) + (d - a) * float(v)
                         : c + (d - c) * float(1 - u) + (b - c) * float(1 - v);
        else // triangles abc and acd
          p = u >= v ? a + (b - a) * float(u) + (c - b) * float(v)
                     : a + (c - d) * float(u) + (d - a) * float(v);
        Vec4f& q = to.at(i, j);
        const Vec3f offset = q.xyz() - p;
        const double distance = length(offset);
        if (distance > cap) {
          const Vec3f limited = p + offset * float(cap / distance);
          q = {limited.x, limited.y, limited.z, q.w};
        }
      }
  });
  copyIdentified(to.grid(), 4, reinterpret_cast<float*>(to.texels().data()));
}

void resizeLayer(const Layer& from, Layer& to, const SampleGrid& fromGrid,
                 const SampleGrid& toGrid) {
  to = from;
  if (from.uniform()) return;
  const std::size_t side = static_cast<std::size_t>(fromGrid.width + 1),
                    ch = static_cast<std::size_t>(from.channels);
  to.texels = resampleField(fromGrid, toGrid, from.channels, true, [&](Sample s, float* v) {
    const float* t =
        &from.texels[(static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i)) * ch];
    std::copy_n(t, ch, v);
  });
}

// The grid `factor` times finer (or coarser, factor < 1 as a halving: 1 / 2) than `grid`.
SampleGrid scaledGrid(const SampleGrid& grid, int numerator, int denominator) {
  return {grid.topology, grid.width * numerator / denominator,
          grid.height * numerator / denominator};
}

} // namespace

namespace {

// One resampling step, n → m with m ≥ n or m = n/2.
// Up, n → m > n: Catmull-Rom, positions limited (limitOvershoot), painted layers clamped.
Document resizeUp(const Document& document, int m) {
  const SampleGrid& from = document.positions.grid();
  const SampleGrid to = scaledGrid(from, m, from.width);
  Document out = document;
  out.positions = GeometryImage(to.topology, to.width, to.height);
  const std::vector<float> positions = resampleField(from, to, 4, false, [&](Sample s, float* v) {
    const Vec4f& p = document.positions.at(s);
    v[0] = p.x, v[1] = p.y, v[2] = p.z, v[3] = p.w;
  });
  std::span<Vec4f> texels = out.positions.texels();
  for (std::size_t t = 0; t < texels.size(); ++t)
    texels[t] = {positions[4 * t], positions[4 * t + 1], positions[4 * t + 2],
                 positions[4 * t + 3]};
  limitOvershoot(document.positions, out.positions);
  resizeLayer(document.diffuse, out.diffuse, from, to);
  resizeLayer(document.feature, out.feature, from, to);
  resizeLayer(document.mask, out.mask, from, to);
  return out;
}

// Down, n → n/2, by lifting (Sweldens 1996) with resizeUp as its prediction: the even samples
// e, predicted back up, leave the details d = y − resizeUp(e) (0 on the even samples); each
// new sample is e plus d's mean around it, weighted 1/8 on the four samples beside and 1/16 on
// the four diagonal ones, the weights that cancel the grid's Nyquist frequencies along each
// axis and both. A document that resizeUp made has no details, so down after up gives it back
// bit for bit, where the up's limit acted too. Painted layers are clamped to the 3 × 3 samples
// around (no ringing at a paint edge).
Document resizeDown(const Document& document) {
  const SampleGrid& finer = document.positions.grid();
  const SampleGrid coarse = scaledGrid(finer, 1, 2);
  const int n = finer.width, m = coarse.width, mh = coarse.height;
  const bool sheet = coarse.topology == Topology::Plane;
  const std::size_t oldSide = static_cast<std::size_t>(n + 1),
                    side = static_cast<std::size_t>(m + 1);
  Document even = document;
  even.positions = GeometryImage(coarse.topology, m, mh);
  for (int j = 0; j <= mh; ++j)
    for (int i = 0; i <= m; ++i)
      even.positions.at(i, j) = document.positions.at(2 * i, 2 * j);
  for (const auto& [from, to] : {std::pair{&document.diffuse, &even.diffuse},
                                 {&document.feature, &even.feature},
                                 {&document.mask, &even.mask}}) {
    if (from->uniform()) continue;
    const std::size_t ch = static_cast<std::size_t>(from->channels);
    to->texels.assign(side * static_cast<std::size_t>(mh + 1) * ch, 0.0f);
    for (int j = 0; j <= mh; ++j)
      for (int i = 0; i <= m; ++i)
        std::copy_n(&from->texels[(std::size_t(2 * j) * oldSide + std::size_t(2 * i)) * ch], ch,
                    &to->texels[(std::size_t(j) * side + std::size_t(i)) * ch]);
  }
  const Document predicted = resizeUp(even, n);
  Document out = even;
  // new(i, j) = e(i, j) + Σ w · (y − predicted) around (2i, 2j), each channel of `count`.
  const auto update = [&](int count, const auto& fine, const auto& guess, const auto& write,
                          bool clamp) {
    detail::parallelRows(mh + 1, [&](int rowBegin, int rowEnd) {
      std::array<float, 4> y{}, p{};
      std::array<double, 4> sum{}, lo{}, hi{};
      for (int j = rowBegin; j < rowEnd; ++j)
        for (int i = 0; i <= m; ++i) {
          sum.fill(0);
          lo.fill(1e300);
          hi.fill(-1e300);
          // A sheet's outline is lifted along itself alone (weights 1/4 beside, the 1D
          // update), so it stays on its curve; its corners stay.
          const bool edgeI = sheet && (i == 0 || i == m), edgeJ = sheet && (j == 0 || j == mh);
          for (int b = -1; b <= 1; ++b)
            for (int a = -1; a <= 1; ++a) {
              if ((edgeI && a != 0) || (edgeJ && b != 0)) continue;
              const Sample s = wrap(finer, {2 * i + a, 2 * j + b});
              fine(s, y.data());
              guess(s, p.data());
              const double w = a == 0 && b == 0   ? 0.0
                               : edgeI || edgeJ   ? 0.25
                               : a == 0 || b == 0 ? 0.125
                                                  : 0.0625;
              for (int c = 0; c < count; ++c) {
                sum[std::size_t(c)] += w * (double(y[std::size_t(c)]) - double(p[std::size_t(c)]));
                lo[std::size_t(c)] = std::min(lo[std::size_t(c)], double(y[std::size_t(c)]));
                hi[std::size_t(c)] = std::max(hi[std::size_t(c)], double(y[std::size_t(c)]));
              }
            }
          fine(Sample{2 * i, 2 * j}, y.data());
          for (int c = 0; c < count; ++c) {
            const double v = double(y[std::size_t(c)]) + sum[std::size_t(c)];
            sum[std::size_t(c)] = clamp ? std::clamp(v, lo[std::size_t(c)], hi[std::size_t(c)]) : v;
          }
          write(i, j, sum.data());
        }
    });
  };
  update(
      4,
      [&](Sample s, float* v) {
        const Vec4f& q = document.positions.at(s);
        v[0] = q.x, v[1] = q.y, v[2] = q.z, v[3] = q.w;
      },
      [&](Sample s, float* v) {
        const Vec4f& q = predicted.positions.at(s);
        v[0] = q.x, v[1] = q.y, v[2] = q.z, v[3] = q.w;
      },
      [&](int i, int j, const double* v) {
        out.positions.at(i, j) = {float(v[0]), float(v[1]), float(v[2]), float(v[3])};
      },
      false);
  for (const auto& [from, guess, to] :
       {std::tuple{&document.diffuse, &predicted.diffuse, &out.diffuse},
        {&document.feature, &predicted.feature, &out.feature},
        {&document.mask, &predicted.mask, &out.mask}}) {
    if (from->uniform()) continue;
    const int ch = from->channels;
    const std::size_t chs = static_cast<std::size_t>(ch);
    const auto read = [oldSide, chs](const Layer& layer) {
      return [&layer, oldSide, chs](Sample s, float* v) {
        std::copy_n(&layer.texels[(std::size_t(s.j) * oldSide + std::size_t(s.i)) * chs], chs, v);
      };
    };
    Layer* const target = to; // clang 14 (the fuzz build) captures no structured binding
    update(
        ch, read(*from), read(*guess),
        [&, chs, target](int i, int j, const double* v) {
          float* o = &target->texels[(std::size_t(j) * side + std::size_t(i)) * chs];
          for (std::size_t c = 0; c < chs; ++c)
            o[c] = static_cast<float>(v[c]);
        },
        true);
  }
  // Identified samples: the canonical one's bits.
  copyIdentified(coarse, 4, reinterpret_cast<float*>(out.positions.texels().data()));
  for (Layer* l : {&out.diffuse, &out.feature, &out.mask})
    if (!l->uniform())
      copyIdentified(coarse, static_cast<std::size_t>(l->channels), l->texels.data());
  return out;
}

} // namespace

Document resizeDocument(const Document& document, int m) {
  requireValidSize(m);
  // A torus or plane: W becomes m, H in proportion (a valid grid of its topology).
  const SampleGrid& grid = document.positions.grid();
  if (grid.topology != Topology::Octahedral) {
    const SampleGrid to{grid.topology, m,
                        m >= grid.width ? grid.height * (m / grid.width)
                                        : grid.height / (grid.width / m)};
    if (!isValidGrid(to))
      throw Error(ErrorKind::InvalidArgument,
                  "size " + std::to_string(m) + " would make this " + std::to_string(grid.width) +
                      " × " + std::to_string(grid.height) + " " +
                      std::string(topologyName(grid.topology)) + " " + std::to_string(to.width) +
                      " × " + std::to_string(to.height) +
                      ": its sides must be powers of two up to 8192, at least " +
                      std::to_string(grid.topology == Topology::Torus ? kMinTorusSize : kMinSize));
  }
  if (const auto problem = positionsProblem(document.positions))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be resized");
  Document out = document;
  while (out.size() > m)
    out = resizeDown(out);
  if (out.size() < m) out = resizeUp(out, m);
  return out;
}

ResizeResult resizeAndCheck(const Document& document, const ResizeOptions& options) {
  ResizeResult out;
  Document resized = resizeDocument(document, options.size);
  const int n = document.size(), m = options.size;
  out.before = summarizeStretch(document.positions);
  out.after = summarizeStretch(resized.positions);
  const TriangleMesh before = extractMesh(document.positions);
  if (boundingBox(before).diagonal() > 0)
    out.moved = compareSurfaces(before, extractMesh(resized.positions),
                                {.samplesPerSurface = options.samplesPerSurface});
  const double scale = m < n ? double(n / m) * double(n / m) : 1.0;
  if (const auto problem = positionsProblem(resized.positions))
    out.reason = "the result would not be finite (" + *problem + ")";
  else
    out.reason = detail::surfaceMovedTooFar(out.moved, scale * options.rmsTolerance,
                                            scale * options.hausdorffTolerance);
  if (!out.reason.empty()) {
    if (m < n)
      out.reason += ": N = " + std::to_string(m) +
                    " has too few samples for its stretched parts (Remesh first, or keep N)";
    out.document = document;
    return out;
  }
  out.document = std::move(resized);
  out.changed = m != n;
  return out;
}

} // namespace octaclay::core
