#pragma once

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_step.h"
#include "octaclay/core/geometry/tile_bounds.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_objects.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <utility>
#include <vector>

namespace octaclay::gpu {

namespace detail {
class AreaNormalPass;
class FiniteCheckPass;
class TileBoundsPass;
} // namespace detail

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

/// The area vectors (cross products) of the triangles near a point, summed, and how many.
struct AreaSum {
  core::Vec3f sum;
  int triangles = 0;
};

/// A document being edited: its layers as GPU textures (each with a scratch twin for
/// ping-pong passes), which hold the truth while editing, and a CPU mirror of them. During a
/// stroke (deferPulls) a pass's changed regions are only recorded, and read back in bulk when a
/// reader needs them: document() syncs the mirror first, so every reader outside the dab path
/// sees the textures' state (saving, exporting, the CPU's LOD, history, picking). Positions are
/// deferred too where the driver's texture memory is not the CPU's (a real GPU: positionsDeferred)
/// and then the tile bounds come from a reduction on the GPU (only the tiles' boxes read back);
/// on a software rasterizer, where a read-back is a copy in the same memory, they are read back
/// at once and the bounds refreshed from them. The stroke's own reads use mirror() after
/// syncRegion() of what they read. All calls need the engine's context current.
class GpuDocument {
public:
  /// Uploads every layer, in row bands; progress (optional) is called after each with the
  /// fraction done, on this thread (a GUI thread may process events there). Throws GlError.
  explicit GpuDocument(core::Document document, const std::function<void(float)>& progress = {});
  /// The layers' textures, made ahead: on another thread with a context that shares this one's
  /// objects (a software rasterizer zeroes each new texture's memory as it makes it: 0.6 GB at
  /// N = 4096, kept off a GUI thread that way). Positions, diffuse, feature, mask.
  using Storage = std::array<Texture, 4>;
  /// The textures a document of this grid needs (any context current; no framebuffer made).
  static Storage makeStorage(const core::SampleGrid& grid);
  /// The same upload into `storage` (from makeStorage for this document's grid, finished on its
  /// context before this call); an empty storage is made here as the constructor above does.
  GpuDocument(core::Document document, const std::function<void(float)>& progress, Storage storage);
  ~GpuDocument();
  GpuDocument(GpuDocument&&) noexcept;
  GpuDocument& operator=(GpuDocument&&) noexcept;

  /// N of the ball; W of a W × H torus or plane (as core::GeometryImage::size()).
  int size() const { return document_.size(); }
  /// The image's shape: topology, W and H in cells.
  const core::SampleGrid& grid() const { return document_.positions.grid(); }
  core::Topology topology() const { return document_.positions.topology(); }
  /// The textures' width W+1 (the row stride of every layer) and height H+1, in texels.
  int side() const { return document_.positions.side(); }
  int rows() const { return document_.positions.rows(); }
  /// The image's samples across, for lengths measured in samples (a uv brush's radius, a
  /// material's uv tiles): N of the ball, √(W·H) of a W × H image, so a radius covers about the
  /// same share of the samples on every topology.
  float samplesAcross() const {
    return static_cast<float>(
        std::sqrt(double(document_.positions.width()) * double(document_.positions.height())));
  }
  /// Every texel: {0, 0, side(), rows()}.
  core::TexelRect whole() const { return {0, 0, side(), rows()}; }
  /// The document as the textures hold it: the mirror, synced first where read-backs wait.
  const core::Document& document() const;
  /// The mirror as it is, read-backs still waiting or not: for the dab path, which syncs what it
  /// reads (syncRegion), and for what the textures do not change (sizes, fills, uniform flags).
  const core::Document& mirror() const { return document_; }
  /// Reads back the waiting regions of the positions that meet rects (the mirror is a cache
  /// of the textures: syncing it changes nothing a reader sees).
  void syncRegion(std::span<const core::TexelRect> rects) const;
  /// The tile bounds, always current (refreshed after every pass, from the GPU where positions
  /// are deferred).
  const core::TileBounds& bounds() const { return bounds_; }
  /// Whether a stroke's position read-backs wait for a reader (by default where the driver is
  /// not a software rasterizer; $OCTACLAY_DEFER_POSITIONS = 1 or 0 overrides that). Tests set it
  /// to run both ways on one machine.
  bool positionsDeferred() const { return deferPositions_; }
  /// Whether the driver renders on the CPU (llvmpipe): its textures in the CPU's memory.
  bool softwareRenderer() const { return software_; }
  void setPositionsDeferred(bool on);

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

