// Per-sample normals computed through wrap(): accuracy on the sphere, agreement across seams,
// and exact face normals on the cube.

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <vector>

using namespace octaclay::core;

namespace {

double angleDegrees(Vec3f a, Vec3f b) {
  const double c = std::clamp(static_cast<double>(dot(normalize(a), normalize(b))), -1.0, 1.0);
  return std::acos(c) * 180.0 / M_PI;
}

QString str(Vec3f v) {
  return QString("(%1, %2, %3)").arg(v.x).arg(v.y).arg(v.z);
}

} // namespace

class NormalsTest : public QObject {
  Q_OBJECT

private slots:
  void sphereMatchesAnalytic();
  void seamSamplesAgree();
  void computeNormalsMatchesVertexNormal();
  void cubeFaceCentres();
};

void NormalsTest::sphereMatchesAnalytic() {
  const int n = 256;
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  double worst = 0;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Vec3f normal = vertexNormal(image, {i, j});
      if (std::abs(length(normal) - 1.0f) > 1e-5f)
        QFAIL(qPrintable(QString("normal at (%1,%2) not unit: %3").arg(i).arg(j).arg(str(normal))));
      const double a = angleDegrees(normal, image.at(i, j).xyz());
      worst = std::max(worst, a);
      if (a > 0.5)
        QFAIL(
            qPrintable(QString("normal at (%1,%2) is %3° off the sphere's").arg(i).arg(j).arg(a)));
    }
  }
  qInfo("worst angle to the analytic normal: %g°", worst);
  // A normal from only one side of a seam would be tens of degrees off at N = 256; the worst
  // case is well below that bound, not just under 0.5°.
  QVERIFY(worst < 0.5);
}

void NormalsTest::seamSamplesAgree() {
  for (BaseShape shape : {BaseShape::Sphere, BaseShape::Cube, BaseShape::Blob}) {
    const int n = 256;
    const GeometryImage image = makeBaseShape(shape, n);
    for (int k = 0; k <= n; ++k) {
      for (Sample s : {Sample{k, 0}, Sample{k, n}, Sample{0, k}, Sample{n, k}}) {
        std::array<Sample, 4> group{};
        const int c = identifiedSamples(n, s, group);
        const Vec3f ref = vertexNormal(image, s);
        for (int g = 0; g < c; ++g) {
          const Vec3f other = vertexNormal(image, group[g]);
          if (length(other - ref) > 1e-5f)
            QFAIL(qPrintable(QString("%1: normals at (%2,%3) %4 and (%5,%6) %7 differ")
                                 .arg(QString::fromUtf8(baseShapeName(shape).data(),
                                                        baseShapeName(shape).size()))
                                 .arg(s.i)
                                 .arg(s.j)
                                 .arg(str(ref))
                                 .arg(group[g].i)
                                 .arg(group[g].j)
                                 .arg(str(other))));
        }
      }
    }
  }
}

void NormalsTest::computeNormalsMatchesVertexNormal() {
  const int n = 128;
  const GeometryImage image = makeBaseShape(BaseShape::Blob, n);
  const std::vector<Vec3f> all = computeNormals(image);
  QCOMPARE(all.size(), static_cast<std::size_t>(n + 1) * (n + 1));
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const Vec3f a = all[static_cast<std::size_t>(j) * (n + 1) + i];
      const Vec3f b = vertexNormal(image, {i, j});
      if (length(a - b) > 1e-6f)
        QFAIL(qPrintable(QString("(%1,%2): computeNormals %3, vertexNormal %4")
                             .arg(i)
                             .arg(j)
                             .arg(str(a))
                             .arg(str(b))));
    }
  }
}

void NormalsTest::cubeFaceCentres() {
  const int n = 256;
  const GeometryImage image = makeBaseShape(BaseShape::Cube, n);
  const std::array<Vec3f, 6> axes{Vec3f{0, 0, 1},  Vec3f{0, 0, -1}, Vec3f{1, 0, 0},
                                  Vec3f{-1, 0, 0}, Vec3f{0, 1, 0},  Vec3f{0, -1, 0}};
  for (const Vec3f& axis : axes) {
    // The sample whose octahedron direction is the axis: the centre of that cube face.
    Sample best{};
    float bestDot = -2;
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const float d = dot(octahedralDirection(n, i, j), axis);
        if (d > bestDot) bestDot = d, best = {i, j};
      }
    QVERIFY2(bestDot > 1 - 1e-6f, qPrintable(str(axis)));
    QVERIFY2(length(image.at(best).xyz() - axis) < 1e-6f,
             qPrintable(str(axis) + " sample " + str(image.at(best).xyz())));
    const Vec3f normal = vertexNormal(image, best);
    QVERIFY2(length(normal - axis) < 1e-6f, qPrintable(str(axis) + " normal " + str(normal)));
  }
}

QTEST_APPLESS_MAIN(NormalsTest)
#include "normals_test.moc"
