// Undo/redo store (core/edit_history.h): strokes recorded from tiles read before and after,
// undone and redone bit-exactly, memory that follows the changed texels, and the budget.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/geometry_image.h"

#include <QtTest>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace octaclay::core;

namespace {

constexpr int kT = EditStepRecorder::kTileSize;

// Runs f, which must throw core::Error(InvalidArgument). Returns what went wrong, empty if fine.
QString expectInvalid(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::InvalidArgument)
      return QString("wrong ErrorKind %1: %2").arg(int(e.kind())).arg(e.what());
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  }
  return "did not throw";
}

#define EXPECT_INVALID(call)                                                                       \
  do {                                                                                             \
    const QString why_ = expectInvalid([&] { call; });                                             \
    QVERIFY2(why_.isEmpty(), qPrintable(QString(#call ": ") + why_));                              \
  } while (false)

bool sameBits(const GeometryImage& a, const GeometryImage& b) {
  return a.side() == b.side() &&
         std::memcmp(a.texels().data(), b.texels().data(), a.byteSize()) == 0;
}

// The texels of region r of a position image, row-major, 4 floats each, bits as stored.
std::vector<float> readTile(const GeometryImage& img, TexelRect r) {
  std::vector<float> out(std::size_t(r.width) * std::size_t(r.height) * 4);
  for (int row = 0; row < r.height; ++row)
    std::memcpy(out.data() + std::size_t(row) * std::size_t(r.width) * 4, &img.at(r.x, r.y + row),
                std::size_t(r.width) * sizeof(Vec4f));
  return out;
}

// Number of texels whose 16 bytes differ between a and b (independent of the recorder).
std::size_t changedTexels(const GeometryImage& a, const GeometryImage& b) {
  std::size_t n = 0;
  for (std::size_t k = 0; k < a.texelCount(); ++k)
    n += std::memcmp(&a.texels()[k], &b.texels()[k], sizeof(Vec4f)) != 0;
  return n;
}

GeometryImage randomImage(int n, std::mt19937& rng) {
  GeometryImage img(n);
  std::normal_distribution<float> d(0.0f, 1.0f);
  for (Vec4f& t : img.texels())
    t = {d(rng), d(rng), d(rng), std::abs(d(rng))};
  return img;
}

// Records every tile in `tiles` of image side `side` from the two images.
EditStep recordTiles(const GeometryImage& before, const GeometryImage& after,
                     const std::vector<std::pair<int, int>>& tiles, const std::string& label) {
  EditStepRecorder rec(before.side());
  for (auto [tx, ty] : tiles) {
    const TexelRect r = EditStepRecorder::tileRegion(before.side(), tx, ty);
    rec.addTile(EditLayer::Positions, tx, ty, 4, readTile(before, r), readTile(after, r));
  }
  return rec.finish(label);
}

// A brush-like stroke: moves a random disc of texels (radius in [rMin, rMax], clipped to the
// image; about 10% of the disc is left as it was, the centre always moves) and records the
// tiles the disc's bounding box overlaps plus `extraTiles` random others, in random order.
EditStep randomStroke(GeometryImage& img, std::mt19937& rng, const std::string& label, int rMin,
                      int rMax, int extraTiles) {
  const GeometryImage before = img;
  const int side = img.side();
  std::uniform_int_distribution<int> pos(0, side - 1), rad(rMin, rMax);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::normal_distribution<float> d(0.0f, 0.05f);
  const int cx = pos(rng), cy = pos(rng), r = rad(rng);
  const int x0 = std::max(0, cx - r), x1 = std::min(side - 1, cx + r);
  const int y0 = std::max(0, cy - r), y1 = std::min(side - 1, cy + r);
  for (int j = y0; j <= y1; ++j)
    for (int i = x0; i <= x1; ++i) {
      if ((i - cx) * (i - cx) + (j - cy) * (j - cy) > r * r) continue;
      if (u(rng) < 0.1f && !(i == cx && j == cy)) continue;
      Vec4f& t = img.at(i, j);
      t.x += d(rng) + 1e-3f;
      t.y += d(rng);
      t.z += d(rng);
      if (u(rng) < 0.5f) t.w = u(rng);
    }
  const int tiles = EditStepRecorder::tilesPerSide(side);
  std::vector<std::pair<int, int>> list;
  for (int ty = y0 / kT; ty <= y1 / kT; ++ty)
    for (int tx = x0 / kT; tx <= x1 / kT; ++tx)
      list.emplace_back(tx, ty);
  std::uniform_int_distribution<int> tile(0, tiles - 1);
  for (int e = 0; e < extraTiles; ++e) {
    const std::pair<int, int> t{tile(rng), tile(rng)};
    if (std::find(list.begin(), list.end(), t) == list.end()) list.push_back(t);
  }
  std::shuffle(list.begin(), list.end(), rng);
  return recordTiles(before, img, list, label);
}

} // namespace

class EditHistoryTest : public QObject {
  Q_OBJECT

private slots:
  void tileGeometry();
  void randomStrokesUndoRedo();
  void newStrokeClearsRedo();
  void memoryFollowsChangedTexels();
  void budgetDropsOldest();
  void singleHugeStrokeIsKept();
  void loweredBudgetDropsOldestUndoStepsOnly();
  void dropOldestAndClearRedoOnRequest();
  void nanAndNegativeZeroBitExact();
  void documentLayers();
  void badInputThrows();
  void replacedDocumentsAreStepsOfTheOneHistory();
  void imagesWiderThanHighAreTiledAndUndone();
};

void EditHistoryTest::tileGeometry() {
  QCOMPARE(EditStepRecorder::tilesPerSide(257), 5);
  QCOMPARE(EditStepRecorder::tilesPerSide(1025), 17);
  QCOMPARE(EditStepRecorder::tilesPerSide(64), 1);
  QCOMPARE(EditStepRecorder::tilesPerSide(65), 2);
  QCOMPARE(EditStepRecorder::tileRegion(257, 0, 0), (TexelRect{0, 0, 64, 64}));
  QCOMPARE(EditStepRecorder::tileRegion(257, 3, 1), (TexelRect{192, 64, 64, 64}));
  QCOMPARE(EditStepRecorder::tileRegion(257, 4, 2), (TexelRect{256, 128, 1, 64}));
  QCOMPARE(EditStepRecorder::tileRegion(257, 4, 4), (TexelRect{256, 256, 1, 1}));
  QCOMPARE(EditStepRecorder::tileRegion(3, 0, 0), (TexelRect{0, 0, 3, 3}));
  // Tiles cover the image exactly once.
  for (int side : {3, 65, 129, 257}) {
    std::vector<int> cover(std::size_t(side) * std::size_t(side), 0);
    const int t = EditStepRecorder::tilesPerSide(side);
    for (int ty = 0; ty < t; ++ty)
      for (int tx = 0; tx < t; ++tx) {
        const TexelRect r = EditStepRecorder::tileRegion(side, tx, ty);
        for (int j = r.y; j < r.y + r.height; ++j)
          for (int i = r.x; i < r.x + r.width; ++i)
            ++cover[std::size_t(j) * std::size_t(side) + std::size_t(i)];
      }
    QVERIFY2(std::all_of(cover.begin(), cover.end(), [](int c) { return c == 1; }),
             qPrintable(QString("side %1").arg(side)));
  }
  QCOMPARE(editLayerChannels(EditLayer::Positions), 4);
  QCOMPARE(editLayerChannels(EditLayer::Diffuse), 4);
  QCOMPARE(editLayerChannels(EditLayer::Feature), 3);
  QCOMPARE(editLayerChannels(EditLayer::Mask), 1);
}

void EditHistoryTest::randomStrokesUndoRedo() {
  std::mt19937 rng(20240611);
  GeometryImage img = randomImage(256, rng);
  const GeometryImage start = img;
  EditHistory history;
  std::vector<GeometryImage> snapshots{img}; // state after 0, 10, 20, … strokes
  std::vector<std::size_t> expectedChanged;
  std::size_t bytesSum = 0;
  for (int k = 0; k < 100; ++k) {
    const GeometryImage before = img;
    EditStep s = randomStroke(img, rng, "stroke " + std::to_string(k), 1, 48, 3);
    QCOMPARE(s.changedTexels, changedTexels(before, img));
    QVERIFY(s.changedTexels > 0);
    bytesSum += s.bytes;
    expectedChanged.push_back(s.changedTexels);
    history.record(std::move(s));
    QCOMPARE(history.undoCount(), std::size_t(k + 1));
    QCOMPARE(history.redoCount(), std::size_t(0));
    if ((k + 1) % 10 == 0) snapshots.push_back(img);
  }
  const GeometryImage end = img;
  QCOMPARE(history.bytes(), bytesSum);
  QVERIFY(!sameBits(start, end));

  // Every applier call writes only changed texels: the texels written per step add up to the
  // stroke's changed count.
  std::size_t written = 0;
  const TileApplier write = applierFor(img);
  const TileApplier counting = [&](EditLayer layer, TexelRect r, std::span<const float> texels) {
    written += std::size_t(r.width) * std::size_t(r.height);
    write(layer, r, texels);
  };
  for (int k = 99; k >= 0; --k) {
    written = 0;
    const EditStep* s = history.undo(counting);
    QVERIFY(s);
    QCOMPARE(s->label, "stroke " + std::to_string(k));
    QCOMPARE(written, expectedChanged[std::size_t(k)]);
    if (k % 10 == 0)
      QVERIFY2(sameBits(img, snapshots[std::size_t(k / 10)]),
               qPrintable(QString::fromStdString(s->label)));
  }
  QVERIFY(sameBits(img, start));
  QVERIFY(!history.canUndo());
  QVERIFY(history.undo(counting) == nullptr);
  QVERIFY(sameBits(img, start));
  QCOMPARE(history.redoCount(), std::size_t(100));

  for (int k = 0; k < 100; ++k) {
    written = 0;
    const EditStep* s = history.redo(counting);
    QVERIFY(s);
    QCOMPARE(s->label, "stroke " + std::to_string(k));
    QCOMPARE(written, expectedChanged[std::size_t(k)]);
    if ((k + 1) % 10 == 0)
      QVERIFY2(sameBits(img, snapshots[std::size_t((k + 1) / 10)]),
               qPrintable(QString::fromStdString(s->label)));
  }
  QVERIFY(sameBits(img, end));
  QVERIFY(!history.canRedo());
  QVERIFY(history.redo(counting) == nullptr);
  QCOMPARE(history.undoCount(), std::size_t(100));
  QCOMPARE(history.bytes(), bytesSum);
}

void EditHistoryTest::newStrokeClearsRedo() {
  std::mt19937 rng(7);
  GeometryImage img = randomImage(128, rng);
  EditHistory history;
  std::vector<GeometryImage> states{img};
  std::vector<std::size_t> sizes;
  for (int k = 0; k < 6; ++k) {
    EditStep s = randomStroke(img, rng, "s" + std::to_string(k), 2, 30, 1);
    sizes.push_back(s.bytes);
    history.record(std::move(s));
    states.push_back(img);
  }
  const std::size_t bytesSix = history.bytes();
  const TileApplier apply = applierFor(img);
  for (int k = 0; k < 3; ++k)
    QVERIFY(history.undo(apply));
  QVERIFY(sameBits(img, states[3]));
  QCOMPARE(history.undoCount(), std::size_t(3));
  QCOMPARE(history.redoCount(), std::size_t(3));
  QVERIFY(history.canRedo());
  QCOMPARE(history.nextRedo()->label, std::string("s3"));
  QCOMPARE(history.nextUndo()->label, std::string("s2"));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(img, states[4]));
  QCOMPARE(history.bytes(), bytesSix); // undo/redo move steps, they do not free them

  // A new stroke from state 4 replaces the redo steps (s4, s5).
  EditStep fresh = randomStroke(img, rng, "fresh", 2, 30, 0);
  const std::size_t freshBytes = fresh.bytes;
  history.record(std::move(fresh));
  const GeometryImage afterFresh = img;
  QVERIFY(!history.canRedo());
  QCOMPARE(history.redoCount(), std::size_t(0));
  QCOMPARE(history.undoCount(), std::size_t(5));
  QCOMPARE(history.bytes(), bytesSix - sizes[4] - sizes[5] + freshBytes); // s4, s5 freed
  QVERIFY(history.redo(apply) == nullptr);
  QVERIFY(sameBits(img, afterFresh));
  QCOMPARE(history.undo(apply)->label, std::string("fresh"));
  QVERIFY(sameBits(img, states[4]));
  for (int k = 3; k >= 0; --k)
    QCOMPARE(history.undo(apply)->label, "s" + std::to_string(k));
  QVERIFY(sameBits(img, states[0]));
  QCOMPARE(history.redoCount(), std::size_t(5));
  history.clear();
  QCOMPARE(history.bytes(), std::size_t(0));
  QVERIFY(!history.canUndo() && !history.canRedo());
}

void EditHistoryTest::memoryFollowsChangedTexels() {
  std::mt19937 rng(99);
  const GeometryImage base = randomImage(256, rng);
  const int tiles = EditStepRecorder::tilesPerSide(base.side());
  // Changes `count` texels of tile (1, 1), in row-major order from its corner (or scattered
  // with a stride), and records `recordTiles` (the changed tile always included).
  auto strokeBytes = [&](int count, int stride, bool allTiles) {
    GeometryImage after = base;
    const TexelRect r = EditStepRecorder::tileRegion(base.side(), 1, 1);
    for (int k = 0; k < count; ++k) {
      const int t = (k * stride) % (r.width * r.height);
      after.at(r.x + t % r.width, r.y + t / r.width).x += 0.25f;
    }
    std::vector<std::pair<int, int>> list{{1, 1}};
    if (allTiles)
      for (int ty = 0; ty < tiles; ++ty)
        for (int tx = 0; tx < tiles; ++tx)
          if (tx != 1 || ty != 1) list.emplace_back(tx, ty);
    const EditStep s = recordTiles(base, after, list, "m");
    if (s.changedTexels != std::size_t(count)) qFatal("changed %zu of %d", s.changedTexels, count);
    if (s.bytes != s.computeBytes()) qFatal("stroke bytes not up to date");
    return s.bytes;
  };
  const std::size_t ten = strokeBytes(10, 1, false);
  const std::size_t tenScattered = strokeBytes(10, 397, false);
  const std::size_t tenAllTiles = strokeBytes(10, 1, true);
  const std::size_t hundred = strokeBytes(100, 1, false);
  const std::size_t thousand = strokeBytes(1000, 1, false);
  const std::size_t whole = strokeBytes(kT * kT, 1, false);
  const std::size_t nothing = recordTiles(base, base, {{0, 0}, {1, 1}, {4, 4}}, "none").bytes;
  qInfo("stroke bytes: 0 changed (3 tiles touched) %zu, 10 texels %zu, 10 scattered %zu, "
        "10 texels with all %d tiles touched %zu, 100 %zu, 1000 %zu, whole 64x64 tile %zu",
        nothing, ten, tenScattered, tiles * tiles, tenAllTiles, hundred, thousand, whole);
  QVERIFY2(ten * 10 < whole, qPrintable(QString("%1 vs %2").arg(ten).arg(whole)));
  QVERIFY(tenScattered * 10 < whole);
  // Touched-but-unchanged tiles cost nothing.
  QCOMPARE(tenAllTiles, ten);
  QVERIFY(nothing < ten);
  QVERIFY(ten < hundred && hundred < thousand && thousand < whole);
  // A changed positions texel stores before (16 bytes) and the XOR (16 bytes): the whole tile
  // costs at least that, plus a bounded overhead (runs, structs), not a second copy.
  const std::size_t payload = std::size_t(kT * kT) * 32;
  QVERIFY(whole >= payload);
  QVERIFY2(whole < payload + 1024, qPrintable(QString::number(whole)));
  QVERIFY(thousand < 1000 * 32 + 1024);

  // A typical dab-sized stroke on the whole image, for the report.
  GeometryImage img = base;
  EditHistory history;
  std::size_t texels = 0, bytes = 0;
  for (int k = 0; k < 20; ++k) {
    EditStep s = randomStroke(img, rng, "r", 16, 16, 0);
    texels += s.changedTexels;
    bytes += s.bytes;
    history.record(std::move(s));
  }
  qInfo("20 strokes of radius 16 at N=256: %zu changed texels, %zu bytes (%.1f bytes/texel)",
        texels, bytes, double(bytes) / double(texels));
  QCOMPARE(history.bytes(), bytes);
  QVERIFY(double(bytes) / double(texels) < 40.0);
}

void EditHistoryTest::budgetDropsOldest() {
  std::mt19937 rng(3);
  GeometryImage img = randomImage(128, rng);
  const std::size_t budget = 100u << 10;
  EditHistory history(budget);
  QCOMPARE(history.budget(), budget);
  std::vector<GeometryImage> states{img};
  std::vector<std::size_t> sizes;
  bool dropped = false;
  for (int k = 0; k < 40; ++k) {
    EditStep s = randomStroke(img, rng, "b" + std::to_string(k), 4, 20, 2);
    sizes.push_back(s.bytes);
    QVERIFY(s.bytes <= budget);
    const std::size_t countBefore = history.undoCount();
    history.record(std::move(s));
    states.push_back(img);
    // Expected: the newest strokes whose sizes fit the budget together.
    std::size_t keep = 0, sum = 0;
    for (std::size_t i = sizes.size(); i-- > 0;) {
      if (sum + sizes[i] > budget) break;
      sum += sizes[i];
      ++keep;
    }
    QVERIFY2(history.bytes() <= budget, qPrintable(QString::number(history.bytes())));
    QCOMPARE(history.undoCount(), keep);
    QCOMPARE(history.bytes(), sum);
    if (history.undoCount() <= countBefore) dropped = true;
  }
  QVERIFY2(dropped, "the strokes never exceeded the budget: the test does not test the budget");
  // The steps held are the newest ones and undo to the state before the oldest kept.
  const std::size_t kept = history.undoCount();
  const TileApplier apply = applierFor(img);
  for (std::size_t k = 0; k < kept; ++k)
    QCOMPARE(history.undo(apply)->label, "b" + std::to_string(39 - k));
  QVERIFY(!history.canUndo());
  QVERIFY(sameBits(img, states[40 - kept]));
  QVERIFY(!sameBits(img, states[0]));
  for (std::size_t k = 0; k < kept; ++k)
    QVERIFY(history.redo(apply));
  QVERIFY(sameBits(img, states[40]));
}

// Edit ▸ Preferences lowers the budget: the oldest undo steps go until the rest fit; the redo
// steps and the newest undo step stay, and undo/redo still reach the same states.
void EditHistoryTest::loweredBudgetDropsOldestUndoStepsOnly() {
  std::mt19937 rng(5);
  GeometryImage img = randomImage(128, rng);
  EditHistory history; // 256 MiB: everything fits
  std::vector<GeometryImage> states{img};
  std::vector<std::size_t> sizes;
  for (int k = 0; k < 10; ++k) {
    EditStep s = randomStroke(img, rng, "p" + std::to_string(k), 4, 20, 2);
    sizes.push_back(s.bytes);
    history.record(std::move(s));
    states.push_back(img);
  }
  const TileApplier apply = applierFor(img);
  QVERIFY(history.undo(apply) && history.undo(apply)); // p9 and p8 become redo steps
  const std::size_t redoBytes = sizes[8] + sizes[9];
  // Room for the redo steps and the newest three undo steps (p5, p6, p7).
  const std::size_t budget = redoBytes + sizes[5] + sizes[6] + sizes[7];
  history.setBudget(budget);
  QCOMPARE(history.budget(), budget);
  QCOMPARE(history.undoCount(), std::size_t(3));
  QCOMPARE(history.redoCount(), std::size_t(2));
  QCOMPARE(history.bytes(), budget);
  QCOMPARE(history.nextUndo()->label, std::string("p7"));
  while (history.canUndo())
    history.undo(apply);
  QVERIFY(sameBits(img, states[5]));
  while (history.canRedo())
    history.redo(apply);
  QVERIFY(sameBits(img, states[10]));
  // A budget below one step: the newest undo step stays, alone.
  history.setBudget(1);
  QCOMPARE(history.undoCount(), std::size_t(1));
  QCOMPARE(history.nextUndo()->label, std::string("p9"));
}

// A history of several documents (the modeller's scene) drops a document's oldest step and its
// redo steps itself: the bytes follow, the rest still undo and redo to the same states.
void EditHistoryTest::dropOldestAndClearRedoOnRequest() {
  std::mt19937 rng(11);
  GeometryImage img = randomImage(128, rng);
  EditHistory history;
  std::vector<GeometryImage> states{img};
  std::vector<std::size_t> sizes;
  for (int k = 0; k < 6; ++k) {
    EditStep s = randomStroke(img, rng, "d" + std::to_string(k), 4, 20, 2);
    sizes.push_back(s.bytes);
    history.record(std::move(s));
    states.push_back(img);
  }
  const TileApplier apply = applierFor(img);
  QVERIFY(history.undo(apply) && history.undo(apply)); // d5 and d4 become redo steps
  history.dropOldest();
  history.dropOldest();
  QCOMPARE(history.dropped(), std::size_t(2));
  QCOMPARE(history.undoCount(), std::size_t(2));
  QCOMPARE(history.redoCount(), std::size_t(2));
  QCOMPARE(history.bytes(), sizes[2] + sizes[3] + sizes[4] + sizes[5]);
  QCOMPARE(history.stepAt(0)->label, std::string("d2"));
  history.clearRedo();
  QCOMPARE(history.redoCount(), std::size_t(0));
  QCOMPARE(history.bytes(), sizes[2] + sizes[3]);
  QCOMPARE(history.nextUndo()->label, std::string("d3"));
  while (history.canUndo())
    history.undo(apply);
  QVERIFY(sameBits(img, states[2]));
  // Nothing undoable: nothing to drop, redo steps stay.
  history.dropOldest();
  QCOMPARE(history.redoCount(), std::size_t(2));
  QCOMPARE(history.dropped(), std::size_t(2));
  while (history.canRedo())
    history.redo(apply);
  QVERIFY(sameBits(img, states[4]));
}

void EditHistoryTest::singleHugeStrokeIsKept() {
  std::mt19937 rng(5);
  GeometryImage img = randomImage(128, rng);
  const std::size_t budget = 100u << 10;
  EditHistory history(budget);
  history.record(randomStroke(img, rng, "small0", 4, 8, 0));
  history.record(randomStroke(img, rng, "small1", 4, 8, 0));
  QCOMPARE(history.undoCount(), std::size_t(2));
  const GeometryImage beforeHuge = img;

  // Every texel changes: 129² × 32 bytes, about 5× the budget.
  for (Vec4f& t : img.texels())
    t.y = -t.y - 1.0f;
  std::vector<std::pair<int, int>> all;
  const int tiles = EditStepRecorder::tilesPerSide(img.side());
  for (int ty = 0; ty < tiles; ++ty)
    for (int tx = 0; tx < tiles; ++tx)
      all.emplace_back(tx, ty);
  EditStep huge = recordTiles(beforeHuge, img, all, "huge");
  const std::size_t hugeBytes = huge.bytes;
  qInfo("whole-image stroke at N=128: %zu texels, %zu bytes", huge.changedTexels, hugeBytes);
  QVERIFY(hugeBytes > budget);
  history.record(std::move(huge));
  QCOMPARE(history.undoCount(), std::size_t(1));
  QCOMPARE(history.bytes(), hugeBytes);
  QVERIFY(history.bytes() > budget);
  const GeometryImage afterHuge = img;
  const TileApplier apply = applierFor(img);
  QCOMPARE(history.undo(apply)->label, std::string("huge"));
  QVERIFY(sameBits(img, beforeHuge));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(img, afterHuge));

  // The next small stroke pushes the huge one out.
  history.record(randomStroke(img, rng, "small2", 4, 8, 0));
  QCOMPARE(history.undoCount(), std::size_t(1));
  QVERIFY(history.bytes() <= budget);
  QCOMPARE(history.nextUndo()->label, std::string("small2"));

  // A zero budget keeps exactly the newest stroke.
  EditHistory none(0);
  none.record(randomStroke(img, rng, "z0", 4, 8, 0));
  none.record(randomStroke(img, rng, "z1", 4, 8, 0));
  QCOMPARE(none.undoCount(), std::size_t(1));
  QCOMPARE(none.nextUndo()->label, std::string("z1"));
}

