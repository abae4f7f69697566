// Saving and opening a scene of 16 objects of N = 256 against one object of N = 1024 (about the
// same samples: 16 × 257² = 1 056 784 against 1025² = 1 050 625), issue 33's target: a scene no
// slower per sample than one object. Each benchmark reports ns_per_sample. The files go to
// $OCTACLAY_BENCH_DIR (else the temporary folder) and are removed at the end. Times are the best
// of the iterations: the machine is shared.
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

fs::path benchFile(int objects) {
  const char* folder = std::getenv("OCTACLAY_BENCH_DIR");
  return (folder && *folder ? fs::path(folder) : fs::temp_directory_path()) /
         ("octaclay_bench_scene_" + std::to_string(objects) + ".exr");
}

// objects blobs of N = n, painted (a non-uniform diffuse layer), side by side.
Scene makeScene(int objects, int n) {
  Scene scene;
  const Document blob = makeDocument(makeBaseShape(BaseShape::Blob, n));
  for (int k = 0; k < objects; ++k) {
    Document document = blob;
    document.diffuse.texels.assign(document.positions.texelCount() * 4, 0.5f);
    for (std::size_t t = 0; t < document.diffuse.texels.size(); t += 5)
      document.diffuse.texels[t] = 0.25f;
    scene.objects.push_back({scene.uniqueName("Blob"),
                             std::move(document),
                             {{3.0f * float(k), 0, 0}, {}, {1, 1, 1}},
                             true,
                             false});
  }
  return scene;
}

std::size_t samples(const Scene& scene) {
  std::size_t total = 0;
  for (const SceneObject& object : scene.objects)
    total += object.document.positions.texelCount();
  return total;
}

template <class Work> void timeBest(benchmark::State& state, std::size_t count, Work&& work) {
  double best = std::numeric_limits<double>::infinity();
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    work();
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, s);
    state.SetIterationTime(s);
  }
  state.counters["best_ms"] = best * 1e3;
  state.counters["ns_per_sample"] = best * 1e9 / double(count);
}

// Args: objects, N.
void BM_WriteScene(benchmark::State& state) {
  const Scene scene = makeScene(int(state.range(0)), int(state.range(1)));
  const fs::path path = benchFile(int(state.range(0)));
  timeBest(state, samples(scene), [&] { writeScene(scene, path); });
  fs::remove(path);
}

void BM_ReadScene(benchmark::State& state) {
  const Scene scene = makeScene(int(state.range(0)), int(state.range(1)));
  const fs::path path = benchFile(int(state.range(0)));
  writeScene(scene, path);
  timeBest(state, samples(scene), [&] { benchmark::DoNotOptimize(readScene(path)); });
  fs::remove(path);
}

} // namespace

BENCHMARK(BM_WriteScene)->Args({1, 1024})->Args({16, 256})->UseManualTime()->Iterations(5);
BENCHMARK(BM_ReadScene)
    ->Args({1, 1024})
    ->Args({16, 256})
    ->Args({1, 256})
    ->UseManualTime()
    ->Iterations(5);
BENCHMARK_MAIN();
