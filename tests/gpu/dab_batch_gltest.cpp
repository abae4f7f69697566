// Dabs in one pass (issue 32 item 5): dabs whose passes cannot see each other's texels (a dab's
// mirror images) are drawn in one pass per layer, each rectangle with its dab's values, and leave
// the same bits as the same dabs one after the other, in the mirror and the textures, with the
// same tiles reported; BrushEngine::batches says yes only for such dabs.

#include "brush_test_support.h"

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"

#include <QtTest>

#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

// Every layer's texels as the GPU textures hold them.
std::vector<std::vector<float>> textureTexels(GpuDocument& document) {
  std::vector<std::vector<float>> layers;
  for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                core::EditLayer::Feature, core::EditLayer::Mask})
    layers.push_back(document.texture(layer).read(document.whole()));
  return layers;
}

// A sphere (N = n) whose mask is painted in a band when masked: the programs then sample it.
core::Document startDocument(int n, bool masked) {
  core::Document d = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, n));
  if (masked) {
    d.mask.texels.assign(static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1),
                         d.mask.fill[0]);
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i)
        if ((i / 8 + j / 8) % 3 == 0)
          d.mask.texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
                        static_cast<std::size_t>(i)] = 0.25f;
  }
  return d;
}

// Places a sixth, a third and a half of the way across both axes and their mixes: far apart and
// clear of the border at every N tested.
std::vector<core::Sample> farApart(int n, int count) {
  const int at[3] = {n / 4, n / 2, 3 * n / 4};
  std::vector<core::Sample> samples;
  for (int k = 0; k < count; ++k)
    samples.push_back({at[k % 3], at[(k / 3) % 3]});
  return samples;
}

} // namespace

class DabBatchTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() {
    try {
      context_.emplace(GlContext::createHeadless());
      engine_.emplace();
      loadBuiltIns(*engine_);
      const BrushManifest relax = builtInManifest("relax");
      engine_->load(relax, readFile(relax.shaderPath()));
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
  }

  void batchedDabsEqualOneByOne_data() {
    QTest::addColumn<QString>("brush");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("count");
    QTest::addColumn<float>("radius");
    QTest::addColumn<bool>("masked");
    QTest::newRow("push, 2 dabs") << "push" << 512 << 2 << 0.03f << false;
    QTest::newRow("push, 8 dabs") << "push" << 512 << 8 << 0.02f << false;
    QTest::newRow("push, 3 dabs, masked") << "push" << 512 << 3 << 0.03f << true;
    QTest::newRow("push, 2 dabs, N 1024") << "push" << 1024 << 2 << 0.02f << false;
    QTest::newRow("inflate, 4 dabs") << "inflate" << 512 << 4 << 0.03f << false;
    QTest::newRow("flatten, 2 dabs") << "flatten" << 512 << 2 << 0.03f << true;
    QTest::newRow("smooth, 2 dabs") << "smooth" << 512 << 2 << 0.01f << false;
    QTest::newRow("sphere-add, 3 dabs") << "sphere-add" << 512 << 3 << 0.01f << true;
    QTest::newRow("paint, 5 dabs") << "paint" << 512 << 5 << 0.03f << true;
    QTest::newRow("mask, 2 dabs") << "mask" << 512 << 2 << 0.03f << false;
  }

