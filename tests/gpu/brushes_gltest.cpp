// The built-in brushes run as GPU passes on a sphere: each asserts its numeric effect against
// a CPU computation, that samples it cannot reach stay bit-identical, and that identified
// samples stay equal (seams closed) wherever the dab lands.

#include "brush_test_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"

#include <QtTest>

#include <algorithm>
#include <fstream>
#include <optional>
#include <sstream>

using namespace octaclay;
using namespace octaclay::gpu;

using namespace octaclay::gpu::testing;

namespace {
const std::filesystem::path kBrushes = kBuiltInBrushes;
} // namespace

class BrushesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void pushMovesCentreAndNothingOutside_data();
  void pushMovesCentreAndNothingOutside();
  void dabsOnSeamsAndPolesKeepTheSurfaceClosed();
  void maskAtZeroBlocksEveryBrush();
  void sphereSubtractLeavesNoSampleInside();
  void paintChangesOnlyDiffuse();
  void brokenShaderNamesFileAndLine();
  void uvAreaContinuesAcrossSeamsAndCorners();
  void seamRunsAreTheReachedBorderAndItsPartners();
  void centreNormalIsSkippedOnlyWhereNoPassReadsIt();

private:
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
};

void BrushesTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    loadBuiltIns(*engine_);
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

void BrushesTest::pushMovesCentreAndNothingOutside_data() {
  QTest::addColumn<int>("n");
  QTest::newRow("N=128") << 128;
  QTest::newRow("N=512") << 512;
}

void BrushesTest::pushMovesCentreAndNothingOutside() {
  QFETCH(int, n);
  const core::GeometryImage before = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(before));
  const float radius = 0.1f * 2.0f * std::sqrt(3.0f); // 10 % of the bbox diagonal
  const core::Sample centre{n / 2, n / 2};            // the +z pole
  const Dab dab = dabAt(before, centre, radius, 0.5f);
  const DabResult result = engine_->dab(document, "push", dab);
  QVERIFY(!result.tiles.empty());

  const core::GeometryImage& after = document.document().positions;
  // Strength 0.5 moves the centre sample by half the radius along its normal.
  const core::Vec3f moved = after.at(centre).xyz() - before.at(centre).xyz();
  QVERIFY2(std::abs(core::length(moved) - 0.5f * radius) < 1e-5f,
           qPrintable(QString::number(core::length(moved))));
  QVERIFY(core::dot(core::normalize(moved), dab.centreNormal) > 0.99999f);

  int outside = 0, changedInside = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const core::Vec3f p = before.at(i, j).xyz();
      const bool same = std::memcmp(&before.at(i, j), &after.at(i, j), sizeof(core::Vec4f)) == 0;
      if (core::length(p - dab.centre) >= radius) {
        ++outside;
        if (!same)
          QFAIL(qPrintable(QString("sample (%1,%2) outside the radius changed").arg(i).arg(j)));
      } else {
        changedInside += !same;
      }
    }
  QVERIFY(outside > 0);
  QVERIFY(changedInside > 10);
  QCOMPARE(core::maxSeamGap(after), 0.0f);
}

void BrushesTest::dabsOnSeamsAndPolesKeepTheSurfaceClosed() {
  const int n = 128;
  const core::GeometryImage start = core::makeBaseShape(core::BaseShape::Blob, n);
  GpuDocument document(core::makeDocument(start));
  const float radius = 0.15f;
  for (const char* brush : {"push", "inflate", "smooth", "flatten", "sphere-add"})
    for (core::Sample s :
         {core::Sample{0, 0}, core::Sample{0, n / 4}, core::Sample{n / 2, 0},
          core::Sample{n, 3 * n / 4}, core::Sample{n / 3, n}, core::Sample{0, n / 2}}) {
      engine_->dab(document, brush, dabAt(document.document().positions, s, radius, 0.4f));
      const float gap = core::maxSeamGap(document.document().positions);
      QVERIFY2(
          gap == 0.0f,
          qPrintable(QString("%1 at (%2,%3): seam gap %4").arg(brush).arg(s.i).arg(s.j).arg(gap)));
    }
  // The GPU textures and the CPU mirror agree everywhere.
  const int side = n + 1;
  const std::vector<float> gpu =
      document.texture(core::EditLayer::Positions).read({0, 0, side, side});
  QVERIFY(std::memcmp(gpu.data(), document.document().positions.texels().data(),
                      gpu.size() * sizeof(float)) == 0);
  QVERIFY(std::memcmp(gpu.data(), start.texels().data(), gpu.size() * sizeof(float)) != 0);
}

