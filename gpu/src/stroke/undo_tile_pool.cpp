#include "undo_tile_pool.h"

#include "half_float.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <cstdint>
#include <cstring>

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
  const int k = used_[index(layer)]++;
  const int perPage = kSlotsPerSide * kSlotsPerSide;
  std::vector<Texture>& pages = pages_[index(layer)];
  if (k / perPage >= static_cast<int>(pages.size()))
    pages.emplace_back(kSlotsPerSide * kTile, kSlotsPerSide * kTile, source.format());
  Slot slot;
  slot.layer = layer;
  slot.region = region;
  slot.page = k / perPage;
  slot.x = (k % perPage % kSlotsPerSide) * kTile;
  slot.y = (k % perPage / kSlotsPerSide) * kTile;
  glCopyImageSubData(source.id(), GL_TEXTURE_2D, 0, region.x, region.y, 0, page(slot).id(),
                     GL_TEXTURE_2D, 0, slot.x, slot.y, 0, region.width, region.height, 1);
  slots_.push_back(std::move(slot));
  unstarted_.push_back(static_cast<int>(slots_.size()) - 1);
  return static_cast<int>(slots_.size()) - 1;
}

void UndoTilePool::startDownloads() {
  if (!unstarted_.empty()) {
    Batch batch;
    for (int k : unstarted_) {
      Slot& s = slots_[static_cast<std::size_t>(k)];
      s.batch = static_cast<int>(batches_.size());
      s.offset = batch.bytes;
      batch.bytes +=
          static_cast<std::size_t>(s.region.width) * s.region.height * page(s).packedTexelBytes();
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
    for (int k : unstarted_) {
      const Slot& s = slots_[static_cast<std::size_t>(k)];
      page(s).readToPackBuffer({s.x, s.y, s.region.width, s.region.height}, batch.buffer.id(),
                               s.offset);
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
    if (page(s).format() == TextureFormat::Rgba16f) { // RGBA halves; feature keeps rgb
      std::vector<std::uint16_t> halves(texels * 4);
      std::memcpy(halves.data(), mapped + s.offset, halves.size() * sizeof(std::uint16_t));
      for (std::size_t t = 0; t < texels; ++t)
        for (int j = 0; j < c; ++j)
          s.texels[t * c + j] = widenHalf(halves[t * 4 + j]);
    } else { // float32, as many channels as the layer has
      std::memcpy(s.texels.data(), mapped + s.offset, s.texels.size() * sizeof(float));
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
