#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_step.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_objects.h"

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <utility>
#include <vector>

namespace octaclay::gpu {

/// What a change of the document was part of, for the followers that act only when an edit
/// settles (the saliency, the live LOD).
enum class ChangeKind {
  Dabs,        ///< a stroke's dabs, and keep detail's relaxations between them (more may follow)
  StrokeEnd,   ///< a stroke ended (its last dabs and relaxation, or nothing more)
  Undo,        ///< history stepped back
  Redo,        ///< history stepped forward
  Applied,     ///< a whole-document change applied in place (Even Out) or a refused stroke undone
  NewDocument, ///< every layer uploaded anew
};

/// One change of a layer's texture (and mirror): the one kind of event GpuDocument reports to
/// its followers (the renderer's normals and stretch map, the saliency, the live LOD). The
/// saliency written into the positions' alpha (writeSaliency) is not a change of the surface and
/// is not reported.
struct DocumentChange {
  ChangeKind kind = ChangeKind::Dabs;
  core::EditLayer layer = core::EditLayer::Positions;
  std::vector<core::TexelRect> rects; ///< merged (core::mergeRects); empty: nothing of the layer
};

/// A document being edited: its layers as GPU textures (each with a scratch twin for
/// ping-pong passes) and a CPU mirror that the engine keeps equal to them, region by region,
/// after every dab. The mirror answers tile bounds, picking, undo and saving without reading
/// the full image back. With deferred paint pulls (a stroke's lifetime) the paint layers'
/// changed regions are only recorded and read back together by syncMirror(); positions are
/// always read back at once. All calls need the engine's context current.
class GpuDocument {
public:
  /// Uploads every layer, in row bands; progress (optional) is called after each with the
  /// fraction done, on this thread (a GUI thread may process events there). Throws GlError.
  explicit GpuDocument(core::Document document, const std::function<void(float)>& progress = {});

  int size() const { return document_.size(); }
  const core::Document& document() const { return document_; }
  const core::TileBounds& bounds() const { return bounds_; }

  Texture& texture(core::EditLayer layer) { return textures_[index(layer)]; }
  /// The layer's scratch twin, made on first use: a document edited only by brushes that write
  /// positions never holds its paint layers' twins (where the driver's texture memory is the
  /// CPU's, as on llvmpipe, they are as large as the layers). Throws GlError.
  Texture& scratch(core::EditLayer layer);
  /// Exchanges a layer's texture and its scratch twin: after a pass that wrote every texel of
  /// the scratch, this replaces copying it back.
  void swapScratch(core::EditLayer layer) {
    scratch(layer);
    std::swap(textures_[index(layer)], scratch_[index(layer)]);
  }

  /// Copies rect of the layer's texture into the mirror (and refreshes tile bounds for
  /// positions). Painted-but-uniform mirror layers get their texels first.
  void pull(core::EditLayer layer, core::TexelRect rect);
  /// A pass changed rect of the layer's texture: pulled now, or for a paint layer while pulls
  /// are deferred, recorded for syncMirror() (the layer gets its mirror texels now, so it stops
  /// counting as uniform at once).
  void changed(core::EditLayer layer, core::TexelRect rect);
  /// The same for several rectangles of one pass (tile bounds refreshed once for all); the
  /// single-rectangle form comes through here, so a pass's changes reach the feed here.
  void changed(core::EditLayer layer, std::span<const core::TexelRect> rects);
  /// Whether changed() reads this layer back at once (positions always, paint layers unless
  /// their pulls are deferred): the caller must know the passes that wrote it finished.
  bool readsAtOnce(core::EditLayer layer) const {
    return !deferring_ || layer == core::EditLayer::Positions;
  }
  /// While on, changed() defers paint layers' pulls. Turning it off syncs the mirror.
  void deferPaintPulls(bool on);
  /// Whether some paint layer's mirror lags its texture (deferred pulls not yet synced).
  bool mirrorStale() const;
  /// Reads every deferred region back into the mirror, in merged rectangles.
  void syncMirror();
  /// Writes rect of the mirror (e.g. restored by undo) to the layer's texture.
  void push(core::EditLayer layer, core::TexelRect rect);
  /// The mirror's texels of rect, row-major, channels per texel as the layer has.
  std::vector<float> mirrorTexels(core::EditLayer layer, core::TexelRect rect) const;
  /// Replaces rect of the mirror with texels (the layout of mirrorTexels) and pushes it.
  void restore(core::EditLayer layer, core::TexelRect rect, std::span<const float> texels);

  /// restore() with the texture's texels copied on the GPU from `from` at (fromX, fromY) (an
  /// undo pool's copy of them, equal to texels) instead of uploaded from the CPU.
  void restoreCopy(core::EditLayer layer, core::TexelRect rect, std::span<const float> texels,
                   const Texture& from, int fromX, int fromY);

  static int channels(core::EditLayer layer);

  // The change feed: every texture write that goes through changed(), push() or restore() is
  // collected per layer and reported by publishChanges() to the one follower, so no caller
  // passes rectangles around.

  /// The function told of each change (one call per layer changed); empty: none.
  void setChangeFollower(std::function<void(const DocumentChange&)> follower) {
    follower_ = std::move(follower);
  }
  /// Reports what changed since the last call, as kind, then forgets it. Returns whether
  /// anything had changed.
  bool publishChanges(ChangeKind kind);
  /// Marks every texel of every layer changed (a new upload).
  void markAllChanged();

  /// Writes saliency ((N+1)² values, row-major) into the positions' alpha of the mirror and the
  /// texture; xyz stay as they are. Throws core::Error(InvalidArgument) for a wrong count.
  void writeSaliency(std::span<const float> saliency);

private:
  static std::size_t index(core::EditLayer layer) { return static_cast<std::size_t>(layer); }
  core::Layer* mirrorLayer(core::EditLayer layer);
  const core::Layer* mirrorLayer(core::EditLayer layer) const;
  /// pull without the tile bounds' refresh.
  void readBack(core::EditLayer layer, core::TexelRect rect);
  void writeMirror(core::EditLayer layer, core::TexelRect rect, std::span<const float> texels);
  /// The mirror layer's floats (row-major, channels(layer) per texel), given texels if uniform.
  float* mirrorData(core::EditLayer layer);
  /// mirrorData for a layer a pass changed: a changed mask is one the document saves.
  float* editedMirror(core::EditLayer layer);

  core::Document document_;
  core::TileBounds bounds_;
  std::array<Texture, 4> textures_, scratch_;
  bool deferring_ = false;
  /// Per layer, a flag per kStaleBlock² block of texels whose pull is deferred (empty: none).
  static constexpr int kStaleBlock = 32;
  std::array<std::vector<std::uint8_t>, 4> staleBlocks_;
  std::array<std::vector<core::TexelRect>, 4> unpublished_; // changed since publishChanges()
  std::array<std::size_t, 4> mergedCount_{}; // unpublished_'s size after its last merge
  std::function<void(const DocumentChange&)> follower_;
  /// Notes rect of layer as changed for the next publishChanges().
  void note(core::EditLayer layer, core::TexelRect rect);
};

/// Undo/redo writes through this: each region goes to the mirror and the texture.
core::TileApplier undoApplier(GpuDocument& document);

} // namespace octaclay::gpu