void BrushesTest::maskAtZeroBlocksEveryBrush() {
  const int n = 64;
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
  doc.mask.fill[0] = 0.0f;
  doc.hasMask = true;
  const core::GeometryImage before = doc.positions;
  GpuDocument document(std::move(doc));
  for (const char* brush :
       {"push", "inflate", "smooth", "flatten", "sphere-add", "sphere-subtract"})
    engine_->dab(document, brush, dabAt(before, {n / 2, n / 3}, 0.5f, 0.8f));
  QVERIFY(std::memcmp(before.texels().data(), document.document().positions.texels().data(),
                      before.byteSize()) == 0);
}

void BrushesTest::sphereSubtractLeavesNoSampleInside() {
  const int n = 256;
  const core::GeometryImage before = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(before));
  const Dab dab = dabAt(before, {n / 3, n / 2}, 0.6f, 0.5f);
  engine_->dab(document, "sphere-subtract", dab);
  // The sphere of brush.glsl: radius half the brush's, cutting strength × its radius deep.
  const float sphereRadius = 0.5f * dab.radius;
  const core::Vec3f sphereCentre =
      dab.centre + dab.centreNormal * (sphereRadius * (1 - dab.strength));
  const core::GeometryImage& after = document.document().positions;
  int moved = 0;
  for (const core::Vec4f& t : after.texels())
    QVERIFY(core::length(t.xyz() - sphereCentre) >= sphereRadius * (1 - 1e-5f));
  for (std::size_t k = 0; k < after.texelCount(); ++k)
    moved += !(after.texels()[k] == before.texels()[k]);
  QVERIFY(moved > 20);
  // The dimple is strength × sphere radius deep at the centre.
  QVERIFY(std::abs(core::length(after.at(n / 3, n / 2).xyz() - dab.centre) -
                   dab.strength * sphereRadius) < 1e-4f);
}

void BrushesTest::paintChangesOnlyDiffuse() {
  const int n = 64;
  const core::GeometryImage before = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(before));
  Dab dab = dabAt(before, {n / 2, n / 2}, 0.5f, 1.0f);
  dab.parameters["color"] = {0.0f, 0.0f, 1.0f, 1.0f};
  engine_->dab(document, "paint", dab);
  const core::Document& doc = document.document();
  QVERIFY(std::memcmp(before.texels().data(), doc.positions.texels().data(), before.byteSize()) ==
          0);
  QVERIFY(doc.feature.uniform());
  QVERIFY(doc.mask.uniform());
  QVERIFY(!doc.diffuse.uniform());
  const std::size_t centre = (static_cast<std::size_t>(n / 2) * (n + 1) + n / 2) * 4;
  QCOMPARE(doc.diffuse.texels[centre + 2], 1.0f); // full strength at the centre: pure blue
  QCOMPARE(doc.diffuse.texels[centre + 0], 0.0f);
  // The far pole is untouched: the fill value as the half-float texture holds it.
  QVERIFY(std::abs(doc.diffuse.texels[0] - doc.diffuse.fill[0]) < 1e-3f);
}

void BrushesTest::brokenShaderNamesFileAndLine() {
  BrushManifest manifest = parseBrushManifest(kBrushes / "push" / "manifest.json");
  manifest.id = "push";
  try {
    engine_->load(manifest,
                  "vec4 brush(vec4 value, BrushInput b) {\n  return value +\n  nothing;\n}\n");
    QFAIL("a broken brush compiled");
  } catch (const GlError& e) {
    const QString message = e.what();
    QVERIFY2(message.contains("push/brush.glsl:3"), qPrintable(message));
    QVERIFY2(message.contains("nothing"), qPrintable(message));
  }
  // The good version stays loaded and works.
  const core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, 32);
  GpuDocument document(core::makeDocument(image));
  engine_->dab(document, "push", dabAt(image, {16, 16}, 0.5f, 0.5f));
  QVERIFY(document.document().positions.at(16, 16).z > 1.2f);
}

