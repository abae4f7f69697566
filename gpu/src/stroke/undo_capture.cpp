#include "undo_capture.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace octaclay::gpu::detail {

UndoCapture::UndoCapture(GpuDocument& document, std::vector<core::EditLayer> layers)
    : document_(document), pool_(document), layers_(std::move(layers)), side_(document.side()),
      rows_(document.rows()), tiles_(core::EditStepRecorder::tilesPerSide(side_)) {}

void UndoCapture::capture(core::EditLayer layer, int tx, int ty) {
  const int slot = pool_.capture(layer, core::EditStepRecorder::tileRegion(side_, rows_, tx, ty));
  before_.push_back({layer, tx, ty, slot});
}

void UndoCapture::cover(core::TexelRect rect) {
  pool_.startDownloads(); // earlier dabs' tiles: downloads started, those arrived taken in
  const int size = core::EditStepRecorder::kTileSize;
  for (int ty = rect.y / size; ty <= (rect.y + rect.height - 1) / size; ++ty)
    for (int tx = rect.x / size; tx <= (rect.x + rect.width - 1) / size; ++tx)
      if (const auto [at, added] = seen_.emplace(ty * tiles_ + tx, -1); added)
        for (core::EditLayer layer : layers_) {
          if (layer == core::EditLayer::Positions) at->second = static_cast<int>(before_.size());
          capture(layer, tx, ty);
        }
  pool_.flushCopies(); // copied before the dab that follows writes the layers
}

void UndoCapture::coverTile(core::EditLayer layer, int tx, int ty) {
  if (std::find(layers_.begin(), layers_.end(), layer) != layers_.end()) {
    cover(core::EditStepRecorder::tileRegion(side_, rows_, tx, ty));
    return;
  }
  if (extra_.insert({static_cast<int>(layer), tx, ty}).second) {
    capture(layer, tx, ty);
    pool_.flushCopies();
  }
}

core::Vec3f UndoCapture::positionBefore(core::Sample s) const {
  const int size = core::EditStepRecorder::kTileSize;
  const auto at = seen_.find((s.j / size) * tiles_ + s.i / size);
  // Not captured: nothing the stroke changed, so the mirror holds it even where read-backs wait.
  if (at == seen_.end() || at->second < 0) return document_.mirror().positions.at(s).xyz();
  const Tile& t = before_[static_cast<std::size_t>(at->second)];
  const core::TexelRect r = core::EditStepRecorder::tileRegion(side_, rows_, t.x, t.y);
  const std::size_t k = static_cast<std::size_t>((s.j - r.y) * r.width + (s.i - r.x)) *
                        static_cast<std::size_t>(GpuDocument::channels(t.layer));
  const std::vector<float>& texels = pool_.texels(t.slot);
  return {texels[k], texels[k + 1], texels[k + 2]};
}

void UndoCapture::restore() {
  for (const Tile& t : before_)
    pool_.restore(t.slot);
}

core::EditStep UndoCapture::finish(const std::string& label) {
  // The finite check on the GPU, one flag per layer read back; only a stroke it flags is
  // checked again on the CPU, which names the sample.
  std::array<std::vector<core::TexelRect>, 4> written;
  for (const Tile& t : before_)
    written[static_cast<std::size_t>(t.layer)].push_back(
        core::EditStepRecorder::tileRegion(side_, rows_, t.x, t.y));
  bool clean = true;
  for (std::size_t k = 0; k < written.size() && clean; ++k)
    if (!written[k].empty())
      clean = document_.holdsOnlyFinite(static_cast<core::EditLayer>(k),
                                        core::mergeRects(std::move(written[k])));
  core::EditStepRecorder recorder(side_, rows_);
  for (const Tile& t : before_) {
    std::vector<float> after = texels(t.layer, t.x, t.y);
    if (!clean) checkFinite(t, after);
    recorder.addTile(t.layer, t.x, t.y, GpuDocument::channels(t.layer), pool_.texels(t.slot),
                     after);
  }
  return recorder.finish(label);
}

core::EditStep UndoCapture::record(const std::string& label) const {
  core::EditStepRecorder recorder(side_, rows_);
  for (const Tile& t : before_)
    recorder.addTile(t.layer, t.x, t.y, GpuDocument::channels(t.layer), pool_.texels(t.slot),
                     texels(t.layer, t.x, t.y));
  return recorder.finish(label);
}

std::vector<float> UndoCapture::texels(core::EditLayer layer, int tx, int ty) const {
  const core::TexelRect r = core::EditStepRecorder::tileRegion(side_, rows_, tx, ty);
  // Mid-stroke (recordSoFar) deferred positions may wait for their read-back.
  if (layer == core::EditLayer::Positions) document_.syncRegion(std::span(&r, 1));
  return document_.mirrorTexels(layer, {r.x, r.y, r.width, r.height});
}

void UndoCapture::checkFinite(const Tile& t, const std::vector<float>& after) {
  const bool positions = t.layer == core::EditLayer::Positions;
  const std::size_t channels = static_cast<std::size_t>(GpuDocument::channels(t.layer));
  for (std::size_t k = 0; k < after.size(); ++k) {
    const float v = after[k];
    // Positions' xyz are bounded; their w (saliency) and paint channels only need be finite.
    const bool bounded = positions && k % channels < 3;
    if (std::isfinite(v) && (!bounded || std::abs(v) <= kMaxCoordinate)) continue;
    const core::TexelRect r = core::EditStepRecorder::tileRegion(side_, rows_, t.x, t.y);
    const int texel = static_cast<int>(k / channels);
    const std::string sample = "(" + std::to_string(r.x + texel % r.width) + ", " +
                               std::to_string(r.y + texel / r.width) + ")";
    restore();
    const std::string layer(toManifestName(t.layer));
    throw core::Error(core::ErrorKind::InvalidInput,
                      std::isfinite(v)
                          ? "the brush moved sample " + sample +
                                " beyond the ±1e15 a coordinate may have; the "
                                "stroke was undone"
                          : "the brush produced a non-finite value at sample " + sample +
                                " of the " + layer + " layer; the stroke was undone");
  }
}

} // namespace octaclay::gpu::detail