  void batchedDabsEqualOneByOne() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    QFETCH(int, count);
    QFETCH(float, radius);
    QFETCH(bool, masked);
    const std::string id = brush.toStdString();
    GpuDocument together(startDocument(n, masked)), apart(startDocument(n, masked));
    const core::GeometryImage& image = together.document().positions;
    std::vector<Dab> dabs;
    std::vector<std::vector<core::TexelRect>> reaches;
    for (const core::Sample s : farApart(n, count)) {
      Dab d = dabAt(image, s, radius * together.bounds().diagonal(), 0.5f);
      d.drag = d.strokeDelta = d.strokeDirection = d.centreNormal * 0.01f;
      d.pressure = 0.75f + 0.05f * static_cast<float>(dabs.size()); // each dab its own values
      reaches.push_back(engine_->reach(together, id, d));
      dabs.push_back(d);
    }
    QVERIFY2(engine_->batches(together, id, dabs, reaches), "the dabs should batch");
    const std::vector<DabResult> batched = engine_->dabs(together, id, dabs, reaches);
    std::vector<DabResult> single;
    for (const Dab& d : dabs)
      single.push_back(engine_->dab(apart, id, d));
    engine_->finishPasses();
    QCOMPARE(batched.size(), single.size());
    for (std::size_t k = 0; k < dabs.size(); ++k) {
      QVERIFY(batched[k].tiles == single[k].tiles);
      QCOMPARE(batched[k].texels, single[k].texels);
      QVERIFY(batched[k].seams.empty() && single[k].seams.empty());
    }
    QVERIFY2(!sameBits(snapshot(together), snapshot(GpuDocument(startDocument(n, masked)))),
             "the dabs changed nothing");
    QVERIFY2(sameBits(snapshot(together), snapshot(apart)), "the mirrors differ");
    QVERIFY2(sameBits(textureTexels(together), textureTexels(apart)), "the textures differ");
  }

  void batchesOnlyDabsThatCannotSeeEachOther() {
    const int n = 256;
    GpuDocument document(startDocument(n, false));
    const core::GeometryImage& image = document.document().positions;
    const float diagonal = document.bounds().diagonal();
    const auto dabsAt = [&](std::vector<core::Sample> at, float radius) {
      std::vector<Dab> dabs;
      for (const core::Sample s : at)
        dabs.push_back(dabAt(image, s, radius * diagonal, 0.5f));
      return dabs;
    };
    const auto batches = [&](const std::string& id, const std::vector<Dab>& dabs) {
      std::vector<std::vector<core::TexelRect>> reaches;
      for (const Dab& d : dabs)
        reaches.push_back(engine_->reach(document, id, d));
      return engine_->batches(document, id, dabs, reaches);
    };
    const std::vector<Dab> far = dabsAt({{64, 128}, {192, 128}}, 0.03f);
    QVERIFY(batches("push", far));
    QVERIFY(batches("smooth", far));
    QVERIFY(!batches("push", dabsAt({{128, 128}}, 0.03f)));             // one dab: nothing to gain
    QVERIFY(!batches("push", dabsAt({{120, 128}, {136, 128}}, 0.03f))); // overlapping
    QVERIFY(!batches("push", dabsAt({{2, 128}, {192, 128}}, 0.03f)));   // at the border: seams
    QVERIFY(!batches("relax", far));   // reparameterize: its field is kept from dab to dab
    std::vector<Dab> twoColours = far; // parameters are one program's: the same for every dab
    twoColours[0].parameters["color"] = {1, 0, 0, 1};
    twoColours[1].parameters["color"] = {0, 0, 1, 1};
    QVERIFY(!batches("paint", twoColours));
    twoColours[1].parameters["color"] = {1, 0, 0, 1};
    QVERIFY(batches("paint", twoColours));
    // Apart by less than their reach: clear for a brush that reads its texel alone, not for one
    // that reads the layer around it (smooth).
    const std::vector<Dab> near = dabsAt({{96, 128}, {160, 128}}, 0.03f);
    QVERIFY(batches("push", near));
    QVERIFY(!batches("smooth", near));
    // Eight small dabs of a 3 × 3 grid batch; all nine are more than kMaxBatch.
    std::vector<core::Sample> nine;
    for (int k = 0; k < 9; ++k)
      nine.push_back({48 + 80 * (k % 3), 48 + 80 * (k / 3)});
    QVERIFY(batches("push", dabsAt({nine.begin(), nine.begin() + 8}, 0.005f)));
    QVERIFY(!batches("push", dabsAt(nine, 0.005f)));
    // Dabs that do not batch still run, one after the other, through dabs().
    const std::vector<Dab> overlapping = dabsAt({{120, 128}, {136, 128}}, 0.03f);
    std::vector<std::vector<core::TexelRect>> reaches;
    for (const Dab& d : overlapping)
      reaches.push_back(engine_->reach(document, "push", d));
    GpuDocument apart(startDocument(n, false));
    const std::vector<DabResult> made = engine_->dabs(document, "push", overlapping, reaches);
    for (std::size_t k = 0; k < overlapping.size(); ++k)
      engine_->dab(apart, "push", overlapping[k], reaches[k]);
    QCOMPARE(made.size(), std::size_t{2});
    QVERIFY(sameBits(snapshot(document), snapshot(apart)));
  }

private:
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
};

QTEST_GUILESS_MAIN(DabBatchTest)
#include "dab_batch_gltest.moc"