void BrushesTest::uvAreaContinuesAcrossSeamsAndCorners() {
  BrushManifest manifest = parseBrushManifest(kBrushes / "paint" / "manifest.json");
  manifest.id = "paint-uv";
  manifest.area = AreaMode::Uv;
  engine_->load(manifest, readFile(manifest.shaderPath()));
  const int n = 128;
  const core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, n);
  GpuDocument document(core::makeDocument(image));
  // 6 samples of radius: the radius is the same fraction of N as of the bbox diagonal.
  const float radius = 6.0f / float(n) * document.bounds().diagonal();
  auto colour = [&](int i, int j) {
    // Green: 0.8 in the default fill, 0.2 in the default paint colour.
    return document.document().diffuse.texels[(static_cast<std::size_t>(j) * (n + 1) + i) * 4 + 1];
  };
  // On the left seam: samples two columns in, mirrored across the fold, are painted alike.
  engine_->dab(document, "paint-uv", dabAt(image, {0, n / 4}, radius, 1.0f));
  QVERIFY(colour(2, n / 4) < 0.7f);
  QCOMPARE(colour(2, n / 4), colour(2, 3 * n / 4));
  QCOMPARE(colour(1, n / 4 + 2), colour(1, 3 * n / 4 - 2));
  QVERIFY(colour(10, n / 4) > 0.79f); // outside the radius: the fill
  // At the corner pole: the four corners' neighbourhoods are one disc.
  engine_->dab(document, "paint-uv", dabAt(image, {0, 0}, radius, 1.0f));
  QVERIFY(colour(2, 1) < 0.7f);
  QCOMPARE(colour(2, 1), colour(n - 2, n - 1));
  QCOMPARE(colour(1, 2), colour(n - 1, n - 2));
  QCOMPARE(colour(2, 1), colour(n - 2, 1));
  QCOMPARE(colour(2, 1), colour(2, n - 1));
  QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
}

// The seaming pass rewrites only the border samples a dab's tiles reach and those identified
// with them: (N - i, j) on the rows, (i, N - j) on the columns, all four corners at once.
void BrushesTest::seamRunsAreTheReachedBorderAndItsPartners() {
  const int n = 256, side = n + 1;
  const auto runs = [&](std::vector<core::TexelRect> tiles) {
    std::vector<std::array<int, 4>> out;
    for (const core::TexelRect& r : seamRuns(tiles, side))
      out.push_back({r.x, r.y, r.width, r.height});
    std::sort(out.begin(), out.end());
    return out;
  };
  QVERIFY(runs({{32, 32, 32, 32}}).empty()); // inside: nothing to seam
  // Left column rows 100-131 and their partners 125-156: one run.
  QCOMPARE(runs({{0, 100, 32, 32}}), (std::vector<std::array<int, 4>>{{0, 100, 1, 57}}));
  // Bottom row columns 64-95 and 161-192 (apart).
  QCOMPARE(runs({{64, 0, 32, 32}}),
           (std::vector<std::array<int, 4>>{{64, 0, 32, 1}, {161, 0, 32, 1}}));
  // A corner tile: its row and column with their partners, and the four corners.
  QCOMPARE(runs({{0, 0, 32, 32}}), (std::vector<std::array<int, 4>>{{0, 0, 32, 1},
                                                                    {0, 1, 1, 31},
                                                                    {0, 225, 1, 31},
                                                                    {0, n, 1, 1},
                                                                    {225, 0, 32, 1},
                                                                    {n, n, 1, 1}}));
}

void BrushesTest::centreNormalIsSkippedOnlyWhereNoPassReadsIt() {
  // A stroke computes the area normal only for a brush whose passes read the centre normal:
  // a dab with another normal must then give the same bits (smooth), and must not where the
  // engine says the normal is read (push).
  const int n = 64;
  const core::GeometryImage sphere = core::makeBaseShape(core::BaseShape::Sphere, n);
  const auto after = [&](const std::string& brush, core::Vec3f normal) {
    GpuDocument document(core::makeDocument(sphere));
    Dab dab = dabAt(sphere, {n / 2 + 3, n / 2 - 5}, 0.4f, 0.5f);
    dab.centreNormal = normal;
    engine_->dab(document, brush, dab);
    return snapshot(document);
  };
  const core::Vec3f tilted = core::normalize(core::Vec3f{0.3f, -0.2f, 1.0f});
  for (const std::string brush : {"smooth", "push"})
    try {
      GpuDocument document(core::makeDocument(sphere));
      const bool reads = engine_->usesCentreNormal(document, brush, {});
      const bool same = sameBits(after(brush, {0, 0, 1}), after(brush, tilted));
      QVERIFY2(reads == (brush != "smooth"), brush.c_str());
      QVERIFY2(same == !reads, brush.c_str());
    } catch (const std::exception& e) {
      QFAIL((brush + ": " + e.what()).c_str());
    }
}

QTEST_APPLESS_MAIN(BrushesTest)
#include "brushes_gltest.moc"
