#pragma once

#include <algorithm>
#include <thread>
#include <vector>

namespace octaclay::core::detail {

/// Whether this thread runs a band of a parallelRows call: a nested call then runs its rows on
/// this thread alone (the cores are taken already; a scene's objects read in parallel, each
/// object's rows serially).
inline thread_local bool inParallelRows = false;

/// Calls body(rowBegin, rowEnd) on disjoint bands of [0, rows), one band per hardware thread,
/// and waits for all. Small jobs, and calls from inside a band, run on the caller's thread alone.
/// body must not throw.
template <class Body> void parallelRows(int rows, Body&& body, int minRowsPerThread = 64) {
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  const int threads =
      inParallelRows ? 1 : std::clamp(rows / std::max(1, minRowsPerThread), 1, cores);
  if (threads == 1) {
    body(0, rows);
    return;
  }
  const auto band = [&body](int begin, int end) {
    inParallelRows = true;
    body(begin, end);
    inParallelRows = false;
  };
  std::vector<std::thread> workers;
  const int size = (rows + threads - 1) / threads;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back(
        [&band, t, size, rows] { band(t * size, std::min(rows, (t + 1) * size)); });
  band(0, std::min(rows, size));
  for (auto& w : workers)
    w.join();
}

} // namespace octaclay::core::detail
