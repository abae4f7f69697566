#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace octaclay::core::detail {

/// Calls body(rowBegin, rowEnd) on disjoint bands of [0, rows), one band per hardware thread,
/// and waits for all. Small jobs run on the caller's thread alone. body must not throw.
template <class Body> void parallelRows(int rows, Body&& body, int minRowsPerThread = 64) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads = std::clamp(rows / std::max(1, minRowsPerThread), 1, cores);
  if (threads == 1) {
    body(0, rows);
    return;
  }
  std::vector<std::thread> workers;
  const int band = (rows + threads - 1) / threads;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back(
        [&body, t, band, rows] { body(t * band, std::min(rows, (t + 1) * band)); });
  body(0, std::min(rows, band));
  for (auto& w : workers)
    w.join();
}

} // namespace octaclay::core::detail
