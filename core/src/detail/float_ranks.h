#pragma once

// Exact order statistics of many non-negative floats on every core: a radix selection over the
// floats' bits (for x ≥ 0 their order is the order of the bits as unsigned integers), one pass
// counting the high 16 bits and one counting the low 16 bits inside the bins that hold the ranks.
// Two reads of the values (or two makings of them) instead of std::nth_element's partitioning on
// one thread (summarizing an N = 8192 image's 134 million edges took seconds).

#include "detail/parallel_rows.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <mutex>
#include <span>
#include <vector>

namespace octaclay::core::detail {

struct FloatRanks {
  std::size_t count = 0; ///< how many values took part (the non-negative ones)
  float largest = 0;     ///< the largest of them (0 when none)
  std::vector<float> at; ///< per asked rank, the value of that rank (0-based, ascending)
};

/// The values of the asked ranks among the non-negative values that forBlock gives (negative
/// ones, e.g. -1 marking a missing value, are left out; -0 counts as 0), by nearest rank:
/// rankOf(count) gives each rank once the count is known, each below count. forBlock(b, visit)
/// calls visit(value) for every value of block b in [0, blocks), on any thread, twice over: the
/// values may be made again rather than kept (summarizeStretch's 134 million edges at N = 8192
/// are 537 MB). With no non-negative value, every rank's value is 0. NaN values must not occur.
/// O(values) time on every core, 2 × 256 KiB per thread.
template <class ForBlock, class RankOf>
FloatRanks selectFloatRanksOf(int blocks, ForBlock&& forBlock, RankOf&& rankOf,
                              int minBlocksPerThread = 4) {
  constexpr int kBins = 1 << 16;
  constexpr std::uint32_t kMissing = 0xffffffffu;
  const auto key = [](float v) -> std::uint32_t {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    if (bits == 0x80000000u) return 0;             // -0 is 0
    return (bits & 0x80000000u) ? kMissing : bits; // negative: left out
  };

  FloatRanks result;
  std::vector<std::uint64_t> high(kBins, 0);
  std::mutex merge;
  parallelRows(
      blocks,
      [&](int b0, int b1) {
        std::vector<std::uint32_t> local(kBins, 0);
        float largest = 0;
        for (int b = b0; b < b1; ++b)
          forBlock(b, [&](float value) {
            const std::uint32_t bits = key(value);
            if (bits == kMissing) return;
            ++local[bits >> 16];
            largest = std::max(largest, value);
          });
        const std::lock_guard lock(merge);
        for (int h = 0; h < kBins; ++h)
          high[static_cast<std::size_t>(h)] += local[static_cast<std::size_t>(h)];
        result.largest = std::max(result.largest, largest);
      },
      minBlocksPerThread);
  for (std::uint64_t c : high)
    result.count += c;
  const std::vector<std::size_t> ranks =
      result.count ? rankOf(result.count) : std::vector<std::size_t>{};
  result.at.assign(ranks.size(), 0.0f);
  if (ranks.empty()) return result;

  // Each rank's high bin and its rank inside that bin.
  std::vector<std::uint32_t> bin(ranks.size());
  std::vector<std::uint64_t> inside(ranks.size());
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    std::uint64_t below = 0;
    std::uint32_t h = 0;
    while (below + high[h] <= ranks[r])
      below += high[h++];
    bin[r] = h;
    inside[r] = ranks[r] - below;
  }
  std::vector<std::uint32_t> bins = bin;
  std::sort(bins.begin(), bins.end());
  bins.erase(std::unique(bins.begin(), bins.end()), bins.end());
  std::vector<std::vector<std::uint64_t>> low(bins.size(), std::vector<std::uint64_t>(kBins, 0));
  parallelRows(
      blocks,
      [&](int b0, int b1) {
        std::vector<std::vector<std::uint32_t>> local(bins.size(),
                                                      std::vector<std::uint32_t>(kBins, 0));
        for (int b = b0; b < b1; ++b)
          forBlock(b, [&](float value) {
            const std::uint32_t bits = key(value);
            if (bits == kMissing) return;
            for (std::size_t t = 0; t < bins.size(); ++t)
              if ((bits >> 16) == bins[t]) ++local[t][bits & 0xffffu];
          });
        const std::lock_guard lock(merge);
        for (std::size_t t = 0; t < bins.size(); ++t)
          for (int l = 0; l < kBins; ++l)
            low[t][static_cast<std::size_t>(l)] += local[t][static_cast<std::size_t>(l)];
      },
      minBlocksPerThread);
  for (std::size_t r = 0; r < ranks.size(); ++r) {
    const auto& counts = low[static_cast<std::size_t>(
        std::lower_bound(bins.begin(), bins.end(), bin[r]) - bins.begin())];
    std::uint64_t below = 0;
    std::uint32_t l = 0;
    while (below + counts[l] <= inside[r])
      below += counts[l++];
    const std::uint32_t bits = (bin[r] << 16) | l;
    std::memcpy(&result.at[r], &bits, 4);
  }
  return result;
}

/// selectFloatRanksOf over values held in memory.
template <class RankOf>
FloatRanks selectFloatRanks(std::span<const float> values, RankOf&& rankOf) {
  constexpr std::size_t kBlock = 1 << 14; // values per block handed to parallelRows
  const int blocks = static_cast<int>((values.size() + kBlock - 1) / kBlock);
  return selectFloatRanksOf(
      blocks,
      [&](int b, auto&& visit) {
        const std::size_t begin = static_cast<std::size_t>(b) * kBlock;
        const std::size_t end = std::min(values.size(), begin + kBlock);
        for (std::size_t k = begin; k < end; ++k)
          visit(values[k]);
      },
      std::forward<RankOf>(rankOf));
}

} // namespace octaclay::core::detail