  /// A pass changed rect of the layer's texture: read back into the mirror now, or while pulls
  /// are deferred (a paint layer, or positions where positionsDeferred()) recorded for a sync (a
  /// paint layer gets its mirror texels now, so it stops counting as uniform at once). The tile
  /// bounds follow at once either way.
  void changed(core::EditLayer layer, core::TexelRect rect);
  /// The same for several rectangles of one pass (tile bounds refreshed once for all); the
  /// single-rectangle form comes through here, so a pass's changes reach the feed here.
  void changed(core::EditLayer layer, std::span<const core::TexelRect> rects);
  /// Whether changed() reads from this layer at once (positions always: their texels or their
  /// tile bounds; paint layers unless their pulls are deferred): the caller must know the passes
  /// that wrote it finished.
  bool readsAtOnce(core::EditLayer layer) const {
    return !deferring_ || layer == core::EditLayer::Positions;
  }
  /// While on (a stroke), changed() defers paint layers' pulls, and positions' where
  /// positionsDeferred(). Turning it off syncs the mirror.
  void deferPulls(bool on);
  /// Whether some layer's mirror lags its texture (deferred pulls not yet synced).
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

  /// Whether every texel of rects in the layer's texture is finite (positions: their xyz also
  /// within ±core::kMaxCoordinate), reduced on the GPU to one flag read back. Throws GlError.
  bool holdsOnlyFinite(core::EditLayer layer, std::span<const core::TexelRect> rects);

  /// The sum of the area vectors of the triangles of tiles (core::TileBounds numbers) whose
  /// centroid lies within radius of centre, reduced on the GPU from the positions texture:
  /// only the quarters' sums are read back, not the texels. Throws GlError.
  AreaSum areaSum(std::span<const int> tiles, core::Vec3f centre, float radius) const;
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

  /// Writes saliency ((W+1)(H+1) values, row-major) into the positions' alpha of the mirror and the
  /// texture; xyz stay as they are. Throws core::Error(InvalidArgument) for a wrong count.
  void writeSaliency(std::span<const float> saliency);

private:
  static std::size_t index(core::EditLayer layer) { return static_cast<std::size_t>(layer); }
  core::Layer* mirrorLayer(core::EditLayer layer);
  const core::Layer* mirrorLayer(core::EditLayer layer) const;
  /// Copies rect of the layer's texture into the mirror (no tile bounds' refresh).
  /// Painted-but-uniform mirror layers get their texels first.
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
  bool deferPositions_ = false;
  bool software_ = false; ///< softwareRenderer()
  /// Per layer, a flag per kStaleBlock² block of texels whose pull is deferred (empty: none).
  static constexpr int kStaleBlock = 32;
  std::array<std::vector<std::uint8_t>, 4> staleBlocks_;
  std::array<std::vector<core::TexelRect>, 4> unpublished_; // changed since publishChanges()
  std::array<std::size_t, 4> mergedCount_{}; // unpublished_'s size after its last merge
  std::function<void(const DocumentChange&)> follower_;
  /// The tile bounds' refresh after a pass: a reduction on the GPU (made on first use).
  std::unique_ptr<detail::TileBoundsPass> boundsPass_;
  std::unique_ptr<detail::FiniteCheckPass> finitePass_;      // holdsOnlyFinite's, made on first use
  mutable std::unique_ptr<detail::AreaNormalPass> areaPass_; // areaSum's, made on first use
  void refreshBounds(std::span<const core::TexelRect> rects);
  /// Marks the kStaleBlock² blocks that rects meet as waiting for a read-back.
  void markStale(core::EditLayer layer, std::span<const core::TexelRect> rects);
  /// Notes rect of layer as changed for the next publishChanges().
  void note(core::EditLayer layer, core::TexelRect rect);
};

/// Undo/redo writes through this: each region goes to the mirror and the texture.
core::TileApplier undoApplier(GpuDocument& document);

} // namespace octaclay::gpu
