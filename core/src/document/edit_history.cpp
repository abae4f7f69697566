// Undo/redo store for brush strokes: per-tile XOR deltas with zero-run compression.
// Based on the usual delta-undo scheme of paint programs (store the old pixels of touched tiles),
// made sparse: a texel whose bits did not change is a count in a run, not a stored value.

#include "octaclay/core/document/edit_history.h"

#include "octaclay/core/error.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

namespace octaclay::core {

namespace {

[[noreturn]] void invalid(const std::string& message) {
  throw Error(ErrorKind::InvalidArgument, message);
}

std::uint32_t bitsOf(const float* f) {
  std::uint32_t u;
  std::memcpy(&u, f, sizeof u);
  return u;
}

const char* layerName(EditLayer layer) {
  switch (layer) {
  case EditLayer::Positions:
    return "positions";
  case EditLayer::Diffuse:
    return "diffuse";
  case EditLayer::Feature:
    return "feature";
  case EditLayer::Mask:
    return "mask";
  }
  return "unknown";
}

int layerIndex(EditLayer layer) {
  const int index = static_cast<int>(layer);
  if (index < 0 || index > 3) invalid("edit history: unknown layer " + std::to_string(index));
  return index;
}

std::size_t area(TexelRect r) {
  return static_cast<std::size_t>(r.width) * static_cast<std::size_t>(r.height);
}

// Checks that region lies inside a side × side image and texels holds it with `channels` floats
// per texel.
void checkRegion(TexelRect region, int side, int channels, std::size_t floats) {
  if (region.width <= 0 || region.height <= 0 || region.x < 0 || region.y < 0 ||
      region.x > side - region.width || region.y > side - region.height)
    invalid("edit history: region (" + std::to_string(region.x) + ", " + std::to_string(region.y) +
            ") " + std::to_string(region.width) + "x" + std::to_string(region.height) +
            " is outside the " + std::to_string(side) + "x" + std::to_string(side) +
            " image; apply strokes only to the image they were recorded on");
  if (floats != area(region) * static_cast<std::size_t>(channels))
    invalid("edit history: " + std::to_string(floats) + " floats given for a region of " +
            std::to_string(area(region)) + " texels with " + std::to_string(channels) +
            " channels");
}

// Copies a row-major region of texels into a row-major side × side image of `channels` floats
// per texel, bits as they are.
void writeRegion(float* image, int side, int channels, TexelRect region,
                 std::span<const float> texels) {
  const std::size_t c = static_cast<std::size_t>(channels);
  const std::size_t rowFloats = static_cast<std::size_t>(region.width) * c;
  for (int row = 0; row < region.height; ++row) {
    const std::size_t dst =
        (static_cast<std::size_t>(region.y + row) * static_cast<std::size_t>(side) +
         static_cast<std::size_t>(region.x)) *
        c;
    std::memcpy(image + dst, texels.data() + static_cast<std::size_t>(row) * rowFloats,
                rowFloats * sizeof(float));
  }
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
  if (tile.size() != area(region) * c)
    invalid("TileChange::patch: the tile buffer holds " + std::to_string(tile.size()) +
            " floats, expected " + std::to_string(area(region) * c) + " (" +
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

std::size_t Stroke::computeBytes() const {
  std::size_t total =
      sizeof(Stroke) + label.capacity() + (tiles.capacity() - tiles.size()) * sizeof(TileChange);
  for (const TileChange& t : tiles)
    total += t.bytes();
  return total;
}

// ---------------------------------------------------------------------------------------------
// StrokeRecorder

StrokeRecorder::StrokeRecorder(int imageSide) : side_(imageSide) {
  if (imageSide < 2)
    invalid("StrokeRecorder: image side " + std::to_string(imageSide) +
            " is too small; pass N+1 of the geometry image (at least 3)");
  stroke_.imageSide = side_;
  const int tiles = tilesPerSide(side_);
  seen_.assign(4u * static_cast<std::size_t>(tiles) * static_cast<std::size_t>(tiles), 0);
}

int StrokeRecorder::tilesPerSide(int imageSide) {
  return imageSide <= 0 ? 0 : (imageSide + kTileSize - 1) / kTileSize;
}

TexelRect StrokeRecorder::tileRegion(int imageSide, int tileX, int tileY) {
  const int tiles = tilesPerSide(imageSide);
  if (tileX < 0 || tileY < 0 || tileX >= tiles || tileY >= tiles)
    invalid("edit history: tile (" + std::to_string(tileX) + ", " + std::to_string(tileY) +
            ") is outside the image of side " + std::to_string(imageSide) + ", which has " +
            std::to_string(tiles) + "x" + std::to_string(tiles) + " tiles of " +
            std::to_string(kTileSize) + " texels");
  const int x = tileX * kTileSize, y = tileY * kTileSize;
  return {x, y, std::min(kTileSize, imageSide - x), std::min(kTileSize, imageSide - y)};
}

void StrokeRecorder::addTile(EditLayer layer, int tileX, int tileY, int channels,
                             std::span<const float> before, std::span<const float> after) {
  const int li = layerIndex(layer);
  const TexelRect region = tileRegion(side_, tileX, tileY);
  if (channels != editLayerChannels(layer))
    invalid(std::string("StrokeRecorder::addTile: the ") + layerName(layer) + " layer has " +
            std::to_string(editLayerChannels(layer)) + " channels, not " +
            std::to_string(channels));
  const std::size_t c = static_cast<std::size_t>(channels);
  const std::size_t texelCount = area(region);
  if (before.size() != texelCount * c || after.size() != texelCount * c)
    invalid("StrokeRecorder::addTile: tile (" + std::to_string(tileX) + ", " +
            std::to_string(tileY) + ") is " + std::to_string(region.width) + "x" +
            std::to_string(region.height) + " texels x " + std::to_string(channels) +
            " channels = " + std::to_string(texelCount * c) + " floats, but before has " +
            std::to_string(before.size()) + " and after " + std::to_string(after.size()));
  const int tiles = tilesPerSide(side_);
  std::uint8_t& seen = seen_[static_cast<std::size_t>((li * tiles + tileY) * tiles + tileX)];
  if (seen)
    invalid(std::string("StrokeRecorder::addTile: tile (") + std::to_string(tileX) + ", " +
            std::to_string(tileY) + ") of the " + layerName(layer) +
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

Stroke StrokeRecorder::finish(std::string label) {
  Stroke done = std::move(stroke_);
  done.label = std::move(label);
  done.tiles.shrink_to_fit();
  done.bytes = done.computeBytes();
  stroke_ = Stroke{};
  stroke_.imageSide = side_;
  std::fill(seen_.begin(), seen_.end(), std::uint8_t{0});
  return done;
}

// ---------------------------------------------------------------------------------------------
// EditHistory

namespace {

// A Stroke can be built by hand: check that applying it cannot read or write out of bounds.
void validateStroke(const Stroke& s) {
  if (s.imageSide < 2)
    invalid("EditHistory::record: the stroke has image side " + std::to_string(s.imageSide) +
            "; build strokes with StrokeRecorder");
  std::size_t changed = 0;
  for (const TileChange& t : s.tiles) {
    const TexelRect expected = StrokeRecorder::tileRegion(s.imageSide, t.tileX, t.tileY);
    if (t.region != expected || t.channels != editLayerChannels(t.layer))
      invalid("EditHistory::record: tile (" + std::to_string(t.tileX) + ", " +
              std::to_string(t.tileY) +
              ") has a region or channel count that does not match its layer and image; build "
              "strokes with StrokeRecorder");
    std::size_t covered = 0, count = 0;
    for (std::size_t r = 0; r + 1 < t.runs.size(); r += 2) {
      covered += std::size_t{t.runs[r]} + t.runs[r + 1];
      count += t.runs[r + 1];
    }
    const std::size_t c = static_cast<std::size_t>(t.channels);
    if (t.runs.size() % 2 != 0 || covered > area(t.region) || count != t.changedTexels ||
        t.before.size() != count * c || t.xorBits.size() != count * c)
      invalid("EditHistory::record: tile (" + std::to_string(t.tileX) + ", " +
              std::to_string(t.tileY) +
              ") has an inconsistent payload; build strokes with StrokeRecorder");
    changed += count;
  }
  if (changed != s.changedTexels)
    invalid("EditHistory::record: the stroke's changedTexels does not match its tiles");
}

} // namespace

EditHistory::EditHistory(std::size_t budgetBytes) : budget_(budgetBytes) {}

void EditHistory::record(Stroke stroke) {
  if (stroke.tiles.empty()) return;
  validateStroke(stroke);
  if (!strokes_.empty() && strokes_.front().imageSide != stroke.imageSide)
    invalid("EditHistory::record: the stroke is for an image of side " +
            std::to_string(stroke.imageSide) + " but the history holds strokes for side " +
            std::to_string(strokes_.front().imageSide) + "; clear() the history first");
  stroke.bytes = stroke.computeBytes();
  while (strokes_.size() > cursor_) {
    bytes_ -= strokes_.back().bytes;
    strokes_.pop_back();
  }
  bytes_ += stroke.bytes;
  strokes_.push_back(std::move(stroke));
  cursor_ = strokes_.size();
  while (bytes_ > budget_ && strokes_.size() > 1) {
    bytes_ -= strokes_.front().bytes;
    strokes_.pop_front();
    --cursor_;
  }
}

const Stroke* EditHistory::nextUndo() const {
  return canUndo() ? &strokes_[cursor_ - 1] : nullptr;
}

const Stroke* EditHistory::nextRedo() const {
  return canRedo() ? &strokes_[cursor_] : nullptr;
}

const Stroke* EditHistory::undo(const TileApplier& apply) {
  if (!canUndo()) return nullptr;
  const Stroke& s = strokes_[cursor_ - 1];
  for (auto it = s.tiles.rbegin(); it != s.tiles.rend(); ++it)
    it->apply(TileState::Before, apply);
  --cursor_;
  return &s;
}

const Stroke* EditHistory::redo(const TileApplier& apply) {
  if (!canRedo()) return nullptr;
  const Stroke& s = strokes_[cursor_];
  for (const TileChange& t : s.tiles)
    t.apply(TileState::After, apply);
  ++cursor_;
  return &s;
}

void EditHistory::clear() {
  strokes_.clear();
  cursor_ = 0;
  bytes_ = 0;
}

// ---------------------------------------------------------------------------------------------
// Appliers

TileApplier applierFor(GeometryImage& image) {
  return [&image](EditLayer layer, TexelRect region, std::span<const float> texels) {
    if (layer != EditLayer::Positions)
      invalid(std::string("applierFor(GeometryImage&): cannot write the ") + layerName(layer) +
              " layer into a position image; use applierFor(Document&)");
    checkRegion(region, image.side(), 4, texels.size());
    static_assert(sizeof(Vec4f) == 4 * sizeof(float));
    writeRegion(reinterpret_cast<float*>(image.texels().data()), image.side(), 4, region, texels);
  };
}

TileApplier applierFor(Document& doc) {
  return [&doc](EditLayer layer, TexelRect region, std::span<const float> texels) {
    if (layer == EditLayer::Positions) {
      applierFor(doc.positions)(layer, region, texels);
      return;
    }
    Layer& target = layer == EditLayer::Diffuse   ? doc.diffuse
                    : layer == EditLayer::Feature ? doc.feature
                                                  : doc.mask;
    const int side = doc.positions.side();
    const int c = editLayerChannels(layer);
    if (target.channels != c)
      invalid("applierFor(Document&): the document's " + target.name + " layer has " +
              std::to_string(target.channels) + " channels, the edit " + std::to_string(c));
    checkRegion(region, side, c, texels.size());
    const std::size_t texelCount = static_cast<std::size_t>(side) * static_cast<std::size_t>(side);
    if (target.uniform()) {
      target.texels.resize(texelCount * static_cast<std::size_t>(c));
      for (std::size_t t = 0; t < texelCount; ++t)
        std::copy_n(target.fill.begin(), c,
                    target.texels.begin() + static_cast<std::ptrdiff_t>(t) * c);
    }
    if (target.texels.size() != texelCount * static_cast<std::size_t>(c))
      invalid("applierFor(Document&): the " + target.name + " layer holds " +
              std::to_string(target.texels.size()) + " floats, not " +
              std::to_string(texelCount * static_cast<std::size_t>(c)) +
              " for its image; the document is inconsistent");
    if (layer == EditLayer::Mask) doc.hasMask = true;
    writeRegion(target.texels.data(), side, c, region, texels);
  };
}

} // namespace octaclay::core