void EditHistoryTest::nanAndNegativeZeroBitExact() {
  // N = 2: one 3×3 tile, 36 floats. Special values on both sides, some changed only in the
  // sign bit or the NaN payload (equal as floats or unordered, different as bits).
  const std::vector<std::uint32_t> beforeBits{
      0x00000000u, 0x80000000u, 0x7f800001u, 0x7fc00000u, 0x7fd23456u, 0xffc00001u,
      0x7f800000u, 0xff800000u, 0x00000001u, 0x807fffffu, 0x3f800000u, 0xbf800000u,
      0x7fa00000u, 0x12345678u, 0x00000000u, 0x80000000u, 0x7fc00000u, 0xffffffffu};
  std::vector<std::uint32_t> b(36), a(36);
  for (std::size_t k = 0; k < 36; ++k)
    b[k] = beforeBits[k % beforeBits.size()];
  a = b;
  a[0] = 0x80000000u;  // +0 → -0
  a[1] = 0x00000000u;  // -0 → +0
  a[2] = 0x7f800002u;  // sNaN payload
  a[4] = 0x7fd23457u;  // qNaN payload
  a[5] = 0x7fc00001u;  // NaN sign
  a[9] = 0x7f800001u;  // denormal → sNaN
  a[13] = 0xffc00000u; // number → NaN
  a[35] = 0x80000000u; // last texel, last channel
  std::vector<float> before(36), after(36);
  std::memcpy(before.data(), b.data(), 36 * 4);
  std::memcpy(after.data(), a.data(), 36 * 4);

  EditStepRecorder rec(3);
  rec.addTile(EditLayer::Positions, 0, 0, 4, before, after);
  EditStep s = rec.finish("special");
  QCOMPARE(s.tiles.size(), std::size_t(1));
  // Texels 0..3 changed (floats 0-2, 4-5, 9, 13), 4..7 unchanged, 8 changed (float 35):
  // runs (skip 0, 4 changed) (skip 4, 1 changed).
  QCOMPARE(s.changedTexels, std::size_t(5));
  QCOMPARE(s.tiles[0].runs, (std::vector<std::uint32_t>{0, 4, 4, 1}));

  // patch(): from one side to the other through the compressed form.
  std::vector<float> buf = after;
  s.tiles[0].patch(TileState::Before, buf);
  QVERIFY(std::memcmp(buf.data(), before.data(), 36 * 4) == 0);
  s.tiles[0].patch(TileState::After, buf);
  QVERIFY(std::memcmp(buf.data(), after.data(), 36 * 4) == 0);

  // undo()/redo() through an applier into the image.
  GeometryImage img(2);
  std::memcpy(static_cast<void*>(img.texels().data()), after.data(), 36 * 4);
  EditHistory history;
  history.record(std::move(s));
  QVERIFY(history.undo(applierFor(img)));
  QVERIFY(std::memcmp(img.texels().data(), before.data(), 36 * 4) == 0);
  QVERIFY(history.redo(applierFor(img)));
  QVERIFY(std::memcmp(img.texels().data(), after.data(), 36 * 4) == 0);
}

