// Time per dab of push and smooth at N = 256, 1024, 4096 with radii of 2, 10 and 30 % of the
// bounding-box diagonal, material splat dabs at N = 1024, a whole-image smooth pass at each N, and
// effective bytes/s of a dab beside a memcpy of the same bytes in the same run (issue 3's targets;
// ANCHORS.md's Blender), and a push dab at N = 1024 with and without the GPU watchdog (issue 20).
#include "../gpu/path_stroke.h"
#include "bench_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/material_catalog.h"
#include "octaclay/gpu/stroke.h"

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <cstring>
#include <memory>
#include <vector>

using namespace octaclay;

namespace {

struct Session {
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushLibrary library{{std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"}};
  int sphereSize = 0;
  core::GeometryImage sphere;
  std::unique_ptr<gpu::GpuDocument> current;

  Session() {
    gpu::MaterialCatalog materials; // for the splat brush (its default material, brick)
    materials.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "resources/materials"});
    library.engine().setMaterials(materials);
  }

  // A fresh sphere for every run, so no run inherits another's edits.
  gpu::GpuDocument& freshDocument(int n) {
    current.reset(); // one large document at a time: N = 4096 holds 2 x 268 MB textures
    if (sphereSize != n) {
      sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
      sphereSize = n;
    }
    current = std::make_unique<gpu::GpuDocument>(core::makeDocument(sphere));
    return *current;
  }
};

Session& session() {
  static Session s;
  return s;
}

// Dabs cycle through three samples around the +z pole, two dabs at each, so the surface keeps
// changing. A push's second dab pulls back what its first pushed, so every push dab starts on
// the sphere or one shallow bump away from it, as a splat does (its relief is a small fraction of
// the radius): both brushes work on nearly the same surface. (Three pushes and then three pulls
// left dents 0.3 radii deep, whose dabs touched 6-11 % fewer texels than a splat's.) Returns the
// seconds the dab took, its GPU work included.
double timedDab(Session& s, gpu::GpuDocument& document, const char* brush, float radius, int k,
                gpu::DabResult* result = nullptr) {
  const int n = document.size();
  const core::GeometryImage& image = document.document().positions;
  const core::Sample centres[] = {{n / 2, n / 2}, {n / 2 + n / 64, n / 2}, {n / 2, n / 2 + n / 64}};
  gpu::Dab dab;
  dab.centreTexel = centres[(k / 2) % 3];
  dab.centre = image.at(dab.centreTexel).xyz();
  dab.centreNormal = core::vertexNormal(image, dab.centreTexel);
  dab.radius = radius;
  dab.strength = brush[0] == 'p' ? (k % 2 == 0 ? 0.02f : -0.02f) : 0.5f;
  const auto start = std::chrono::steady_clock::now();
  gpu::DabResult made = s.library.engine().dab(document, brush, dab);
  glFinish(); // count the GPU's work, not just its queueing
  if (result != nullptr) *result = std::move(made);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void runDabs(benchmark::State& state, const char* brush, float radiusFraction) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.freshDocument(n);
  const core::GeometryImage& image = document.document().positions;
  const float radius = radiusFraction * document.bounds().diagonal();
  double seconds = 0;
  std::size_t texels = 0, inside = 0;
  int k = 0;
  // As in a stroke: paint layers are read back once after the dabs (timed apart, sync_ms).
  document.deferPulls(true);
  for (auto _ : state) {
    gpu::DabResult result;
    const int at = k++;
    const double elapsed = timedDab(s, document, brush, radius, at, &result);
    state.SetIterationTime(elapsed);
    seconds += elapsed;
    texels += result.texels;
    if (inside == 0) {
      const core::Vec3f centre = image.at({n / 2, n / 2}).xyz();
      for (const core::Vec4f& t : image.texels())
        inside += core::length(t.xyz() - centre) < radius;
    }
  }
  const auto syncStart = std::chrono::steady_clock::now();
  document.deferPulls(false);
  state.counters["sync_ms"] =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - syncStart)
          .count();
  const double perDab = seconds / static_cast<double>(state.iterations());
  texels /= static_cast<std::size_t>(state.iterations()); // per dab
  const std::size_t bytes = texels * 16 * 2;              // RGBA32F read and written
  state.counters["ms_per_dab"] = perDab * 1e3;
  state.counters["dabs_per_s"] = 1.0 / perDab;
  state.counters["texels"] = static_cast<double>(texels);
  // Issue 32: a dab's time must not grow with its texels at CPU speed.
  state.counters["ms_per_mtexel"] =
      texels > 0 ? perDab * 1e3 / (static_cast<double>(texels) * 1e-6) : 0.0;
  state.counters["inside"] = static_cast<double>(inside);
  state.counters["bytes_per_s"] = static_cast<double>(bytes) / perDab;
  state.counters["x_memcpy"] = perDab / memcpySeconds(bytes);
}

