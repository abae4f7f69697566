// Saving and opening a scene of 16 objects of N = 512 against one object of N = 2048 (about the
// same samples), and of 16 of N = 256 against one of N = 1024, issue 33's target: a scene no
// slower per sample than one object. Each benchmark times both in turn and reports each one's
// ns per sample and their ratio (scene over object; ≤ 1 meets the target); part_ratio compares
// the scene with one object of its parts' N (what saving or opening the parts one by one would
// cost per sample: a small object's data codes a little slower per sample than a large, smoother
// one's, so part_ratio shows the scene's own overhead apart from that). The files go to
// $OCTACLAY_BENCH_DIR (else the temporary folder) and are removed at the end. Times are the best
// of the iterations: the machine is shared.
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

// objects 0: the file of one object of the parts' N.
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

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The scene and the one object are timed in turn in each iteration, in alternating order (the
// machine is shared: a busy moment falls on both alike), the best of each kept; ratio is the
// scene's time per sample over the object's, issue 33's target ≤ 1.
void report(benchmark::State& state, double sceneBest, std::size_t sceneSamples, double oneBest,
            std::size_t oneSamples, double partBest, std::size_t partSamples) {
  state.counters["part_ratio"] =
      (sceneBest / double(sceneSamples)) / (partBest / double(partSamples));
  state.counters["scene_ms"] = sceneBest * 1e3;
  state.counters["one_ms"] = oneBest * 1e3;
  state.counters["scene_ns_per_sample"] = sceneBest * 1e9 / double(sceneSamples);
  state.counters["one_ns_per_sample"] = oneBest * 1e9 / double(oneSamples);
  state.counters["ratio"] = (sceneBest / double(sceneSamples)) / (oneBest / double(oneSamples));
}

// The file's compression: argument 3, 0 for the default (DocumentCompression::Automatic: RLE up
// to N = 2048 an object), 1 for none (the lines written and read straight, raw_exr_lines).
DocumentWriteOptions writeOptions(const benchmark::State& state) {
  return {state.range(3) == 1 ? DocumentCompression::None : DocumentCompression::Automatic, 1};
}

// Args: objects, their N, the one object's N (about the same samples), compression.
void BM_SaveSceneAgainstOne(benchmark::State& state) {
  const Scene scene = makeScene(int(state.range(0)), int(state.range(1)));
  const Scene one = makeScene(1, int(state.range(2))), part = makeScene(1, int(state.range(1)));
  const fs::path scenePath = benchFile(int(state.range(0))), onePath = benchFile(1),
                 partPath = benchFile(0);
  const DocumentWriteOptions options = writeOptions(state);
  double sceneBest = std::numeric_limits<double>::infinity(), oneBest = sceneBest,
         partBest = sceneBest;
  bool sceneFirst = false; // the order alternates: the second write may wait on the first's
  for (auto _ : state) {
    const auto one_ = [&] {
      oneBest = std::min(oneBest, secondsOf([&] { writeScene(one, onePath, options); }));
    };
    if (!sceneFirst) one_();
    const double s = secondsOf([&] { writeScene(scene, scenePath, options); });
    if (sceneFirst) one_();
    partBest = std::min(partBest, secondsOf([&] { writeScene(part, partPath, options); }));
    sceneFirst = !sceneFirst;
    sceneBest = std::min(sceneBest, s);
    state.SetIterationTime(s);
  }
  report(state, sceneBest, samples(scene), oneBest, samples(one), partBest, samples(part));
  for (const fs::path& path : {scenePath, onePath, partPath})
    fs::remove(path);
}

void BM_OpenSceneAgainstOne(benchmark::State& state) {
  const fs::path scenePath = benchFile(int(state.range(0))), onePath = benchFile(1),
                 partPath = benchFile(0);
  std::size_t sceneSamples = 0, oneSamples = 0, partSamples = 0;
  {
    const Scene scene = makeScene(int(state.range(0)), int(state.range(1)));
    const Scene one = makeScene(1, int(state.range(2))), part = makeScene(1, int(state.range(1)));
    writeScene(scene, scenePath, writeOptions(state));
    writeScene(one, onePath, writeOptions(state));
    writeScene(part, partPath, writeOptions(state));
    sceneSamples = samples(scene);
    oneSamples = samples(one);
    partSamples = samples(part);
  }
  double sceneBest = std::numeric_limits<double>::infinity(), oneBest = sceneBest,
         partBest = sceneBest;
  bool sceneFirst = false;
  for (auto _ : state) {
    const auto one_ = [&] {
      oneBest = std::min(oneBest, secondsOf([&] { benchmark::DoNotOptimize(readScene(onePath)); }));
    };
    if (!sceneFirst) one_();
    const double s = secondsOf([&] { benchmark::DoNotOptimize(readScene(scenePath)); });
    if (sceneFirst) one_();
    partBest =
        std::min(partBest, secondsOf([&] { benchmark::DoNotOptimize(readScene(partPath)); }));
    sceneFirst = !sceneFirst;
    sceneBest = std::min(sceneBest, s);
    state.SetIterationTime(s);
  }
  report(state, sceneBest, sceneSamples, oneBest, oneSamples, partBest, partSamples);
  for (const fs::path& path : {scenePath, onePath, partPath})
    fs::remove(path);
}

} // namespace

// 16 × 513² = 4 210 704 samples against 2049² = 4 198 401; 16 × 257² against 1025².
BENCHMARK(BM_SaveSceneAgainstOne)
    ->ArgsProduct({{16}, {512}, {2048}, {0, 1}})
    ->ArgsProduct({{16}, {256}, {1024}, {0, 1}})
    ->UseManualTime()
    ->Iterations(16);
BENCHMARK(BM_OpenSceneAgainstOne)
    ->ArgsProduct({{16}, {512}, {2048}, {0, 1}})
    ->ArgsProduct({{16}, {256}, {1024}, {0, 1}})
    ->UseManualTime()
    ->Iterations(16);
BENCHMARK_MAIN();
