// The two-level tile bounds: the tiles found near a sphere are exactly those a brute-force scan
// of every sample finds (plus tiles whose box, not samples, touches it), and refresh after an
// edit keeps that true.

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/tile_bounds.h"

#include <QtTest>

#include <algorithm>
#include <random>
#include <set>

using namespace octaclay::core;

namespace {

// Tiles holding a sample (or the first sample past them) within radius of centre.
std::set<int> bruteForce(const GeometryImage& image, const TileBounds& bounds, Vec3f centre,
                         float radius) {
  std::set<int> tiles;
  const int n = image.size(), t = bounds.tilesPerSide();
  for (int ty = 0; ty < t; ++ty)
    for (int tx = 0; tx < t; ++tx) {
      const TexelRect r = bounds.tileRect(tx, ty);
      for (int j = r.y; j <= std::min(r.y + r.height, n); ++j)
        for (int i = r.x; i <= std::min(r.x + r.width, n); ++i)
          if (length(image.at(i, j).xyz() - centre) <= radius) tiles.insert(ty * t + tx);
    }
  return tiles;
}

} // namespace

class TileBoundsTest : public QObject {
  Q_OBJECT

private slots:
  void tilesCoverTheImageExactly();
  void nearSphereFindsEveryReachableTile();
  void refreshFollowsEdits();
  void mergedRectsCoverTheSameTexelsOnce();
  void quartersHoldEverySampleWithinTheSphere();
};

void TileBoundsTest::tilesCoverTheImageExactly() {
  for (int n : {2, 16, 32, 64, 512}) {
    const TileBounds bounds(makeBaseShape(BaseShape::Sphere, n));
    std::vector<int> covered(static_cast<std::size_t>(n + 1) * (n + 1), 0);
    for (int ty = 0; ty < bounds.tilesPerSide(); ++ty)
      for (int tx = 0; tx < bounds.tilesPerSide(); ++tx) {
        const TexelRect r = bounds.tileRect(tx, ty);
        for (int j = r.y; j < r.y + r.height; ++j)
          for (int i = r.x; i < r.x + r.width; ++i)
            ++covered[static_cast<std::size_t>(j) * (n + 1) + i];
      }
    QVERIFY2(std::all_of(covered.begin(), covered.end(), [](int c) { return c == 1; }),
             qPrintable(QString("N = %1").arg(n)));
  }
}

void TileBoundsTest::nearSphereFindsEveryReachableTile() {
  const GeometryImage image = makeBaseShape(BaseShape::Blob, 512);
  const TileBounds bounds(image);
  std::mt19937 random(3);
  std::uniform_int_distribution<int> index(0, 512);
  for (int k = 0; k < 40; ++k) {
    const Vec3f centre = image.at(index(random), index(random)).xyz();
    const float radius = 0.02f + 0.3f * float(k) / 40.0f;
    const std::vector<int> found = bounds.tilesNearSphere(centre, radius);
    const std::set<int> foundSet(found.begin(), found.end());
    for (int t : bruteForce(image, bounds, centre, radius))
      QVERIFY(foundSet.count(t));
    // Boxes are conservative but tight: at most a ring of extra tiles.
    QVERIFY(found.size() <= bruteForce(image, bounds, centre, radius * 1.5f + 0.05f).size());
  }
}

void TileBoundsTest::refreshFollowsEdits() {
  GeometryImage image = makeBaseShape(BaseShape::Sphere, 128);
  TileBounds bounds(image);
  const Vec3f far{5, 0, 0};
  QVERIFY(bounds.tilesNearSphere(far, 0.5f).empty());
  image.at(64, 32) = {5, 0, 0, 0}; // a spike out to x = 5
  bounds.refresh(image, {64, 32, 1, 1});
  const std::vector<int> found = bounds.tilesNearSphere(far, 0.5f);
  // The sample's own tile, and the tiles whose boxes take it as their first sample past them.
  QVERIFY(!found.empty());
  const std::set<int> expected = bruteForce(image, bounds, far, 0.5f);
  QCOMPARE(std::set<int>(found.begin(), found.end()), expected);
  QVERIFY(bounds.diagonal() > 6.0f);
}

