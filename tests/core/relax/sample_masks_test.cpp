// Keep-detail's masks (core/src/relax/sample_masks): the samples a relaxation frees, grown from
// what a stroke changed, and the cells its surface check covers. The box dilation grownMask
// uses off the image's border must give the breadth-first search's mask, everywhere it is used.
#include "../../../core/src/relax/sample_masks.h"

#include <QTest>

#include <cstdint>
#include <random>
#include <vector>

using namespace octaclay::core;

namespace {

std::size_t index(int n, int i, int j) {
  return static_cast<std::size_t>(j) * static_cast<std::size_t>(n + 1) +
         static_cast<std::size_t>(i);
}

std::size_t count(const std::vector<std::uint8_t>& mask) {
  std::size_t c = 0;
  for (std::uint8_t m : mask)
    c += m != 0;
  return c;
}

// A stroke's changed samples: `blobs` discs of random radius up to `radius` around random
// centres in [lo, hi]², marked with random non-zero values (only non-zero counts).
std::vector<std::uint8_t> strokeLike(int n, int blobs, int radius, int lo, int hi,
                                     std::mt19937& random) {
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  std::uniform_int_distribution<int> centre(lo, hi), size(0, radius), value(1, 255);
  for (int b = 0; b < blobs; ++b) {
    const int ci = centre(random), cj = centre(random), r = size(random);
    for (int j = cj - r; j <= cj + r; ++j)
      for (int i = ci - r; i <= ci + r; ++i)
        if (i >= 0 && j >= 0 && i <= n && j <= n &&
            (i - ci) * (i - ci) + (j - cj) * (j - cj) <= r * r)
          changed[index(n, i, j)] = static_cast<std::uint8_t>(value(random));
  }
  return changed;
}

} // namespace

class SampleMasksTest : public QObject {
  Q_OBJECT

private slots:
  void oneSampleGrowsIntoItsSquare();
  void dilationEqualsTheSearchOffTheBorder();
  void nearTheBorderTheSearchCrossesTheSeam();
  void cellsNearFreeEqualTheirDefinition();
};

void SampleMasksTest::oneSampleGrowsIntoItsSquare() {
  const int n = 64;
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  changed[index(n, 20, 30)] = 1;
  for (const int margin : {0, 1, 5, 19}) {
    const std::vector<std::uint8_t> grown = detail::grownMask(n, changed, margin);
    QCOMPARE(count(grown), static_cast<std::size_t>((2 * margin + 1) * (2 * margin + 1)));
    QCOMPARE(grown[index(n, 20 - margin, 30 + margin)], std::uint8_t{1});
    QCOMPARE(grown[index(n, 20 + margin + 1, 30)], std::uint8_t{0});
  }
}

void SampleMasksTest::dilationEqualsTheSearchOffTheBorder() {
  std::mt19937 random(5);
  for (const int n : {64, 128, 256})
    for (const int margin : {0, 1, 3, 8, 17})
      for (int trial = 0; trial < 6; ++trial) {
        // Changed samples kept far enough from the border that the grown box stays off it
        // (the fast path), up to exactly one sample from it.
        const int lo = margin + 1 + trial % 2, hi = n - 1 - margin - trial % 2;
        if (hi - lo < 4) continue;
        const int radius = std::min(6, (hi - lo) / 4);
        std::vector<std::uint8_t> changed =
            strokeLike(n, 1 + trial, radius, lo + radius, hi - radius, random);
        const std::vector<std::uint8_t> fast = detail::grownMask(n, changed, margin);
        const std::vector<std::uint8_t> search = detail::grownMaskBySearch(n, changed, margin);
        QVERIFY2(
            fast == search,
            qPrintable(QStringLiteral("N %1, margin %2, trial %3").arg(n).arg(margin).arg(trial)));
        QVERIFY(count(fast) > count(changed) || margin == 0);
      }
}

void SampleMasksTest::nearTheBorderTheSearchCrossesTheSeam() {
  // A changed sample two samples from the left edge, grown by four: the mask reaches the border
  // and goes on across the seam, where a box dilation would stop.
  const int n = 64;
  std::vector<std::uint8_t> changed(static_cast<std::size_t>(n + 1) * (n + 1), 0);
  changed[index(n, 2, 20)] = 1;
  const std::vector<std::uint8_t> grown = detail::grownMask(n, changed, 4);
  QVERIFY(grown == detail::grownMaskBySearch(n, changed, 4));
  QCOMPARE(grown[index(n, 0, 20)], std::uint8_t{1});
  // The left edge folds onto itself about its midpoint (j ↔ n - j): samples past it sit near
  // (0, n - 20) on the other side of the seam.
  QCOMPARE(grown[index(n, 1, n - 20)], std::uint8_t{1});
  QVERIFY(count(grown) > 9 * 9);
}

void SampleMasksTest::cellsNearFreeEqualTheirDefinition() {
  std::mt19937 random(9);
  for (const int n : {16, 64, 128}) {
    // Free samples anywhere, the border and the corners included.
    const std::vector<std::uint8_t> free = strokeLike(n, 5, n / 8, 0, n, random);
    const std::vector<std::uint8_t> cells = detail::cellsNearFree(n, free);
    QCOMPARE(cells.size(), static_cast<std::size_t>(n) * n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        bool near = false;
        for (int dj = -1; dj <= 2; ++dj)
          for (int di = -1; di <= 2; ++di)
            if (i + di >= 0 && j + dj >= 0 && i + di <= n && j + dj <= n)
              near = near || free[index(n, i + di, j + dj)] != 0;
        QCOMPARE(cells[static_cast<std::size_t>(j) * n + i] != 0, near);
      }
  }
}

QTEST_APPLESS_MAIN(SampleMasksTest)
#include "sample_masks_test.moc"
