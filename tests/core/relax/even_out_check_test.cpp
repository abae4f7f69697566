// core::evenOut (issue 30): the even-out that checks its own result. Whatever it is given, it
// either returns a document within its tolerance and no more stretched, or the input unchanged
// with the reason; the figures it reports are checked here against an independent measure.
#include "octaclay/core/document/document_info.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"
#include "octaclay/core/relax/relax.h"

#include <QTest>

#include <algorithm>
#include <cmath>
#include <cstring>

using namespace octaclay::core;

namespace {

// A unit sphere with a limb pulled out of the point `axis` points at (`length` long over a cap of
// `cap` radians): a thick limb for a small cap and moderate length, a needle for a long one.
Document pulledDocument(int n, Vec3f axis, float length, float cap) {
  GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  axis = normalize(axis);
  for (Vec4f& p : image.texels()) {
    const float angle =
        std::acos(std::clamp(dot(p.xyz(), axis) / octaclay::core::length(p.xyz()), -1.0f, 1.0f));
    const float t = 1.0f - angle / cap;
    if (t <= 0) continue;
    const Vec3f moved = p.xyz() + axis * (length * t * t * t);
    p = {moved.x, moved.y, moved.z, p.w};
  }
  return makeDocument(std::move(image));
}

bool sameBits(const Document& a, const Document& b) {
  return a.size() == b.size() &&
         std::memcmp(a.positions.texels().data(), b.positions.texels().data(),
                     a.positions.byteSize()) == 0 &&
         a.diffuse.texels == b.diffuse.texels;
}

// What the user is promised: improved within tolerance, or unchanged.
void checkPromise(const Document& input, const EvenOutResult& r, const char* name) {
  const StretchSummary before = summarizeStretch(input.positions);
  if (!r.changed) {
    qInfo("%s: unchanged: %s", name, r.reason.c_str());
    QVERIFY(!r.reason.empty());
    QVERIFY(sameBits(input, r.document));
    return;
  }
  const StretchSummary after = summarizeStretch(r.document.positions);
  // Measured again, with more points than the check used.
  const SurfaceDistance d =
      compareSurfaces(extractMesh(input.positions), extractMesh(r.document.positions),
                      {.samplesPerSurface = 300'000, .seed = 7});
  qInfo("%s: step %.3g, longest/median %.1f -> %.1f, stretched samples %zu -> %zu, moved RMS "
        "%.4f %%, Hausdorff %.4f %%",
        name, r.step, before.longestOverMedian, after.longestOverMedian, r.stretchedBefore,
        r.stretchedAfter, 100 * d.rms, 100 * d.hausdorff);
  QVERIFY(r.reason.empty());
  QCOMPARE(r.after.longestOverMedian, after.longestOverMedian);
  QVERIFY(after.longestOverMedian <= before.longestOverMedian);
  QVERIFY(r.stretchedAfter >= r.stretchedBefore);
  QVERIFY(d.rms <= 1e-4 * 1.05); // a few percent for the measure's own sampling
  QVERIFY(d.hausdorff <= 1e-3 * 1.05);
  const DocumentInfo info = describeDocument(r.document);
  QCOMPARE(info.seamGap, 0.0f);
  QCOMPARE(info.euler, 2LL);
}

} // namespace

class EvenOutCheckTest : public QObject {
  Q_OBJECT
private slots:
  void improvesOrLeavesAlone_data();
  void improvesOrLeavesAlone();
  void secondRunIsNeverWorse();
  void tightToleranceLeavesTheDocumentUnchanged();
  void cancelThrows();
};

void EvenOutCheckTest::improvesOrLeavesAlone_data() {
  QTest::addColumn<int>("n");
  QTest::addColumn<float>("x");
  QTest::addColumn<float>("y");
  QTest::addColumn<float>("z");
  QTest::addColumn<float>("length");
  QTest::addColumn<float>("cap");
  // Off the image's centre, across its corners (-z) and seams, thick and needle-thin.
  QTest::newRow("limb +z 128") << 128 << 0.f << 0.f << 1.f << 1.5f << 0.35f;
  QTest::newRow("limb off-centre 256") << 256 << 0.6f << -0.4f << 0.5f << 1.2f << 0.3f;
  QTest::newRow("limb across the corner 128") << 128 << 0.1f << 0.05f << -1.f << 1.5f << 0.35f;
  QTest::newRow("needle 128") << 128 << 0.5f << 0.3f << 0.7f << 4.0f << 0.06f;
  QTest::newRow("sphere 64") << 64 << 0.f << 0.f << 1.f << 0.f << 0.3f;
}

void EvenOutCheckTest::improvesOrLeavesAlone() {
  QFETCH(int, n);
  QFETCH(float, x);
  QFETCH(float, y);
  QFETCH(float, z);
  QFETCH(float, length);
  QFETCH(float, cap);
  const Document input = pulledDocument(n, {x, y, z}, length, cap);
  const EvenOutResult r = evenOut(input);
  checkPromise(input, r, QTest::currentDataTag());
}

void EvenOutCheckTest::secondRunIsNeverWorse() {
  const Document input = pulledDocument(128, {0.6f, -0.4f, 0.5f}, 1.5f, 0.3f);
  const EvenOutResult first = evenOut(input);
  checkPromise(input, first, "first");
  const EvenOutResult second = evenOut(first.document);
  checkPromise(first.document, second, "second");
}

void EvenOutCheckTest::tightToleranceLeavesTheDocumentUnchanged() {
  const Document input = pulledDocument(64, {0, 0, 1}, 1.5f, 0.35f);
  EvenOutCheckOptions check;
  check.rmsTolerance = 1e-9;
  const EvenOutResult r = evenOut(input, {}, check);
  QVERIFY(!r.changed);
  QVERIFY2(r.reason.find("surface would move") != std::string::npos, r.reason.c_str());
  QVERIFY(r.reason.find("smaller step") != std::string::npos);
  QCOMPARE(r.tries, 4);
  QVERIFY(sameBits(input, r.document));
  QCOMPARE(r.after.longestOverMedian, r.before.longestOverMedian);
}

void EvenOutCheckTest::cancelThrows() {
  const Document input = pulledDocument(64, {0, 0, 1}, 1.5f, 0.35f);
  float last = 0;
  bool thrown = false;
  try {
    evenOut(input, {}, {}, [&](float f) {
      last = f;
      return f < 0.75f; // cancelled while the steps are measured
    });
  } catch (const Error& e) {
    thrown = e.kind() == ErrorKind::Cancelled;
  }
  QVERIFY(thrown);
  QVERIFY(last >= 0.75f);
}

QTEST_GUILESS_MAIN(EvenOutCheckTest)
#include "even_out_check_test.moc"
