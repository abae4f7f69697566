// Normal-map baking and LOD export (issue 7): the cost of the output side of
// `octaclay-cli lod` on a blob at N = 512 and 1024 with a 20 k-triangle LOD, map at N².
// Prints time per bake; never a test.

#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/normal_map.h"

#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>

using namespace octaclay::core;

namespace {

struct Case {
  GeometryImage full;
  LodMesh lod;
};

const Case& sample(int n) {
  static std::map<int, Case> cases;
  auto it = cases.find(n);
  if (it == cases.end()) {
    Case c;
    c.full = makeBaseShape(BaseShape::Blob, n);
    c.lod = generateLod(c.full,
                        {.size = 128, .method = ResampleMethod::Point, .targetTriangles = 20000});
    it = cases.emplace(n, std::move(c)).first;
  }
  return it->second;
}

void bake(benchmark::State& state, NormalMapSpace space) {
  const int n = static_cast<int>(state.range(0));
  const Case& c = sample(n);
  for (auto _ : state)
    benchmark::DoNotOptimize(bakeNormalMap(c.full, c.lod, space, n));
  state.counters["lod_triangles"] = static_cast<double>(c.lod.mesh.triangles.size());
  state.counters["texels"] = static_cast<double>(n) * n;
}

void BM_BakeObject(benchmark::State& state) {
  bake(state, NormalMapSpace::Object);
}
void BM_BakeTangent(benchmark::State& state) {
  bake(state, NormalMapSpace::Tangent);
}

void BM_WriteGlb(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Case& c = sample(n);
  const NormalMap map = bakeNormalMap(c.full, c.lod, NormalMapSpace::Tangent, n);
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "octaclay_bench_normal_map.glb";
  for (auto _ : state)
    benchmark::DoNotOptimize(writeLodMesh(c.lod, map, path));
  std::filesystem::remove(path);
}

} // namespace

BENCHMARK(BM_BakeObject)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_BakeTangent)->Arg(512)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteGlb)->Arg(1024)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