// Issue 5's ratio, robust to a shared machine whose speed drifts between benchmarks: every
// iteration runs a block of push dabs and then a block of splat dabs of the same radius, each
// brush on its own sphere; splat_over_push is the ratio of their summed times. Blocks, not single
// dabs in turn: as in a stroke, each brush's dabs follow one another with its layers in cache.
void BM_SplatOverPush(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  s.freshDocument(n);
  s.current.reset();
  gpu::GpuDocument pushed(core::makeDocument(s.sphere)), splatted(core::makeDocument(s.sphere));
  const float radius = static_cast<float>(state.range(1)) / 1000.0f * pushed.bounds().diagonal();
  pushed.deferPulls(true);
  splatted.deferPulls(true);
  double push = 0, splat = 0;
  int k = 0;
  constexpr int kBlock = 8;
  std::size_t pushTexels = 0, splatTexels = 0;
  const auto block = [&](gpu::GpuDocument& document, const char* brush, std::size_t& texels) {
    double seconds = 0;
    for (int b = 0; b < kBlock; ++b) {
      gpu::DabResult result;
      seconds += timedDab(s, document, brush, radius, k + b, &result);
      texels += result.texels;
    }
    return seconds;
  };
  for (auto _ : state) {
    const double p = block(pushed, "push", pushTexels), q = block(splatted, "splat", splatTexels);
    k += kBlock;
    state.SetIterationTime(p + q);
    push += p;
    splat += q;
  }
  const auto iterations = static_cast<double>(state.iterations()) * kBlock;
  state.counters["push_ms"] = push * 1e3 / iterations;
  state.counters["splat_ms"] = splat * 1e3 / iterations;
  state.counters["splat_over_push"] = splat / push;
  // Near 1: both brushes touched the same texels (the ratio compares equal work).
  state.counters["texels_ratio"] =
      static_cast<double>(splatTexels) / static_cast<double>(std::max<std::size_t>(pushTexels, 1));
}

// Issue 23's target: a dab of each brush of the sculpt set at most 1.5 x a push dab of the same
// radius. As BM_SplatOverPush: blocks of push dabs and of the brush's dabs, each on its own sphere,
// in turn; brush_over_push is the ratio of their summed times. The brush's dabs are one stroke
// (engine.beginStroke()), so a brush that needs the stroke-start positions copies them once, at
// its first dab, which is timed apart (first_dab_ms) and left out of the ratio.
void BM_SculptOverPush(benchmark::State& state, const char* brush) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  s.freshDocument(n);
  s.current.reset();
  gpu::GpuDocument pushed(core::makeDocument(s.sphere)), sculpted(core::makeDocument(s.sphere));
  const float radius = static_cast<float>(state.range(1)) / 1000.0f * pushed.bounds().diagonal();
  gpu::BrushEngine& engine = s.library.engine();
  // The brush's dab: around the pole as timedDab's, dragging a little along x and back.
  const auto sculptDab = [&](int k) {
    const core::GeometryImage& image = sculpted.document().positions;
    const core::Sample centres[] = {
        {n / 2, n / 2}, {n / 2 + n / 64, n / 2}, {n / 2, n / 2 + n / 64}};
    gpu::Dab dab;
    dab.centreTexel = centres[(k / 2) % 3];
    dab.centre = image.at(dab.centreTexel).xyz();
    dab.centreNormal = core::vertexNormal(image, dab.centreTexel);
    dab.radius = radius;
    dab.strength = k % 2 == 0 ? 0.02f : -0.02f;
    const float step = (k % 2 == 0 ? 0.02f : -0.02f) * radius;
    dab.strokeDelta = {step, 0, 0};
    dab.strokeDirection = {step > 0 ? 1.0f : -1.0f, 0, 0};
    dab.drag = {k % 2 == 0 ? step : 0.0f, 0, 0};
    const auto start = std::chrono::steady_clock::now();
    engine.dab(sculpted, brush, dab);
    glFinish();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  engine.beginStroke();
  state.counters["first_dab_ms"] = sculptDab(0) * 1e3;
  double push = 0, sculpt = 0;
  int k = 0;
  constexpr int kBlock = 8;
  for (auto _ : state) {
    double p = 0, q = 0;
    for (int b = 0; b < kBlock; ++b)
      p += timedDab(s, pushed, "push", radius, k + b);
    for (int b = 0; b < kBlock; ++b)
      q += sculptDab(k + b + 1);
    k += kBlock;
    state.SetIterationTime(p + q);
    push += p;
    sculpt += q;
  }
  engine.endStroke();
  const auto dabs = static_cast<double>(state.iterations()) * kBlock;
  state.counters["push_ms"] = push * 1e3 / dabs;
  state.counters["brush_ms"] = sculpt * 1e3 / dabs;
  state.counters["brush_over_push"] = sculpt / push;
}

