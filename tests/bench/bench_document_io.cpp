// Reading and writing EXR documents at N = 1024, 4096 and 8192, each beside a plain read (cat)
// or copy (cp) of the same file's bytes measured in the same run (issue 32: a read within 3x of
// cat, a write within 3x of cp). BM_Info and BM_New are what `octaclay-cli info` and `new` do
// besides starting: the positions read and every figure info prints; the sphere made and written.
// The files go to $OCTACLAY_BENCH_DIR (else the temporary folder) and are removed at the end; N =
// 8192 needs about 2 GB of disk and 4 GB of memory. Times are the best of the iterations: the
// machine is shared.
#include "octaclay/core/document/document_info.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/measure/stretch.h"

#include <benchmark/benchmark.h>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

fs::path benchFolder() {
  const char* folder = std::getenv("OCTACLAY_BENCH_DIR");
  return folder && *folder ? fs::path(folder) : fs::temp_directory_path();
}

fs::path documentPath(int n) {
  return benchFolder() / ("octaclay_bench_io_" + std::to_string(n) + ".exr");
}

// Arg 1 of every benchmark: 0 the automatic choice, then the choices it was measured against.
constexpr std::array<DocumentWriteOptions, 6> kCompressions{{
    {DocumentCompression::Automatic, 1},
    {DocumentCompression::None, 1},
    {DocumentCompression::Rle, 1},
    {DocumentCompression::Zips, 1},
    {DocumentCompression::Zip, 1},
    {DocumentCompression::Zip, 4},
}};

fs::path copyPath(int n) {
  return benchFolder() / ("octaclay_bench_io_" + std::to_string(n) + "_copy.exr");
}

// One document at a time: N = 8192 holds 1 GB of positions.
const Document& document(int n) {
  static std::unique_ptr<Document> held;
  if (!held || held->size() != n) {
    held.reset();
    held = std::make_unique<Document>(makeDocument(makeBaseShape(BaseShape::Sphere, n)));
  }
  return *held;
}

template <class F> double bestSeconds(benchmark::State& state, F&& f) {
  double best = 1e30;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    f();
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(s);
    best = std::min(best, s);
  }
  return best;
}

