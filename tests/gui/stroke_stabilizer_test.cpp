// Lazy-mouse stroke stabilizer (app/gui/viewport/stroke_stabilizer.h): passthrough at strength 0,
// the dead zone of the string, the taut string after a long pull, dab spacing, and that it really
// smooths a jittery hand.

#include "stroke_stabilizer.h"

#include <QtTest>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

using octaclay::app::Point2;
using octaclay::app::StrokeStabilizer;

namespace {

double distance(Point2 a, Point2 b) {
  return std::hypot(double(a.x) - b.x, double(a.y) - b.y);
}

// Sum of |direction change| in radians over a polyline, skipping zero-length segments (repeated
// points have no direction).
double totalTurning(const std::vector<Point2>& path) {
  double turning = 0.0;
  bool havePrevious = false;
  double previous = 0.0;
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double dx = double(path[i].x) - path[i - 1].x;
    const double dy = double(path[i].y) - path[i - 1].y;
    if (std::hypot(dx, dy) < 1e-9) continue;
    const double angle = std::atan2(dy, dx);
    if (havePrevious) {
      double change = std::abs(angle - previous);
      if (change > std::numbers::pi) change = 2.0 * std::numbers::pi - change;
      turning += change;
    }
    previous = angle;
    havePrevious = true;
  }
  return turning;
}

// Root-mean-square distance of the points from the horizontal line y = 0, over points with
// x ≥ fromX (so the stabilizer's start-up lag does not count either way).
double rmsLateral(const std::vector<Point2>& path, float fromX) {
  double sum = 0.0;
  int count = 0;
  for (const Point2& p : path) {
    if (p.x < fromX) continue;
    sum += double(p.y) * p.y;
    ++count;
  }
  return count ? std::sqrt(sum / count) : 0.0;
}

// The largest gap between consecutive dabs, starting from where the brush was.
double largestGap(Point2 start, const std::vector<Point2>& dabs) {
  double gap = 0.0;
  Point2 previous = start;
  for (const Point2& p : dabs) {
    gap = std::max(gap, distance(previous, p));
    previous = p;
  }
  return gap;
}

} // namespace

class StrokeStabilizerTest : public QObject {
  Q_OBJECT

private slots:
  void strengthIsClamped();
  void strengthZeroFollowsCursor();
  void shortMoveInsideStringKeepsBrush();
  void longMovePullsBrushToStringLength();
  void dabsAreSpacedAtMostTwoPixels();
  void smoothsJitteryInput();
  void finishEndsWhereBrushIs();
};

void StrokeStabilizerTest::strengthIsClamped() {
  StrokeStabilizer s(2.0f);
  QCOMPARE(s.strength(), 1.0f);
  QCOMPARE(s.lengthPixels(), StrokeStabilizer::kDefaultMaxLengthPixels);
  s.setStrength(-1.0f);
  QCOMPARE(s.strength(), 0.0f);
  s.setStrength(std::numeric_limits<float>::quiet_NaN());
  QCOMPARE(s.strength(), 0.0f);
  s.setStrength(0.5f);
  s.setMaxLengthPixels(-3.0f);
  QCOMPARE(s.lengthPixels(), 0.0f);
  s.setMaxLengthPixels(80.0f);
  QCOMPARE(s.lengthPixels(), 40.0f);
}

void StrokeStabilizerTest::strengthZeroFollowsCursor() {
  StrokeStabilizer s;
  s.begin({10.0f, 20.0f});
  // A sub-pixel move is a single dab on the cursor.
  auto dabs = s.moveTo({10.5f, 20.25f});
  QCOMPARE(dabs.size(), std::size_t(1));
  QCOMPARE(dabs.back().x, 10.5f);
  QCOMPARE(dabs.back().y, 20.25f);

  std::mt19937 rng(7);
  std::uniform_real_distribution<float> coordinate(-500.0f, 500.0f);
  for (int i = 0; i < 200; ++i) {
    const Point2 cursor{coordinate(rng), coordinate(rng)};
    const Point2 before = s.brush();
    dabs = s.moveTo(cursor);
    QVERIFY(!dabs.empty());
    // Exact: strength 0 must not perturb the stroke by even one rounding step.
    QCOMPARE(dabs.back().x, cursor.x);
    QCOMPARE(dabs.back().y, cursor.y);
    QCOMPARE(s.brush().x, cursor.x);
    QCOMPARE(s.brush().y, cursor.y);
    QVERIFY(largestGap(before, dabs) <= StrokeStabilizer::kMaxDabSpacingPixels);
  }
  // Not moving is no dab.
  QVERIFY(s.moveTo(s.brush()).empty());
}

void StrokeStabilizerTest::shortMoveInsideStringKeepsBrush() {
  StrokeStabilizer s(0.5f); // L = 30 px
  QCOMPARE(s.lengthPixels(), 30.0f);
  s.begin({100.0f, 100.0f});
  QVERIFY(s.moveTo({110.0f, 100.0f}).empty());
  QVERIFY(s.moveTo({100.0f, 90.0f}).empty());
  QVERIFY(s.moveTo({121.0f, 121.0f}).empty()); // 29.7 px away: still slack
  QCOMPARE(s.brush().x, 100.0f);
  QCOMPARE(s.brush().y, 100.0f);
}

