#include "relax/sample_masks.h"

#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <array>

namespace octaclay::core::detail {

std::vector<std::uint8_t> grownMaskBySearch(int n, const std::vector<std::uint8_t>& changed,
                                            int margin) {
  const std::size_t side = static_cast<std::size_t>(n + 1);
  auto index = [side](Sample s) {
    return static_cast<std::size_t>(s.j) * side + static_cast<std::size_t>(s.i);
  };
  std::vector<std::uint8_t> in(changed.size(), 0);
  std::vector<Sample> front;
  auto reach = [&](Sample s, std::vector<Sample>& next) {
    std::array<Sample, 4> copies;
    const int k = identifiedSamples(n, wrap(n, s), copies);
    for (int c = 0; c < k; ++c) {
      const Sample q = copies[static_cast<std::size_t>(c)];
      if (in[index(q)]) continue;
      in[index(q)] = 1;
      next.push_back(q);
    }
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      if (changed[index({i, j})]) reach({i, j}, front);
  for (int d = 0; d < margin && !front.empty(); ++d) {
    std::vector<Sample> next;
    for (const Sample s : front)
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di)
          if (di != 0 || dj != 0) reach({s.i + di, s.j + dj}, next);
    front = std::move(next);
  }
  return in;
}

// Off the border no seam is reached and no sample has a copy: the search's mask is the box
// dilation.
std::vector<std::uint8_t> grownMask(int n, const std::vector<std::uint8_t>& changed, int margin) {
  const std::size_t side = static_cast<std::size_t>(n + 1);
  int i0 = n + 1, j0 = n + 1, i1 = -1, j1 = -1; // the changed samples' bounding box
  for (int j = 0; j <= n; ++j) {
    const std::uint8_t* row = changed.data() + static_cast<std::size_t>(j) * side;
    int first = 0, last = n;
    while (first <= n && !row[first])
      ++first;
    if (first > n) continue;
    while (!row[last])
      --last;
    i0 = std::min(i0, first);
    i1 = std::max(i1, last);
    j0 = std::min(j0, j);
    j1 = j;
  }
  if (i1 < 0) return std::vector<std::uint8_t>(changed.size(), 0);
  if (i0 - margin < 1 || j0 - margin < 1 || i1 + margin > n - 1 || j1 + margin > n - 1)
    return grownMaskBySearch(n, changed, margin);
  // Rows: per sample, whether a changed one lies within `margin` along its row (a running count
  // over the window), over the box's rows; then the same down the columns.
  const int bi0 = i0 - margin, bi1 = i1 + margin, bj0 = j0 - margin, bj1 = j1 + margin;
  const std::size_t width = static_cast<std::size_t>(bi1 - bi0 + 1);
  std::vector<std::uint8_t> rows(width * static_cast<std::size_t>(j1 - j0 + 1), 0);
  for (int j = j0; j <= j1; ++j) {
    const std::uint8_t* in = changed.data() + static_cast<std::size_t>(j) * side;
    std::uint8_t* out = rows.data() + static_cast<std::size_t>(j - j0) * width;
    int count = 0; // changed samples in [i - margin, i + margin]
    for (int i = bi0 - margin; i <= bi1; ++i) {
      if (i + margin <= i1) count += in[i + margin];
      if (i - margin - 1 >= i0) count -= in[i - margin - 1];
      if (i >= bi0) out[i - bi0] = count > 0;
    }
  }
  std::vector<std::uint8_t> grown(changed.size(), 0);
  std::vector<int> counts(width, 0);
  for (int j = bj0 - margin; j <= bj1; ++j) {
    if (j + margin >= j0 && j + margin <= j1) {
      const std::uint8_t* add = rows.data() + static_cast<std::size_t>(j + margin - j0) * width;
      for (std::size_t x = 0; x < width; ++x)
        counts[x] += add[x];
    }
    if (j - margin - 1 >= j0 && j - margin - 1 <= j1) {
      const std::uint8_t* drop =
          rows.data() + static_cast<std::size_t>(j - margin - 1 - j0) * width;
      for (std::size_t x = 0; x < width; ++x)
        counts[x] -= drop[x];
    }
    if (j < bj0) continue;
    std::uint8_t* out = grown.data() + static_cast<std::size_t>(j) * side + bi0;
    for (std::size_t x = 0; x < width; ++x)
      out[x] = counts[x] > 0;
  }
  return grown;
}

// A box dilation by rows, then columns.
std::vector<std::uint8_t> cellsNearFree(int n, const std::vector<std::uint8_t>& freeSamples) {
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  std::vector<std::uint8_t> rows(side * side, 0); // a free sample at i - 1 … i + 2 of row j
  for (int j = 0; j <= n; ++j) {
    const std::uint8_t* free = freeSamples.data() + static_cast<std::size_t>(j) * side;
    std::uint8_t* out = rows.data() + static_cast<std::size_t>(j) * side;
    for (int i = 0; i < n; ++i)
      out[i] = (i > 0 && free[i - 1]) || free[i] || free[i + 1] || (i + 2 <= n && free[i + 2]);
  }
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 0);
  for (int j = 0; j < n; ++j) {
    const auto row = [&](int r) { return rows.data() + static_cast<std::size_t>(r) * side; };
    const std::uint8_t *up = j > 0 ? row(j - 1) : nullptr, *at = row(j), *next = row(j + 1),
                       *down = j + 2 <= n ? row(j + 2) : nullptr;
    std::uint8_t* out = cells.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(n);
    for (int i = 0; i < n; ++i)
      out[i] = (up && up[i]) || at[i] || next[i] || (down && down[i]);
  }
  return cells;
}

bool stretchedAt(const GeometryImage& image, const std::vector<std::uint8_t>& changed,
                 float limit) {
  const int side = image.side();
  for (int j = 0; j < image.rows(); ++j)
    for (int i = 0; i < side; ++i) {
      if (!changed[static_cast<std::size_t>(j) * static_cast<std::size_t>(side) +
                   static_cast<std::size_t>(i)])
        continue;
      const Vec3f p = image.at(i, j).xyz();
      for (const Sample d : {Sample{1, 0}, Sample{-1, 0}, Sample{0, 1}, Sample{0, -1}})
        if (length(image.positionWrapped({i + d.i, j + d.j}) - p) > limit) return true;
    }
  return false;
}

} // namespace octaclay::core::detail
