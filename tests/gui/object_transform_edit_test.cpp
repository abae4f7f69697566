// The transform maths G / R / S and the gizmo use (object_transform_edit): a turn about any axis
// is the rotation Q · R it should be, whatever the Euler angles before (poles included); the
// turns that are one Euler angle and a typed move or factor are one exact float operation; a
// scale along a world axis takes the object's own axis nearest it.
#include "object_transform_edit.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <numbers>
#include <random>

using namespace octaclay;
using app::Direction;

namespace {

using Matrix = std::array<double, 9>;

Matrix rotation(const core::ObjectTransform& t) {
  core::ObjectTransform unit = t;
  unit.scale = {1, 1, 1};
  return core::linearPart(unit);
}

Matrix multiply(const Matrix& a, const Matrix& b) {
  Matrix m{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k)
        m[r * 3 + c] += a[r * 3 + k] * b[k * 3 + c];
  return m;
}

// The rotation by degrees about unit axis a, built column by column from Rodrigues' formula
// applied to the basis vectors (not the closed form the code uses).
Matrix turn(Direction a, double degrees) {
  const double length = std::hypot(a[0], a[1], a[2]);
  for (double& c : a)
    c /= length;
  const double angle = degrees * std::numbers::pi / 180, c = std::cos(angle), s = std::sin(angle);
  Matrix m{};
  for (int col = 0; col < 3; ++col) {
    const double v[3] = {double(col == 0), double(col == 1), double(col == 2)};
    const double along = a[0] * v[0] + a[1] * v[1] + a[2] * v[2];
    const double cross[3] = {a[1] * v[2] - a[2] * v[1], a[2] * v[0] - a[0] * v[2],
                             a[0] * v[1] - a[1] * v[0]};
    for (int row = 0; row < 3; ++row)
      m[row * 3 + col] = v[row] * c + cross[row] * s + a[row] * along * (1 - c);
  }
  return m;
}

double largestDifference(const Matrix& a, const Matrix& b) {
  double most = 0;
  for (int k = 0; k < 9; ++k)
    most = std::max(most, std::abs(a[k] - b[k]));
  return most;
}

core::ObjectTransform randomTransform(std::mt19937& random) {
  std::uniform_real_distribution<float> angle(-180, 180), offset(-3, 3), scale(0.2f, 3);
  return {{offset(random), offset(random), offset(random)},
          {angle(random), angle(random), angle(random)},
          {scale(random), scale(random), scale(random)}};
}

} // namespace

class ObjectTransformEditTest : public QObject {
  Q_OBJECT

private slots:
  void aTurnAboutAnyAxisIsThatRotationAfterTheOldOne();
  void aTurnThroughThePolesKeepsTheRotation();
  void oneAngleTurnsAndTypedAmountsAreExact();
  void aTurnAboutTheObjectsOwnAxisComesAfterItsRotation();
  void scaleAlongAWorldAxisTakesTheNearestOwnAxis();
  void manyTurnsStayWithinTheTransformsBounds();
};

void ObjectTransformEditTest::aTurnAboutAnyAxisIsThatRotationAfterTheOldOne() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> component(-1, 1), degrees(-200, 200);
  for (int trial = 0; trial < 200; ++trial) {
    const core::ObjectTransform before = randomTransform(random);
    const Direction axis{component(random), component(random), component(random)};
    const double d = degrees(random);
    const core::ObjectTransform after = app::rotatedAbout(before, axis, d);
    const double error =
        largestDifference(rotation(after), multiply(turn(axis, d), rotation(before)));
    QVERIFY2(error < 2e-6, qPrintable(QString("trial %1: %2").arg(trial).arg(error)));
    QCOMPARE(after.translation, before.translation); // about its origin
    QCOMPARE(after.scale, before.scale);
    QVERIFY(!core::transformProblem(after));
    // World axes that are not one Euler angle here (Y and Z angles not 0) go the same way.
    for (int w = 0; w < 2; ++w) {
      const Direction e{double(w == 0), double(w == 1), 0};
      const double worldError =
          largestDifference(rotation(app::rotatedAboutWorldAxis(before, w, d)),
                            multiply(turn(e, d), rotation(before)));
      QVERIFY2(worldError < 2e-6, qPrintable(QString("axis %1: %2").arg(w).arg(worldError)));
    }
  }
  // An axis of no length leaves the transform as it was.
  const core::ObjectTransform t{{1, 2, 3}, {10, 20, 30}, {1, 1, 1}};
  QCOMPARE(app::rotatedAbout(t, {0, 0, 0}, 45), t);
}

