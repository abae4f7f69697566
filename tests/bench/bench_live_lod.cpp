// The modeller's live level of detail (issue 7 target: N = 1024, 20 k triangles, regeneration
// ≤ 16 ms): one regeneration step as the modeller runs it after each change of the surface —
// the snapshot of the positions (the GPU document's mirror, kept equal to the texture after
// every dab, copied as ViewportWidget::positionsSnapshot does), core::generateLod, and the upload
// of the LOD mesh for drawing (ModelRenderer::setLodMesh, glFinish) — timed per part on a sphere
// sculpted by push dabs between iterations; the per-frame step between regenerations (the LOD
// following its source samples, app::LodFollower, and the upload); and the GPU saliency pass
// the salient methods read.
#include "lod_follow.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/saliency.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"
#include "octaclay/gpu/saliency.h"

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>
#include <meshoptimizer.h>

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>

using namespace octaclay;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct Session {
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushLibrary library{{std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"}};
  gpu::ModelRenderer renderer;
  gpu::SaliencyPass saliency;
  std::map<int, std::unique_ptr<gpu::GpuDocument>> documents;

  // A sphere with saliency, sculpted by a ring of push dabs (made once per N).
  gpu::GpuDocument& document(int n) {
    auto& d = documents[n];
    if (d) return *d;
    d = std::make_unique<gpu::GpuDocument>(
        core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n)));
    for (int k = 0; k < 16; ++k)
      sculpt(*d, k);
    saliency.run(*d);
    glFinish();
    return *d;
  }

  void sculpt(gpu::GpuDocument& document, int k) {
    const int n = document.size();
    const core::GeometryImage& image = document.document().positions;
    gpu::Dab dab;
    dab.centreTexel = {n / 2 + (k % 8) * n / 64, n / 2 + (k % 5) * n / 64};
    dab.centre = image.at(dab.centreTexel).xyz();
    dab.centreNormal = core::vertexNormal(image, dab.centreTexel);
    dab.radius = 0.05f * document.bounds().diagonal();
    dab.strength = k % 2 ? 0.1f : -0.05f;
    library.engine().dab(document, "push", dab);
  }
};

Session& session() {
  static Session s;
  return s;
}

// range(0): N; range(1): the method (ResampleMethod); range(2): the triangle target (0: the
// resampled grid of size range(4) alone, no collapse); range(3): 1 refits the resampled
// vertices to the surface (generateLod's default), 0 does not.
void BM_LiveLodRegeneration(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.document(n);
  core::LodOptions options;
  options.method = static_cast<core::ResampleMethod>(state.range(1));
  options.targetTriangles = static_cast<std::size_t>(state.range(2));
  options.refitToSurface = state.range(3) != 0;
  options.size = static_cast<int>(state.range(4));
  double snapshotMs = 0, generateMs = 0, uploadMs = 0;
  std::size_t triangles = 0;
  int k = 0;
  for (auto _ : state) {
    s.sculpt(document, k++); // the stroke goes on between regenerations (not timed)
    glFinish();
    const auto start = Clock::now();
    const auto snapshot =
        std::make_shared<const core::GeometryImage>(document.document().positions);
    const double snapshotAt = msSince(start);
    const core::LodMesh lod = core::generateLod(*snapshot, options);
    const double generatedAt = msSince(start);
    s.renderer.setLodMesh(lod);
    glFinish();
    const double total = msSince(start);
    state.SetIterationTime(total / 1e3);
    snapshotMs += snapshotAt;
    generateMs += generatedAt - snapshotAt;
    uploadMs += total - generatedAt;
    triangles = lod.mesh.triangles.size();
  }
  const double runs = static_cast<double>(state.iterations());
  state.counters["ms"] = (snapshotMs + generateMs + uploadMs) / runs;
  state.counters["snapshot_ms"] = snapshotMs / runs;
  state.counters["generate_ms"] = generateMs / runs;
  state.counters["upload_ms"] = uploadMs / runs;
  state.counters["triangles"] = static_cast<double>(triangles);
  state.SetLabel(std::string(core::methodName(options.method)) +
                 (options.refitToSurface ? ", refit" : ""));
}

