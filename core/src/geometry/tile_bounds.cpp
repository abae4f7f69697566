#include "octaclay/core/geometry/tile_bounds.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#if defined(__SSE__)
#include <xmmintrin.h>
#endif
#include <tuple>

namespace octaclay::core {
namespace {

// Tiles are square: kTileSize samples, or the image's shorter side when it is smaller.
int tileSide(const GeometryImage& image) {
  return std::min({TileBounds::kTileSize, image.width(), image.height()});
}

} // namespace

TileBounds::TileBounds(const GeometryImage& image)
    : width_(image.width()), height_(image.height()),
      tilesX_(std::max(1, image.width() / tileSide(image))),
      tilesY_(std::max(1, image.height() / tileSide(image))),
      boxes_(static_cast<std::size_t>(tilesX_) * tilesY_),
      groups_(static_cast<std::size_t>(groupsX()) * groupsY()), quarters_(4 * boxes_.size()) {
  refresh(image, {0, 0, image.side(), image.rows()});
}

TexelRect TileBounds::tileRect(int tx, int ty) const {
  const int size = std::min({kTileSize, width_, height_});
  const int x = tx * size, y = ty * size;
  // The last tile of a row or column also takes sample W (or H).
  const int width = tx == tilesX_ - 1 ? width_ + 1 - x : size;
  const int height = ty == tilesY_ - 1 ? height_ + 1 - y : size;
  return {x, y, width, height};
}

void TileBounds::refresh(const GeometryImage& image, TexelRect rect) {
  refresh(image, std::span<const TexelRect>(&rect, 1));
}

void TileBounds::refresh(const GeometryImage& image, std::span<const TexelRect> rects) {
  const std::vector<int> tiles = tilesTouching(rects);
  std::vector<BoundingBox> quarters(4 * tiles.size());
  for (std::size_t k = 0; k < tiles.size(); ++k)
    for (int q = 0; q < 4; ++q)
      quarters[4 * k + static_cast<std::size_t>(q)] =
          rectBox(image, quarterRect(tiles[k] % tilesX_, tiles[k] / tilesX_, q));
  setQuarterBoxes(tiles, quarters);
}

std::vector<int> TileBounds::tilesTouching(std::span<const TexelRect> rects) const {
  std::vector<int> tiles;
  if (rects.empty()) return tiles;
  const int size = std::min({kTileSize, width_, height_});
  // Each tile once however many rectangles overlap it. A tile's box also holds the first sample
  // past it, so a box bounds its cells' triangles: a changed sample on a tile's first row or
  // column also moves the box of the tile before it.
  int tx0 = tilesX_, ty0 = tilesY_, tx1 = -1, ty1 = -1;
  const auto span = [&](TexelRect rect) {
    return std::array<int, 4>{std::min(std::max(rect.x - 1, 0) / size, tilesX_ - 1),
                              std::min(std::max(rect.y - 1, 0) / size, tilesY_ - 1),
                              std::min((rect.x + rect.width - 1) / size, tilesX_ - 1),
                              std::min((rect.y + rect.height - 1) / size, tilesY_ - 1)};
  };
  for (const TexelRect& rect : rects) {
    const auto [x0, y0, x1, y1] = span(rect);
    tx0 = std::min(tx0, x0), ty0 = std::min(ty0, y0), tx1 = std::max(tx1, x1),
    ty1 = std::max(ty1, y1);
  }
  const int w = tx1 - tx0 + 1;
  std::vector<std::uint8_t> stale(static_cast<std::size_t>(w) * (ty1 - ty0 + 1), 0);
  for (const TexelRect& rect : rects) {
    const auto [x0, y0, x1, y1] = span(rect);
    for (int ty = y0; ty <= y1; ++ty)
      for (int tx = x0; tx <= x1; ++tx)
        stale[static_cast<std::size_t>(ty - ty0) * w + (tx - tx0)] = 1;
  }
  for (int ty = ty0; ty <= ty1; ++ty)
    for (int tx = tx0; tx <= tx1; ++tx)
      if (stale[static_cast<std::size_t>(ty - ty0) * w + (tx - tx0)])
        tiles.push_back(ty * tilesX_ + tx);
  return tiles;
}

void TileBounds::setQuarterBoxes(std::span<const int> tiles,
                                 std::span<const BoundingBox> quarters) {
  if (tiles.empty()) return;
  int tx0 = tilesX_, ty0 = tilesY_, tx1 = -1, ty1 = -1;
  for (std::size_t k = 0; k < tiles.size(); ++k) {
    const std::size_t tile = static_cast<std::size_t>(tiles[k]);
    const int tx = tiles[k] % tilesX_, ty = tiles[k] / tilesX_;
    tx0 = std::min(tx0, tx), ty0 = std::min(ty0, ty), tx1 = std::max(tx1, tx),
    ty1 = std::max(ty1, ty);
    BoundingBox box;
    for (std::size_t q = 0; q < 4; ++q) {
      const BoundingBox& quarter = quarters[4 * k + q];
      quarters_[4 * tile + q] = quarter;
      box.extend(quarter.min);
      box.extend(quarter.max);
    }
    boxes_[tile] = box;
  }
  for (int gy = ty0 / kGroup; gy <= ty1 / kGroup; ++gy)
    for (int gx = tx0 / kGroup; gx <= tx1 / kGroup; ++gx) {
      BoundingBox group;
      for (int ty = gy * kGroup; ty < std::min(tilesY_, (gy + 1) * kGroup); ++ty)
        for (int tx = gx * kGroup; tx < std::min(tilesX_, (gx + 1) * kGroup); ++tx) {
          group.extend(boxes_[static_cast<std::size_t>(ty) * tilesX_ + tx].min);
          group.extend(boxes_[static_cast<std::size_t>(ty) * tilesX_ + tx].max);
        }
      groups_[static_cast<std::size_t>(gy) * groupsX() + gx] = group;
    }
}

TexelRect TileBounds::quarterRect(int tx, int ty, int q) const {
  const TexelRect t = tileRect(tx, ty);
  // Split at half the tile's size (the last tile's extra sample goes with its far half); a tile
  // of one sample is its own four quarters.
  const int half = std::max(1, std::min({kTileSize, width_, height_}) / 2);
  const int splitX = std::min(half, t.width), splitY = std::min(half, t.height);
  const bool right = q & 1, top = q & 2;
  const int x = right && splitX < t.width ? t.x + splitX : t.x;
  const int y = top && splitY < t.height ? t.y + splitY : t.y;
  const int width = splitX < t.width ? (right ? t.width - splitX : splitX) : t.width;
  const int height = splitY < t.height ? (top ? t.height - splitY : splitY) : t.height;
  return {x, y, width, height};
}

BoundingBox TileBounds::rectBox(const GeometryImage& image, TexelRect r) const {
  const int lastI = std::min(r.x + r.width, width_), lastJ = std::min(r.y + r.height, height_);
  Vec3f lo, hi;
#if defined(__SSE__)
  // Min/max over whole texels (w along, unused), one vector each, since this runs after every
  // dab; two pairs of running bounds (even and odd texels), so a min waits for the one before
  // it every second texel only. The order changes no min or max of finite values.
  __m128 lo4 = _mm_loadu_ps(&image.at(r.x, r.y).x), hi4 = lo4, lo4b = lo4, hi4b = lo4;
  for (int j = r.y; j <= lastJ; ++j) {
    const float* row = &image.at(0, j).x;
    int i = r.x;
    for (; i + 1 <= lastI; i += 2) {
      const __m128 v = _mm_loadu_ps(row + 4 * static_cast<std::ptrdiff_t>(i));
      const __m128 w = _mm_loadu_ps(row + 4 * static_cast<std::ptrdiff_t>(i) + 4);
      lo4 = _mm_min_ps(v, lo4);
      hi4 = _mm_max_ps(v, hi4);
      lo4b = _mm_min_ps(w, lo4b);
      hi4b = _mm_max_ps(w, hi4b);
    }
    if (i <= lastI) {
      const __m128 v = _mm_loadu_ps(row + 4 * static_cast<std::ptrdiff_t>(i));
      lo4 = _mm_min_ps(v, lo4);
      hi4 = _mm_max_ps(v, hi4);
    }
  }
  lo4 = _mm_min_ps(lo4b, lo4);
  hi4 = _mm_max_ps(hi4b, hi4);
  alignas(16) float l[4], h[4];
  _mm_store_ps(l, lo4);
  _mm_store_ps(h, hi4);
  lo = {l[0], l[1], l[2]};
  hi = {h[0], h[1], h[2]};
#else
  lo = image.at(r.x, r.y).xyz(), hi = lo;
  for (int j = r.y; j <= lastJ; ++j) {
    const Vec4f* row = &image.at(0, j);
    for (int i = r.x; i <= lastI; ++i) {
      lo = {std::min(lo.x, row[i].x), std::min(lo.y, row[i].y), std::min(lo.z, row[i].z)};
      hi = {std::max(hi.x, row[i].x), std::max(hi.y, row[i].y), std::max(hi.z, row[i].z)};
    }
  }
#endif
  return BoundingBox{lo, hi};
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

std::vector<TexelRect> TileBounds::rectsNearSphere(Vec3f centre, float radius) const {
  const float r2 = radius * radius;
  std::vector<TexelRect> rects;
  for (int t : tilesNearSphere(centre, radius)) {
    const int tx = t % tilesX_, ty = t / tilesX_;
    for (int q = 0; q < 4; ++q) {
      const BoundingBox& b =
          quarters_[4 * static_cast<std::size_t>(t) + static_cast<std::size_t>(q)];
      const float dx = std::max({b.min.x - centre.x, 0.0f, centre.x - b.max.x});
      const float dy = std::max({b.min.y - centre.y, 0.0f, centre.y - b.max.y});
      const float dz = std::max({b.min.z - centre.z, 0.0f, centre.z - b.max.z});
      if (dx * dx + dy * dy + dz * dz <= r2) rects.push_back(quarterRect(tx, ty, q));
    }
  }
  // A tile of one sample has the same rectangle four times.
  rects.erase(std::unique(rects.begin(), rects.end()), rects.end());
  return rects;
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
  for (int gy = 0; gy < groupsY(); ++gy)
    for (int gx = 0; gx < groupsX(); ++gx) {
      if (!near(groups_[static_cast<std::size_t>(gy) * groupsX() + gx])) continue;
      for (int ty = gy * kGroup; ty < std::min(tilesY_, (gy + 1) * kGroup); ++ty)
        for (int tx = gx * kGroup; tx < std::min(tilesX_, (gx + 1) * kGroup); ++tx)
          if (near(boxes_[static_cast<std::size_t>(ty) * tilesX_ + tx]))
            tiles.push_back(ty * tilesX_ + tx);
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