void StrokeStabilizerTest::longMovePullsBrushToStringLength() {
  StrokeStabilizer s(0.5f);
  const Point2 start{100.0f, 100.0f};
  s.begin(start);
  const Point2 cursor{160.0f, 180.0f}; // 100 px away along (0.6, 0.8)
  const auto dabs = s.moveTo(cursor);
  QVERIFY(!dabs.empty());
  const Point2 brush = s.brush();
  QCOMPARE(dabs.back().x, brush.x);
  QCOMPARE(dabs.back().y, brush.y);
  QVERIFY2(std::abs(distance(brush, cursor) - 30.0) < 1e-4,
           qPrintable(QString("brush %1 px from the cursor").arg(distance(brush, cursor))));
  // On the line from the start to the cursor: 70 px along it.
  QVERIFY(std::abs(distance(start, brush) - 70.0) < 1e-4);
  const double cross = (double(brush.x) - start.x) * (cursor.y - start.y) -
                       (double(brush.y) - start.y) * (cursor.x - start.x);
  QVERIFY2(std::abs(cross) / 100.0 < 1e-4, "brush left the line to the cursor");
  // Every dab lies on that segment too, in order.
  double along = 0.0;
  for (const Point2& p : dabs) {
    const double d = distance(start, p);
    QVERIFY(d > along);
    along = d;
    QVERIFY(std::abs((double(p.x) - start.x) * 0.8 - (double(p.y) - start.y) * 0.6) < 1e-3);
  }

  // Pulling further along the same line keeps the string taut at L.
  s.moveTo({220.0f, 260.0f});
  QVERIFY(std::abs(distance(s.brush(), {220.0f, 260.0f}) - 30.0) < 1e-4);
  // Far from the origin too (float precision is coarser there).
  s.begin({10000.0f, -8000.0f});
  s.moveTo({10333.0f, -8444.0f});
  QVERIFY(std::abs(distance(s.brush(), {10333.0f, -8444.0f}) - 30.0) < 1e-3);
}

void StrokeStabilizerTest::dabsAreSpacedAtMostTwoPixels() {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> jump(-300.0f, 300.0f);
  for (float strength : {0.0f, 0.25f, 1.0f}) {
    StrokeStabilizer s(strength);
    s.begin({0.0f, 0.0f});
    Point2 cursor{0.0f, 0.0f};
    for (int i = 0; i < 300; ++i) {
      cursor = {cursor.x + jump(rng), cursor.y + jump(rng)};
      const Point2 before = s.brush();
      const auto dabs = s.moveTo(cursor);
      const double gap = largestGap(before, dabs);
      QVERIFY2(gap <= StrokeStabilizer::kMaxDabSpacingPixels,
               qPrintable(QString("strength %1: dabs %2 px apart").arg(strength).arg(gap)));
      // Fewest dabs that honour the spacing, give or take the rounding margin.
      if (!dabs.empty()) {
        const double travel = distance(before, dabs.back());
        QVERIFY(double(dabs.size()) <= std::ceil(travel / 1.999) + 1.0);
      }
    }
  }
}

void StrokeStabilizerTest::smoothsJitteryInput() {
  // A hand dragging right at 3 px per event with ±8 px of tremor, alternating side each event
  // plus noise: the worst case for an unstabilized stroke.
  std::mt19937 rng(3);
  std::uniform_real_distribution<float> noise(-3.0f, 3.0f);
  std::vector<Point2> input;
  for (int i = 0; i <= 400; ++i)
    input.push_back({3.0f * float(i), (i % 2 ? 8.0f : -8.0f) + noise(rng)});

  StrokeStabilizer s(0.5f); // L = 30 px
  s.begin(input.front());
  std::vector<Point2> output{input.front()};
  for (std::size_t i = 1; i < input.size(); ++i)
    for (const Point2& p : s.moveTo(input[i]))
      output.push_back(p);
  QVERIFY(output.size() > 100);
  // The brush still gets there, 30 px behind.
  QVERIFY(std::abs(distance(s.brush(), input.back()) - 30.0) < 1e-3);

  const double turningIn = totalTurning(input);
  const double turningOut = totalTurning(output);
  const double lateralIn = rmsLateral(input, 60.0f);
  const double lateralOut = rmsLateral(output, 60.0f);
  const QString report = QString("turning %1 → %2 rad, lateral RMS %3 → %4 px")
                             .arg(turningIn)
                             .arg(turningOut)
                             .arg(lateralIn)
                             .arg(lateralOut);
  qInfo("%s", qPrintable(report));
  QVERIFY2(turningOut / turningIn < 0.5, qPrintable(report));
  QVERIFY2(lateralOut / lateralIn < 0.5, qPrintable(report));
}

void StrokeStabilizerTest::finishEndsWhereBrushIs() {
  StrokeStabilizer s(1.0f); // L = 60 px
  s.begin({0.0f, 0.0f});
  s.moveTo({100.0f, 0.0f});
  const Point2 brush = s.brush();
  QVERIFY(s.active());
  QVERIFY(s.finish().empty());
  QVERIFY(!s.active());
  QCOMPARE(s.brush().x, brush.x);
  QCOMPARE(s.brush().y, brush.y);
  // moveTo() without begin() starts the next stroke on the cursor and dabs nothing yet.
  QVERIFY(s.moveTo({500.0f, 500.0f}).empty());
  QVERIFY(s.active());
  QCOMPARE(s.brush().x, 500.0f);
  QCOMPARE(s.brush().y, 500.0f);
}

QTEST_APPLESS_MAIN(StrokeStabilizerTest)
#include "stroke_stabilizer_test.moc"
