#include "codec/grid.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace octaclay::core::detail {

void requireCodableImage(const FloatImage& image, std::string_view codec) {
  requireValidSize(image.n);
  if (image.channels < 1 || image.channels > 4)
    throw Error(ErrorKind::InvalidArgument, std::string(codec) + ": " +
                                                std::to_string(image.channels) +
                                                " channels; a layer has 1 to 4");
  if (image.texels.size() != sampleCount(image.n) * static_cast<std::size_t>(image.channels))
    throw Error(ErrorKind::InvalidArgument,
                std::string(codec) + ": " + std::to_string(image.texels.size()) +
                    " floats, expected (N+1)² × channels = " +
                    std::to_string(sampleCount(image.n) * image.channels));
}

void requireDecodableShape(int n, int channels, std::string_view codec) {
  if (!isValidSize(n) || channels < 1 || channels > 4)
    throw Error(ErrorKind::InvalidInput, std::string(codec) +
                                             ": cannot decode N = " + std::to_string(n) + " with " +
                                             std::to_string(channels) + " channels");
}

bool isCanonical(int n, int i, int j) {
  return canonical(n, {i, j}) == Sample{i, j};
}

namespace {

// Calls f(sample, its canonical sample) for every border sample that is a copy.
template <class F> void forEachCopy(int n, F&& f) {
  const auto visit = [&](int i, int j) {
    const Sample c = canonical(n, {i, j});
    if (c != Sample{i, j}) f(Sample{i, j}, c);
  };
  for (int k = 0; k <= n; ++k) {
    visit(k, 0);
    visit(k, n);
  }
  for (int k = 1; k < n; ++k) {
    visit(0, k);
    visit(n, k);
  }
}

} // namespace

bool seamsBitExact(const FloatImage& image) {
  const std::size_t side = static_cast<std::size_t>(image.n + 1);
  const std::size_t c = static_cast<std::size_t>(image.channels);
  bool exact = true;
  forEachCopy(image.n, [&](Sample s, Sample from) {
    const float* a = &image.texels[(s.j * side + s.i) * c];
    const float* b = &image.texels[(from.j * side + from.i) * c];
    exact = exact && std::memcmp(a, b, c * sizeof(float)) == 0;
  });
  return exact;
}

void copySeams(FloatImage& image) {
  const std::size_t side = static_cast<std::size_t>(image.n + 1);
  const std::size_t c = static_cast<std::size_t>(image.channels);
  forEachCopy(image.n, [&](Sample s, Sample from) {
    std::memcpy(&image.texels[(s.j * side + s.i) * c], &image.texels[(from.j * side + from.i) * c],
                c * sizeof(float));
  });
}

void parallelTasks(int count, const std::function<void(int)>& task) {
  const int threads =
      std::clamp(static_cast<int>(std::thread::hardware_concurrency()), 1, std::max(1, count));
  std::atomic<int> next{0};
  std::exception_ptr failure;
  std::mutex failureMutex;
  const auto work = [&] {
    for (int k = next++; k < count; k = next++) {
      try {
        task(k);
      } catch (...) {
        const std::lock_guard lock(failureMutex);
        if (!failure) failure = std::current_exception();
      }
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
    workers.emplace_back(work);
  work();
  for (auto& w : workers)
    w.join();
  if (failure) std::rethrow_exception(failure);
}

} // namespace octaclay::core::detail
