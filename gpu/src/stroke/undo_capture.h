#pragma once

// A stroke's undo capture: each undo tile of the written layers, copied on the GPU (the
// UndoTilePool) the first time a dab may touch it and downloaded in the background. It also
// makes a stroke all-or-nothing: a failed dab or a result that is not finite puts the captured
// tiles back, bit for bit, from the GPU's copies.

#include "undo_tile_pool.h"

#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/document/edit_step.h"
#include "octaclay/gpu/gpu_document.h"

#include <array>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace octaclay::gpu::detail {

/// The largest |coordinate| a stroke may leave in the positions: the one every reader accepts.
using core::kMaxCoordinate;

class UndoCapture {
public:
  UndoCapture(GpuDocument& document, std::vector<core::EditLayer> layers);

  /// Captures the tiles of rect not captured yet.
  void cover(core::TexelRect rect);
  /// Captures undo tile (tx, ty) of layer if not captured yet, whether or not the brush writes
  /// that layer (a change made between dabs, keep-detail's relaxation, resamples every layer).
  void coverTile(core::EditLayer layer, int tx, int ty);
  /// The position of sample s as it was when the stroke began: from the captured tile when the
  /// stroke writes positions and has covered s (waiting for its download if it has not arrived),
  /// else from the mirror (which nothing the stroke may have changed differs from).
  core::Vec3f positionBefore(core::Sample s) const;
  /// Writes every captured tile back to the mirror and the texture (the stroke is undone): the
  /// textures from the pool's copies on the GPU.
  void restore();
  /// The stroke's undo record, from the captured tiles and the mirror as it is now (synced).
  /// When a written texel is not finite, or a position lies beyond kMaxCoordinate (a reduction
  /// on the GPU, read once), restores the captured tiles first and throws
  /// core::Error(InvalidInput) naming the sample.
  core::EditStep finish(const std::string& label);
  /// The record so far, without the finite check: the stroke goes on.
  core::EditStep record(const std::string& label) const;

private:
  struct Tile {
    core::EditLayer layer;
    int x, y;
    int slot; ///< in pool_
  };

  /// The mirror's texels of a tile (the after state, once the mirror is synced).
  std::vector<float> texels(core::EditLayer layer, int tx, int ty) const;
  /// Captures tile (tx, ty) of layer into the pool, as before_'s next tile.
  void capture(core::EditLayer layer, int tx, int ty);
  /// Throws (after restore()) when after, tile t's texels now, holds a value not to commit.
  void checkFinite(const Tile& t, const std::vector<float>& after);

  GpuDocument& document_;
  mutable UndoTilePool pool_; ///< collecting a download changes nothing the capture answers
  std::vector<core::EditLayer> layers_;
  int side_, rows_, tiles_; ///< the image's W+1 and H+1; tiles along a row
  std::map<int, int> seen_; ///< tile index → its positions tile in before_, or -1
  std::vector<Tile> before_;
  std::set<std::array<int, 3>> extra_; ///< (layer, tx, ty) captured beyond layers_
};

} // namespace octaclay::gpu::detail
