#include "shared_data.h"
#include "test_meshes.h"

#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/import/import.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <QElapsedTimer>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

using namespace octaclay::core;

namespace {

// testing::unitSphere scaled per axis: 8·4^levels triangles, outward.
TriangleMesh ellipsoid(int levels, Vec3f axes) {
  TriangleMesh mesh = testing::unitSphere(levels);
  for (Vec3f& p : mesh.positions)
    p = {p.x * axes.x, p.y * axes.y, p.z * axes.z};
  return mesh;
}

SurfaceDistanceOptions distanceOptions() {
  SurfaceDistanceOptions options;
  options.samplesPerSurface = 200'000;
  return options;
}

} // namespace

class SphericalParameterizationTest : public QObject {
  Q_OBJECT

private slots:
  void squarePointInvertsOctahedralDirection();
  void sphereMapsNearIsometrically();
  void ellipsoidMapsWithBoundedStretch();
  void rejectsMeshesThatAreNotSpheres();
  void progressCancels();
  void cubeResamplesClosely();
  void coloursFollowTheSurface();
  void importsSharedMeshes_data();
  void importsSharedMeshes();
};

void SphericalParameterizationTest::squarePointInvertsOctahedralDirection() {
  const int n = 16;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f d = octahedralDirection(n, i, j);
      const auto [s, t] = octahedralSquarePoint(d * 3.0f);
      // On the folds several points share a direction: compare the sample they stand for.
      const Sample back{static_cast<int>(std::lround(s * n)), static_cast<int>(std::lround(t * n))};
      QCOMPARE(std::abs(s * n - back.i) < 1e-5, true);
      QCOMPARE(std::abs(t * n - back.j) < 1e-5, true);
      QCOMPARE(canonical(n, back), canonical(n, Sample{i, j}));
    }
}

void SphericalParameterizationTest::sphereMapsNearIsometrically() {
  const TriangleMesh mesh = ellipsoid(4, {2, 2, 2});
  const SphericalMap map = parameterizeOnSphere(mesh);
  QCOMPARE(map.sphere.size(), mesh.positions.size());
  QCOMPARE(map.flipped, 0);
  for (const Vec3f& p : map.sphere)
    QVERIFY(std::abs(length(p) - 1.0f) < 1e-5f);
  qInfo("sphere: stretch L2 %.4f Linf %.4f", double(map.stretchL2), double(map.stretchLinf));
  QVERIFY(map.stretchL2 >= 1.0f - 1e-4f);
  QVERIFY(map.stretchL2 < 1.01f);
  QVERIFY(map.stretchLinf < 1.1f);
}

void SphericalParameterizationTest::ellipsoidMapsWithBoundedStretch() {
  const TriangleMesh mesh = ellipsoid(5, {1.0f, 0.6f, 0.35f});
  const SphericalMap map = parameterizeOnSphere(mesh);
  QCOMPARE(map.flipped, 0);
  qInfo("ellipsoid: stretch L2 %.4f Linf %.4f", double(map.stretchL2), double(map.stretchLinf));
  QVERIFY(map.stretchL2 < 1.3f);
  QVERIFY(map.stretchLinf < 3.0f);
  const GeometryImage image = resampleOctahedral(mesh, map, 64);
  QCOMPARE(maxSeamGap(image), 0.0f);
}

void SphericalParameterizationTest::rejectsMeshesThatAreNotSpheres() {
  TriangleMesh open = ellipsoid(1, {1, 1, 1});
  open.triangles.pop_back();
  QVERIFY_THROWS_EXCEPTION(Error, parameterizeOnSphere(open));
  TriangleMesh inward = ellipsoid(1, {1, 1, 1});
  for (auto& t : inward.triangles)
    std::swap(t[1], t[2]);
  QVERIFY_THROWS_EXCEPTION(Error, parameterizeOnSphere(inward));
  TriangleMesh two = ellipsoid(1, {1, 1, 1});
  const TriangleMesh other = ellipsoid(1, {1, 1, 1});
  const auto offset = static_cast<std::uint32_t>(two.positions.size());
  for (const Vec3f& p : other.positions)
    two.positions.push_back(p + Vec3f{3, 0, 0});
  for (const auto& t : other.triangles)
    two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  QVERIFY_THROWS_EXCEPTION(Error, parameterizeOnSphere(two));
  QVERIFY_THROWS_EXCEPTION(Error, parameterizeOnSphere(TriangleMesh{}));
  try {
    parameterizeOnSphere(open);
  } catch (const Error& e) {
    QCOMPARE(e.kind(), ErrorKind::InvalidInput);
  }
}

void SphericalParameterizationTest::progressCancels() {
  const TriangleMesh mesh = ellipsoid(3, {1, 1, 0.5f});
  float last = -1;
  bool increasing = true;
  parameterizeOnSphere(mesh, [&](float f) {
    increasing = increasing && f >= last && f <= 1;
    last = f;
    return true;
  });
  QVERIFY(increasing);
  QCOMPARE(last, 1.0f);
  int calls = 0;
  QVERIFY_THROWS_EXCEPTION(Cancelled,
                           parameterizeOnSphere(mesh, [&](float) { return ++calls < 3; }));
  QCOMPARE(calls, 3);
}

