#pragma once

#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/texel_rect.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <span>
#include <vector>

namespace octaclay::core {

/// Bounding boxes of the positions per square tile of the image, and of groups of kGroup² tiles
/// above them (a two-level min/max pyramid), so a brush finds the samples it can reach without
/// scanning the image. Tiles are kTileSize samples wide; the last row and
/// column of tiles are one sample wider (the image is (W+1)×(H+1) and tiles cover it exactly).
class TileBounds {
public:
  static constexpr int kTileSize = 32;
  static constexpr int kGroup = 8;

  TileBounds() = default;
  explicit TileBounds(const GeometryImage& image);

  /// Tiles along a row (the image's width) and down a column; equal for a square image.
  int tilesX() const { return tilesX_; }
  int tilesY() const { return tilesY_; }
  int tileCount() const { return tilesX_ * tilesY_; }
  /// tilesX(): the tiles per side of a square image (tile t is tx + ty · tilesX()).
  int tilesPerSide() const { return tilesX_; }
  int groupsX() const { return (tilesX_ + kGroup - 1) / kGroup; }
  int groupsY() const { return (tilesY_ + kGroup - 1) / kGroup; }
  /// The samples of tile (tx, ty).
  TexelRect tileRect(int tx, int ty) const;
  /// Recomputes the boxes of every tile that overlaps rect.
  void refresh(const GeometryImage& image, TexelRect rect);
  /// The same for several rectangles (a dab's), each tile once.
  void refresh(const GeometryImage& image, std::span<const TexelRect> rects);
  /// The tiles (as tx + ty · tilesX, in row order) whose boxes a change of rects moves:
  /// those they overlap and the ones before them in i and j (a box holds the first sample past
  /// its tile).
  std::vector<int> tilesTouching(std::span<const TexelRect> rects) const;
  /// Sets the boxes of tiles from their quarters' boxes, computed elsewhere (the GPU's
  /// reduction): four per tile, quarter q at 4k + q, each the bounds of quarterRect's samples
  /// and of the first sample past it in i and j, as refresh computes them. The tiles' and their
  /// groups' boxes follow.
  void setQuarterBoxes(std::span<const int> tiles, std::span<const BoundingBox> quarters);
  /// Tiles (as tx + ty · tilesX) whose box comes within `radius` of `centre`.
  std::vector<int> tilesNearSphere(Vec3f centre, float radius) const;
  /// Quarter q (0 to 3: +i, +j by bits) of tile (tx, ty): the tile split at half its size.
  TexelRect quarterRect(int tx, int ty, int q) const;
  /// The quarters of tiles whose box comes within `radius` of `centre`, tile by tile in
  /// tilesNearSphere's order: a brush's pass runs over about a fifth fewer samples than over
  /// whole tiles.
  std::vector<TexelRect> rectsNearSphere(Vec3f centre, float radius) const;
  /// Bounds of the tile's samples and of the first sample past it in i and j (its cells).
  const BoundingBox& box(int tile) const { return boxes_[tile]; }
  /// Diagonal of the whole image's bounding box (the union of the tiles' boxes).
  float diagonal() const;

private:
  /// Bounds of r's samples and the first sample past it in i and j, read from image.
  BoundingBox rectBox(const GeometryImage& image, TexelRect r) const;
  int width_ = 0, height_ = 0, tilesX_ = 0, tilesY_ = 0;
  std::vector<BoundingBox> boxes_, groups_;
  std::vector<BoundingBox> quarters_; ///< four per tile (quarterRect), as boxes_ for its cells
};

/// The texels of disjoint rects covered by fewer, still disjoint rectangles: runs of
/// side-by-side rects in a row band, then runs of equal spans in consecutive bands. A dab's
/// tiles become a few rectangles, so it costs a few passes and read-backs instead of one a tile.
std::vector<TexelRect> mergeRects(std::vector<TexelRect> rects);

} // namespace octaclay::core
