// guessFacing (facing.h): a head's face (a nose, two eyes, a mouth) on one side of a sphere turns
// the guess to that side, whichever side it is; smooth or symmetric shapes and a feature on top
// keep the default front, +z.

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/lod/facing.h"
#include "octaclay/core/lod/saliency.h"

#include <QtTest>

#include <cmath>

using namespace octaclay::core;

Q_DECLARE_METATYPE(octaclay::core::Vec3f)

namespace {

// The unit sphere with a face looking along `front` (horizontal, unit): a nose bump, two eye
// dents and a mouth groove, all within 50° of `front`; the back stays smooth.
GeometryImage head(int n, Vec3f front) {
  const Vec3f up{0, 1, 0};
  const Vec3f right = cross(up, front);
  const auto at = [&](float rightAngle, float upAngle) {
    return normalize(front + right * std::tan(rightAngle) + up * std::tan(upAngle));
  };
  const struct {
    Vec3f centre;
    float width, height;
  } features[] = {{at(0, 0), 0.12f, 0.25f},                                             // nose
                  {at(-0.35f, 0.3f), 0.1f, -0.08f},                                     // eyes
                  {at(0.35f, 0.3f), 0.1f, -0.08f},  {at(-0.15f, -0.4f), 0.08f, -0.05f}, // mouth
                  {at(0, -0.4f), 0.08f, -0.05f},    {at(0.15f, -0.4f), 0.08f, -0.05f}};
  GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  for (Vec4f& t : image.texels()) {
    const Vec3f d = normalize(t.xyz());
    float r = 1;
    for (const auto& f : features) {
      const float a = std::acos(std::clamp(dot(d, f.centre), -1.0f, 1.0f)) / f.width;
      r += f.height * std::exp(-a * a);
    }
    t = {d.x * r, d.y * r, d.z * r, 0};
  }
  return image;
}

bool near(Vec3f a, Vec3f b) {
  return length(a - b) < 1e-4f;
}

QString text(Vec3f v) {
  return QStringLiteral("(%1, %2, %3)").arg(double(v.x)).arg(double(v.y)).arg(double(v.z));
}

} // namespace

class FacingTest : public QObject {
  Q_OBJECT
private slots:
  void faceOnAnySideIsFound_data();
  void faceOnAnySideIsFound();
  void symmetricShapesKeepTheDefaultFront();
  void featureOnTopKeepsTheDefaultFront();
  void torusAndPlaneKeepTheDefaultFront();
};

void FacingTest::faceOnAnySideIsFound_data() {
  QTest::addColumn<Vec3f>("front");
  QTest::addColumn<int>("n");
  const float d = std::sqrt(0.5f);
  QTest::newRow("+z") << Vec3f{0, 0, 1} << 128;
  QTest::newRow("-z") << Vec3f{0, 0, -1} << 128;
  QTest::newRow("+x") << Vec3f{1, 0, 0} << 128;
  QTest::newRow("-x") << Vec3f{-1, 0, 0} << 128;
  QTest::newRow("-x-z") << Vec3f{-d, 0, -d} << 128;
  QTest::newRow("-z at N=512") << Vec3f{0, 0, -1} << 512; // subsampled to 128 first
  QTest::newRow("+x at N=64") << Vec3f{1, 0, 0} << 64;
}

void FacingTest::faceOnAnySideIsFound() {
  QFETCH(Vec3f, front);
  QFETCH(int, n);
  const Vec3f guess = guessFacing(head(n, front));
  QVERIFY2(near(guess, front), qPrintable(text(guess)));
}

void FacingTest::symmetricShapesKeepTheDefaultFront() {
  for (BaseShape shape : {BaseShape::Sphere, BaseShape::Cube, BaseShape::Cylinder}) {
    const Vec3f guess = guessFacing(makeBaseShape(shape, 128));
    QVERIFY2(near(guess, {0, 0, 1}), qPrintable(text(guess)));
  }
}

// The up axis stays up: a face looking straight up gives no horizontal pull.
void FacingTest::featureOnTopKeepsTheDefaultFront() {
  GeometryImage image = head(128, {0, 0, 1});
  for (Vec4f& t : image.texels())
    t = {t.x, t.z, -t.y, 0}; // the face turned from +z to +y
  const Vec3f guess = guessFacing(image);
  QVERIFY2(near(guess, {0, 0, 1}), qPrintable(text(guess)));
}

// A torus (W ≠ H) or plane opened in the modeller faces +z; its saliency reads its own grid
// (a torus's periods, a plane's boundary) and never past its rows: every value in [0, 1].
void FacingTest::torusAndPlaneKeepTheDefaultFront() {
  for (const GeometryImage& image : {makeTorus(Torus{}, 64, 32), makeSheet(Sheet::Disc, 64)}) {
    const Vec3f f = guessFacing(image);
    QCOMPARE(f.x, 0.0f);
    QCOMPARE(f.y, 0.0f);
    QCOMPARE(f.z, 1.0f);
    GeometryImage copy = image;
    computeSaliency(copy);
    float peak = 0;
    for (std::size_t k = 0; k < copy.texelCount(); ++k) {
      const float w = copy.texels()[k].w;
      QVERIFY2(w >= 0 && w <= 1, qPrintable(QString::number(double(w))));
      peak = std::max(peak, w);
      QCOMPARE(copy.texels()[k].x, image.texels()[k].x); // xyz untouched
    }
    QVERIFY(peak == 1.0f || peak == 0.0f); // normalised by its maximum
  }
}

QTEST_APPLESS_MAIN(FacingTest)
#include "facing_test.moc"