// What `cat file > /dev/null` does: the file read through one 128 KiB buffer.
double catSeconds(const fs::path& path, int repeats) {
  std::vector<char> buffer(128 << 10);
  double best = 1e30;
  for (int k = 0; k < repeats; ++k) {
    const auto start = std::chrono::steady_clock::now();
    const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
    while (::read(fd, buffer.data(), buffer.size()) > 0) {
    }
    ::close(fd);
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  return best;
}

// What `cp file copy` does (copy_file, no fsync).
double copySeconds(const fs::path& from, const fs::path& to, int repeats) {
  double best = 1e30;
  for (int k = 0; k < repeats; ++k) {
    fs::remove(to);
    const auto start = std::chrono::steady_clock::now();
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
    best = std::min(
        best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  fs::remove(to);
  return best;
}

// The file the reading benchmarks read: the one BM_WriteDocument left, else written now with
// the benchmark's compression (a filter that runs a read alone).
const fs::path& fileToRead(const benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  static fs::path path;
  path = documentPath(n);
  if (!fs::exists(path))
    writeDocument(document(n), path, kCompressions.at(static_cast<std::size_t>(state.range(1))));
  return path;
}

void report(benchmark::State& state, double best, double baseline, const char* ratioName,
            const fs::path& file) {
  state.counters["best_s"] = best;
  state.counters["baseline_s"] = baseline;
  state.counters[ratioName] = best / baseline;
  state.counters["file_MB"] = static_cast<double>(fs::file_size(file)) / 1e6;
}

void BM_WriteDocument(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Document& doc = document(n);
  const DocumentWriteOptions& options = kCompressions.at(static_cast<std::size_t>(state.range(1)));
  const double best = bestSeconds(state, [&] { writeDocument(doc, documentPath(n), options); });
  report(state, best, copySeconds(documentPath(n), copyPath(n), 3), "x_cp", documentPath(n));
}

// Every layer, as the modeller and `stroke` read (the file BM_WriteDocument left).
void BM_ReadDocument(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  fileToRead(state);
  const double best = bestSeconds(state, [&] {
    Document read = readDocument(documentPath(n));
    benchmark::DoNotOptimize(read.positions.texels().data());
  });
  report(state, best, catSeconds(documentPath(n), 3), "x_cat", documentPath(n));
}

// Positions only, as `info` reads.
void BM_ReadPositions(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  fileToRead(state);
  const double best = bestSeconds(state, [&] {
    Document read = readDocument(documentPath(n), {.layers = false});
    benchmark::DoNotOptimize(read.positions.texels().data());
  });
  report(state, best, catSeconds(documentPath(n), 3), "x_cat", documentPath(n));
}

// What `octaclay-cli info` does once started: the positions read, the mesh facts and the
// stretch summary it prints; read_s, describe_s and stretch_s are each phase's best.
void BM_Info(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  fileToRead(state);
  std::array<double, 3> phase{1e30, 1e30, 1e30};
  const auto since = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const double best = bestSeconds(state, [&] {
    auto start = std::chrono::steady_clock::now();
    const Document read = readDocument(documentPath(n), {.layers = false});
    phase[0] = std::min(phase[0], since(start));
    start = std::chrono::steady_clock::now();
    const DocumentInfo info = describeDocument(read);
    phase[1] = std::min(phase[1], since(start));
    start = std::chrono::steady_clock::now();
    const StretchSummary stretch = summarizeStretch(read.positions);
    phase[2] = std::min(phase[2], since(start));
    benchmark::DoNotOptimize(info.degenerateTriangles);
    benchmark::DoNotOptimize(stretch.p99OverMedian);
  });
  report(state, best, catSeconds(documentPath(n), 3), "x_cat", documentPath(n));
  state.counters["read_s"] = phase[0];
  state.counters["describe_s"] = phase[1];
  state.counters["stretch_s"] = phase[2];
}

// What `octaclay-cli new --size N` does once started: the sphere made and written (fsync
// included; cp's copy is not synced); make_s and write_s are each phase's best.
void BM_New(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const DocumentWriteOptions& options = kCompressions.at(static_cast<std::size_t>(state.range(1)));
  std::array<double, 2> phase{1e30, 1e30};
  const auto since = [](std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  const double best = bestSeconds(state, [&] {
    auto start = std::chrono::steady_clock::now();
    const Document made = makeDocument(makeBaseShape(BaseShape::Sphere, n));
    phase[0] = std::min(phase[0], since(start));
    start = std::chrono::steady_clock::now();
    writeDocument(made, documentPath(n), options);
    phase[1] = std::min(phase[1], since(start));
  });
  report(state, best, copySeconds(documentPath(n), copyPath(n), 3), "x_cp", documentPath(n));
  state.counters["make_s"] = phase[0];
  state.counters["write_s"] = phase[1];
}

} // namespace

// Registered N by N and choice by choice: each write leaves the file its reads then read. The
// second argument indexes kCompressions (0: what writeDocument chooses by itself).
int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  for (const int n : {1024, 4096, 8192}) {
    const int iterations = n <= 1024 ? 5 : 3;
    for (std::size_t c = 0; c < kCompressions.size(); ++c)
      for (const auto& [name, fn] :
           std::vector<std::pair<std::string, void (*)(benchmark::State&)>>{
               {"BM_WriteDocument", BM_WriteDocument},
               {"BM_ReadDocument", BM_ReadDocument},
               {"BM_ReadPositions", BM_ReadPositions},
               {"BM_Info", BM_Info},
               {"BM_New", BM_New}})
        benchmark::RegisterBenchmark(name.c_str(), fn)
            ->Args({n, static_cast<int64_t>(c)})
            ->Iterations(iterations)
            ->Unit(benchmark::kMillisecond)
            ->UseManualTime();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (const int n : {1024, 4096, 8192}) {
    std::error_code ignored;
    fs::remove(documentPath(n), ignored);
    fs::remove(copyPath(n), ignored);
  }
  return 0;
}