void SphericalParameterizationTest::cubeResamplesClosely() {
  const TriangleMesh mesh = extractMesh(makeBaseShape(BaseShape::Cube, 64));
  QElapsedTimer timer;
  timer.start();
  const SphericalMap map = parameterizeOnSphere(mesh);
  const GeometryImage image = resampleOctahedral(mesh, map, 128);
  const qint64 ms = timer.elapsed();
  QCOMPARE(map.flipped, 0);
  QCOMPARE(maxSeamGap(image), 0.0f);
  QCOMPARE(analyzeTopology(extractMesh(image)).euler, 2);
  const ImportQuality quality = measureImport(mesh, map, image, distanceOptions());
  qInfo("cube N=128: stretch L2 %.3f Linf %.3f, RMS %.5f%%, Hausdorff %.4f%%, %lld ms",
        double(map.stretchL2), double(map.stretchLinf), 100 * quality.distance.rms,
        100 * quality.distance.hausdorff, ms);
  QVERIFY(quality.distance.rms <= 0.002);
}

void SphericalParameterizationTest::coloursFollowTheSurface() {
  const TriangleMesh mesh = ellipsoid(3, {1, 1, 1});
  std::vector<Vec4f> colours;
  for (const Vec3f& p : mesh.positions)
    colours.push_back({0.5f + 0.5f * p.x, 0.5f + 0.5f * p.y, 0.5f + 0.5f * p.z, 1});
  const SphericalMap map = parameterizeOnSphere(mesh);
  const Document document = importToDocument(mesh, map, 32, colours);
  QVERIFY(!document.diffuse.uniform());
  // Colour is linear in position on each triangle, so it must match the resampled position.
  for (int j = 0; j <= 32; ++j)
    for (int i = 0; i <= 32; ++i) {
      const Vec3f p = document.positions.at(i, j).xyz();
      const float* c = &document.diffuse.texels[(static_cast<std::size_t>(j) * 33 + i) * 4];
      QVERIFY(std::abs(c[0] - (0.5f + 0.5f * p.x)) < 1e-4f);
      QVERIFY(std::abs(c[2] - (0.5f + 0.5f * p.z)) < 1e-4f);
      QVERIFY(std::abs(c[3] - 1.0f) < 1e-5f);
    }
  QVERIFY_THROWS_EXCEPTION(Error, importToDocument(mesh, map, 32, std::span(colours).first(3)));
}

void SphericalParameterizationTest::importsSharedMeshes_data() {
  QTest::addColumn<QString>("file");
  // Trim this list to shorten the run; each row prints its quality and time.
  QTest::newRow("spot") << "spot.obj";
  QTest::newRow("bunny_npm") << "bunny_npm.obj";
  QTest::newRow("max_planck") << "max_planck_decimated.obj";
  QTest::newRow("fandisk") << "fandisk.obj";
  QTest::newRow("airplane") << "airplane.obj";
  QTest::newRow("blub") << "blub.obj";
  QTest::newRow("wingnut") << "wingnut.obj";
  QTest::newRow("sword") << "sword.obj";
  QTest::newRow("bunny_cgal") << "bunny_cgal.obj";
  QTest::newRow("armadillo") << "armadillo.obj";
  QTest::newRow("horse") << "horse.ply";
  QTest::newRow("scorpion") << "scorpion.obj";
  QTest::newRow("koala") << "koala.obj";
  QTest::newRow("nefertiti") << "nefertiti.obj";
  // Every shared genus-0 mesh, the 269 k-triangle igea included (about 20 s in Release).
  // OCTACLAY_IMPORT_N sets N.
  QTest::newRow("igea") << "igea.ply";
}

void SphericalParameterizationTest::importsSharedMeshes() {
  QFETCH(QString, file);
  const QString path = QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/" + file;
  if (!QFileInfo::exists(path)) OCTACLAY_MISSING_SHARED_DATA(file);
  const TriangleMesh mesh = loadGenus0Mesh(path.toStdString()).mesh;
  const int n = qEnvironmentVariableIntValue("OCTACLAY_IMPORT_N") > 0
                    ? qEnvironmentVariableIntValue("OCTACLAY_IMPORT_N")
                    : 256;
  QElapsedTimer timer;
  timer.start();
  const SphericalMap map = parameterizeOnSphere(mesh);
  const qint64 parameterizeMs = timer.restart();
  const GeometryImage image = resampleOctahedral(mesh, map, n);
  const qint64 resampleMs = timer.elapsed();
  const ImportQuality quality = measureImport(mesh, map, image, distanceOptions());
  qInfo("%-12s V %6zu  flips %d  stretch L2 %7.3f Linf %9.2f  RMS %.4f%%  Hausdorff %.3f%%  "
        "param %5lld ms  resample %4lld ms",
        qPrintable(file), mesh.positions.size(), map.flipped, double(map.stretchL2),
        double(map.stretchLinf), 100 * quality.distance.rms, 100 * quality.distance.hausdorff,
        parameterizeMs, resampleMs);
  QCOMPARE(map.flipped, 0);
  QCOMPARE(maxSeamGap(image), 0.0f);
  QVERIFY(quality.distance.rms <= 0.002);
}

QTEST_APPLESS_MAIN(SphericalParameterizationTest)
#include "spherical_parameterization_test.moc"