void EditHistoryTest::documentLayers() {
  std::mt19937 rng(11);
  Document doc = makeDocument(randomImage(64, rng)); // side 65: tiles 2×2, last 1 wide
  const int side = doc.positions.side();
  QVERIFY(doc.diffuse.uniform() && doc.mask.uniform());
  const std::vector<float> diffuseFill(doc.diffuse.fill.begin(), doc.diffuse.fill.begin() + 4);

  // Paint diffuse in tile (1, 0) (1 × 64 texels) and the mask in tile (0, 0) (64 × 64).
  const TexelRect rd = EditStepRecorder::tileRegion(side, 1, 0);
  const TexelRect rm = EditStepRecorder::tileRegion(side, 0, 0);
  QCOMPARE(rd, (TexelRect{64, 0, 1, 64}));
  std::vector<float> dBefore, dAfter, mBefore(std::size_t(rm.width * rm.height), 1.0f), mAfter;
  for (int k = 0; k < rd.width * rd.height; ++k)
    dBefore.insert(dBefore.end(), diffuseFill.begin(), diffuseFill.end());
  dAfter = dBefore;
  for (std::size_t k = 0; k < dAfter.size(); k += 8)
    dAfter[k] = 0.1f;
  mAfter = mBefore;
  mAfter[5] = 0.0f;
  mAfter[100] = 0.5f;
  EditStepRecorder rec(side);
  rec.addTile(EditLayer::Diffuse, 1, 0, 4, dBefore, dAfter);
  rec.addTile(EditLayer::Mask, 0, 0, 1, mBefore, mAfter);
  rec.addTile(EditLayer::Feature, 0, 0, 3, std::vector<float>(std::size_t(64 * 64 * 3), 0.0f),
              std::vector<float>(std::size_t(64 * 64 * 3), 0.0f));
  EditStep s = rec.finish("paint");
  QCOMPARE(s.tiles.size(), std::size_t(2)); // the unchanged feature tile is not stored
  QCOMPARE(s.changedTexels, std::size_t(32 + 2));

  // The document starts in the "before" state: redo paints, undo restores the fills.
  EditHistory history;
  history.record(std::move(s));
  QVERIFY(history.undo(applierFor(doc)));
  QVERIFY(history.redo(applierFor(doc)));
  QVERIFY(!doc.diffuse.uniform());
  QVERIFY(doc.hasMask);
  QCOMPARE(doc.diffuse.texels.size(), std::size_t(side * side * 4));
  QCOMPARE(doc.mask.texels.size(), std::size_t(side * side));
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t t = std::size_t(j * side + i);
      for (std::size_t c = 0; c < 4; ++c) {
        float expected = diffuseFill[c];
        if (i == 64 && j < 64) expected = dAfter[std::size_t(j) * 4 + c];
        QCOMPARE(doc.diffuse.texels[t * 4 + c], expected);
      }
      float m = 1.0f;
      if (i < 64 && j < 64) m = mAfter[std::size_t(j * 64 + i)];
      QCOMPARE(doc.mask.texels[t], m);
    }
  QVERIFY(history.undo(applierFor(doc)));
  for (std::size_t t = 0; t < std::size_t(side * side); ++t) {
    QCOMPARE(doc.mask.texels[t], 1.0f);
    QCOMPARE(doc.diffuse.texels[t * 4], diffuseFill[0]);
  }
}

