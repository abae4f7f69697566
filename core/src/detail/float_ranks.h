#pragma once

// Exact order statistics of many non-negative floats on every core: a radix selection over the
// floats' bits (for x ≥ 0 their order is the order of the bits as unsigned integers), counting
// the high 16 bits of every value and the low 16 bits of those in the bins that hold the ranks.
// A sample of the blocks guesses those bins, so that one read of the values (or one making of
// them) counts both; a second counts the low bits of a bin the guess missed. Instead of
// std::nth_element's partitioning on one thread (an N = 8192 image's 134 million edges took
// seconds).

#include "parallel_rows.h"

#include <algorithm>
#include <array>
#include <cmath>
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
/// rankOf(count) gives each rank once the count is known (also for a sample's count), each below
/// count. forBlock(b, visit) calls visit(value) for every value of block b in [0, blocks), on any
/// thread, and the same values each time it is called for b: they may be made again rather than
/// kept (summarizeStretch's 134 million edges at N = 8192 are 537 MB). Every 32nd block is read
/// once more, and all of them again when the guess missed. With no non-negative value, every
/// rank's value is 0. NaN values must not occur. O(values) time on every core, 512 KiB and
/// 256 KiB per guessed bin per thread.
template <class ForBlock, class RankOf>
FloatRanks selectFloatRanksOf(int blocks, ForBlock&& forBlock, RankOf&& rankOf,
                              int minBlocksPerThread = 4) {
  constexpr int kBins = 1 << 16;
  constexpr std::uint32_t kMissing = 0xffffffffu;
  // Every kSampleStride-th block guesses the ranks' high bins, so that one pass can count the
  // low bits inside them too (a guess that misses costs the second pass it saves).
  constexpr int kSampleStride = 32;
  constexpr std::uint32_t kGuessedBins = 8; // per rank: 256 KiB of low counts each per thread
  const auto key = [](float v) -> std::uint32_t {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    if (bits == 0x80000000u) return 0;             // -0 is 0
    return (bits & 0x80000000u) ? kMissing : bits; // negative: left out
  };
  std::mutex merge;
  // Each asked rank's high bin, and its rank among that bin's values, from a high histogram.
  const auto binsOf = [](const std::vector<std::uint64_t>& high,
                         const std::vector<std::size_t>& ranks) {
    std::vector<std::pair<std::uint32_t, std::uint64_t>> out;
    for (std::size_t rank : ranks) {
      std::uint64_t below = 0;
      std::uint32_t h = 0;
      while (below + high[h] <= rank)
        below += high[h++];
      out.emplace_back(h, rank - below);
    }
    return out;
  };
  // One pass: the high histogram (when high is not null), the largest value, and the low
  // histogram of every high bin in bins (slot[h]: its index in bins + 1, 0 for none).
  const auto count = [&](std::vector<std::uint64_t>* high, float* largestOut,
                         const std::vector<std::uint32_t>& bins,
                         std::vector<std::vector<std::uint64_t>>& low) {
    std::vector<std::uint8_t> slot(kBins, 0);
    for (std::size_t t = 0; t < bins.size(); ++t)
      slot[bins[t]] = static_cast<std::uint8_t>(t + 1);
    low.assign(bins.size(), std::vector<std::uint64_t>(kBins, 0));
    parallelRows(
        blocks,
        [&](int b0, int b1) {
          // Two high histograms, alternate values in each: runs of values in one bin do not
          // wait on each other's increments.
          std::vector<std::uint32_t> local(high ? 2 * kBins : 0, 0);
          std::vector<std::vector<std::uint32_t>> lowLocal(bins.size(),
                                                           std::vector<std::uint32_t>(kBins, 0));
          float largest = 0;
          std::uint32_t parity = 0;
          for (int b = b0; b < b1; ++b)
            forBlock(b, [&](float value) {
              const std::uint32_t bits = key(value);
              if (bits == kMissing) return;
              if (high) {
                ++local[parity + (bits >> 16)];
                parity ^= kBins;
                largest = std::max(largest, value);
              }
              if (const std::uint8_t t = slot[bits >> 16]) ++lowLocal[t - 1u][bits & 0xffffu];
            });
          const std::lock_guard lock(merge);
          if (high) {
            for (std::size_t h = 0; h < kBins; ++h)
              (*high)[h] += std::uint64_t(local[h]) + local[h + kBins];
            *largestOut = std::max(*largestOut, largest);
          }
          for (std::size_t t = 0; t < bins.size(); ++t)
            for (std::size_t l = 0; l < kBins; ++l)
              low[t][l] += lowLocal[t][l];
        },
        minBlocksPerThread);
  };

  // The guess: for each rank, the bins the sample puts between its fraction of the values less
  // and more 4 standard errors of a quantile (√(f(1-f)/m)), at most kGuessedBins of them.
  std::vector<std::uint32_t> guessed;
  const int sampled = blocks / kSampleStride;
  if (sampled > 0) {
    std::vector<std::uint64_t> sampleHigh(kBins, 0);
    for (int s = 0; s < sampled; ++s)
      forBlock(s * kSampleStride + kSampleStride / 2, [&](float value) {
        const std::uint32_t bits = key(value);
        if (bits != kMissing) ++sampleHigh[bits >> 16];
      });
    std::uint64_t sampleCount = 0;
    for (std::uint64_t c : sampleHigh)
      sampleCount += c;
    if (sampleCount > 0) {
      const double m = double(sampleCount);
      for (std::size_t rank : rankOf(sampleCount)) {
        const double f = double(rank) / m, margin = 4.0 * std::sqrt(f * (1.0 - f) / m) + 2.0 / m;
        const auto rankAt = [&](double g) {
          return static_cast<std::size_t>(std::clamp(g, 0.0, 1.0) * (m - 1.0));
        };
        const auto span = binsOf(sampleHigh, {rankAt(f - margin), rank, rankAt(f + margin)});
        const std::uint32_t first =
            std::max(span[0].first, span[1].first - std::min(span[1].first, kGuessedBins / 2));
        const std::uint32_t last = std::min(span[2].first, first + kGuessedBins - 1);
        for (std::uint32_t h = first; h <= last; ++h)
          guessed.push_back(h);
      }
    }
    std::sort(guessed.begin(), guessed.end());
    guessed.erase(std::unique(guessed.begin(), guessed.end()), guessed.end());
  }

  FloatRanks result;
  std::vector<std::uint64_t> high(kBins, 0);
  std::vector<std::vector<std::uint64_t>> low;
  count(&high, &result.largest, guessed, low);
  for (std::uint64_t c : high)
    result.count += c;
  const std::vector<std::size_t> ranks =
      result.count ? rankOf(result.count) : std::vector<std::size_t>{};
  result.at.assign(ranks.size(), 0.0f);
  if (ranks.empty()) return result;
  const auto wanted = binsOf(high, ranks);

  // The bins the guess missed: a second pass counts their low bits.
  std::vector<std::uint32_t> missed;
  for (const auto& [h, inside] : wanted)
    if (!std::binary_search(guessed.begin(), guessed.end(), h)) missed.push_back(h);
  std::sort(missed.begin(), missed.end());
  missed.erase(std::unique(missed.begin(), missed.end()), missed.end());
  std::vector<std::vector<std::uint64_t>> missedLow;
  if (!missed.empty()) count(nullptr, nullptr, missed, missedLow);

  for (std::size_t r = 0; r < ranks.size(); ++r) {
    const auto [h, inside] = wanted[r];
    const bool wasGuessed = std::binary_search(guessed.begin(), guessed.end(), h);
    const auto& in = wasGuessed ? guessed : missed;
    const auto& counts = (wasGuessed ? low : missedLow)[static_cast<std::size_t>(
        std::lower_bound(in.begin(), in.end(), h) - in.begin())];
    std::uint64_t below = 0;
    std::uint32_t l = 0;
    while (below + counts[l] <= inside)
      below += counts[l++];
    const std::uint32_t bits = (h << 16) | l;
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
