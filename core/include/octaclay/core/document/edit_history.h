#pragma once

// Undo/redo store for brush strokes (DESIGN.md, "Brushes": the engine records what each stroke
// changed, tiles before and after). CPU only: the engine reads tiles back before and after a
// stroke, a StrokeRecorder compresses them, EditHistory keeps them under a memory budget and
// hands the texels back through a TileApplier (a GPU upload, or applierFor() on a CPU image).

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/texel_rect.h"

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {

/// Receives texels to write back: region of layer, row-major, region.width × region.height ×
/// editLayerChannels(layer) floats. The span is only valid during the call.
using TileApplier = std::function<void(EditLayer layer, TexelRect region, std::span<const float>)>;

/// Which side of a change to restore.
enum class TileState { Before, After };

/// What one stroke changed in one tile of one layer, stored compactly: texels whose bits did
/// not change are not stored at all. The tile's texels are scanned row-major; runs of unchanged
/// texels (their after XOR before is zero in every channel) are stored as a count, changed
/// texels as their `before` bits and the XOR of `after` against `before` (uint32 patterns, so
/// NaN payloads and -0.0 survive bit-exactly). Memory therefore follows the changed texels, not
/// the tile size. Unchanged texels are the same on both sides, so restoring one side only
/// writes the changed texels: the target must hold the other side (the history's invariant).
struct TileChange {
  EditLayer layer = EditLayer::Positions;
  int tileX = 0, tileY = 0; ///< tile coordinates, in units of StrokeRecorder::kTileSize
  int channels = 0;         ///< editLayerChannels(layer)
  TexelRect region;         ///< the tile's texels in the image
  std::uint32_t changedTexels = 0;
  /// (skip, count) pairs in texels, in row-major order over region: skip unchanged, then count
  /// changed texels. Sum of counts == changedTexels.
  std::vector<std::uint32_t> runs;
  std::vector<float> before;          ///< changedTexels × channels, bits as read
  std::vector<std::uint32_t> xorBits; ///< changedTexels × channels, after ^ before

  /// Memory held by this change: the struct plus its payload capacities, in bytes.
  std::size_t bytes() const;
  /// Calls apply once per rectangle of changed texels (a run split at row ends into at most
  /// three rectangles) with the texels of `state`. Rethrows what apply throws.
  void apply(TileState state, const TileApplier& apply) const;
  /// Writes the changed texels of `state` into tile, the whole tile row-major
  /// (region.width × region.height × channels floats); other texels are left alone.
  /// Throws Error(InvalidArgument) if tile has the wrong size.
  void patch(TileState state, std::span<float> tile) const;
};

/// One undoable step: a label for the UI and the tiles it changed.
struct Stroke {
  std::string label;
  int imageSide = 0;             ///< N+1 of the image the tiles belong to
  std::vector<TileChange> tiles; ///< only tiles with at least one changed texel
  std::size_t changedTexels = 0; ///< sum over tiles
  std::size_t bytes = 0;         ///< memory held, set by StrokeRecorder::finish()

  /// Recomputes the memory held: the struct, the label, the tile array and every tile's payload.
  std::size_t computeBytes() const;
};

/// Builds a Stroke from tiles read before and after it. Tiles are square, kTileSize texels; the
/// last row and column of tiles are smaller (the image is (N+1)², tiles cover it exactly).
class StrokeRecorder {
public:
  static constexpr int kTileSize = 64;

  /// Throws Error(InvalidArgument) unless imageSide (N+1, in texels) is at least 2.
  explicit StrokeRecorder(int imageSide);

  /// Tiles per row (and per column) of an image imageSide texels wide: ceil(side / kTileSize).
  static int tilesPerSide(int imageSide);
  /// The texels of tile (tileX, tileY). Throws Error(InvalidArgument) if it is outside.
  static TexelRect tileRegion(int imageSide, int tileX, int tileY);

  int imageSide() const { return side_; }

  /// Records tile (tileX, tileY) of layer: before and after are its texels, row-major,
  /// tileRegion().width × height × channels floats. A tile with no changed bit costs nothing.
  /// Throws Error(InvalidArgument) if the tile is outside the image, channels is not
  /// editLayerChannels(layer), a span has the wrong size, or the tile was already added.
  void addTile(EditLayer layer, int tileX, int tileY, int channels, std::span<const float> before,
               std::span<const float> after);
  /// The stroke recorded so far, labelled; the recorder is left empty for the next stroke.
  Stroke finish(std::string label);

private:
  int side_ = 0;
  Stroke stroke_;
  std::vector<std::uint8_t> seen_; // per layer and tile: already added
};

/// Linear undo/redo history of strokes under a memory budget. Not thread-safe: call it from
/// the thread that owns the document.
class EditHistory {
public:
  /// budgetBytes: most memory the history may hold (see bytes()); default 256 MiB.
  explicit EditHistory(std::size_t budgetBytes = std::size_t{256} << 20);

  /// Adds stroke as the newest undo step and clears the redo steps. Then, while bytes() exceeds
  /// the budget, drops the oldest steps, never stroke itself (alone over budget, it is kept and
  /// everything older is dropped). A stroke with no tiles is ignored. Throws
  /// Error(InvalidArgument) if stroke.imageSide differs from the strokes held (clear() first).
  void record(Stroke stroke);

  bool canUndo() const { return cursor_ > 0; }
  bool canRedo() const { return cursor_ < strokes_.size(); }
  std::size_t undoCount() const { return cursor_; }
  std::size_t redoCount() const { return strokes_.size() - cursor_; }
  /// The step undo() would revert, or nullptr.
  const Stroke* nextUndo() const;
  /// The step redo() would reapply, or nullptr.
  const Stroke* nextRedo() const;

  /// Reverts the newest step: apply receives every changed texel's `before` (tiles in reverse
  /// recording order). The target must hold the step's `after` state. Returns the step (valid
  /// until the next record(), clear() or destruction), or nullptr if there is nothing to undo.
  /// If apply throws, the history is unchanged and the exception propagates.
  const Stroke* undo(const TileApplier& apply);
  /// Reapplies the newest undone step: apply receives every changed texel's `after`. Same
  /// contract as undo().
  const Stroke* redo(const TileApplier& apply);

  /// Memory held in bytes: per stroke its struct, label and tile array, per tile its struct and
  /// compressed payload (capacities, not sizes).
  std::size_t bytes() const { return bytes_; }
  std::size_t budget() const { return budget_; }
  /// Drops every step.
  void clear();

private:
  std::size_t budget_;
  std::size_t bytes_ = 0;
  std::deque<Stroke> strokes_; // oldest first; [0, cursor_) undoable, [cursor_, end) redoable
  std::size_t cursor_ = 0;
};

/// A TileApplier writing Positions tiles into image (4 floats per texel, bits copied as they
/// are). The image must outlive the applier. The applier throws Error(InvalidArgument) for
/// another layer or a region outside the image.
TileApplier applierFor(GeometryImage& image);

/// A TileApplier writing any layer into doc; a uniform layer is first filled out to texels
/// (and the mask marked present when written). The document must outlive the applier. Throws
/// Error(InvalidArgument) for a region outside the image.
TileApplier applierFor(Document& doc);

} // namespace octaclay::core
