// Ray picking through the tile bounds: the hit is the sample under the ray, exact to one sample
// at N = 4096, and rays that miss report no hit.

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/ray_pick.h"

#include <QtTest>

#include <random>

using namespace octaclay::core;

class RayPickTest : public QObject {
  Q_OBJECT

private slots:
  void hitsTheSampleUnderTheRay_data();
  void hitsTheSampleUnderTheRay();
  void cameraRayThroughCentreHitsTheFront();
  void missesReportNothing();
};

void RayPickTest::hitsTheSampleUnderTheRay_data() {
  QTest::addColumn<int>("n");
  QTest::addColumn<int>("shape");
  QTest::newRow("sphere 256") << 256 << int(BaseShape::Sphere);
  QTest::newRow("blob 1024") << 1024 << int(BaseShape::Blob);
  QTest::newRow("sphere 4096") << 4096 << int(BaseShape::Sphere);
}

void RayPickTest::hitsTheSampleUnderTheRay() {
  QFETCH(int, n);
  QFETCH(int, shape);
  const GeometryImage image = makeBaseShape(BaseShape(shape), n);
  const TileBounds bounds(image);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> index(0, n);
  for (int k = 0; k < 200; ++k) {
    const Sample s{index(random), index(random)};
    const Vec3f p = image.at(s).xyz();
    const Vec3f normal = vertexNormal(image, s);
    // Start just outside: on the blob a far start could meet another bulge first.
    const Ray ray{p + normal * 0.01f, normal * -1.0f};
    const auto hit = pickRay(image, bounds, ray);
    QVERIFY2(hit, qPrintable(QString("no hit for sample (%1,%2)").arg(s.i).arg(s.j)));
    // Exact to one sample: the hit is within one sample spacing of the target's position, and
    // the reported sample is the target or one of its neighbours (through identification).
    // The ray passes through the sample's own position, a vertex of the mesh.
    QVERIFY2(length(hit->position - p) < 1e-5f,
             qPrintable(QString::number(length(hit->position - p))));
    const Vec3f found = image.at(hit->sample).xyz();
    QVERIFY2(length(found - p) <= 1.5f * 3.1416f * 2.0f / float(n),
             qPrintable(QString("(%1,%2) picked (%3,%4)")
                            .arg(s.i)
                            .arg(s.j)
                            .arg(hit->sample.i)
                            .arg(hit->sample.j)));
    // u, v interpolate the image coordinates of the hit.
    const Sample fromUv{int(std::lround(hit->u * float(n))), int(std::lround(hit->v * float(n)))};
    QVERIFY(length(image.at(wrap(n, fromUv)).xyz() - p) <= 1.5f * 3.1416f * 2.0f / float(n));
  }
}

void RayPickTest::cameraRayThroughCentreHitsTheFront() {
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, 128);
  const Camera camera; // at (0, 0, 4) looking at the origin
  const Ray ray = cameraRay(camera, 640, 480, 319.5f, 239.5f);
  const auto hit = pickRay(image, TileBounds(image), ray);
  QVERIFY(hit);
  QVERIFY(std::abs(hit->distance - 3.0f) < 1e-3f);
  QVERIFY(std::abs(hit->position.z - 1.0f) < 1e-3f);
  // The +z pole is the image centre.
  QVERIFY(std::abs(hit->u - 0.5f) < 1.0f / 128 && std::abs(hit->v - 0.5f) < 1.0f / 128);
}

void RayPickTest::missesReportNothing() {
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, 64);
  const TileBounds bounds(image);
  QVERIFY(!pickRay(image, bounds, {{0, 3, 4}, {0, 0, -1}}));
  QVERIFY(!pickRay(image, bounds, {{0, 0, 4}, {0, 0, 1}})); // pointing away
}

QTEST_APPLESS_MAIN(RayPickTest)
#include "ray_pick_test.moc"
