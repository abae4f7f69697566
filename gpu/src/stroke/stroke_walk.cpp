#include "stroke_settings_check.h"
#include "stroke_state.h"
#include "value_text.h"

#include "octaclay/gpu/stroke_rules.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

// The walk along a path: dabs a spacing apart, measured on the surface as the stroke began.
namespace octaclay::gpu {
namespace {

// The parameters t in (0, 1) at which from + t × delta crosses an integer.
void addCrossings(double from, double delta, std::vector<double>& ts) {
  if (delta == 0) return;
  const double lo = std::min(from, from + delta), hi = std::max(from, from + delta);
  for (double k = std::ceil(lo); k <= hi; ++k)
    if (const double t = (k - from) / delta; t > 0 && t < 1) ts.push_back(t);
}

// The parameters 0 = t0 < t1 < … < 1 that cut the segment a → b (image coordinates, in
// samples) where it crosses a cell's side or diagonal: the surface is linear between two.
std::vector<double> linearPieces(std::array<double, 2> a, std::array<double, 2> b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  std::vector<double> ts{0.0, 1.0};
  addCrossings(a[0], dx, ts);
  addCrossings(a[1], dy, ts);
  addCrossings(a[0] + a[1], dx + dy, ts); // anti-diagonals
  addCrossings(a[0] - a[1], dx - dy, ts); // main diagonals
  std::sort(ts.begin(), ts.end());
  ts.erase(std::unique(ts.begin(), ts.end()), ts.end());
  return ts;
}

} // namespace

// Moves the stroke to image point xy (in samples): the first move dabs there, later ones
// walk from the previous point.
int StrokeSession::State::moveTo(std::array<double, 2> xy, float radius, float strength,
                                 float pressure) {
  if (abandoned) throw std::logic_error("StrokeSession::moveTo after a dab failed");
  if (finished) throw std::logic_error("StrokeSession::moveTo after finish()");
  requireFinite("the radius", radius);
  requireFinite("the strength", strength);
  requireFinite("the pressure", pressure);
  const auto start = std::chrono::steady_clock::now();
  const int before = dabs;
  if (!previous || brush.stroke == StrokeKind::Anchored) {
    // An anchored stroke makes one dab where it began, again for each move: no walk.
    if (!previous || xy != *previous) dabAt(xy, radius, strength, pressure);
    previous = xy;
  } else {
    walkTo(xy, radius, strength, pressure);
  }
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  engineMs += ms;
  if (!firstMoveMs && dabs > before) {
    firstMoveMs = ms;
    firstMoveDabs = dabs - before;
  }
  return dabs - before;
}

// Walks the straight segment from the previous point to b (image coordinates, in samples),
// dabbing each time the distance since the last dab reaches spacing (object units). The
// distance is exact on the start surface's triangles; the remainder carries to the next walk.
void StrokeSession::State::walkTo(std::array<double, 2> b, float radius, float strength,
                                  float pressure) {
  const std::array<double, 2> a = *previous;
  const double spacing = spacingFor(radius);
  // The spacing shrank since the last walk (pen pressure on the radius): a dab is due now.
  travelled = std::min(travelled, spacing);
  const auto at = [&](double t) {
    return std::array<double, 2>{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])};
  };
  const std::vector<double> ts = linearPieces(a, b);
  std::vector<double> lengths(ts.size() - 1);
  double total = 0;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const auto p0 = at(ts[k]), p1 = at(ts[k + 1]);
    lengths[k] = core::length(startPosition(p1[0], p1[1]) - startPosition(p0[0], p0[1]));
    total += lengths[k];
  }
  requireDabBudget(total + travelled, spacing);
  previous = b;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t0 = ts[k], t1 = ts[k + 1];
    const double length = lengths[k];
    double used = 0; // of this piece, up to the last dab on it
    while (travelled + (length - used) >= spacing) {
      used += spacing - travelled;
      travelled = 0;
      const double f = length > 0 ? std::clamp(used / length, 0.0, 1.0) : 0.0;
      dabAt(at(t0 + (t1 - t0) * f), radius, strength, pressure);
    }
    travelled += length - used;
  }
}

// Between dabs at this radius, object units: the brush's spacing, and at most 1e4 dabs per
// diagonal (a radius far below a sample would otherwise make dabs without end).
double StrokeSession::State::spacingFor(float radius) const {
  return std::max(static_cast<double>(dabSpacing(brush, settings.spacing)) * std::abs(radius),
                  1e-4 * diagonal);
}

// The length of the straight walk a → b (image coordinates, in samples) on the surface as
// the stroke began.
double StrokeSession::State::walkLength(std::array<double, 2> a, std::array<double, 2> b) const {
  const std::vector<double> ts = linearPieces(a, b);
  double total = 0;
  for (std::size_t k = 0; k + 1 < ts.size(); ++k) {
    const double t0 = ts[k], t1 = ts[k + 1];
    total += core::length(startPosition(a[0] + t1 * (b[0] - a[0]), a[1] + t1 * (b[1] - a[1])) -
                          startPosition(a[0] + t0 * (b[0] - a[0]), a[1] + t0 * (b[1] - a[1])));
  }
  return total;
}

// Refuses, before any dab of this move, a walk of `length` (object units) at `spacing` that
// would take the stroke past kMaxStrokeDabs: a drag to infinity or a radius far below a
// sample would otherwise dab without end.
void StrokeSession::State::requireDabBudget(double length, double spacing) const {
  const double expected = dabs + imagesPerDab() * std::floor(length / spacing);
  if (expected <= kMaxStrokeDabs) return;
  detail::badSetting("the stroke would make about " + detail::shortNumber(expected) +
                     " dabs (a path " + detail::shortNumber(length / diagonal) +
                     " diagonals long at a spacing of " + detail::shortNumber(spacing / diagonal) +
                     " diagonals); a stroke makes at most " + std::to_string(kMaxStrokeDabs) +
                     ": use a larger spacing or radius, or a shorter path");
}

} // namespace octaclay::gpu
