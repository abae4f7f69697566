#include "undo_tile_pool.h"

#include "half_float.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <tuple>
#include <utility>

namespace octaclay::gpu::detail {
namespace {

constexpr int kTile = core::EditStepRecorder::kTileSize;

std::size_t index(core::EditLayer layer) {
  return static_cast<std::size_t>(layer);
}

} // namespace

UndoTilePool::UndoTilePool(GpuDocument& document) : document_(document) {}

UndoTilePool::~UndoTilePool() {
  for (Batch& b : batches_)
    if (b.fence) glDeleteSync(static_cast<GLsync>(b.fence));
}

const Texture& UndoTilePool::page(const Slot& s) const {
  return pages_[index(s.layer)][static_cast<std::size_t>(s.page)];
}

int UndoTilePool::capture(core::EditLayer layer, core::TexelRect region) {
  const Texture& source = document_.texture(layer);
  std::vector<Texture>& pages = pages_[index(layer)];
  int& used = used_[index(layer)];
  int perSide = pages.empty() ? 0 : pages.back().width() / kTile;
  if (used == perSide * perSide) { // none yet, or the last one full: the next, larger
    perSide = pages.empty() ? kFirstSlotsPerSide : std::min(2 * perSide, kMostSlotsPerSide);
    pages.emplace_back(perSide * kTile, perSide * kTile, source.format());
    used = 0;
  }
  const int k = used++;
  Slot slot;
  slot.layer = layer;
  slot.region = region;
  slot.page = static_cast<int>(pages.size()) - 1;
  slot.x = (k % perSide) * kTile;
  slot.y = (k / perSide) * kTile;
  // Joined to the copy held back when it continues it in the source and in the pool (a row
  // of whole tiles): one copy a row of tiles instead of one a tile.
  PendingCopy& copy = pending_[index(layer)];
  if (copy.page == slot.page && copy.toY == slot.y && copy.toX + copy.width == slot.x &&
      copy.fromY == region.y && copy.fromX + copy.width == region.x &&
      copy.height == region.height && copy.width % kTile == 0) {
    copy.width += region.width;
  } else {
    issue(layer, copy);
    copy = {region.x, region.y, slot.page, slot.x, slot.y, region.width, region.height};
  }
  slots_.push_back(std::move(slot));
  unstarted_.push_back(static_cast<int>(slots_.size()) - 1);
  return static_cast<int>(slots_.size()) - 1;
}

void UndoTilePool::issue(core::EditLayer layer, PendingCopy& copy) {
  if (copy.page < 0 || copy.width == 0) return;
  const Texture& target = pages_[index(layer)][static_cast<std::size_t>(copy.page)];
  glCopyImageSubData(document_.texture(layer).id(), GL_TEXTURE_2D, 0, copy.fromX, copy.fromY, 0,
                     target.id(), GL_TEXTURE_2D, 0, copy.toX, copy.toY, 0, copy.width, copy.height,
                     1);
  copy = {};
}

void UndoTilePool::flushCopies() {
  for (std::size_t k = 0; k < pending_.size(); ++k)
    issue(static_cast<core::EditLayer>(k), pending_[k]);
}

void UndoTilePool::startDownloads() {
  flushCopies();
  if (!unstarted_.empty()) {
    // Slots side by side in a row of one page are read together: by layer, page, row, column.
    std::sort(unstarted_.begin(), unstarted_.end(), [this](int a, int b) {
      const Slot &s = slots_[static_cast<std::size_t>(a)], &t = slots_[static_cast<std::size_t>(b)];
      return std::tie(s.layer, s.page, s.y, s.x) < std::tie(t.layer, t.page, t.y, t.x);
    });
    Batch batch;
    struct Run {
      std::size_t first, end; // of unstarted_
      int height;             // the tallest of its slots' regions
    };
    std::vector<Run> runs;
    for (std::size_t first = 0; first < unstarted_.size();) {
      std::size_t end = first + 1;
      while (end < unstarted_.size()) {
        const Slot& last = slots_[static_cast<std::size_t>(unstarted_[end - 1])];
        const Slot& next = slots_[static_cast<std::size_t>(unstarted_[end])];
        if (next.layer != last.layer || next.page != last.page || next.y != last.y ||
            next.x != last.x + kTile)
          break;
        ++end;
      }
      const Slot& head = slots_[static_cast<std::size_t>(unstarted_[first])];
      const Slot& tail = slots_[static_cast<std::size_t>(unstarted_[end - 1])];
      const int width = tail.x + tail.region.width - head.x;
      int height = 0;
      for (std::size_t k = first; k < end; ++k)
        height = std::max(height, slots_[static_cast<std::size_t>(unstarted_[k])].region.height);
      const std::size_t texelBytes = page(head).packedTexelBytes();
      for (std::size_t k = first; k < end; ++k) {
        Slot& s = slots_[static_cast<std::size_t>(unstarted_[k])];
        s.batch = static_cast<int>(batches_.size());
        s.offset = batch.bytes + static_cast<std::size_t>(s.x - head.x) * texelBytes;
        s.stride = width;
      }
      batch.bytes += static_cast<std::size_t>(width) * height * texelBytes;
      runs.push_back({first, end, height});
      first = end;
    }
    std::size_t capacity = 0;
    if (!spare_.empty()) {
      batch.buffer = std::move(spare_.back());
      capacity = spareBytes_.back();
      spare_.pop_back();
      spareBytes_.pop_back();
    } else {
      batch.buffer = Buffer::create();
    }
    if (capacity < batch.bytes) {
      glBindBuffer(GL_PIXEL_PACK_BUFFER, batch.buffer.id());
      glBufferData(GL_PIXEL_PACK_BUFFER, static_cast<GLsizeiptr>(batch.bytes), nullptr,
                   GL_STREAM_READ);
      glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    } else {
      batch.bytes = capacity; // the buffer's size, for the next reuse
    }
    for (const Run& run : runs) {
      const Slot& head = slots_[static_cast<std::size_t>(unstarted_[run.first])];
      page(head).readToPackBuffer({head.x, head.y, head.stride, run.height}, batch.buffer.id(),
                                  head.offset);
    }
    batch.fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
    if (!batch.fence) throw GlError("undo capture: no fence for the tiles' download");
    batch.slots = std::move(unstarted_);
    unstarted_.clear();
    batches_.push_back(std::move(batch));
  }
  // Fences signal in the order they were issued: stop at the first that has not.
  for (; collected_ < batches_.size(); ++collected_) {
    Batch& b = batches_[collected_];
    if (b.fence && !signalled(b)) return;
    collect(b);
  }
}

bool UndoTilePool::signalled(const Batch& batch) const {
  const GLenum state =
      glClientWaitSync(static_cast<GLsync>(batch.fence), GL_SYNC_FLUSH_COMMANDS_BIT, 0);
  return state == GL_ALREADY_SIGNALED || state == GL_CONDITION_SATISFIED;
}

const std::vector<float>& UndoTilePool::texels(int slot) {
  Slot& s = slots_[static_cast<std::size_t>(slot)];
  if (s.batch < 0) startDownloads();
  if (!s.collected) collect(batches_[static_cast<std::size_t>(s.batch)]);
  return s.texels;
}

void UndoTilePool::collect(Batch& b) {
  if (!b.fence) return;
  // Waits without a limit: copies and reads of tiles, behind passes the watchdog watches.
  glClientWaitSync(static_cast<GLsync>(b.fence), GL_SYNC_FLUSH_COMMANDS_BIT, GL_TIMEOUT_IGNORED);
  glDeleteSync(static_cast<GLsync>(b.fence));
  b.fence = nullptr;
  glBindBuffer(GL_PIXEL_PACK_BUFFER, b.buffer.id());
  const auto* mapped = static_cast<const std::byte*>(
      glMapBufferRange(GL_PIXEL_PACK_BUFFER, 0, static_cast<GLsizeiptr>(b.bytes), GL_MAP_READ_BIT));
  if (!mapped) {
    glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    throw GlError("undo capture: the tiles' download could not be mapped");
  }
  for (int k : b.slots) {
    Slot& s = slots_[static_cast<std::size_t>(k)];
    const std::size_t texels = static_cast<std::size_t>(s.region.width) * s.region.height;
    const int c = GpuDocument::channels(s.layer);
    s.texels.resize(texels * static_cast<std::size_t>(c));
    const std::size_t texelBytes = page(s).packedTexelBytes();
    const std::size_t width = static_cast<std::size_t>(s.region.width);
    for (int y = 0; y < s.region.height; ++y) { // its rows within its run's rows
      const std::byte* row =
          mapped + s.offset +
          static_cast<std::size_t>(y) * static_cast<std::size_t>(s.stride) * texelBytes;
      float* out = &s.texels[static_cast<std::size_t>(y) * width * static_cast<std::size_t>(c)];
      if (page(s).format() == TextureFormat::Rgba16f) { // RGBA halves; feature keeps rgb
        std::vector<std::uint16_t> halves(width * 4);
        std::memcpy(halves.data(), row, halves.size() * sizeof(std::uint16_t));
        for (std::size_t t = 0; t < width; ++t)
          for (int j = 0; j < c; ++j)
            out[t * c + j] = widenHalf(halves[t * 4 + j]);
      } else { // float32, as many channels as the layer has
        std::memcpy(out, row, width * static_cast<std::size_t>(c) * sizeof(float));
      }
    }
    s.collected = true;
  }
  glUnmapBuffer(GL_PIXEL_PACK_BUFFER);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  spare_.push_back(std::move(b.buffer));
  spareBytes_.push_back(b.bytes);
  checkGlError("undo capture: the tiles' download");
}

void UndoTilePool::restore(int slot) {
  flushCopies();
  Slot& s = slots_[static_cast<std::size_t>(slot)];
  if (s.batch < 0) startDownloads();
  Batch& b = batches_[static_cast<std::size_t>(s.batch)];
  if (!s.collected && signalled(b)) collect(b);
  if (!s.collected) {
    // Behind a pass that failed or overran: no wait for it. Nothing issued after the copy has
    // been read back into the mirror (a read-back would have waited for the copy too), so the
    // mirror still holds the tile as it was copied.
    s.texels = document_.mirrorTexels(s.layer, s.region);
  }
  document_.restoreCopy(s.layer, s.region, s.texels, page(s), s.x, s.y);
}

} // namespace octaclay::gpu::detail