// Radii are given in per mille of the diagonal.
void BM_PushDab(benchmark::State& state) {
  runDabs(state, "push", static_cast<float>(state.range(1)) / 1000.0f);
}
void BM_SmoothDab(benchmark::State& state) {
  runDabs(state, "smooth", static_cast<float>(state.range(1)) / 1000.0f);
}
// The material splat writes positions, diffuse and feature (all four attributes) in one dab;
// issue 5 compares it with a push dab of the same radius in the same run.
void BM_SplatDab(benchmark::State& state) {
  runDabs(state, "splat", static_cast<float>(state.range(1)) / 1000.0f);
}
// A radius of twice the diagonal covers the whole model: a full-image pass.
void BM_SmoothFullImage(benchmark::State& state) {
  runDabs(state, "smooth", 2.0f);
}

void dabSizes(benchmark::internal::Benchmark* b) {
  for (int n : {256, 1024, 4096})
    for (int radius : {20, 100, 300})
      b->Args({n, radius});
  // As many samples as the 10 % dab at N = 1024 (a quarter of its radius at 4 x the density):
  // whether a dab's cost follows the texels it touches rather than the image's size.
  b->Args({4096, 25});
}

// A stroke of 10 %-radius dabs across the sphere, over two seams and a corner pole, with the
// brush's own spacing, symmetry off, undo capture on, the stroke's end (its deferred read-back
// and undo record) included: the sustained dab rate of push and of the material splat.
void timeStrokes(benchmark::State& state, const char* brush) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.freshDocument(n);
  gpu::testing::PathStroke stroke;
  stroke.brush = brush;
  stroke.path = {{0.5f, 0.5f}, {1.0f, 0.5f}, {1.0f, 0.0f}, {0.5f, 0.0f}, {0.5f, 0.5f}};
  stroke.radius = 0.1f * document.bounds().diagonal();
  stroke.spacing = 0.1f; // the same dabs for both brushes
  const gpu::BrushManifest& manifest = *s.library.catalog().find(brush);
  int dabs = 0, k = 0;
  double seconds = 0;
  for (auto _ : state) {
    stroke.strength = k++ % 2 ? -0.05f : 0.05f; // out and back
    const auto start = std::chrono::steady_clock::now();
    dabs += gpu::testing::strokeAlongPath(s.library.engine(), document, manifest, stroke).dabs;
    glFinish();
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    state.SetIterationTime(elapsed);
    seconds += elapsed;
  }
  state.counters["dabs_per_s"] = dabs / seconds;
  state.counters["ms_per_dab"] = seconds * 1e3 / dabs;
}

// Issue 20's watchdog cost: blocks of push dabs with the watchdog (a fence and a bounded wait per
// pass, the default 2 s limit) and without it (limit 0), alternating on one sphere, first one
// then the other, so a machine whose speed drifts slows both alike. watchdog_over_off is the
// ratio of their summed times (the target: at most 1.02).
void BM_WatchdogCost(benchmark::State& state) {
  Session& s = session();
  gpu::GpuDocument& document = s.freshDocument(static_cast<int>(state.range(0)));
  gpu::BrushEngine& engine = s.library.engine();
  const float radius = static_cast<float>(state.range(1)) / 1000.0f * document.bounds().diagonal();
  const auto block = [&](std::chrono::nanoseconds limit) {
    engine.setPassTimeLimit(limit);
    double seconds = 0;
    for (int k = 0; k < 6; ++k) // an even count: each push is pulled back
      seconds += timedDab(s, document, "push", radius, k);
    return seconds;
  };
  double on = 0, off = 0;
  int iteration = 0;
  for (auto _ : state) {
    const bool onFirst = iteration++ % 2 == 0;
    const double a = block(onFirst ? std::chrono::seconds(2) : std::chrono::nanoseconds(0));
    const double b = block(onFirst ? std::chrono::nanoseconds(0) : std::chrono::seconds(2));
    state.SetIterationTime(a + b);
    on += onFirst ? a : b;
    off += onFirst ? b : a;
  }
  engine.setPassTimeLimit(std::chrono::seconds(2));
  const double dabs = 6.0 * static_cast<double>(state.iterations());
  state.counters["on_ms_per_dab"] = on * 1e3 / dabs;
  state.counters["off_ms_per_dab"] = off * 1e3 / dabs;
  state.counters["watchdog_over_off"] = on / off;
}

