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
#include <type_traits>
#include <utility>
#include <vector>

namespace octaclay::core::detail {

struct FloatRanks {
  std::size_t count = 0; ///< how many values took part (the non-negative ones)
  float largest = 0;     ///< the largest of them (0 when none)
  std::vector<float> at; ///< per asked rank, the value of that rank (0-based, ascending)
};

/// An exact selection in parts, for a caller whose own pass makes the values: guess() reads a
/// sample of the blocks, a Counter on each thread is given every value once and merged, and
/// finish() gives the ranks (reading the blocks again only for a bin the guess missed).
/// selectFloatRanksOf below is the three in a row. The values: non-negative floats (negative
/// ones, e.g. -1 marking a missing value, are left out; -0 counts as 0); NaN must not occur.
/// rankOf(count) gives each asked rank (nearest rank, 0-based) once the count is known, also
/// for a sample's count, each below count. forBlock(b, visit) calls visit(value) for every value
/// of block b in [0, blocks), on any thread, and the same values each time it is called for b:
/// they may be made again rather than kept (summarizeStretch's 134 million edges at N = 8192
/// are 537 MB). Every 32nd block is read by guess(); all of them again by finish() when the
/// guess missed. With no non-negative value, every rank's value is 0. O(values) time on every
/// core, 512 KiB and 256 KiB per guessed bin per thread.
template <class RankOf> class FloatRankSelection {
  static constexpr int kBins = 1 << 16;
  static constexpr std::uint32_t kMissing = 0xffffffffu;
  // Every kSampleStride-th block guesses the ranks' high bins, so that one pass can count the
  // low bits inside them too (a guess that misses costs the second pass it saves).
  static constexpr int kSampleStride = 32;
  static constexpr std::uint32_t kGuessedBins = 8; // per rank: 256 KiB of low counts a thread

  static std::uint32_t key(float v) {
    std::uint32_t bits;
    std::memcpy(&bits, &v, 4);
    if (bits == 0x80000000u) return 0;             // -0 is 0
    return (bits & 0x80000000u) ? kMissing : bits; // negative: left out
  }
  // Each asked rank's high bin, and its rank among that bin's values, from a high histogram.
  static std::vector<std::pair<std::uint32_t, std::uint64_t>>
  binsOf(const std::vector<std::uint64_t>& high, const std::vector<std::size_t>& ranks) {
    std::vector<std::pair<std::uint32_t, std::uint64_t>> out;
    for (std::size_t rank : ranks) {
      std::uint64_t below = 0;
      std::uint32_t h = 0;
      while (below + high[h] <= rank)
        below += high[h++];
      out.emplace_back(h, rank - below);
    }
    return out;
  }

public:
  explicit FloatRankSelection(RankOf rankOf) : rankOf_(std::move(rankOf)) {}

  /// The ranks' high bins as a sample of the blocks puts them: for each rank, the bins between
  /// its fraction of the values less and more 4 standard errors of a quantile (√(f(1-f)/m)),
  /// at most kGuessedBins of them. Without it (or with fewer than 32 blocks) finish() reads
  /// every block again.
  template <class ForBlock> void guess(int blocks, ForBlock&& forBlock) {
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
        for (std::size_t rank : rankOf_(sampleCount)) {
          const double f = double(rank) / m, margin = 4.0 * std::sqrt(f * (1.0 - f) / m) + 2.0 / m;
          const auto rankAt = [&](double g) {
            return static_cast<std::size_t>(std::clamp(g, 0.0, 1.0) * (m - 1.0));
          };
          const auto span = binsOf(sampleHigh, {rankAt(f - margin), rank, rankAt(f + margin)});
          const std::uint32_t first =
              std::max(span[0].first, span[1].first - std::min(span[1].first, kGuessedBins / 2));
          const std::uint32_t last = std::min(span[2].first, first + kGuessedBins - 1);
          for (std::uint32_t h = first; h <= last; ++h)
            guessed_.push_back(h);
        }
      }
      std::sort(guessed_.begin(), guessed_.end());
      guessed_.erase(std::unique(guessed_.begin(), guessed_.end()), guessed_.end());
    }
    slot_.assign(kBins, 0);
    for (std::size_t t = 0; t < guessed_.size(); ++t)
      slot_[guessed_[t]] = static_cast<std::uint8_t>(t + 1);
    low_.assign(guessed_.size(), std::vector<std::uint64_t>(kBins, 0));
  }

  /// One thread's counts: add() every value once, then merge() it.
  class Counter {
  public:
    void add(float value) {
      const std::uint32_t bits = key(value);
      if (bits == kMissing) return;
      // Two high histograms, alternate values in each: runs of values in one bin do not wait
      // on each other's increments.
      ++high_[parity_ + (bits >> 16)];
      parity_ ^= kBins;
      largest_ = std::max(largest_, value);
      if (const std::uint8_t t = (*slot_)[bits >> 16]) ++low_[t - 1u][bits & 0xffffu];
    }

  private:
    friend class FloatRankSelection;
    explicit Counter(const std::vector<std::uint8_t>& slot, std::size_t guessedBins)
        : slot_(&slot), high_(2 * kBins, 0),
          low_(guessedBins, std::vector<std::uint32_t>(kBins, 0)) {}
    const std::vector<std::uint8_t>* slot_;
    std::vector<std::uint32_t> high_;
    std::vector<std::vector<std::uint32_t>> low_;
    float largest_ = 0;
    std::uint32_t parity_ = 0;
  };

  /// A counter for one thread (after guess()).
  Counter counter() const { return Counter(slot_, guessed_.size()); }

  /// Adds a thread's counts; safe from every thread at once.
  void merge(const Counter& c) {
    const std::lock_guard lock(merge_);
    for (std::size_t h = 0; h < kBins; ++h)
      high_[h] += std::uint64_t(c.high_[h]) + c.high_[h + kBins];
    largest_ = std::max(largest_, c.largest_);
    for (std::size_t t = 0; t < guessed_.size(); ++t)
      for (std::size_t l = 0; l < kBins; ++l)
        low_[t][l] += c.low_[t][l];
  }

  /// The asked ranks' values once every value was counted: a bin the guess missed is counted
  /// by a second pass over the blocks.
  template <class ForBlock>
  FloatRanks finish(int blocks, ForBlock&& forBlock, int minBlocksPerThread = 4) {
    FloatRanks result;
    result.largest = largest_;
    for (std::uint64_t c : high_)
      result.count += c;
    const std::vector<std::size_t> ranks =
        result.count ? rankOf_(result.count) : std::vector<std::size_t>{};
    result.at.assign(ranks.size(), 0.0f);
    if (ranks.empty()) return result;
    const auto wanted = binsOf(high_, ranks);
    std::vector<std::uint32_t> missed;
    for (const auto& [h, inside] : wanted)
      if (!std::binary_search(guessed_.begin(), guessed_.end(), h)) missed.push_back(h);
    std::sort(missed.begin(), missed.end());
    missed.erase(std::unique(missed.begin(), missed.end()), missed.end());
    std::vector<std::vector<std::uint64_t>> missedLow(missed.size(),
                                                      std::vector<std::uint64_t>(kBins, 0));
    if (!missed.empty()) {
      std::vector<std::uint8_t> slot(kBins, 0);
      for (std::size_t t = 0; t < missed.size(); ++t)
        slot[missed[t]] = static_cast<std::uint8_t>(t + 1);
      std::mutex merge;
      parallelRows(
          blocks,
          [&](int b0, int b1) {
            std::vector<std::vector<std::uint32_t>> local(missed.size(),
                                                          std::vector<std::uint32_t>(kBins, 0));
            for (int b = b0; b < b1; ++b)
              forBlock(b, [&](float value) {
                const std::uint32_t bits = key(value);
                if (bits == kMissing) return;
                if (const std::uint8_t t = slot[bits >> 16]) ++local[t - 1u][bits & 0xffffu];
              });
            const std::lock_guard lock(merge);
            for (std::size_t t = 0; t < missed.size(); ++t)
              for (std::size_t l = 0; l < kBins; ++l)
                missedLow[t][l] += local[t][l];
          },
          minBlocksPerThread);
    }
    for (std::size_t r = 0; r < ranks.size(); ++r) {
      const auto [h, inside] = wanted[r];
      const bool wasGuessed = std::binary_search(guessed_.begin(), guessed_.end(), h);
      const auto& in = wasGuessed ? guessed_ : missed;
      const auto& counts = (wasGuessed ? low_ : missedLow)[static_cast<std::size_t>(
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

private:
  RankOf rankOf_;
  std::vector<std::uint32_t> guessed_;
  std::vector<std::uint8_t> slot_;
  std::vector<std::uint64_t> high_ = std::vector<std::uint64_t>(kBins, 0);
  std::vector<std::vector<std::uint64_t>> low_;
  float largest_ = 0;
  std::mutex merge_;
};

/// The values of the asked ranks among the non-negative values that forBlock gives (see
/// FloatRankSelection): the guess, one pass counting on every core, the finish.
template <class ForBlock, class RankOf>
FloatRanks selectFloatRanksOf(int blocks, ForBlock&& forBlock, RankOf&& rankOf,
                              int minBlocksPerThread = 4) {
  FloatRankSelection<std::decay_t<RankOf>> selection(std::forward<RankOf>(rankOf));
  selection.guess(blocks, forBlock);
  parallelRows(
      blocks,
      [&](int b0, int b1) {
        auto counter = selection.counter();
        for (int b = b0; b < b1; ++b)
          forBlock(b, [&](float value) { counter.add(value); });
        selection.merge(counter);
      },
      minBlocksPerThread);
  return selection.finish(blocks, forBlock, minBlocksPerThread);
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
