#include "octaclay/core/relax/relax.h"

#include "document/tile_texels.h"
#include "relax/offset_field.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/grid_point.h"
#include "octaclay/core/geometry/mesh_extraction.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace octaclay::core {
namespace {

void checkOptions(const RelaxOptions& options) {
  if (options.iterations < 0 || options.iterations > kMaxRelaxIterations)
    throw Error(ErrorKind::InvalidArgument,
                "iterations " + std::to_string(options.iterations) + " is outside 0 to " +
                    std::to_string(kMaxRelaxIterations) + "; leave it at 0 to choose from N");
}

void checkPositions(const GeometryImage& image) {
  if (const auto problem = positionsProblem(image))
    throw Error(ErrorKind::InvalidInput,
                *problem + "; the document is damaged and cannot be relaxed");
}

int fineIterations(const RelaxOptions& options) {
  return options.iterations > 0 ? options.iterations : 1;
}

TexelRect clipped(TexelRect r, int n) {
  const int x0 = std::max(r.x, 0), y0 = std::max(r.y, 0);
  const int x1 = std::min(r.x + r.width, n + 1), y1 = std::min(r.y + r.height, n + 1);
  return {x0, y0, std::max(0, x1 - x0), std::max(0, y1 - y0)};
}

// An edge longer than kStretchedEdge times the surface's median edge is stretched. Samples are
// taken from the surface around it only while its edges stay within a multiple of the median
// (the even-out's, and keep-detail's, whose reservoir is bounded and pinned at its rim): the
// surface they leave keeps its resolution.
constexpr float kStretchedEdge = 2.0f;
constexpr float kCoarseStretchedEdge = 1.5f;
constexpr float kLongEdge = 0.003f;
constexpr float kEvenOutDonorEdge = 3.0f;
constexpr float kKeepDetailDonorEdge = 5.0f;

float edgeLength(const GeometryImage& image, int i, int j, int di, int dj) {
  return length(image.at(i + di, j + dj).xyz() - image.at(i, j).xyz());
}

// The median grid edge, from every 8th row and column (a fraction of the work, the same figure
// within a few percent).
float medianEdge(const GeometryImage& image) {
  const int n = image.size();
  std::vector<float> edges;
  for (int j = 0; j <= n; j += 8)
    for (int i = 0; i < n; ++i)
      edges.push_back(edgeLength(image, i, j, 1, 0));
  for (int i = 0; i <= n; i += 8)
    for (int j = 0; j < n; ++j)
      edges.push_back(edgeLength(image, i, j, 0, 1));
  std::nth_element(edges.begin(), edges.begin() + static_cast<std::ptrdiff_t>(edges.size() / 2),
                   edges.end());
  return edges[edges.size() / 2];
}

// The bounding box's diagonal, from every 4th sample.
float diagonal(const GeometryImage& image) {
  const int n = image.size();
  Vec3f lo = image.at(0, 0).xyz(), hi = lo;
  for (int j = 0; j <= n; j += 4)
    for (int i = 0; i <= n; i += 4) {
      const Vec3f p = image.at(i, j).xyz();
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  return length(hi - lo);
}

// Keep-detail relaxes edges over kStretchedEdge times the median, and at coarse N (long median
// edges) from kCoarseStretchedEdge times: a long edge's facet cuts across the surface the
// relaxation resamples, so it is relaxed before it is longer than kLongEdge of the diagonal.
float stretchedEdgeLimit(const GeometryImage& image, float median) {
  return std::clamp(kLongEdge * diagonal(image), kCoarseStretchedEdge * median,
                    kStretchedEdge * median);
}

bool stretchedInside(const GeometryImage& image, TexelRect r, float limit) {
  for (int j = r.y; j + 1 < r.y + r.height; ++j)
    for (int i = r.x; i + 1 < r.x + r.width; ++i)
      if (edgeLength(image, i, j, 1, 0) > limit || edgeLength(image, i, j, 0, 1) > limit)
        return true;
  return false;
}

bool stretchedBorder(const GeometryImage& image, TexelRect r, float limit) {
  const int x1 = r.x + r.width - 1, y1 = r.y + r.height - 1;
  for (int i = r.x; i < x1; ++i)
    if (edgeLength(image, i, r.y, 1, 0) > limit || edgeLength(image, i, y1, 1, 0) > limit)
      return true;
  for (int j = r.y; j < y1; ++j)
    if (edgeLength(image, r.x, j, 0, 1) > limit || edgeLength(image, x1, j, 0, 1) > limit)
      return true;
  return false;
}

TexelRect grownBy(TexelRect r, int by, int n) {
  return clipped({r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by}, n);
}

// What to relax around a changed rectangle: grown until its border is no longer stretched
// (the whole pulled part), then by half its size, so that samples can flow in from the
// unstretched surface around it. The last growth may leave the image: the surface goes on
// across the seam (OffsetField::freeInside wraps it), and a rim on the image's border would
// hold the samples there while the other side of the seam moves.
TexelRect relaxedExtent(const GeometryImage& image, TexelRect seed, float limit) {
  const int n = image.size();
  TexelRect r = clipped(seed, n);
  while (r.width < n + 1 || r.height < n + 1) {
    if (!stretchedBorder(image, r, limit)) break;
    r = grownBy(r, std::max(4, std::max(r.width, r.height) / 8), n);
  }
  const int by = std::max({16, r.width, r.height});
  TexelRect e{r.x - by, r.y - by, r.width + 2 * by, r.height + 2 * by};
  if (e.width > n) e.x = -1, e.width = n + 3; // all of the side: every sample, border included
  if (e.height > n) e.y = -1, e.height = n + 3;
  return e;
}

bool meet(TexelRect a, TexelRect b) {
  return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
}

// Overlapping extents become one: a border between two would pin the samples on it.
std::vector<TexelRect> mergedExtents(std::vector<TexelRect> rects) {
  for (bool merged = true; merged;) {
    merged = false;
    for (std::size_t a = 0; a < rects.size() && !merged; ++a)
      for (std::size_t b = a + 1; b < rects.size() && !merged; ++b)
        if (meet(rects[a], rects[b])) {
          const TexelRect p = rects[a], q = rects[b];
          const int x0 = std::min(p.x, q.x), y0 = std::min(p.y, q.y);
          const int x1 = std::max(p.x + p.width, q.x + q.width);
          const int y1 = std::max(p.y + p.height, q.y + q.height);
          rects[a] = {x0, y0, x1 - x0, y1 - y0};
          rects.erase(rects.begin() + static_cast<std::ptrdiff_t>(b));
          merged = true;
        }
  }
  return rects;
}

// The even-out's offsets (the whole model free), solved on document's positions.
detail::OffsetField solveEvenOut(const Document& document, const RelaxOptions& options,
                                 const RelaxProgress& progress) {
  checkOptions(options);
  checkPositions(document.positions);
  detail::OffsetField field(document.size());
  field.freeAll();
  for (Sample s : options.pinned)
    field.pin(s);
  if (!detail::solveOffsets(document.positions, field, fineIterations(options),
                            kEvenOutDonorEdge * medianEdge(document.positions), false, progress))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return field;
}

// Per sample: 1 when one of its grid edges (through the wrap) is over `limit` long.
std::vector<std::uint8_t> stretchedSamples(const GeometryImage& image, double limit) {
  const int n = image.size();
  std::vector<std::uint8_t> out(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f p = image.at(i, j).xyz();
      bool stretched = false;
      for (const Sample d : {Sample{1, 0}, Sample{-1, 0}, Sample{0, 1}, Sample{0, -1}})
        stretched = stretched || length(image.positionWrapped({i + d.i, j + d.j}) - p) > limit;
      out[static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
          static_cast<std::size_t>(i)] = stretched;
    }
  return out;
}

// How many vertices show the stretched part once field (scaled by step) is applied: a vertex
// counts when the grid sample nearest its parameter point is stretched.
std::size_t stretchedShown(const detail::OffsetField& field, double step,
                           const std::vector<std::uint8_t>& stretched) {
  const int n = field.n;
  std::size_t count = 0;
  forEachCanonicalRun(n, [&](int j, int iBegin, int iEnd) {
    for (int i = iBegin; i < iEnd; ++i) {
      const auto& d = field.offset[field.index(i, j)];
      Sample s{i, j};
      if (d[0] != 0.0f || d[1] != 0.0f) {
        const GridPoint p =
            locateGridPoint(n, double(i) + step * double(d[0]), double(j) + step * double(d[1]));
        const auto k = std::max_element(p.weights.begin(), p.weights.end()) - p.weights.begin();
        s = p.corners[static_cast<std::size_t>(k)];
      }
      count += stretched[field.index(s.i, s.j)];
    }
  });
  return count;
}

std::string percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g %%", 100 * fraction);
  return text;
}

std::string times(double ratio) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3gx", ratio);
  return text;
}

} // namespace

