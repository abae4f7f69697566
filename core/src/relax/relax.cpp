#include "octaclay/core/relax/relax.h"

#include "document/tile_texels.h"
#include "relax/offset_field.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"

#include <algorithm>
#include <cmath>
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

// Whether some grid edge inside r is longer than kStretchedEdge times the median edge on r's
// border (the surface around what a stroke changed): only then is there detail to give back.
constexpr float kStretchedEdge = 2.0f;

bool stretchedInside(const GeometryImage& image, TexelRect r) {
  if (r.width < 3 || r.height < 3) return false;
  auto edge = [&](int i, int j, int di, int dj) {
    return length(image.at(i + di, j + dj).xyz() - image.at(i, j).xyz());
  };
  std::vector<float> border;
  for (int i = r.x; i + 1 < r.x + r.width; ++i) {
    border.push_back(edge(i, r.y, 1, 0));
    border.push_back(edge(i, r.y + r.height - 1, 1, 0));
  }
  for (int j = r.y; j + 1 < r.y + r.height; ++j) {
    border.push_back(edge(r.x, j, 0, 1));
    border.push_back(edge(r.x + r.width - 1, j, 0, 1));
  }
  std::nth_element(border.begin(), border.begin() + border.size() / 2, border.end());
  const float limit = kStretchedEdge * border[border.size() / 2];
  for (int j = r.y; j + 1 < r.y + r.height; ++j)
    for (int i = r.x; i + 1 < r.x + r.width; ++i)
      if (edge(i, j, 1, 0) > limit || edge(i, j, 0, 1) > limit) return true;
  return false;
}

} // namespace

Document evenOutSamples(const Document& document, const RelaxOptions& options,
                        const RelaxProgress& progress) {
  checkOptions(options);
  checkPositions(document.positions);
  detail::OffsetField field(document.size());
  field.freeAll();
  for (Sample s : options.pinned)
    field.pin(s);
  if (!detail::solveOffsets(document.positions, field, fineIterations(options), progress))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  Document result = document; // samples that do not move keep their texels
  detail::resampleDocument(document, field, result);
  if (progress && !progress(1.0f))
    throw Error(ErrorKind::Cancelled, "evening out the samples was cancelled");
  return result;
}

Stroke relaxRegionsStep(const Document& document, const std::vector<TexelRect>& regions,
                        std::string label, const RelaxOptions& options) {
  checkOptions(options);
  checkPositions(document.positions);
  const int n = document.size(), side = n + 1;
  detail::OffsetField field(n);
  for (const TexelRect& r : regions)
    if (stretchedInside(document.positions, clipped(r, n))) field.freeInside(clipped(r, n));
  for (Sample s : options.pinned)
    field.pin(s);
  StrokeRecorder recorder(side);
  if (std::find(field.free.begin(), field.free.end(), 1) == field.free.end())
    return recorder.finish(std::move(label));
  detail::solveOffsets(document.positions, field, fineIterations(options), {});
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