void EditHistoryTest::badInputThrows() {
  const int side = 257;
  const TexelRect r = EditStepRecorder::tileRegion(side, 0, 0);
  const std::vector<float> tile(std::size_t(r.width * r.height * 4), 1.0f);
  std::vector<float> changed = tile;
  changed[0] = 2.0f;
  const std::vector<float> shortTile(tile.size() - 1, 1.0f), longTile(tile.size() + 4, 1.0f);
  const std::vector<float> lastTile(4, 1.0f); // tile (4, 4) is 1×1

  EXPECT_INVALID(EditStepRecorder(1));
  EXPECT_INVALID(EditStepRecorder(-5));
  EXPECT_INVALID(EditStepRecorder::tileRegion(side, 5, 0));
  EditStepRecorder rec(side);
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 0, 0, 4, shortTile, tile));
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 0, 0, 4, tile, longTile));
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 0, 0, 3, tile, tile)); // positions are 4
  EXPECT_INVALID(rec.addTile(EditLayer::Mask, 0, 0, 4, tile, tile));
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 5, 0, 4, tile, tile));
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 0, -1, 4, tile, tile));
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 4, 4, 4, tile, tile)); // last tile is 1×1
  EXPECT_INVALID(rec.addTile(static_cast<EditLayer>(7), 0, 0, 4, tile, tile));
  rec.addTile(EditLayer::Positions, 4, 4, 4, lastTile, lastTile);
  rec.addTile(EditLayer::Positions, 0, 0, 4, tile, changed);
  EXPECT_INVALID(rec.addTile(EditLayer::Positions, 0, 0, 4, tile, changed)); // twice
  rec.addTile(EditLayer::Diffuse, 0, 0, 4, tile, changed); // same tile, other layer: fine
  EditStep s = rec.finish("ok");
  QCOMPARE(s.tiles.size(), std::size_t(2));
  QCOMPARE(s.changedTexels, std::size_t(2));

  // After finish() the recorder starts over: the same tile may be added again.
  rec.addTile(EditLayer::Positions, 0, 0, 4, tile, changed);
  QCOMPARE(rec.finish("again").tiles.size(), std::size_t(1));

  EditHistory history;
  history.record(s);
  QCOMPARE(history.undoCount(), std::size_t(1));
  // Another image size in the same history.
  EditStepRecorder small(65);
  const TexelRect rs = EditStepRecorder::tileRegion(65, 0, 0);
  std::vector<float> a(std::size_t(rs.width * rs.height * 4), 0.0f), b = a;
  b[3] = 1.0f;
  small.addTile(EditLayer::Positions, 0, 0, 4, a, b);
  EXPECT_INVALID(history.record(small.finish("other size")));
  // Strokes tampered with by hand.
  EditStep bad = s;
  bad.tiles[0].runs.back() += 1;
  EXPECT_INVALID(history.record(bad));
  bad = s;
  bad.tiles[0].tileX = 9;
  EXPECT_INVALID(history.record(bad));
  bad = s;
  bad.tiles[0].region.width = 63;
  EXPECT_INVALID(history.record(bad));
  QCOMPARE(history.undoCount(), std::size_t(1));
  QCOMPARE(history.redoCount(), std::size_t(0));
  // An empty stroke is ignored and does not clear the redo steps.
  GeometryImage img(256);
  TileApplier paint = [](EditLayer, TexelRect, std::span<const float>) {};
  QVERIFY(history.undo(paint));
  history.record(EditStepRecorder(side).finish("empty"));
  QCOMPARE(history.redoCount(), std::size_t(1));

  // The position-image applier rejects other layers and regions outside the image; the
  // history is unchanged when the applier throws.
  const TileApplier apply = applierFor(img);
  EXPECT_INVALID(history.redo(apply)); // the stroke also holds a diffuse tile
  QCOMPARE(history.redoCount(), std::size_t(1));
  EXPECT_INVALID(apply(EditLayer::Positions, TexelRect{250, 0, 8, 1}, std::vector<float>(32)));
  EXPECT_INVALID(apply(EditLayer::Positions, TexelRect{0, 0, 2, 1}, std::vector<float>(4)));
  EXPECT_INVALID(apply(EditLayer::Positions, TexelRect{-1, 0, 1, 1}, std::vector<float>(4)));
  std::vector<float> wrong(5);
  EXPECT_INVALID(s.tiles[0].patch(TileState::Before, wrong));
  GeometryImage tiny(64); // side 65: a 257 stroke's tiles fall outside it
  EditHistory h2;
  EditStepRecorder far(side);
  std::vector<float> fb(std::size_t(64 * 64 * 4), 0.0f), fa = fb;
  fa[0] = 1.0f;
  far.addTile(EditLayer::Positions, 3, 3, 4, fb, fa);
  h2.record(far.finish("far"));
  EXPECT_INVALID(h2.undo(applierFor(tiny)));
  QCOMPARE(h2.undoCount(), std::size_t(1));
}

