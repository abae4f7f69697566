// The GPU saliency pass against the CPU reference (core::computeSaliency): the same values
// within a tolerance on a sphere with bumps, on an imported mesh and on a torus and a plane with
// bumps (one across the torus's wrap, one on the plane's edge), identified samples equal,
// the mirror equal to the texture, xyz untouched, and the bumps salient where the smooth sphere
// is not.
#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"
#include "octaclay/core/lod/saliency.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/saliency.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <tuple>
#include <utility>
#include <vector>

using namespace octaclay;

namespace {

// A unit sphere with three sharp Gaussian bumps (height 0.15, width 0.06 rad) around fixed
// directions.
core::GeometryImage bumpySphere(int n) {
  core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, n);
  const std::array<core::Vec3f, 3> bumps{core::Vec3f{0, 0, 1}, core::normalize({1, 1, 0}),
                                         core::normalize({-1, 0.3f, -0.5f})};
  for (core::Vec4f& t : image.texels()) {
    const core::Vec3f d = core::normalize(t.xyz());
    float r = 1;
    for (const core::Vec3f& b : bumps) {
      const float angle = std::acos(std::clamp(core::dot(d, b), -1.0f, 1.0f));
      r += 0.15f * std::exp(-angle * angle / (2 * 0.06f * 0.06f));
    }
    t = {d.x * r, d.y * r, d.z * r, 0};
  }
  return image;
}

// Gaussian bumps (height 0.12, width 0.08) on a surface, each centred on a sample's position and
// raised along the surface's normal there, so they are the same bumps on any topology.
core::GeometryImage withBumps(core::GeometryImage image, const std::vector<core::Sample>& at) {
  const core::GeometryImage smooth = image;
  for (const core::Sample c : at) {
    const core::Vec3f centre = smooth.at(c).xyz(), up = core::vertexNormal(smooth, c);
    for (int j = 0; j < image.rows(); ++j)
      for (int i = 0; i < image.side(); ++i) {
        const core::Vec3f p = smooth.at(i, j).xyz();
        const float d2 = core::dot(p - centre, p - centre);
        const core::Vec3f raised = image.at(i, j).xyz() + up * (0.12f * std::exp(-d2 / 0.0128f));
        image.at(i, j) = {raised.x, raised.y, raised.z, 0};
      }
  }
  return image;
}

// The mean saliency of the samples within radius of p, and of those farther than far.
std::pair<double, double> nearAndFar(const core::GeometryImage& image, core::Vec3f p, float radius,
                                     float far) {
  double near = 0, away = 0;
  int nearCount = 0, farCount = 0;
  for (const core::Vec4f& t : image.texels()) {
    const float d = core::length(t.xyz() - p);
    if (d < radius) near += t.w, ++nearCount;
    if (d > far) away += t.w, ++farCount;
  }
  return {near / std::max(1, nearCount), away / std::max(1, farCount)};
}

struct Comparison {
  float maxDifference = 0, meanDifference = 0;
};

Comparison compare(const core::GeometryImage& a, const core::GeometryImage& b) {
  Comparison c;
  double sum = 0;
  for (std::size_t k = 0; k < a.texelCount(); ++k) {
    const float d = std::abs(a.texels()[k].w - b.texels()[k].w);
    c.maxDifference = std::max(c.maxDifference, d);
    sum += d;
  }
  c.meanDifference = static_cast<float>(sum / static_cast<double>(a.texelCount()));
  return c;
}

} // namespace

class SaliencyTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void bumpySphereMatchesTheCpuReference();
  void importedMeshMatchesTheCpuReference();
  void smoothSphereIsFlatAndBumpsStandOut();
  void bumpyTorusAndPlaneMatchTheCpuReference();

private:
  // Runs the pass and checks what every run must hold; returns the document's positions.
  core::GeometryImage runOnGpu(const core::GeometryImage& image);
  std::optional<gpu::GlContext> context_;
  std::optional<gpu::SaliencyPass> pass_;
};

