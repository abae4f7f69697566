// The undo step's encoding: per-tile XOR deltas with zero-run compression. Based on the usual
// delta-undo scheme of paint programs (store the old pixels of touched tiles), made sparse: a
// texel whose bits did not change is a count in a run, not a stored value.

#include "octaclay/core/document/edit_step.h"

#include "document/edit_checks.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/error.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

namespace octaclay::core {

using detail::editLayerName;
using detail::invalidEdit;
using detail::texelArea;

namespace {

std::uint32_t bitsOf(const float* f) {
  std::uint32_t u;
  std::memcpy(&u, f, sizeof u);
  return u;
}

int layerIndex(EditLayer layer) {
  const int index = static_cast<int>(layer);
  if (index < 0 || index > 3) invalidEdit("edit history: unknown layer " + std::to_string(index));
  return index;
}

} // namespace

int editLayerChannels(EditLayer layer) {
  static constexpr int kChannels[] = {4, 4, 3, 1};
  return kChannels[layerIndex(layer)];
}

// ---------------------------------------------------------------------------------------------
// TileChange

std::size_t TileChange::bytes() const {
  return sizeof(TileChange) + runs.capacity() * sizeof(std::uint32_t) +
         before.capacity() * sizeof(float) + xorBits.capacity() * sizeof(std::uint32_t);
}

void TileChange::apply(TileState state, const TileApplier& applyFn) const {
  const std::size_t c = static_cast<std::size_t>(channels);
  const std::size_t w = static_cast<std::size_t>(region.width);
  std::vector<float> scratch;
  std::size_t pos = 0; // texel index in the tile, row-major
  std::size_t lit = 0; // index among the changed texels
  for (std::size_t r = 0; r + 1 < runs.size(); r += 2) {
    pos += runs[r];
    const std::size_t count = runs[r + 1];
    std::span<const float> texels(before.data() + lit * c, count * c);
    if (state == TileState::After) {
      scratch.resize(count * c);
      for (std::size_t k = 0; k < count * c; ++k) {
        const std::uint32_t bits = bitsOf(&before[lit * c + k]) ^ xorBits[lit * c + k];
        std::memcpy(&scratch[k], &bits, sizeof bits);
      }
      texels = scratch;
    }
    // The run covers texels [pos, pos + count) of the tile: a partial first row, whole rows,
    // a partial last row. Each becomes one rectangle so a whole changed tile is one call.
    std::size_t row = pos / w, col = pos % w, remaining = count, done = 0;
    auto emit = [&](std::size_t x, std::size_t y, std::size_t width, std::size_t height) {
      const TexelRect part{region.x + static_cast<int>(x), region.y + static_cast<int>(y),
                           static_cast<int>(width), static_cast<int>(height)};
      applyFn(layer, part, texels.subspan(done * c, width * height * c));
      done += width * height;
      remaining -= width * height;
    };
    if (col != 0) {
      emit(col, row, std::min(remaining, w - col), 1);
      ++row;
    }
    if (remaining >= w) {
      const std::size_t rows = remaining / w;
      emit(0, row, w, rows);
      row += rows;
    }
    if (remaining > 0) emit(0, row, remaining, 1);
    pos += count;
    lit += count;
  }
}

void TileChange::patch(TileState state, std::span<float> tile) const {
  const std::size_t c = static_cast<std::size_t>(channels);
  if (tile.size() != texelArea(region) * c)
    invalidEdit("TileChange::patch: the tile buffer holds " + std::to_string(tile.size()) +
                " floats, expected " + std::to_string(texelArea(region) * c) + " (" +
                std::to_string(region.width) + "x" + std::to_string(region.height) + " texels x " +
                std::to_string(channels) + " channels)");
  std::size_t pos = 0, lit = 0;
  for (std::size_t r = 0; r + 1 < runs.size(); r += 2) {
    pos += runs[r];
    const std::size_t n = static_cast<std::size_t>(runs[r + 1]) * c;
    for (std::size_t k = 0; k < n; ++k) {
      std::uint32_t bits = bitsOf(&before[lit * c + k]);
      if (state == TileState::After) bits ^= xorBits[lit * c + k];
      std::memcpy(&tile[pos * c + k], &bits, sizeof bits);
    }
    pos += runs[r + 1];
    lit += runs[r + 1];
  }
}

// ---------------------------------------------------------------------------------------------
// Stroke

std::size_t EditStep::computeBytes() const {
  std::size_t total =
      sizeof(EditStep) + label.capacity() + (tiles.capacity() - tiles.size()) * sizeof(TileChange);
  for (const TileChange& t : tiles)
    total += t.bytes();
  for (const auto& d : {replacedBefore, replacedAfter})
    if (d)
      for (const Layer* l : {&d->diffuse, &d->feature, &d->mask})
        total += l->texels.capacity() * sizeof(float);
  for (const auto& d : {replacedBefore, replacedAfter})
    if (d) total += d->positions.texels().size() * sizeof(Vec4f);
  return total;
}

// ---------------------------------------------------------------------------------------------
// EditStepRecorder

EditStepRecorder::EditStepRecorder(int imageSide, int imageRows)
    : side_(imageSide), rows_(imageRows == 0 ? imageSide : imageRows) {
  if (imageSide < 2 || rows_ < 2)
    invalidEdit("EditStepRecorder: image side " + std::to_string(imageSide) + " by " +
                std::to_string(rows_) +
                " rows is too small; pass N+1 of the geometry image (at least 3)");
  stroke_.imageSide = side_;
  stroke_.imageRows = rows_ == side_ ? 0 : rows_;
  seen_.assign(4u * static_cast<std::size_t>(tilesPerSide(side_)) *
                   static_cast<std::size_t>(tilesPerSide(rows_)),
               0);
}

int EditStepRecorder::tilesPerSide(int imageSide) {
  return imageSide <= 0 ? 0 : (imageSide + kTileSize - 1) / kTileSize;
}

TexelRect EditStepRecorder::tileRegion(int imageSide, int tileX, int tileY) {
  return tileRegion(imageSide, imageSide, tileX, tileY);
}

TexelRect EditStepRecorder::tileRegion(int imageSide, int imageRows, int tileX, int tileY) {
  const int tilesX = tilesPerSide(imageSide), tilesY = tilesPerSide(imageRows);
  if (tileX < 0 || tileY < 0 || tileX >= tilesX || tileY >= tilesY)
    invalidEdit("edit history: tile (" + std::to_string(tileX) + ", " + std::to_string(tileY) +
                ") is outside the image of " + std::to_string(imageSide) + "x" +
                std::to_string(imageRows) + " texels, which has " + std::to_string(tilesX) + "x" +
                std::to_string(tilesY) + " tiles of " + std::to_string(kTileSize) + " texels");
  const int x = tileX * kTileSize, y = tileY * kTileSize;
  return {x, y, std::min(kTileSize, imageSide - x), std::min(kTileSize, imageRows - y)};
}

void EditStepRecorder::addTile(EditLayer layer, int tileX, int tileY, int channels,
                               std::span<const float> before, std::span<const float> after) {
  const int li = layerIndex(layer);
  const TexelRect region = tileRegion(side_, rows_, tileX, tileY);
  if (channels != editLayerChannels(layer))
    invalidEdit(std::string("EditStepRecorder::addTile: the ") + editLayerName(layer) +
                " layer has " + std::to_string(editLayerChannels(layer)) + " channels, not " +
                std::to_string(channels));
  const std::size_t c = static_cast<std::size_t>(channels);
  const std::size_t texelCount = texelArea(region);
  if (before.size() != texelCount * c || after.size() != texelCount * c)
    invalidEdit("EditStepRecorder::addTile: tile (" + std::to_string(tileX) + ", " +
                std::to_string(tileY) + ") is " + std::to_string(region.width) + "x" +
                std::to_string(region.height) + " texels x " + std::to_string(channels) +
                " channels = " + std::to_string(texelCount * c) + " floats, but before has " +
                std::to_string(before.size()) + " and after " + std::to_string(after.size()));
  const int tiles = tilesPerSide(side_);
  std::uint8_t& seen =
      seen_[static_cast<std::size_t>((li * tilesPerSide(rows_) + tileY) * tiles + tileX)];
  if (seen)
    invalidEdit(std::string("EditStepRecorder::addTile: tile (") + std::to_string(tileX) + ", " +
                std::to_string(tileY) + ") of the " + editLayerName(layer) +
                " layer was already added to this stroke; add each tile once, with its state "
                "before the stroke's first dab and after its last");

  auto changed = [&](std::size_t t) {
    for (std::size_t k = t * c; k < (t + 1) * c; ++k)
      if (bitsOf(&before[k]) != bitsOf(&after[k])) return true;
    return false;
  };
  // First pass sizes the payload exactly, so capacity == size and bytes() is what is needed.
  std::size_t changedCount = 0, runCount = 0;
  bool previous = false;
  for (std::size_t t = 0; t < texelCount; ++t) {
    const bool now = changed(t);
    if (now) {
      ++changedCount;
      if (!previous) ++runCount;
    }
    previous = now;
  }
  seen = 1;
  if (changedCount == 0) return; // touched but unchanged: nothing to undo

  TileChange tile;
  tile.layer = layer;
  tile.tileX = tileX;
  tile.tileY = tileY;
  tile.channels = channels;
  tile.region = region;
  tile.changedTexels = static_cast<std::uint32_t>(changedCount);
  tile.runs.reserve(2 * runCount);
  tile.before.resize(changedCount * c);
  tile.xorBits.resize(changedCount * c);
  std::uint32_t skip = 0;
  std::size_t out = 0;
  previous = false;
  for (std::size_t t = 0; t < texelCount; ++t) {
    const bool now = changed(t);
    if (!now) {
      ++skip;
    } else {
      if (!previous) {
        tile.runs.push_back(skip);
        tile.runs.push_back(0);
        skip = 0;
      }
      ++tile.runs.back();
      std::memcpy(&tile.before[out * c], &before[t * c], c * sizeof(float));
      for (std::size_t k = 0; k < c; ++k)
        tile.xorBits[out * c + k] = bitsOf(&before[t * c + k]) ^ bitsOf(&after[t * c + k]);
      ++out;
    }
    previous = now;
  }
  stroke_.changedTexels += changedCount;
  stroke_.tiles.push_back(std::move(tile));
}

EditStep EditStepRecorder::finish(std::string label) {
  EditStep done = std::move(stroke_);
  done.label = std::move(label);
  done.tiles.shrink_to_fit();
  done.bytes = done.computeBytes();
  stroke_ = EditStep{};
  stroke_.imageSide = side_;
  stroke_.imageRows = rows_ == side_ ? 0 : rows_;
  std::fill(seen_.begin(), seen_.end(), std::uint8_t{0});
  return done;
}

} // namespace octaclay::core
