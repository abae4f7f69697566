// recordDifference and combineSteps on every topology and shape of image: a ball, tori wider
// and taller than they are around, and a tall plane. Changes in the far corners of the positions
// and a painted layer are recorded (tiles of the image's own W+1 columns and H+1 rows, none
// outside it), and undoing or redoing the step, or two combined, gives the documents back bit
// for bit. (A torus's rows used to be counted as its columns: a 128 × 16 torus read past its
// texels, a 16 × 128 one lost the changes below its 17th row.)

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/edit_steps.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <QtTest>

#include <cstring>
#include <random>

using namespace octaclay::core;

namespace {

Document shape(const QString& name) {
  if (name == "ball 64") return makeDocument(makeBaseShape(BaseShape::Sphere, 64));
  if (name == "torus 128x16") return makeDocument(makeTorus({0.7f, 0.1f}, 128, 16));
  if (name == "torus 16x128") return makeDocument(makeTorus({0.7f, 0.3f}, 16, 128));
  GeometryImage tall(Topology::Plane, 32, 128);
  for (int j = 0; j <= 128; ++j)
    for (int i = 0; i <= 32; ++i)
      tall.at(i, j) = {float(i) / 32, float(j) / 32, 0, 0};
  return makeDocument(std::move(tall));
}

// Moves samples around the image's four corners and its middle, and paints them.
Document changed(const Document& before, unsigned seed) {
  Document after = before;
  const int w = after.positions.width(), h = after.positions.height();
  after.diffuse.texels.assign(std::size_t(w + 1) * std::size_t(h + 1) * 4, 0.5f);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> move(-0.01f, 0.01f);
  for (const auto& [ci, cj] : {std::pair{0, 0}, {w, 0}, {0, h}, {w, h}, {w / 2, h / 2}})
    for (int dj = -2; dj <= 2; ++dj)
      for (int di = -2; di <= 2; ++di) {
        const int i = std::clamp(ci + di, 0, w), j = std::clamp(cj + dj, 0, h);
        after.positions.at(i, j).x += move(random);
        after.diffuse.texels[(std::size_t(j) * std::size_t(w + 1) + std::size_t(i)) * 4] =
            float(seed % 7) / 7;
      }
  return after;
}

bool sameBits(const Document& a, const Document& b) {
  return a.positions.texels().size() == b.positions.texels().size() &&
         std::memcmp(a.positions.texels().data(), b.positions.texels().data(),
                     a.positions.byteSize()) == 0 &&
         a.diffuse.texels == b.diffuse.texels;
}

void applyStep(Document& doc, const EditStep& step, TileState state) {
  const TileApplier apply = applierFor(doc);
  for (const TileChange& t : step.tiles)
    t.apply(state, apply);
}

} // namespace

class EditStepsTest : public QObject {
  Q_OBJECT

private slots:
  void differenceUndoesAndRedoesOnEveryImage_data() {
    QTest::addColumn<QString>("shape");
    for (const char* s : {"ball 64", "torus 128x16", "torus 16x128", "plane 32x128"})
      QTest::newRow(s) << s;
  }

  void differenceUndoesAndRedoesOnEveryImage() {
    QFETCH(QString, shape);
    Document before = ::shape(shape);
    before.diffuse.texels.assign(
        std::size_t(before.positions.side()) * std::size_t(before.positions.rows()) * 4, 0.8f);
    const Document middle = changed(before, 1), after = changed(middle, 2);
    const EditStep first = recordDifference(before, middle, "first");
    QCOMPARE(first.imageSide, before.positions.side());
    // Every corner's tile is recorded, in both layers, and none lies outside the image.
    const int lastX = (before.positions.side() - 1) / EditStepRecorder::kTileSize,
              lastY = (before.positions.rows() - 1) / EditStepRecorder::kTileSize;
    bool farCorner = false;
    for (const TileChange& t : first.tiles) {
      QVERIFY(t.region.x + t.region.width <= before.positions.side());
      QVERIFY(t.region.y + t.region.height <= before.positions.rows());
      farCorner = farCorner || (t.tileX == lastX && t.tileY == lastY);
    }
    QVERIFY2(farCorner, "the change at sample (W, H) was not recorded");

    Document doc = middle;
    applyStep(doc, first, TileState::Before);
    QVERIFY(sameBits(doc, before));
    applyStep(doc, first, TileState::After);
    QVERIFY(sameBits(doc, middle));

    const EditStep second = recordDifference(middle, after, "second");
    const EditStep both = combineSteps(first, second, after, "both");
    doc = after;
    applyStep(doc, both, TileState::Before);
    QVERIFY(sameBits(doc, before));
    applyStep(doc, both, TileState::After);
    QVERIFY(sameBits(doc, after));

    // The history takes the steps (it checks each tile against the image) and undoes them.
    EditHistory history;
    history.record(recordDifference(before, after, "all"));
    doc = after;
    QVERIFY(history.undo(applierFor(doc)) != nullptr);
    QVERIFY(sameBits(doc, before));
  }
};

QTEST_APPLESS_MAIN(EditStepsTest)
#include "edit_steps_test.moc"