void SaliencyTest::initTestCase() {
  try {
    context_.emplace(gpu::GlContext::createHeadless());
    pass_.emplace();
  } catch (const gpu::GlError& e) {
    QFAIL(e.what());
  }
}

core::GeometryImage SaliencyTest::runOnGpu(const core::GeometryImage& image) {
  gpu::GpuDocument document(core::makeDocument(image));
  pass_->run(document);
  const core::GeometryImage& mirror = document.document().positions;
  const core::SampleGrid& grid = image.grid();
  // The texture holds what the mirror holds, and xyz are untouched.
  const std::vector<float> texels =
      document.texture(core::EditLayer::Positions).read({0, 0, image.side(), image.rows()});
  bool same = true, xyzKept = true;
  float peak = 0, low = 1;
  for (std::size_t k = 0; k < mirror.texelCount(); ++k) {
    const core::Vec4f m = mirror.texels()[k], o = image.texels()[k];
    same = same && std::memcmp(&m, &texels[4 * k], sizeof(m)) == 0;
    xyzKept = xyzKept && m.x == o.x && m.y == o.y && m.z == o.z;
    peak = std::max(peak, m.w);
    low = std::min(low, m.w);
  }
  [&] {
    QVERIFY(same);
    QVERIFY(xyzKept);
    QCOMPARE(peak, 1.0f); // normalised by its maximum
    QVERIFY(low >= 0.0f);
    // Identified samples are bit-for-bit equal.
    std::array<core::Sample, 4> identified;
    std::vector<core::Sample> border;
    for (int i = 0; i <= grid.width; ++i)
      border.insert(border.end(), {core::Sample{i, 0}, core::Sample{i, grid.height}});
    for (int j = 0; j <= grid.height; ++j)
      border.insert(border.end(), {core::Sample{0, j}, core::Sample{grid.width, j}});
    for (const core::Sample s : border) {
      const int count = core::identifiedSamples(grid, s, identified);
      for (int c = 0; c < count; ++c)
        QCOMPARE(mirror.at(identified[static_cast<std::size_t>(c)]).w, mirror.at(s).w);
    }
  }();
  return mirror;
}

// The GPU sums the same terms in float with the same kernel as the CPU, but its normals and
// fused multiply-adds round differently: measured ~1e-6 of the [0, 1] range; 1e-4 leaves room
// for other drivers and is still far below any real change (the bumps stand out by 0.2).
void SaliencyTest::bumpySphereMatchesTheCpuReference() {
  const core::GeometryImage image = bumpySphere(128);
  core::GeometryImage reference = image;
  core::computeSaliency(reference);
  const core::GeometryImage gpuResult = runOnGpu(image);
  if (QTest::currentTestFailed()) return;
  const Comparison c = compare(gpuResult, reference);
  qInfo("bumpy sphere N = 128: max |GPU - CPU| = %g, mean %g", c.maxDifference, c.meanDifference);
  QVERIFY2(c.maxDifference < 1e-4f, qPrintable(QString::number(c.maxDifference)));
  QVERIFY2(c.meanDifference < 1e-5f, qPrintable(QString::number(c.meanDifference)));
}

void SaliencyTest::importedMeshMatchesTheCpuReference() {
  const std::filesystem::path path =
      std::filesystem::path(OCTACLAY_SHARED_DATA) / "meshes/genus0/fandisk.obj";
  const core::ValidatedMesh mesh = core::loadGenus0Mesh(path);
  const core::SphericalMap map = core::parameterizeOnSphere(mesh.mesh);
  const core::GeometryImage image = core::resampleOctahedral(mesh.mesh, map, 128);
  core::GeometryImage reference = image;
  core::computeSaliency(reference);
  const core::GeometryImage gpuResult = runOnGpu(image);
  if (QTest::currentTestFailed()) return;
  const Comparison c = compare(gpuResult, reference);
  qInfo("fandisk N = 128: max |GPU - CPU| = %g, mean %g", c.maxDifference, c.meanDifference);
  QVERIFY2(c.maxDifference < 1e-4f, qPrintable(QString::number(c.maxDifference)));
  QVERIFY2(c.meanDifference < 1e-5f, qPrintable(QString::number(c.meanDifference)));
}

