// A pointer's move as the stroke walks it (app/session/pointer_legs): on a torus a move across the
// wrap goes the short way, to the edge and on from the opposite one; on the ball a move across
// its border goes to the edge and on from where the border folds it, and a jump far from every
// edge is a jump, not a walk across the image; small moves, and every move on a plane, are one
// straight leg.
#include "pointer_legs.h"

#include <QtTest>

#include <cmath>

using namespace octaclay;
using app::PointerLeg;

namespace {

bool near(core::Vec2f a, core::Vec2f b) {
  return std::abs(a.x - b.x) < 1e-5f && std::abs(a.y - b.y) < 1e-5f;
}

QString text(const std::vector<PointerLeg>& legs) {
  QString out;
  for (const PointerLeg& l : legs)
    out += QString("%1(%2, %3)->(%4, %5) ")
               .arg(l.jumped ? "jump " : "")
               .arg(double(l.from.x))
               .arg(double(l.from.y))
               .arg(double(l.to.x))
               .arg(double(l.to.y));
  return out;
}

} // namespace

class PointerLegsTest : public QObject {
  Q_OBJECT

private slots:
  void smallMovesAreOneLeg();
  void aTorusWrapIsCrossedTheShortWay();
  void aTorusCornerIsCrossedOnBothAxes();
  void aJumpOnTheBallIsNotWalked();
};

void PointerLegsTest::smallMovesAreOneLeg() {
  for (const core::Topology t :
       {core::Topology::Octahedral, core::Topology::Torus, core::Topology::Plane}) {
    const auto legs = app::pointerLegs(t, {0.4f, 0.5f}, {0.45f, 0.52f});
    QCOMPARE(legs.size(), std::size_t{1});
    QVERIFY(!legs[0].jumped && near(legs[0].from, {0.4f, 0.5f}) &&
            near(legs[0].to, {0.45f, 0.52f}));
  }
  // A plane has no seam: even a long move is walked.
  const auto plane = app::pointerLegs(core::Topology::Plane, {0.02f, 0.5f}, {0.98f, 0.5f});
  QCOMPARE(plane.size(), std::size_t{1});
  QVERIFY(!plane[0].jumped);
}

void PointerLegsTest::aTorusWrapIsCrossedTheShortWay() {
  // From u = 0.98 to u = 0.02: 0.04 across the wrap, not 0.96 back across the image.
  const auto legs = app::pointerLegs(core::Topology::Torus, {0.98f, 0.3f}, {0.02f, 0.5f});
  QVERIFY2(legs.size() == 2, qPrintable(text(legs)));
  QVERIFY2(!legs[0].jumped && near(legs[0].from, {0.98f, 0.3f}) && near(legs[0].to, {1.0f, 0.4f}),
           qPrintable(text(legs)));
  QVERIFY2(legs[1].jumped && near(legs[1].from, {0.0f, 0.4f}) && near(legs[1].to, {0.02f, 0.5f}),
           qPrintable(text(legs)));
  // And back the other way, along v.
  const auto back = app::pointerLegs(core::Topology::Torus, {0.5f, 0.01f}, {0.5f, 0.97f});
  QVERIFY2(back.size() == 2 && near(back[0].to, {0.5f, 0.0f}) && near(back[1].from, {0.5f, 1.0f}),
           qPrintable(text(back)));
}

void PointerLegsTest::aTorusCornerIsCrossedOnBothAxes() {
  const auto legs = app::pointerLegs(core::Topology::Torus, {0.99f, 0.98f}, {0.01f, 0.04f});
  QVERIFY2(legs.size() == 3, qPrintable(text(legs)));
  for (const PointerLeg& l : legs)
    QVERIFY2(l.from.x >= 0 && l.from.x <= 1 && l.to.y >= 0 && l.to.y <= 1 &&
                 std::abs(l.to.x - l.from.x) < 0.05f && std::abs(l.to.y - l.from.y) < 0.07f,
             qPrintable(text(legs)));
  QVERIFY(near(legs.back().to, {0.01f, 0.04f}));
}

void PointerLegsTest::aJumpOnTheBallIsNotWalked() {
  // Across the ball's bottom edge (u, 0) is (1 - u, 0): picks at (0.3, 0.02) then (0.68, 0.01)
  // are 0.03 apart on the surface; walked to (0.3133, 0), on from (0.6867, 0).
  const auto bottom = app::pointerLegs(core::Topology::Octahedral, {0.3f, 0.02f}, {0.68f, 0.01f});
  QVERIFY2(bottom.size() == 2 && !bottom[0].jumped &&
               near(bottom[0].to, {0.3f + 0.02f / 1.5f, 0}) && bottom[1].jumped &&
               near(bottom[1].from, {0.7f - 0.02f / 1.5f, 0}) && near(bottom[1].to, {0.68f, 0.01f}),
           qPrintable(text(bottom)));
  // Across the right edge (1, v) is (1, 1 - v).
  const auto right = app::pointerLegs(core::Topology::Octahedral, {0.99f, 0.2f}, {0.98f, 0.82f});
  QVERIFY2(right.size() == 2 && near(right[0].to, {1.0f, 0.2f - 0.02f / 3}) &&
               near(right[1].from, {1.0f, 0.8f + 0.02f / 3}),
           qPrintable(text(right)));
  // Far from every edge: a jump (the pointer left the model and came back), nothing walked.
  const auto jump = app::pointerLegs(core::Topology::Octahedral, {0.3f, 0.5f}, {0.7f, 0.5f});
  QVERIFY2(jump.size() == 1 && jump[0].jumped && near(jump[0].from, {0.7f, 0.5f}) &&
               near(jump[0].to, {0.7f, 0.5f}),
           qPrintable(text(jump)));
}

QTEST_APPLESS_MAIN(PointerLegsTest)
#include "pointer_legs_test.moc"
