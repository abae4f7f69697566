// Issue 33's target: a dab on a torus or a plane within 1.1 x a dab on a ball of the same N.
// As bench_brush's BM_SculptOverPush: blocks of push dabs on the ball and on the other shape, each
// on its own document, in turn; over_ball is the ratio of their summed times. The radius is the
// same in sample spacings (each shape's mean spacing, sqrt(area / N^2)), so the dabs cover about
// as many texels (texels_ratio; the ball's pole has more, its cells being smaller there than its
// mean): the comparison is of the topology's cost, not of the shapes' sizes; per_texel_over_ball
// divides out the difference. Topologies 1 and 2 are square images (N × N); 3 and 4 are W × H
// images of the ball's sample count (2N × N/2): a thin torus (major 0.8, minor 0.2: its cells about
// square) and a flat 4 × 1 plane.
#include "bench_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"

#include <benchmark/benchmark.h>
#include <epoxy/gl.h>

#include <chrono>
#include <cmath>
#include <numbers>

using namespace octaclay;

namespace {

struct Session {
  gpu::GlContext context = gpu::GlContext::createHeadless();
  gpu::BrushLibrary library{{std::filesystem::path(OCTACLAY_SOURCE_DIR) / "plugins/brushes"}};
};

Session& session() {
  static Session s;
  return s;
}

struct Shape {
  core::GeometryImage image;
  double area = 0;     ///< of the surface, object units²
  core::Sample centre; ///< where the dabs land (cells of about the mean size)
};

Shape makeShape(int kind, int n) {
  const double pi = std::numbers::pi;
  switch (kind) {
  case 1: // torus: the top of the tube, where the ring's radius is its major radius
    return {
        core::makeTorus(core::Torus{0.7f, 0.3f}, n, n), 4 * pi * pi * 0.7 * 0.3, {n / 2, n / 4}};
  case 2:
    return {core::makeSheet(core::Sheet::Square, n), 4.0, {n / 2, n / 2}};
  case 3: // a thin ring, 2N cells around it and N/2 around its tube
    return {core::makeTorus(core::Torus{0.8f, 0.2f}, 2 * n, n / 2),
            4 * pi * pi * 0.8 * 0.2,
            {n, n / 8}};
  case 4: { // a 4 × 1 plane, 2N × N/2 square cells
    core::GeometryImage sheet(core::Topology::Plane, 2 * n, n / 2);
    for (int j = 0; j <= n / 2; ++j)
      for (int i = 0; i <= 2 * n; ++i)
        sheet.at(i, j) = {4.0f * float(i) / float(2 * n) - 2.0f, float(j) / float(n / 2) - 0.5f,
                          0.0f, 0.0f};
    return {std::move(sheet), 4.0, {n, n / 4}};
  }
  default:
    return {core::makeBaseShape(core::BaseShape::Sphere, n), 4 * pi, {n / 2, n / 2}};
  }
}

double timedDab(gpu::GpuDocument& document, core::Sample centre, float radius, int k,
                std::size_t& texels) {
  const int n = document.size();
  const core::GeometryImage& image = document.document().positions;
  const core::Sample centres[] = {
      centre, {centre.i + n / 64, centre.j}, {centre.i, centre.j + n / 64}};
  gpu::Dab dab;
  dab.centreTexel = centres[(k / 2) % 3];
  dab.centre = image.at(dab.centreTexel).xyz();
  dab.centreNormal = core::vertexNormal(image, dab.centreTexel);
  dab.radius = radius;
  dab.strength = k % 2 == 0 ? 0.02f : -0.02f;
  const auto start = std::chrono::steady_clock::now();
  texels += session().library.engine().dab(document, "push", dab).texels;
  glFinish();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// range(0) = N, range(1) = the radius in thousandths of N sample spacings, range(2) = 1 torus,
// 2 plane (both N × N), 3 torus, 4 plane (both 2N × N/2).
void BM_DabOverBall(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  session(); // the GL context first: the documents' textures live in it
  const Shape ball = makeShape(0, n), other = makeShape(static_cast<int>(state.range(2)), n);
  gpu::GpuDocument balls(core::makeDocument(ball.image)), others(core::makeDocument(other.image));
  const double samples = double(state.range(1)) / 1000.0 * n;
  const auto radiusOf = [&](const Shape& s) {
    return static_cast<float>(samples * std::sqrt(s.area / (double(n) * n)));
  };
  // Samples within the dab's sphere, the work that is the same per sample on every topology (a
  // rect's samples outside it cost little): a thin tube inside the sphere has more of its rects'
  // samples within it than the ball's curved cap.
  const auto within = [&](const Shape& s) {
    const core::Vec3f c = s.image.at(s.centre).xyz();
    const float r = radiusOf(s);
    std::size_t count = 0;
    for (const core::Vec4f& p : s.image.texels())
      count += core::dot(p.xyz() - c, p.xyz() - c) <= r * r;
    return double(count);
  };
  state.counters["within_ratio"] = within(other) / within(ball);
  double ballSeconds = 0, otherSeconds = 0;
  std::size_t ballTexels = 0, otherTexels = 0;
  int k = 0;
  constexpr int kBlock = 8;
  for (auto _ : state) {
    double a = 0, b = 0;
    for (int d = 0; d < kBlock; ++d)
      a += timedDab(balls, ball.centre, radiusOf(ball), k + d, ballTexels);
    for (int d = 0; d < kBlock; ++d)
      b += timedDab(others, other.centre, radiusOf(other), k + d, otherTexels);
    k += kBlock;
    state.SetIterationTime(a + b);
    ballSeconds += a;
    otherSeconds += b;
  }
  const double dabs = static_cast<double>(state.iterations()) * kBlock;
  state.counters["ball_ms"] = ballSeconds * 1e3 / dabs;
  state.counters["dab_ms"] = otherSeconds * 1e3 / dabs;
  state.counters["over_ball"] = otherSeconds / ballSeconds;
  const double texelsRatio =
      static_cast<double>(otherTexels) / static_cast<double>(std::max<std::size_t>(ballTexels, 1));
  state.counters["texels_ratio"] = texelsRatio;
  // The cost of a texel on the other shape over one on the ball: the ball's pole has smaller cells
  // than its mean (the octahedral map shrinks them there), so its dabs of the same radius in mean
  // spacings cover more texels.
  state.counters["per_texel_over_ball"] = otherSeconds / ballSeconds / texelsRatio;
}

} // namespace

BENCHMARK(BM_DabOverBall)
    ->ArgNames({"N", "radius_permille_of_N", "topology"})
    ->Args({256, 50, 1})
    ->Args({256, 50, 2})
    ->Args({1024, 50, 1})
    ->Args({1024, 50, 2})
    ->Args({1024, 150, 1})
    ->Args({1024, 150, 2})
    ->Args({256, 50, 3})
    ->Args({256, 50, 4})
    ->Args({1024, 50, 3})
    ->Args({1024, 50, 4})
    ->Args({1024, 150, 3})
    ->Args({1024, 150, 4})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