void SaliencyTest::smoothSphereIsFlatAndBumpsStandOut() {
  const int n = 128;
  const core::GeometryImage result = runOnGpu(bumpySphere(n));
  if (QTest::currentTestFailed()) return;
  // Mean saliency within 0.1 rad of a bump's centre against far from every bump.
  const std::array<core::Vec3f, 3> bumps{core::Vec3f{0, 0, 1}, core::normalize({1, 1, 0}),
                                         core::normalize({-1, 0.3f, -0.5f})};
  double near = 0, far = 0;
  int nearCount = 0, farCount = 0;
  for (const core::Vec4f& t : result.texels()) {
    const core::Vec3f d = core::normalize(t.xyz());
    float closest = 10;
    for (const core::Vec3f& b : bumps)
      closest = std::min(closest, std::acos(std::clamp(core::dot(d, b), -1.0f, 1.0f)));
    if (closest < 0.1f) near += t.w, ++nearCount;
    if (closest > 0.8f) far += t.w, ++farCount;
  }
  QVERIFY(nearCount > 0 && farCount > 0);
  near /= nearCount;
  far /= farCount;
  qInfo("mean saliency near bumps %.3f, far from them %.3f", near, far);
  QVERIFY(near > 0.2);
  QVERIFY(far < 0.05);
  QVERIFY(near > 10 * far);
}

// A torus (a W × H image, wrapping both ways) and a plane (clamped at its boundary): the GPU pass
// matches the CPU reference as on the ball, and the bumps stand out, the one across the torus's
// wrap and the one on the plane's edge too.
void SaliencyTest::bumpyTorusAndPlaneMatchTheCpuReference() {
  const core::Torus torus;
  const core::GeometryImage ring = core::makeTorus(torus, 128, core::torusHeight(torus, 128));
  const int w = ring.grid().width, h = ring.grid().height;
  const std::vector<core::Sample> ringBumps{{0, 0}, {w / 3, h / 2}};
  const core::GeometryImage sheet = core::makeSheet(core::Sheet::Square, 128);
  const std::vector<core::Sample> sheetBumps{{64, 64}, {128, 40}};
  for (const auto& [name, smooth, bumps] :
       {std::tuple{"torus", ring, ringBumps}, std::tuple{"plane", sheet, sheetBumps}}) {
    const core::GeometryImage image = withBumps(smooth, bumps);
    core::GeometryImage reference = image;
    core::computeSaliency(reference);
    const core::GeometryImage gpuResult = runOnGpu(image);
    if (QTest::currentTestFailed()) return;
    const Comparison c = compare(gpuResult, reference);
    qInfo("bumpy %s %dx%d: max |GPU - CPU| = %g, mean %g", name, image.grid().width,
          image.grid().height, c.maxDifference, c.meanDifference);
    QVERIFY2(c.maxDifference < 1e-4f, qPrintable(QString::number(c.maxDifference)));
    QVERIFY2(c.meanDifference < 1e-5f, qPrintable(QString::number(c.meanDifference)));
    for (const core::Sample b : bumps) {
      const auto [near, far] = nearAndFar(gpuResult, image.at(b).xyz(), 0.1f, 0.6f);
      qInfo("  bump at (%d, %d): near %.3f, far %.4f", b.i, b.j, near, far);
      QVERIFY2(near > 10 * far && near > 0.1, name);
    }
  }
}

QTEST_GUILESS_MAIN(SaliencyTest)
#include "saliency_gltest.moc"
