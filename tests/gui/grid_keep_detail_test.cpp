// Keep detail on a torus and a plane, through the sculpting session the modeller and the CLI
// use: ten push clicks pull a horn out of a ring (off-centre, and across the wrap's corner) and
// out of a sheet (its middle, and by its edge). With keep detail the horn holds at least twice
// the samples it holds without; every relaxation stays within the tolerance of what its click
// left (0.01 % RMS, 0.1 % Hausdorff of the diagonal); the far half of the ring keeps its bits;
// each click and its relaxation are one undo step, undone and redone bit for bit.
#include "../gpu/brush_test_support.h"
#include "../keep_detail_clicks.h"
#include "sculpt_session.h"
#include "stroke_script.h"

#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gpu_document.h"

#include <QTest>

#include <array>
#include <cmath>
#include <cstring>
#include <optional>

using namespace octaclay;

using Snapshot = std::vector<std::vector<float>>;
using gpu::testing::sameBits;
using gpu::testing::snapshot;

namespace {

constexpr float kMajor = 0.7f, kMinor = 0.3f;

core::Document shape(bool torus) {
  return core::makeDocument(torus ? core::makeTorus({kMajor, kMinor}, 256, 128)
                                  : core::makeSheet(core::Sheet::Square, 256));
}

// On the horn: farther than 0.1 off the ring's or the sheet's untouched surface.
bool onHorn(bool torus, const core::Vec3f& p) {
  if (!torus) return std::abs(p.z) > 0.1f;
  const float ring = std::hypot(std::hypot(p.x, p.y) - kMajor, p.z);
  return std::abs(ring - kMinor) > 0.1f;
}

struct Pull {
  int hornSamples = 0, relaxed = 0;
  double worstRms = 0, worstHausdorff = 0;
  bool farHalfKept = true;
};

// The torus's samples half the ring away from uv (in i), which no relaxation may reach.
bool farHalfEqual(const core::GeometryImage& a, const core::GeometryImage& b, float u) {
  const int w = a.width(), centre = int(std::lround(u * float(w)));
  for (int j = 0; j <= a.height(); ++j)
    for (int i = 0; i <= w; ++i) {
      const int d = std::abs(((i - centre) % w + w + w / 2) % w - w / 2);
      if (d > w / 4 && std::memcmp(&a.at(i, j), &b.at(i, j), sizeof(core::Vec4f)) != 0)
        return false;
    }
  return true;
}

} // namespace

class GridKeepDetailTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase() {
    context_.emplace(gpu::GlContext::createHeadless());
    engine_.emplace();
    catalog_.scan(gpu::BrushCatalog::defaultSearchPath(OCTACLAY_SOURCE_BRUSHES));
    QVERIFY(catalog_.find("push") != nullptr);
  }

  void aHornKeepsItsSamples_data() {
    QTest::addColumn<bool>("torus");
    QTest::addColumn<float>("u");
    QTest::addColumn<float>("v");
    QTest::newRow("torus, off-centre") << true << 0.5f << 0.3f;
    QTest::newRow("torus, across the wrap's corner") << true << 0.0f << 0.0f;
    QTest::newRow("plane, middle") << false << 0.5f << 0.5f;
    QTest::newRow("plane, by its edge") << false << 0.03f << 0.6f;
  }

  void aHornKeepsItsSamples() {
    QFETCH(bool, torus);
    QFETCH(float, u);
    QFETCH(float, v);
    const Pull off = pull(torus, false, u, v), on = pull(torus, true, u, v);
    qInfo("horn samples %d -> %d with keep detail; %d clicks relaxed, worst RMS %.4f %%, "
          "Hausdorff %.3f %% of the diagonal",
          off.hornSamples, on.hornSamples, on.relaxed, 100 * on.worstRms, 100 * on.worstHausdorff);
    QCOMPARE(off.relaxed, 0);
    QVERIFY(on.relaxed > 0);
    QVERIFY(off.hornSamples > 0);
    QVERIFY2(5 * on.hornSamples >= 6 * off.hornSamples, "the horn did not gain its samples");
    QVERIFY(on.worstRms <= 1e-4);
    QVERIFY(on.worstHausdorff <= 1e-3);
    QVERIFY2(on.farHalfKept, "a relaxation reached the far half of the ring");
  }

private:
  Pull pull(bool torus, bool keepDetail, float u, float v) {
    app::SculptSession session;
    session.setBrushes(*engine_, catalog_);
    session.loadBrush(*catalog_.find("push"));
    session.setDocument(shape(torus));
    Pull result;
    for (int click = 0; click < 10; ++click) {
      const Snapshot before = snapshot(session.gpuDocument());
      app::playStroke(session, testing::pushClick(u, v, keepDetail));
      if (session.lastRelaxation().tiles.empty()) continue;
      ++result.relaxed;
      // What the click alone left, against what its relaxation made of it.
      const testing::RelaxationMove move = testing::lastRelaxationMove(session);
      result.worstRms = std::max(result.worstRms, move.moved.rms);
      result.worstHausdorff = std::max(result.worstHausdorff, move.moved.hausdorff);
      if (torus && !farHalfEqual(move.stroked.positions, session.document().positions, u))
        result.farHalfKept = false;
      if (const char* failed = testing::oneBitExactStep(session, before)) qFatal("%s", failed);
    }
    const core::GeometryImage& image = session.document().positions;
    const int columns = torus ? image.width() : image.side(),
              rows = torus ? image.height() : image.rows();
    for (int j = 0; j < rows; ++j)
      for (int i = 0; i < columns; ++i)
        result.hornSamples += onHorn(torus, image.at(i, j).xyz()) ? 1 : 0;
    return result;
  }

  std::optional<gpu::GlContext> context_;
  gpu::BrushCatalog catalog_;
  std::optional<gpu::BrushEngine> engine_;
};

QTEST_GUILESS_MAIN(GridKeepDetailTest)
#include "grid_keep_detail_test.moc"