void TileBoundsTest::mergedRectsCoverTheSameTexelsOnce() {
  const GeometryImage image = makeBaseShape(BaseShape::Sphere, 256);
  const TileBounds bounds(image);
  const int tiles = bounds.tilesPerSide();
  std::mt19937 random(7);
  for (int round = 0; round < 50; ++round) {
    // A random sphere's tiles, the set a dab touches.
    const Vec4f c = image.texels()[random() % image.texelCount()];
    const float radius = 0.05f + 0.6f * float(random() % 1000) / 1000.0f;
    std::vector<TexelRect> rects;
    for (int t : bounds.tilesNearSphere(c.xyz(), radius))
      rects.push_back(bounds.tileRect(t % tiles, t / tiles));
    const std::vector<TexelRect> merged = mergeRects(rects);
    QVERIFY(merged.size() <= rects.size());
    std::vector<int> before(image.texelCount(), 0), after(image.texelCount(), 0);
    const auto count = [&](const std::vector<TexelRect>& from, std::vector<int>& counts) {
      for (const TexelRect& r : from)
        for (int y = r.y; y < r.y + r.height; ++y)
          for (int x = r.x; x < r.x + r.width; ++x)
            ++counts[static_cast<std::size_t>(y) * image.side() + x];
    };
    count(rects, before);
    count(merged, after);
    QVERIFY(before == after);
    QVERIFY(std::all_of(after.begin(), after.end(), [](int k) { return k <= 1; }));
    if (rects.size() > 8) QVERIFY(merged.size() < rects.size());
  }
}

void TileBoundsTest::quartersHoldEverySampleWithinTheSphere() {
  // A tile's four quarters cover it exactly, at every N (a last tile one sample wider, a tile
  // of three samples).
  for (int n : {2, 4, 16, 64, 512}) {
    const TileBounds bounds(makeBaseShape(BaseShape::Sphere, n));
    for (int ty = 0; ty < bounds.tilesPerSide(); ++ty)
      for (int tx = 0; tx < bounds.tilesPerSide(); ++tx) {
        const TexelRect t = bounds.tileRect(tx, ty);
        std::set<std::pair<int, int>> seen;
        int count = 0;
        for (int q = 0; q < 4; ++q) {
          const TexelRect r = bounds.quarterRect(tx, ty, q);
          for (int j = r.y; j < r.y + r.height; ++j)
            for (int i = r.x; i < r.x + r.width; ++i) {
              seen.insert({i, j});
              ++count;
            }
        }
        QCOMPARE(count, t.width * t.height);
        QCOMPARE(static_cast<int>(seen.size()), t.width * t.height);
        QCOMPARE(seen.begin()->first, t.x);
        QCOMPARE(seen.rbegin()->second, t.y + t.height - 1);
      }
  }
  // Every sample within the radius lies in a quarter found (the pass must reach it), and the
  // quarters hold fewer samples than their whole tiles.
  GeometryImage image = makeBaseShape(BaseShape::Blob, 512);
  TileBounds bounds(image);
  std::mt19937 random(5);
  std::uniform_int_distribution<int> index(0, 512);
  long long quarterSamples = 0, tileSamples = 0;
  for (int k = 0; k < 30; ++k) {
    const Vec3f centre = image.at(index(random), index(random)).xyz();
    const float radius = 0.02f + 0.3f * float(k) / 30.0f;
    const std::vector<TexelRect> rects = bounds.rectsNearSphere(centre, radius);
    std::vector<char> covered(image.texelCount(), 0);
    for (const TexelRect& r : rects)
      for (int j = r.y; j < r.y + r.height; ++j)
        for (int i = r.x; i < r.x + r.width; ++i) {
          QVERIFY(!covered[static_cast<std::size_t>(j) * image.side() + i]); // each once
          covered[static_cast<std::size_t>(j) * image.side() + i] = 1;
          ++quarterSamples;
        }
    for (int j = 0; j < image.side(); ++j)
      for (int i = 0; i < image.side(); ++i)
        if (length(image.at(i, j).xyz() - centre) <= radius)
          QVERIFY2(covered[static_cast<std::size_t>(j) * image.side() + i],
                   qPrintable(QString("sample (%1, %2)").arg(i).arg(j)));
    for (int t : bounds.tilesNearSphere(centre, radius)) {
      const TexelRect r = bounds.tileRect(t % bounds.tilesPerSide(), t / bounds.tilesPerSide());
      tileSamples += static_cast<long long>(r.width) * r.height;
    }
  }
  QVERIFY2(
      quarterSamples < tileSamples * 9 / 10,
      qPrintable(
          QString("%1 samples in quarters, %2 in tiles").arg(quarterSamples).arg(tileSamples)));
  // After an edit, the spike's quarter is found.
  image.at(100, 40) = {5, 0, 0, 0};
  bounds.refresh(image, {100, 40, 1, 1});
  const std::vector<TexelRect> spike = bounds.rectsNearSphere({5, 0, 0}, 0.5f);
  QVERIFY(std::any_of(spike.begin(), spike.end(), [](const TexelRect& r) {
    return r.x <= 100 && 100 < r.x + r.width && r.y <= 40 && 40 < r.y + r.height;
  }));
}

QTEST_APPLESS_MAIN(TileBoundsTest)
#include "tile_bounds_test.moc"
