#pragma once

// One undoable step and its encoding (DESIGN.md, "Brushes": the engine records what each stroke
// changed, tiles before and after). CPU only: the engine reads tiles back before and after a
// stroke or an operation, an EditStepRecorder compresses them into an EditStep, which the
// budgeted EditHistory (edit_history.h) keeps; a step hands its texels back through a
// TileApplier.

#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/texel_rect.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace octaclay::core {

struct Document;

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
  int tileX = 0, tileY = 0; ///< tile coordinates, in units of EditStepRecorder::kTileSize
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
struct EditStep {
  std::string label;
  int imageSide = 0;             ///< N+1 (W+1) of the image the tiles belong to
  int imageRows = 0;             ///< H+1 of a W × H image (torus, plane); 0: imageSide (square)
  std::vector<TileChange> tiles; ///< only tiles with at least one changed texel
  std::size_t changedTexels = 0; ///< sum over tiles
  std::size_t bytes = 0;         ///< memory held, set by EditStepRecorder::finish()
  /// A step that replaced the whole document (Remesh, Resolution, Import: N may change) holds
  /// the documents before and after it instead of tiles (EditHistory hands them to a
  /// DocumentReplacer); imageSide is then the after document's N+1.
  std::shared_ptr<const Document> replacedBefore, replacedAfter;
  /// Set by EditHistory::record: unique over the history's life, never 0 (a saved state names
  /// the step it was saved at).
  std::uint64_t serial = 0;

  bool replacesDocument() const { return replacedBefore != nullptr; }

  /// Recomputes the memory held: the struct, the label, the tile array and every tile's payload.
  std::size_t computeBytes() const;
};

/// Builds an EditStep from tiles read before and after it. Tiles are square, kTileSize texels; the
/// last row and column of tiles are smaller (the image is (N+1)², tiles cover it exactly).
class EditStepRecorder {
public:
  static constexpr int kTileSize = 64;

  /// Throws Error(InvalidArgument) unless imageSide (N+1, in texels) is at least 2. imageRows:
  /// H+1 of a W × H image whose rows are not its side (0: square, the ball's).
  explicit EditStepRecorder(int imageSide, int imageRows = 0);

  /// Tiles per row (and per column) of an image imageSide texels wide: ceil(side / kTileSize).
  static int tilesPerSide(int imageSide);
  /// The texels of tile (tileX, tileY). Throws Error(InvalidArgument) if it is outside.
  static TexelRect tileRegion(int imageSide, int tileX, int tileY);
  /// The same for an image imageSide texels wide and imageRows high.
  static TexelRect tileRegion(int imageSide, int imageRows, int tileX, int tileY);

  int imageSide() const { return side_; }
  int imageRows() const { return rows_; }

  /// Records tile (tileX, tileY) of layer: before and after are its texels, row-major,
  /// tileRegion().width × height × channels floats. A tile with no changed bit costs nothing.
  /// Throws Error(InvalidArgument) if the tile is outside the image, channels is not
  /// editLayerChannels(layer), a span has the wrong size, or the tile was already added.
  void addTile(EditLayer layer, int tileX, int tileY, int channels, std::span<const float> before,
               std::span<const float> after);
  /// The stroke recorded so far, labelled; the recorder is left empty for the next stroke.
  EditStep finish(std::string label);

private:
  int side_ = 0, rows_ = 0;
  EditStep stroke_;
  std::vector<std::uint8_t> seen_; // per layer and tile: already added
};

} // namespace octaclay::core