// Issue 31: one history. A step that replaced the document (Remesh, Resolution, Import: N may
// change) sits among the strokes; undo and redo hand its documents to the replacer, strokes of
// either size are checked against the document at the cursor, and position() names every state.
void EditHistoryTest::replacedDocumentsAreStepsOfTheOneHistory() {
  std::mt19937 rng(5);
  GeometryImage shown = randomImage(32, rng);
  GeometryImage original = shown;
  EditHistory history;
  QCOMPARE(history.position(), std::uint64_t(0));
  history.record(randomStroke(shown, rng, "push", 2, 6, 0)); // on the N 32 document
  const GeometryImage stroked = shown;
  const std::uint64_t afterStroke = history.position();
  QVERIFY(afterStroke != 0);

  EditStep replace;
  replace.label = "Resolution 32 → 64";
  replace.replacedBefore = std::make_shared<const Document>(makeDocument(shown));
  replace.replacedAfter = std::make_shared<const Document>(makeDocument(randomImage(64, rng)));
  history.record(std::move(replace));
  QCOMPARE(history.undoCount(), std::size_t(2));
  shown = history.nextUndo()->replacedAfter->positions;
  // A stroke for the N 64 document is accepted now, one for N 32 refused.
  history.record(randomStroke(shown, rng, "crease", 2, 6, 0));
  GeometryImage small = stroked;
  EXPECT_INVALID(history.record(randomStroke(small, rng, "x", 2, 6, 0)));

  const auto replacer = [&](const Document& d) { shown = d.positions; };
  QVERIFY(history.undo(applierFor(shown), replacer)); // the crease
  QVERIFY(history.undo(applierFor(shown), replacer)); // the resolution: back to N 32
  QVERIFY(sameBits(shown, stroked));
  QCOMPARE(history.position(), afterStroke);
  QVERIFY(history.undo(applierFor(shown), replacer));
  QVERIFY(sameBits(shown, original));
  QCOMPARE(history.position(), std::uint64_t(0));
  // Without a replacer the step is refused and the history stays where it was.
  QVERIFY(history.redo(applierFor(shown), replacer));
  EXPECT_INVALID(history.redo(applierFor(shown)));
  QCOMPARE(history.position(), afterStroke);
  QVERIFY(history.redo(applierFor(shown), replacer));
  QCOMPARE(shown.size(), 64);
  QVERIFY(history.redo(applierFor(shown), replacer));
  QVERIFY(!history.canRedo());
  // The two documents count against the budget: a budget below them drops the older steps, and
  // the state before the oldest kept is no longer reachable.
  history.setBudget(history.nextUndo()->bytes + 1);
  QVERIFY(history.dropped() > 0);
  while (history.canUndo())
    history.undo(applierFor(shown), replacer);
  QCOMPARE(history.position(), EditHistory::kUnreachable);
}