Document evenOutSamples(const Document& document, const RelaxOptions& options,
                        const RelaxProgress& progress) {
  const detail::OffsetField field = solveEvenOut(document, options, progress);
  Document result = document; // samples that do not move keep their texels
  detail::resampleDocument(document, field, result);
  if (progress && !progress(1.0f))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return result;
}

EvenOutResult evenOut(const Document& document, const RelaxOptions& options,
                      const EvenOutCheckOptions& check, const RelaxProgress& progress) {
  const auto cancelled = [] {
    return Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  };
  // The solve is most of the work at one try; each try's measure is about as much again.
  const float solveShare = 0.5f;
  const detail::OffsetField field = solveEvenOut(
      document, options, [&](float f) { return !progress || progress(solveShare * f); });
  EvenOutResult out;
  out.before = summarizeStretch(document.positions);
  out.after = out.before;
  const int n = document.size();
  out.vertices = static_cast<std::size_t>(n) * static_cast<std::size_t>(n) + 2;
  const std::vector<std::uint8_t> stretched =
      stretchedSamples(document.positions, kStretchedEdge * out.before.medianEdge);
  out.stretchedBefore = stretchedShown(field, 0.0, stretched);
  out.stretchedAfter = out.stretchedBefore;
  const TriangleMesh surface = extractMesh(document.positions);
  const bool hasScale = boundingBox(surface).diagonal() > 0;
  std::string firstReason;
  for (std::size_t t = 0; t < check.steps.size(); ++t) {
    const double step = check.steps[t];
    if (!(step > 0 && step <= 1))
      throw Error(ErrorKind::InvalidArgument, "an even-out step must be in (0, 1]");
    detail::OffsetField scaled = field;
    for (auto& d : scaled.offset)
      d = {static_cast<float>(step * double(d[0])), static_cast<float>(step * double(d[1]))};
    Document result = document;
    detail::resampleDocument(document, scaled, result);
    ++out.tries;
    const StretchSummary after = summarizeStretch(result.positions);
    const std::size_t shown = stretchedShown(field, step, stretched);
    std::string reason;
    if (after.longestOverMedian > out.before.longestOverMedian * (1 + 1e-6))
      reason = "the longest edge would grow from " + times(out.before.longestOverMedian) + " to " +
               times(after.longestOverMedian) + " the median";
    else if (shown < out.stretchedBefore)
      reason = "the stretched part would lose samples (" + std::to_string(out.stretchedBefore) +
               " -> " + std::to_string(shown) + ")";
    else if (after.longestOverMedian > 0.99 * out.before.longestOverMedian &&
             double(shown) < 1.01 * double(out.stretchedBefore) + 0.5)
      reason = "the samples are already as even as it can make them (longest edge " +
               times(out.before.longestOverMedian) + " the median)";
    SurfaceDistance moved;
    if (reason.empty() && hasScale) {
      moved = compareSurfaces(surface, extractMesh(result.positions),
                              {.samplesPerSurface = check.samplesPerSurface});
      out.moved = moved;
      if (moved.rms > check.rmsTolerance)
        reason = "the surface would move by " + percent(moved.rms) +
                 " of the diagonal (RMS; at most " + percent(check.rmsTolerance) + ")";
      else if (moved.hausdorff > check.hausdorffTolerance)
        reason = "the surface would move by " + percent(moved.hausdorff) +
                 " of the diagonal (Hausdorff; at most " + percent(check.hausdorffTolerance) + ")";
    }
    if (progress &&
        !progress(solveShare + (1 - solveShare) * float(t + 1) / float(check.steps.size())))
      throw cancelled();
    if (reason.empty()) {
      out.document = std::move(result);
      out.changed = true;
      out.step = step;
      out.after = after;
      out.stretchedAfter = shown;
      if (progress && !progress(1.0f)) throw cancelled();
      return out;
    }
    if (firstReason.empty()) firstReason = reason;
  }
  out.document = document;
  out.reason = firstReason;
  if (check.steps.size() > 1) out.reason += ", and no smaller step did better";
  if (progress && !progress(1.0f)) throw cancelled();
  return out;
}

