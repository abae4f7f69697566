#pragma once

// A stroke's before-tiles on the GPU: each copied from its layer's texture into a pool texture
// (glCopyImageSubData) the first time a dab may touch it, and downloaded to CPU memory in the
// background: the tiles captured since the last download are read from the pool into one
// pixel-pack buffer behind one fence, collected once it has signalled (a dab later). The
// capture never waits for the GPU, and a stroke undone whole is copied back on the GPU.

#include "octaclay/core/document/edit_step.h"
#include "octaclay/gpu/gl_objects.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <cstddef>
#include <vector>

namespace octaclay::gpu::detail {

class UndoTilePool {
public:
  explicit UndoTilePool(GpuDocument& document);
  ~UndoTilePool();
  UndoTilePool(const UndoTilePool&) = delete;
  UndoTilePool& operator=(const UndoTilePool&) = delete;

  /// Copies region (at most kTileSize square) of the layer's texture into a free slot of the
  /// pool, on the GPU; returns the slot. Its download starts at the next startDownloads().
  /// Throws GlError.
  int capture(core::EditLayer layer, core::TexelRect region);
  /// Issues the copies capture() holds back to join side-by-side tiles into one: before the
  /// layers they come from are written.
  void flushCopies();
  /// Starts downloading the slots captured since the last call (one buffer, one fence), and
  /// takes in the downloads whose fences have signalled, without waiting for the others.
  void startDownloads();
  /// The slot's texels (row-major, GpuDocument::channels of its layer per texel), as the
  /// texture held them at capture(); waits for its download when it has not arrived yet.
  const std::vector<float>& texels(int slot);
  /// Writes the slot back: the texture from the pool's copy on the GPU, the mirror from the
  /// downloaded texels.
  void restore(int slot);

private:
  /// Pool textures hold (slots per side)² tiles each, in their layer's format: the first
  /// kFirstSlotsPerSide across, each next one twice as many up to kMostSlotsPerSide, so a small
  /// stroke makes one small texture and a large one few (a texture made costs more than the
  /// copies into it on a real GPU's driver).
  static constexpr int kFirstSlotsPerSide = 4;
  static constexpr int kMostSlotsPerSide = 16;
  struct Slot {
    core::EditLayer layer = core::EditLayer::Positions;
    core::TexelRect region;
    int page = 0, x = 0, y = 0; // the pool page and the slot's corner in it
    int batch = -1;             // its download; -1: not started
    std::size_t offset = 0;     // of its first texel in the batch's buffer
    int stride = 0;             // texels from one of its rows to the next there
    bool collected = false;
    std::vector<float> texels;
  };
  struct Batch {
    Buffer buffer;
    std::size_t bytes = 0;
    void* fence = nullptr; // GLsync; null once collected
    std::vector<int> slots;
  };
  const Texture& page(const Slot& s) const;
  void collect(Batch& batch);
  bool signalled(const Batch& batch) const;

  /// A copy of side-by-side tiles into side-by-side slots, not issued yet (per layer).
  struct PendingCopy {
    int fromX = 0, fromY = 0, page = -1, toX = 0, toY = 0, width = 0, height = 0;
  };
  void issue(core::EditLayer layer, PendingCopy& copy);
  GpuDocument& document_;
  std::array<PendingCopy, 4> pending_;
  std::array<std::vector<Texture>, 4> pages_; // per layer
  std::array<int, 4> used_{};                 // slots used in each layer's last page
  std::vector<Slot> slots_;
  std::vector<int> unstarted_; // captured, download not started
  std::vector<Batch> batches_;
  std::size_t collected_ = 0; // batches before this one are all collected
  std::vector<Buffer> spare_; // collected batches' buffers, for reuse
  std::vector<std::size_t> spareBytes_;
};

} // namespace octaclay::gpu::detail
