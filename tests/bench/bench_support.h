// Shared by the benchmarks: the memcpy baseline every ratio (x_memcpy) is measured against.
#pragma once

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <vector>

// Best-of-5 wall time of one memcpy of `bytes`, in seconds.
inline double memcpySeconds(std::size_t bytes) {
  std::vector<char> from(bytes, 1), to(bytes, 0);
  double best = 1e9;
  for (int k = 0; k < 5; ++k) {
    const auto start = std::chrono::steady_clock::now();
    std::memcpy(to.data(), from.data(), bytes);
    benchmark::DoNotOptimize(to.data());
    benchmark::ClobberMemory();
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}