Stroke relaxRegionsStep(const Document& document, const std::vector<TexelRect>& regions,
                        std::string label, const RelaxOptions& options) {
  checkOptions(options);
  checkPositions(document.positions);
  const int n = document.size(), side = n + 1;
  detail::OffsetField field(n);
  const float median = medianEdge(document.positions);
  const float limit = stretchedEdgeLimit(document.positions, median);
  std::vector<TexelRect> extents;
  for (const TexelRect& r : regions)
    if (r.width > 0 && r.height > 0 && stretchedInside(document.positions, clipped(r, n), limit))
      extents.push_back(relaxedExtent(document.positions, r, limit));
  for (const TexelRect& r : mergedExtents(std::move(extents)))
    field.freeInside(r);
  for (Sample s : options.pinned)
    field.pin(s);
  StrokeRecorder recorder(side);
  if (std::find(field.free.begin(), field.free.end(), 1) == field.free.end())
    return recorder.finish(std::move(label));
  detail::solveOffsets(document.positions, field, fineIterations(options),
                       kKeepDetailDonorEdge * median, true, {});
  const int tiles = StrokeRecorder::tilesPerSide(side);
  std::vector<std::uint8_t> moved(static_cast<std::size_t>(tiles) * tiles, 0);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto& d = field.offset[field.index(i, j)];
      if (d[0] != 0.0f || d[1] != 0.0f)
        moved[static_cast<std::size_t>(j / StrokeRecorder::kTileSize) * tiles +
              static_cast<std::size_t>(i / StrokeRecorder::kTileSize)] = 1;
    }
  for (EditLayer layer :
       {EditLayer::Positions, EditLayer::Diffuse, EditLayer::Feature, EditLayer::Mask}) {
    // A uniform layer resamples to its own fill: nothing changes.
    if ((layer == EditLayer::Diffuse && document.diffuse.uniform()) ||
        (layer == EditLayer::Feature && document.feature.uniform()) ||
        (layer == EditLayer::Mask && (!document.hasMask || document.mask.uniform())))
      continue;
    const std::size_t ch = static_cast<std::size_t>(editLayerChannels(layer));
    for (int ty = 0; ty < tiles; ++ty)
      for (int tx = 0; tx < tiles; ++tx) {
        if (!moved[static_cast<std::size_t>(ty) * tiles + static_cast<std::size_t>(tx)]) continue;
        const TexelRect r = StrokeRecorder::tileRegion(side, tx, ty);
        const std::vector<float> before = detail::tileTexels(document, layer, r);
        std::vector<float> after(before.size());
        std::size_t o = 0;
        for (int j = r.y; j < r.y + r.height; ++j)
          for (int i = r.x; i < r.x + r.width; ++i, o += ch)
            detail::resampleTexel(document, field, layer, i, j, &after[o]);
        recorder.addTile(layer, tx, ty, static_cast<int>(ch), before, after);
      }
  }
  return recorder.finish(std::move(label));
}

std::vector<TexelRect> relaxRegions(Document& document, const std::vector<TexelRect>& regions,
                                    const RelaxOptions& options) {
  const Stroke step = relaxRegionsStep(document, regions, "relax", options);
  const TileApplier apply = applierFor(document);
  std::vector<TexelRect> changed;
  for (const TileChange& t : step.tiles) {
    t.apply(TileState::After, apply);
    if (t.layer == EditLayer::Positions) changed.push_back(t.region);
  }
  return changed;
}

} // namespace octaclay::core