// Issue 32 item 5, dabs that cannot see each other's texels in one pass per layer: a push dab
// and its mirror image (x symmetry: two places an eighth of the image either side of its centre),
// in blocks drawn as one batch (BrushEngine::dabs) and as two dabs one after the other, alternating
// which block goes first. batched_over_one_by_one is the ratio of their summed times.
void BM_MirroredPush(benchmark::State& state) {
  Session& s = session();
  const int n = static_cast<int>(state.range(0));
  gpu::GpuDocument& document = s.freshDocument(n);
  gpu::BrushEngine& engine = s.library.engine();
  const core::GeometryImage& image = document.document().positions;
  const float radius = static_cast<float>(state.range(1)) / 1000.0f * document.bounds().diagonal();
  std::array<gpu::Dab, 2> pair;
  const std::array<core::Sample, 2> at{{{n / 2 - n / 8, n / 2}, {n / 2 + n / 8, n / 2}}};
  for (std::size_t k = 0; k < 2; ++k) {
    pair[k].centreTexel = at[k];
    pair[k].centre = image.at(at[k]).xyz();
    pair[k].centreNormal = core::vertexNormal(image, at[k]);
    pair[k].radius = radius;
  }
  const auto reaches = [&] {
    return std::vector<std::vector<core::TexelRect>>{engine.reach(document, "push", pair[0]),
                                                     engine.reach(document, "push", pair[1])};
  };
  if (!engine.batches(document, "push", pair, reaches())) {
    state.SkipWithError("the two dabs do not batch");
    return;
  }
  document.deferPulls(true);
  int flip = 0;
  const auto block = [&](bool batched) {
    const auto start = std::chrono::steady_clock::now();
    for (int k = 0; k < 6; ++k) { // an even count: each push is pulled back
      for (gpu::Dab& d : pair)
        d.strength = (flip % 2 == 0) ? 0.02f : -0.02f;
      ++flip;
      if (batched)
        engine.dabs(document, "push", pair, reaches());
      else
        for (const gpu::Dab& d : pair)
          engine.dab(document, "push", d);
    }
    glFinish(); // count the GPU's work, not just its queueing
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  double together = 0, apart = 0;
  int iteration = 0;
  for (auto _ : state) {
    const bool batchFirst = iteration++ % 2 == 0;
    const double a = block(batchFirst), b = block(!batchFirst);
    state.SetIterationTime(a + b);
    together += batchFirst ? a : b;
    apart += batchFirst ? b : a;
  }
  document.deferPulls(false);
  const double dabs = 12.0 * static_cast<double>(state.iterations());
  state.counters["batched_ms_per_dab"] = together * 1e3 / dabs;
  state.counters["one_by_one_ms_per_dab"] = apart * 1e3 / dabs;
  state.counters["batched_over_one_by_one"] = together / apart;
}

void BM_PushStroke(benchmark::State& state) {
  timeStrokes(state, "push");
}
void BM_SplatStroke(benchmark::State& state) {
  timeStrokes(state, "splat");
}

BENCHMARK(BM_PushDab)
    ->Apply(dabSizes)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(0.3);
BENCHMARK(BM_SmoothDab)
    ->Apply(dabSizes)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(0.3);
BENCHMARK(BM_SplatDab)
    ->Args({1024, 20})
    ->Args({1024, 100})
    ->Args({1024, 300})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(0.3);
BENCHMARK(BM_SplatOverPush)
    ->Args({1024, 20})
    ->Args({1024, 100})
    ->Args({1024, 300})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, grab, "grab")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, snake_hook, "snake-hook")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, pinch, "pinch")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, crease, "crease")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, layer, "layer")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, clay_strips, "clay-strips")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, scrape, "scrape")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK_CAPTURE(BM_SculptOverPush, twist, "twist")
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK(BM_SmoothFullImage)
    ->Arg(256)
    ->Arg(1024)
    ->Arg(4096)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(10);
BENCHMARK(BM_WatchdogCost)
    ->Args({1024, 100})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(2.0);
BENCHMARK(BM_MirroredPush)
    ->Args({1024, 20})
    ->Args({1024, 50})
    ->Args({4096, 20})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->MinTime(1.0);
BENCHMARK(BM_PushStroke)->Arg(1024)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(4);
BENCHMARK(BM_SplatStroke)->Arg(1024)->Unit(benchmark::kMillisecond)->UseManualTime()->Iterations(4);

} // namespace

BENCHMARK_MAIN();