void ObjectTransformEditTest::aTurnThroughThePolesKeepsTheRotation() {
  // Y angle ±90: X and Z turn about one axis there; the matrix must still be the one asked for.
  for (const double y : {90.0, -90.0}) {
    const core::ObjectTransform before{{}, {30, 0, 0}, {1, 1, 1}};
    const core::ObjectTransform after = app::rotatedAbout(before, {0, 1, 0}, y);
    QVERIFY(std::abs(std::abs(after.rotationDegrees.y) - 90.0f) < 1e-3f);
    QVERIFY(largestDifference(rotation(after), multiply(turn({0, 1, 0}, y), rotation(before))) <
            2e-6);
  }
}

void ObjectTransformEditTest::oneAngleTurnsAndTypedAmountsAreExact() {
  const core::ObjectTransform before{
      {0.1f, -2.3f, 7.7f}, {13.1f, 27.3f, -41.9f}, {0.3f, 1.7f, 2.9f}};
  // About world Z: always the Z angle alone.
  core::ObjectTransform z = app::rotatedAboutWorldAxis(before, 2, 90);
  QCOMPARE(z.rotationDegrees.z, before.rotationDegrees.z + 90.0f);
  QCOMPARE(z.rotationDegrees.x, before.rotationDegrees.x);
  QCOMPARE(z.rotationDegrees.y, before.rotationDegrees.y);
  // About world Y with no Z angle, about world X with neither: their own angle alone, the turn
  // added in double and rounded once.
  const core::ObjectTransform flat{{}, {13.1f, 27.3f, 0}, {1, 1, 1}};
  QCOMPARE(app::rotatedAboutWorldAxis(flat, 1, 33.3).rotationDegrees,
           (core::Vec3f{13.1f, float(double(27.3f) + 33.3), 0}));
  const core::ObjectTransform level{{}, {13.1f, 0, 0}, {1, 1, 1}};
  QCOMPARE(app::rotatedAboutWorldAxis(level, 0, -12.5).rotationDegrees,
           (core::Vec3f{13.1f - 12.5f, 0, 0}));
  // Typed moves and factors: one float operation.
  QCOMPARE(app::translated(before, {0.5f, 0, 0}).translation,
           (core::Vec3f{0.1f + 0.5f, -2.3f, 7.7f}));
  QCOMPARE(app::scaled(before, 2).scale, (core::Vec3f{0.6f, 3.4f, 5.8f}));
  QCOMPARE(app::scaled(before, 0.5, 1).scale, (core::Vec3f{0.3f, 0.85f, 2.9f}));
}

void ObjectTransformEditTest::aTurnAboutTheObjectsOwnAxisComesAfterItsRotation() {
  std::mt19937 random(11);
  for (int trial = 0; trial < 50; ++trial) {
    const core::ObjectTransform before = randomTransform(random);
    for (int axis = 0; axis < 3; ++axis) {
      const core::ObjectTransform after = app::rotatedAboutLocalAxis(before, axis, 37);
      const Direction e{double(axis == 0), double(axis == 1), double(axis == 2)};
      QVERIFY(largestDifference(rotation(after), multiply(rotation(before), turn(e, 37))) < 2e-6);
      const Direction d = app::localAxisDirection(before, axis);
      const Matrix r = rotation(before);
      QVERIFY(std::abs(d[0] - r[axis]) + std::abs(d[1] - r[3 + axis]) +
                  std::abs(d[2] - r[6 + axis]) <
              1e-12);
    }
    // About its own X: the X angle alone.
    QCOMPARE(app::rotatedAboutLocalAxis(before, 0, 37).rotationDegrees.x,
             float(double(before.rotationDegrees.x) + 37.0));
  }
}

void ObjectTransformEditTest::scaleAlongAWorldAxisTakesTheNearestOwnAxis() {
  const core::ObjectTransform straight{};
  for (int w = 0; w < 3; ++w)
    QCOMPARE(app::localAxisNearest(straight, w), w);
  // Turned 90° about Z: its own Y lies along world X, its own X along world Y.
  const core::ObjectTransform turned{{}, {0, 0, 90}, {1, 1, 1}};
  QCOMPARE(app::localAxisNearest(turned, 0), 1);
  QCOMPARE(app::localAxisNearest(turned, 1), 0);
  QCOMPARE(app::localAxisNearest(turned, 2), 2);
}

void ObjectTransformEditTest::manyTurnsStayWithinTheTransformsBounds() {
  core::ObjectTransform t{};
  for (int k = 0; k < 200; ++k) {
    t = app::rotatedAboutWorldAxis(t, 2, 90);
    QVERIFY2(!core::transformProblem(t), qPrintable(QString::number(t.rotationDegrees.z)));
  }
  // 200 quarter turns: a whole number of turns, the Z angle back to 0 modulo 360.
  QCOMPARE(std::fmod(double(t.rotationDegrees.z), 360.0), 0.0);
}

QTEST_MAIN(ObjectTransformEditTest)
#include "object_transform_edit_test.moc"