// A torus or plane image W × H (here 256 × 64 cells: 257 × 65 texels): tiles cover its rows, not
// its side, and a stroke over its last row undoes and redoes bit for bit.
void EditHistoryTest::imagesWiderThanHighAreTiledAndUndone() {
  QCOMPARE(EditStepRecorder::tileRegion(257, 65, 4, 1), (TexelRect{256, 64, 1, 1}));
  QCOMPARE(EditStepRecorder::tileRegion(257, 65, 2, 0), (TexelRect{128, 0, 64, 64}));
  EXPECT_INVALID(EditStepRecorder::tileRegion(257, 65, 0, 2)); // past the last row of tiles
  GeometryImage before(Topology::Torus, 256, 64);
  std::mt19937 rng(33);
  std::normal_distribution<float> d(0.0f, 1.0f);
  for (Vec4f& t : before.texels())
    t = {d(rng), d(rng), d(rng), 0.0f};
  GeometryImage after = before;
  for (int i = 100; i <= 256; ++i)
    after.at(i, 64).z += 1.0f; // the last row, to the last column
  EditStepRecorder recorder(257, 65);
  for (int tx = 1; tx < 5; ++tx) {
    const TexelRect r = EditStepRecorder::tileRegion(257, 65, tx, 1);
    recorder.addTile(EditLayer::Positions, tx, 1, 4, readTile(before, r), readTile(after, r));
  }
  EditStep step = recorder.finish("wide");
  QCOMPARE(step.imageSide, 257);
  QCOMPARE(step.imageRows, 65);
  QCOMPARE(step.changedTexels, std::size_t(157));
  EditHistory history(std::size_t(1) << 24);
  history.record(std::move(step));
  GeometryImage image = after;
  const TileApplier apply = applierFor(image);
  QVERIFY(history.undo(apply));
  QVERIFY(sameBits(image, before));
  QVERIFY(history.redo(apply));
  QVERIFY(sameBits(image, after));
}

QTEST_APPLESS_MAIN(EditHistoryTest)
#include "edit_history_test.moc"
