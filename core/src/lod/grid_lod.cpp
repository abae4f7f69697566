// generateLod (lod.h) for a torus or a plane. LOD sample (a, b) stands for full-resolution
// sample (a·d, b·d). A torus's wrap lines (column and row 0, identified with W and H) and a
// plane's boundary are treated as the ball's seams: salient samples on them pick along them,
// and a collapse slides their vertices only along them, so the wrap stays exact and the sheet
// keeps its outline. A plane's boundary samples average along the boundary only.
#include "lod/grid_lod.h"

#include "detail/parallel_rows.h"
#include "lod/lod_corners.h"
#include "lod/quadric_collapse.h"
#include "lod/refit.h"
#include "lod/resampling.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <string>

namespace octaclay::core::detail {
namespace {

int minCells(Topology topology) {
  return topology == Topology::Torus ? kMinTorusSize : kMinSize;
}

// d, a power of two: from options.size (M = max(W, H)/d) or the triangle target.
int chooseDivisor(const GeometryImage& image, const LodOptions& options) {
  const int w = image.width(), h = image.height();
  const int longest = std::max(w, h), shortest = std::min(w, h);
  const int fewest = minCells(image.topology());
  const std::string shape = std::to_string(w) + " × " + std::to_string(h) + " " +
                            std::string(topologyName(image.topology()));
  if (options.size != 0) {
    requireLodSize(longest, options.size);
    const int d = longest / options.size;
    if (shortest / d < fewest)
      throw Error(ErrorKind::InvalidArgument,
                  "LOD size " + std::to_string(options.size) + " leaves fewer than " +
                      std::to_string(fewest) + " cells across this " + shape + "; use at least " +
                      std::to_string(longest / (shortest / fewest)));
    return d;
  }
  if (shortest / 2 < fewest)
    throw Error(ErrorKind::InvalidArgument,
                "this " + shape + " is too small for a level of detail");
  int d = shortest / fewest; // the coarsest grid, then finer until the target is reached
  while (d > 2 && options.targetTriangles > 0 &&
         2.0 * double(w / d) * double(h / d) < double(options.targetTriangles))
    d /= 2;
  if (options.targetTriangles == 0) d = 2;
  return std::max(2, d / options.oversample);
}

// Whether LOD sample (a, b) of an mw × mh grid lies on a wrap line or the boundary (per axis).
struct OnLine {
  bool i = false, j = false;
};

OnLine onLine(int mw, int mh, Sample s) {
  return {s.i == 0 || s.i == mw, s.j == 0 || s.j == mh};
}

struct Choice {
  Vec4f texel;
  Sample source;
};

// The footprint's mean (weight ½ on its rim rows and columns), through the grid's wrap; along
// a line only where `along` says (a plane's boundary keeps its outline).
Choice averageFootprint(const GeometryImage& image, Sample centre, int half, OnLine along,
                        bool salient) {
  return {footprintMean(centre, along.i ? 0 : half, along.j ? 0 : half, salient,
                        [&](Sample s) -> const Vec4f& { return image.at(wrap(image.grid(), s)); }),
          centre};
}

// The most salient sample within d/4 of the centre (ties: nearest, then first in row order),
// along its lines only; where two lines meet the sample stays. Inside the image: no wrap.
Choice salientFootprint(const GeometryImage& image, Sample centre, int step, OnLine line) {
  Choice best{image.at(centre), centre};
  if (line.i && line.j) return best;
  const int reach = step / 4;
  int bestDistance = 0;
  for (int dj = line.j ? 0 : -reach; dj <= (line.j ? 0 : reach); ++dj)
    for (int di = line.i ? 0 : -reach; di <= (line.i ? 0 : reach); ++di) {
      const Sample s{centre.i + di, centre.j + dj};
      const Vec4f& t = image.at(s);
      const int distance = di * di + dj * dj;
      if (t.w > best.texel.w || (t.w == best.texel.w && distance < bestDistance)) {
        best = {t, s};
        bestDistance = distance;
      }
    }
  return best;
}

ResampledImage resampleGrid(const GeometryImage& image, int d, ResampleMethod method) {
  const int mw = image.width() / d, mh = image.height() / d;
  const bool torus = image.topology() == Topology::Torus;
  ResampledImage out{GeometryImage(image.topology(), mw, mh), {}};
  const int side = mw + 1;
  out.source.resize(static_cast<std::size_t>(side) * static_cast<std::size_t>(mh + 1));
  parallelRows(
      mh + 1,
      [&](int rowBegin, int rowEnd) {
        for (int b = rowBegin; b < rowEnd; ++b)
          for (int a = 0; a <= mw; ++a) {
            const Sample lod{a, b}, centre{a * d, b * d};
            const OnLine line = onLine(mw, mh, lod);
            Choice c{image.at(centre), centre};
            if (method == ResampleMethod::Average || method == ResampleMethod::SalientAverage)
              c = averageFootprint(image, centre, d / 2, torus ? OnLine{} : line,
                                   method == ResampleMethod::SalientAverage);
            else if (method == ResampleMethod::SalientPoint)
              c = salientFootprint(image, centre, d, line);
            out.image.at(lod) = c.texel;
            out.source[static_cast<std::size_t>(b) * side + a] = {float(c.source.i),
                                                                  float(c.source.j)};
          }
      },
      32);
  if (torus) // column mw and row mh are column and row 0 again, one period on
    for (int b = 0; b <= mh; ++b)
      for (int a = 0; a <= mw; ++a) {
        if (a < mw && b < mh) continue;
        const Sample c{a % mw, b % mh};
        out.image.at(a, b) = out.image.at(c);
        const Vec2f src = out.source[static_cast<std::size_t>(c.j) * side + c.i];
        out.source[static_cast<std::size_t>(b) * side + a] = {
            src.x + float(a == mw ? image.width() : 0),
            src.y + float(b == mh ? image.height() : 0)};
      }
  return out;
}

// Where a vertex may go in a collapse: interior anywhere; a line vertex along its line (into one
// of the same line or a vertex where lines meet on it); where two lines meet, nowhere.
enum class LineClass : std::uint8_t { Interior, Corner, Left, Right, Bottom, Top };

LineClass lineClass(int mw, int mh, Sample s) {
  const OnLine line = onLine(mw, mh, s);
  if (line.i && line.j) return LineClass::Corner;
  if (line.i) return s.i == 0 ? LineClass::Left : LineClass::Right;
  if (line.j) return s.j == 0 ? LineClass::Bottom : LineClass::Top;
  return LineClass::Interior;
}

bool onSameLine(LineClass c, Sample a, Sample b) {
  switch (c) {
  case LineClass::Left:
  case LineClass::Right:
    return a.i == b.i;
  case LineClass::Bottom:
  case LineClass::Top:
    return a.j == b.j;
  default:
    return false;
  }
}

} // namespace

LodMesh gridLod(const GeometryImage& image, const LodOptions& options) {
  ResampleMethod method = options.method;
  if (method == ResampleMethod::Auto)
    method = options.autoMayCollapse ? ResampleMethod::Collapse : ResampleMethod::SalientPoint;
  if (method == ResampleMethod::Adaptive) method = ResampleMethod::Collapse;
  const bool fullCollapse = method == ResampleMethod::Collapse;
  // The collapse method keeps every sample and, without a target, collapses to the d grid's
  // triangles, as the ball's does to its M grid's.
  const int d = chooseDivisor(image, options);
  const ResampledImage resampled =
      fullCollapse ? resampleGrid(image, 1, ResampleMethod::Point) : resampleGrid(image, d, method);
  const SampleGrid& grid = resampled.image.grid();
  const int mw = grid.width, mh = grid.height, side = mw + 1;
  const bool torus = grid.topology == Topology::Torus;

  LodMesh lod;
  lod.resampledSize = std::max(mw, mh);
  lod.methodUsed = method;
  lod.mesh = extractMesh(resampled.image);
  // Vertex v is sample (v mod columns, v / columns) (the grid mesh's order).
  const int columns = torus ? mw : mw + 1;
  std::vector<Sample> sampleOf(lod.mesh.positions.size());
  std::vector<VertexCopies> copies(lod.mesh.positions.size());
  const float invW = 1.0f / float(image.width()), invH = 1.0f / float(image.height());
  for (std::size_t v = 0; v < sampleOf.size(); ++v) {
    const Sample s{int(v % std::size_t(columns)), int(v / std::size_t(columns))};
    sampleOf[v] = s;
    std::array<Sample, 4> same;
    VertexCopies& c = copies[v];
    c.count = identifiedSamples(grid, s, same);
    for (int k = 0; k < c.count; ++k) {
      const Vec2f src = resampled.source[static_cast<std::size_t>(same[k].j) * side + same[k].i];
      c.uv[k] = {src.x * invW, src.y * invH};
    }
  }

  std::size_t target = options.targetTriangles;
  if (fullCollapse && target == 0 && options.maxError == 0)
    target = 2 * std::size_t(image.width() / d) * std::size_t(image.height() / d);
  if ((target > 0 && target < lod.mesh.triangles.size()) || options.maxError > 0) {
    LodOptions collapseWith = options;
    collapseWith.targetTriangles = target;
    if (fullCollapse) { // as the ball's collapse method: no aspect bound, 90° per collapse
      collapseWith.maxAspectRatio = 0;
      collapseWith.maxNormalTurnDegrees = kCollapseNormalTurnDegrees;
    }
    std::vector<LineClass> classes(sampleOf.size());
    for (std::size_t v = 0; v < sampleOf.size(); ++v)
      classes[v] = lineClass(mw, mh, sampleOf[v]);
    VertexCollapseOptions collapseOptions = collapseOptionsFor(
        collapseWith, copies, fullCollapse,
        fullCollapse ? saliencyWeights(image, sampleOf, options.collapseSaliencyWeight)
                     : std::vector<float>{});
    collapseOptions.openBoundary = grid.topology == Topology::Plane;
    collapseOptions.allowCollapse = [&](std::uint32_t from, std::uint32_t to) {
      const LineClass c = classes[from];
      if (c == LineClass::Interior) return true;
      if (c == LineClass::Corner) return false;
      return classes[to] == c ||
             (classes[to] == LineClass::Corner && onSameLine(c, sampleOf[from], sampleOf[to]));
    };
    // A torus or plane mesh has no seams for the Decimater's closed-mesh check to pass: the
    // fast engine, which collapses a plane's boundary too, always.
    takeCollapsed(lod, quadricCollapse(lod.mesh, collapseOptions), copies);
  } else {
    setCornerCoordinates(lod, copies);
  }
  if (options.refitToSurface) {
    const double cells = double(image.width()) * double(image.height());
    refitToSurface(image, lod.cornerUv, lod.mesh, refitStride(cells, lod.mesh.triangles.size()),
                   refitIterations(cells, lod.mesh.triangles.size()),
                   fullCollapse ? kCollapseRefitCreaseDegrees : 0);
  }
  return lod;
}

} // namespace octaclay::core::detail
