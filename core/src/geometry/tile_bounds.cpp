#include "octaclay/core/geometry/tile_bounds.h"

#include <algorithm>
#include <tuple>

namespace octaclay::core {

TileBounds::TileBounds(const GeometryImage& image)
    : n_(image.size()), tiles_(std::max(1, image.size() / kTileSize)),
      boxes_(static_cast<std::size_t>(tiles_) * tiles_),
      groups_(static_cast<std::size_t>(groupsPerSide()) * groupsPerSide()) {
  refresh(image, {0, 0, image.side(), image.side()});
}

TexelRect TileBounds::tileRect(int tx, int ty) const {
  const int size = std::min(kTileSize, n_);
  const int x = tx * size, y = ty * size;
  // The last tile of a row or column also takes sample N.
  const int width = tx == tiles_ - 1 ? n_ + 1 - x : size;
  const int height = ty == tiles_ - 1 ? n_ + 1 - y : size;
  return {x, y, width, height};
}

void TileBounds::refresh(const GeometryImage& image, TexelRect rect) {
  const int size = std::min(kTileSize, n_);
  // A tile's box also holds the first sample past it, so a box bounds its cells' triangles: a
  // changed sample on a tile's first row or column also moves the box of the tile before it.
  const int tx0 = std::min(std::max(rect.x - 1, 0) / size, tiles_ - 1);
  const int ty0 = std::min(std::max(rect.y - 1, 0) / size, tiles_ - 1);
  const int tx1 = std::min((rect.x + rect.width - 1) / size, tiles_ - 1);
  const int ty1 = std::min((rect.y + rect.height - 1) / size, tiles_ - 1);
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx) {
      const TexelRect r = tileRect(tx, ty);
      // Plain min/max over rows (not BoundingBox::extend) so the compiler vectorizes it: this
      // runs after every dab.
      Vec3f lo = image.at(r.x, r.y).xyz(), hi = lo;
      const int lastI = std::min(r.x + r.width, n_);
      for (int j = r.y; j <= std::min(r.y + r.height, n_); ++j) {
        const Vec4f* row = &image.at(0, j);
        for (int i = r.x; i <= lastI; ++i) {
          lo = {std::min(lo.x, row[i].x), std::min(lo.y, row[i].y), std::min(lo.z, row[i].z)};
          hi = {std::max(hi.x, row[i].x), std::max(hi.y, row[i].y), std::max(hi.z, row[i].z)};
        }
      }
      boxes_[static_cast<std::size_t>(ty) * tiles_ + tx] = BoundingBox{lo, hi};
    }
  for (int gy = ty0 / kGroup; gy <= ty1 / kGroup; ++gy)
    for (int gx = tx0 / kGroup; gx <= tx1 / kGroup; ++gx) {
      BoundingBox group;
      for (int ty = gy * kGroup; ty < std::min(tiles_, (gy + 1) * kGroup); ++ty)
        for (int tx = gx * kGroup; tx < std::min(tiles_, (gx + 1) * kGroup); ++tx) {
          group.extend(boxes_[static_cast<std::size_t>(ty) * tiles_ + tx].min);
          group.extend(boxes_[static_cast<std::size_t>(ty) * tiles_ + tx].max);
        }
      groups_[static_cast<std::size_t>(gy) * groupsPerSide() + gx] = group;
    }
}

float TileBounds::diagonal() const {
  BoundingBox all;
  for (const BoundingBox& b : boxes_)
    if (!b.empty()) {
      all.extend(b.min);
      all.extend(b.max);
    }
  return all.diagonal();
}

std::vector<int> TileBounds::tilesNearSphere(Vec3f centre, float radius) const {
  const float r2 = radius * radius;
  auto near = [&](const BoundingBox& b) {
    const float dx = std::max({b.min.x - centre.x, 0.0f, centre.x - b.max.x});
    const float dy = std::max({b.min.y - centre.y, 0.0f, centre.y - b.max.y});
    const float dz = std::max({b.min.z - centre.z, 0.0f, centre.z - b.max.z});
    return dx * dx + dy * dy + dz * dz <= r2;
  };
  std::vector<int> tiles;
  const int groups = groupsPerSide();
  for (int gy = 0; gy < groups; ++gy)
    for (int gx = 0; gx < groups; ++gx) {
      if (!near(groups_[static_cast<std::size_t>(gy) * groups + gx])) continue;
      for (int ty = gy * kGroup; ty < std::min(tiles_, (gy + 1) * kGroup); ++ty)
        for (int tx = gx * kGroup; tx < std::min(tiles_, (gx + 1) * kGroup); ++tx)
          if (near(boxes_[static_cast<std::size_t>(ty) * tiles_ + tx]))
            tiles.push_back(ty * tiles_ + tx);
    }
  std::sort(tiles.begin(), tiles.end());
  return tiles;
}

std::vector<TexelRect> mergeRects(std::vector<TexelRect> rects) {
  const auto byRow = [](TexelRect a, TexelRect b) {
    return std::tie(a.y, a.height, a.x) < std::tie(b.y, b.height, b.x);
  };
  std::sort(rects.begin(), rects.end(), byRow);
  std::vector<TexelRect> rows;
  for (TexelRect r : rects) {
    TexelRect* last = rows.empty() ? nullptr : &rows.back();
    if (last && last->y == r.y && last->height == r.height && last->x + last->width == r.x)
      last->width += r.width;
    else
      rows.push_back(r);
  }
  const auto byColumn = [](TexelRect a, TexelRect b) {
    return std::tie(a.x, a.width, a.y) < std::tie(b.x, b.width, b.y);
  };
  std::sort(rows.begin(), rows.end(), byColumn);
  std::vector<TexelRect> merged;
  for (TexelRect r : rows) {
    TexelRect* last = merged.empty() ? nullptr : &merged.back();
    if (last && last->x == r.x && last->width == r.width && last->y + last->height == r.y)
      last->height += r.height;
    else
      merged.push_back(r);
  }
  return merged;
}

} // namespace octaclay::core