// What the modeller does each frame of a stroke between regenerations: the newest LOD's
// vertices follow their source samples in the mirror (app::LodFollower), then the upload.
void BM_LiveLodFollow(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.document(n);
  core::LodOptions options;
  options.method = core::ResampleMethod::SalientPoint;
  options.targetTriangles = static_cast<std::size_t>(state.range(1));
  const core::GeometryImage source = document.document().positions;
  const app::LodFollower follower(core::generateLod(source, options), source);
  std::size_t triangles = 0;
  int k = 0;
  for (auto _ : state) {
    s.sculpt(document, k++);
    glFinish();
    const auto start = Clock::now();
    const core::LodMesh lod = follower.follow(document.document().positions);
    s.renderer.setLodMesh(lod);
    glFinish();
    state.SetIterationTime(msSince(start) / 1e3);
    triangles = lod.mesh.triangles.size();
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}

// For comparison (not what the modeller runs): the resampled grid collapsed to the target by
// meshopt_simplify instead of generateLod's own collapse (no seam vetoes, so its
// corners' image coordinates would still need choosing): what a faster collapse would cost.
void BM_LiveLodMeshoptCollapse(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.document(n);
  core::LodOptions options;
  options.method = core::ResampleMethod::SalientPoint;
  options.refitToSurface = false;
  options.size = static_cast<int>(state.range(1));
  const std::size_t target = static_cast<std::size_t>(state.range(2));
  double collapseMs = 0;
  std::size_t triangles = 0;
  int k = 0;
  for (auto _ : state) {
    s.sculpt(document, k++);
    glFinish();
    const auto start = Clock::now();
    const auto snapshot =
        std::make_shared<const core::GeometryImage>(document.document().positions);
    core::LodMesh lod = core::generateLod(*snapshot, options);
    const auto collapseStart = Clock::now();
    std::vector<unsigned> indices;
    for (const auto& t : lod.mesh.triangles)
      indices.insert(indices.end(), t.begin(), t.end());
    std::vector<unsigned> simplified(indices.size());
    simplified.resize(meshopt_simplify(simplified.data(), indices.data(), indices.size(),
                                       &lod.mesh.positions[0].x, lod.mesh.positions.size(),
                                       sizeof(core::Vec3f), target * 3, 0.05f, 0, nullptr));
    lod.mesh.triangles.resize(simplified.size() / 3);
    lod.cornerUv.resize(simplified.size() / 3);
    for (std::size_t t = 0; t < simplified.size() / 3; ++t)
      lod.mesh.triangles[t] = {simplified[3 * t], simplified[3 * t + 1], simplified[3 * t + 2]};
    collapseMs += msSince(collapseStart);
    s.renderer.setLodMesh(lod);
    glFinish();
    state.SetIterationTime(msSince(start) / 1e3);
    triangles = lod.mesh.triangles.size();
  }
  state.counters["collapse_ms"] = collapseMs / static_cast<double>(state.iterations());
  state.counters["triangles"] = static_cast<double>(triangles);
}

void BM_GpuSaliency(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  Session& s = session();
  gpu::GpuDocument& document = s.document(n);
  for (auto _ : state) {
    const auto start = Clock::now();
    s.saliency.run(document);
    glFinish();
    state.SetIterationTime(msSince(start) / 1e3);
  }
}

// The CPU reference on the same image, for comparison with the GPU pass.
void BM_CpuSaliency(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  core::GeometryImage image = session().document(n).document().positions;
  for (auto _ : state) {
    const auto start = Clock::now();
    core::computeSaliency(image);
    state.SetIterationTime(msSince(start) / 1e3);
  }
}

constexpr int kSalientPoint = static_cast<int>(core::ResampleMethod::SalientPoint);
constexpr int kPoint = static_cast<int>(core::ResampleMethod::Point);

} // namespace

BENCHMARK(BM_LiveLodRegeneration)
    ->Args({1024, kSalientPoint, 20000, 1, 0})
    ->Args({1024, kPoint, 20000, 1, 0})
    ->Args({1024, kSalientPoint, 20000, 0, 0})
    ->Args({1024, kSalientPoint, 0, 1, 128})
    ->Args({1024, kSalientPoint, 0, 0, 128})
    ->Args({1024, kSalientPoint, 0, 0, 64})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(20);
BENCHMARK(BM_LiveLodFollow)
    ->Args({1024, 20000})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(50);
BENCHMARK(BM_LiveLodMeshoptCollapse)
    ->Args({1024, 128, 20000})
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(20);
BENCHMARK(BM_GpuSaliency)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(2);

BENCHMARK(BM_CpuSaliency)
    ->Arg(256)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond)
    ->UseManualTime()
    ->Iterations(2);

BENCHMARK_MAIN();
