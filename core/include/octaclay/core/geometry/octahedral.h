#pragma once

#include "octaclay/core/geometry/vec.h"

#include <array>
#include <cstdint>

namespace octaclay::core {

/// An integer sample position: i along the image's columns (u), j along its rows (v).
struct Sample {
  int i = 0, j = 0;
  friend bool operator==(Sample a, Sample b) = default;
};

inline constexpr int kMinSize = 2;
inline constexpr int kMaxSize = 8192;

/// True for N = 2, 4, … 8192: the sizes a geometry image may have.
bool isValidSize(int n);

/// Throws Error(InvalidArgument) naming n when !isValidSize(n).
void requireValidSize(int n);

/// The unit octahedron direction of sample (i, j) of an N grid, normalized.
Vec3f octahedralDirection(int n, int i, int j);

/// The point (s, t) ∈ [0, 1]² of the octahedral square whose direction is `direction` (any
/// non-zero vector): the inverse of octahedralDirection, so that sample (i, j) of an N grid
/// has (s, t) = (i / N, j / N). Directions on a fold of the square (z < 0 with x = 0 or
/// y = 0) have two or four such points; one of them is returned.
std::array<double, 2> octahedralSquarePoint(Vec3f direction);

/// wrap() and the symmetry of the tiling that takes the grid sample back to s: a translation,
/// or a half-turn (a 180° rotation, which negates offsets measured at the grid sample).
struct OrientedSample {
  Sample sample;
  bool halfTurn = false;
};
/// wrapOriented() of a sample outside the grid.
OrientedSample wrapOrientedOutside(int n, Sample s);
/// Inline, so the relaxation's sweeps and every located grid point pay no call for the samples
/// inside the grid (nearly all): they are themselves.
inline OrientedSample wrapOriented(int n, Sample s) {
  if (s.i >= 0 && s.j >= 0 && s.i <= n && s.j <= n) return {s, false};
  return wrapOrientedOutside(n, s);
}

/// The grid sample (0 ≤ i, j ≤ n) that integer position s stands for in the octahedral tiling of
/// the plane. Works for any int position (many periods away too); identity inside the grid.
inline Sample wrap(int n, Sample s) {
  return wrapOriented(n, s).sample;
}

/// The one representative of the samples identified with grid sample s (corners → (0,0); a side
/// sample → the one in the side's first half). Precondition: s inside the grid.
Sample canonical(int n, Sample s);

/// The grid samples that are the same vertex as s, s included; returns how many (1, 2 or 4).
int identifiedSamples(int n, Sample s, std::array<Sample, 4>& out);

/// Calls run(j, iBegin, iEnd) for each row j = 0 … n with the half-open range of columns whose
/// samples are canonical, in row-major order: the order in which vertices are numbered.
template <class Run> void forEachCanonicalRun(int n, Run&& run) {
  run(0, 0, n / 2 + 1);
  for (int j = 1; j <= n / 2; ++j)
    run(j, 0, n + 1);
  for (int j = n / 2 + 1; j < n; ++j)
    run(j, 1, n);
  run(n, 1, n / 2 + 1);
}

/// How the cell with lower-left sample (i, j) of the tiled plane is split into two triangles:
/// along the anti-diagonal (i, j+1)–(i+1, j) or the main diagonal (i, j)–(i+1, j+1).
enum class CellSplit { AntiDiagonal, MainDiagonal };
CellSplit cellSplit(int n, int i, int j);

/// The two triangles of cell (i, j), counter-clockwise in (i, j) (outward on the surface).
std::array<std::array<Sample, 3>, 2> cellTriangles(int n, int i, int j);

/// Triangles of the tiled plane incident to position s (4 or 6), counter-clockwise, each
/// rotated so that s comes first. Positions are unwrapped: pass them through wrap().
int incidentTriangles(int n, Sample s, std::array<std::array<Sample, 3>, 6>& out);

} // namespace octaclay::core
