// Every built-in brush on a torus across its wrap and on a plane to its edge, on square and
// W × H images (a thin ring sampled evenly): the prelude's neighbour reads and the seaming pass
// go through the topology, so the torus's seams stay exact (column W and row H equal column and
// row 0 bit for bit), its mesh closed with Euler characteristic 0, the plane's one boundary loop
// with Euler characteristic 1; a dab on the wrap equals the same dab away from it, and a torus
// stroke's undo and redo restore every bit.

#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/seaming.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/material_catalog.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

// Whether any layer differs at texel (i, j) between two snapshots of an image side texels wide
// and rows high (0: side).
bool changedAt(const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b,
               int side, int i, int j, int rows = 0) {
  if (rows == 0) rows = side;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const std::size_t channels = a[k].size() / (std::size_t(side) * rows);
    for (std::size_t c = 0; c < channels; ++c) {
      const std::size_t at = (std::size_t(j) * side + i) * channels + c;
      if (a[k][at] != b[k][at]) return true;
    }
  }
  return false;
}

// A flat W × H plane image over [-1, 1] × [-H/W, H/W] (square cells).
core::GeometryImage flatSheet(int w, int h) {
  core::GeometryImage image(core::Topology::Plane, w, h);
  for (int j = 0; j <= h; ++j)
    for (int i = 0; i <= w; ++i)
      image.at(i, j) = {2.0f * float(i) / float(w) - 1.0f, (2.0f * float(j) - float(h)) / float(w),
                        0.0f, 0.0f};
  return image;
}

// Whether every layer's column W equals column 0 and row H row 0, bit for bit.
bool torusSeamsExact(const std::vector<std::vector<float>>& layers, int w, int h) {
  const std::size_t side = std::size_t(w) + 1, rows = std::size_t(h) + 1;
  for (const std::vector<float>& l : layers) {
    const std::size_t channels = l.size() / (side * rows);
    for (std::size_t j = 0; j < rows; ++j)
      if (std::memcmp(&l[(j * side + std::size_t(w)) * channels], &l[j * side * channels],
                      channels * sizeof(float)) != 0)
        return false;
    if (std::memcmp(&l[std::size_t(h) * side * channels], l.data(),
                    side * channels * sizeof(float)) != 0)
      return false;
  }
  return true;
}

bool allFinite(const core::GeometryImage& image) {
  for (const core::Vec4f& t : image.texels())
    if (!std::isfinite(t.x) || !std::isfinite(t.y) || !std::isfinite(t.z)) return false;
  return true;
}

} // namespace

class TopologyBrushesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() {
    try {
      context_.emplace(GlContext::createHeadless());
      engine_.emplace();
      MaterialCatalog materials; // the splat brush's default material (brick)
      materials.scan({std::filesystem::path(OCTACLAY_SOURCE_DIR) / "resources/materials"});
      engine_->setMaterials(materials);
      for (const auto& entry : std::filesystem::directory_iterator(kBuiltInBrushes)) {
        const BrushManifest manifest = builtInManifest(entry.path().filename().string());
        engine_->load(manifest, readFile(manifest.shaderPath()));
        manifests_.emplace(manifest.id, manifest);
      }
      QVERIFY(manifests_.size() >= 20);
      BrushManifest uv = builtInManifest("paint"); // as a user may set it: area uv
      uv.id = "paint-uv";
      uv.area = AreaMode::Uv;
      engine_->load(uv, readFile(uv.shaderPath()));
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
  }

  void everyBrushAcrossTheTorusWrap_data() {
    QTest::addColumn<QString>("brush");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("h");
    // At 32 cells around the ring one (0.2) is wider than sphere-add's cap. 128 × 64 and
    // 256 × 128: the thin ring (major 0.7, minor 0.3) with cells about square.
    for (const auto& entry : std::filesystem::directory_iterator(kBuiltInBrushes))
      for (const auto& [n, h] : {std::pair{64, 64}, std::pair{128, 64}, std::pair{256, 128}})
        QTest::addRow("%s %dx%d", entry.path().filename().c_str(), n, h)
            << QString::fromStdString(entry.path().filename().string()) << n << h;
  }
  void everyBrushAcrossTheTorusWrap() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    QFETCH(int, h);
    GpuDocument document(core::makeDocument(core::makeTorus(core::Torus{0.7f, 0.3f}, n, h)));
    const auto before = snapshot(document);
    // From column 0 (= column N) on the outer equator's far side of row 0 = row N: the footprint
    // spans both wraps at once.
    PathStroke stroke;
    stroke.brush = brush.toStdString();
    stroke.path = {{0.0f, 0.0f}, {0.03f, 0.02f}};
    stroke.radius = 0.3f;
    stroke.strength = 0.5f;
    try {
      strokeAlongPath(*engine_, document, manifests_.at(stroke.brush), stroke);
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    const core::GeometryImage& after = document.document().positions;
    QVERIFY(allFinite(after));
    QCOMPARE(core::maxSeamGap(after), 0.0f);
    const auto now = snapshot(document);
    // Every layer seamed: column W is column 0, row H is row 0.
    QVERIFY(torusSeamsExact(now, n, h));
    // Every brush but relax (nothing to even out on an even grid) changed something; where it
    // reached across the wraps is checked dab by dab below.
    if (brush != "relax") QVERIFY(!sameBits(before, now));
    const core::MeshTopology topology = core::analyzeTopology(core::extractMesh(after));
    QVERIFY(topology.closed());
    QVERIFY(topology.manifold());
    QCOMPARE(topology.euler, 0LL);
  }

  // One dab centred on a sample of a wrap of a torus, away from the other: on column 0 at row N/8
  // (mirror i -> N - i, y -> -y) or on row 0 at column N/8 (mirror j -> N - j, z -> -z). The torus
  // and the dab are symmetric under the mirror, so a brush whose neighbour reads go through the
  // torus's wrap changes the samples on both sides of it alike (to float rounding: mirrored
  // samples' angles round apart). Read through the ball's fold instead, column -1 would be
  // column 1 at row N - N/8 and the smooth, inflate and flatten dabs would lose the symmetry.
  void aDabOnBothWrapsIsMirrorSymmetric_data() {
    QTest::addColumn<QString>("brush");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("h");
    QTest::addColumn<bool>("acrossColumns");
    for (const char* id : {"push", "inflate", "smooth", "flatten", "pinch", "crease", "layer",
                           "sphere-add", "sphere-subtract", "paint", "mask", "paint-uv"})
      for (int n : {64, 256})
        for (bool columns : {true, false})
          QTest::addRow("%s N=%d %s", id, n, columns ? "column 0" : "row 0")
              << QString(id) << n << (n == 256 ? 128 : n) << columns;
  }
  void aDabOnBothWrapsIsMirrorSymmetric() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    QFETCH(int, h);
    QFETCH(bool, acrossColumns);
    const core::GeometryImage torus = core::makeTorus(core::Torus{0.7f, 0.3f}, n, h);
    GpuDocument document(core::makeDocument(torus));
    const auto before = snapshot(document);
    const float radius = 0.25f;
    const core::Sample centre = acrossColumns ? core::Sample{0, h / 8} : core::Sample{n / 8, 0};
    Dab dab = dabAt(torus, centre, radius, 0.4f);
    // Central differences: symmetric under the mirror (the triangles' normal is not, every cell
    // being split along its anti-diagonal).
    dab.centreNormal = core::gridNormal(torus, centre);
    try {
      engine_->dab(document, brush.toStdString(), dab);
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    const auto now = snapshot(document);
    QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
    const int side = n + 1;
    // Each layer's change at (i, j), positions mirrored into the (i, j) side's frame.
    const auto change = [&](std::size_t layer, int i, int j, bool flipY, bool flipZ) {
      const std::size_t channels = now[layer].size() / (std::size_t(side) * (h + 1));
      std::array<float, 4> d{};
      for (std::size_t c = 0; c < channels; ++c) {
        const std::size_t at = (std::size_t(j) * side + i) * channels + c;
        d[c] = now[layer][at] - before[layer][at];
      }
      if (layer == 0 && flipY) d[1] = -d[1];
      if (layer == 0 && flipZ) d[2] = -d[2];
      return d;
    };
    float largest = 0, asymmetry = 0;
    int reached = 0; // samples changed on the far side of a wrap (i or j above N/2)
    for (std::size_t layer = 0; layer < now.size(); ++layer)
      for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= n; ++i) {
          const auto d = change(layer, i, j, false, false);
          const auto m = acrossColumns ? change(layer, n - i, j, true, false)
                                       : change(layer, i, h - j, false, true);
          for (int c = 0; c < 4; ++c) {
            largest = std::max(largest, std::abs(d[c]));
            asymmetry = std::max(asymmetry, std::abs(d[c] - m[c]));
          }
          const bool farSide = acrossColumns ? 2 * i > n && i < n : 2 * j > h && j < h;
          if (farSide && d != std::array<float, 4>{}) ++reached;
        }
    qInfo("%s %dx%d: largest change %g, asymmetry %g, %d samples changed past the wraps",
          qPrintable(brush), n, h, double(largest), double(asymmetry), reached);
    QVERIFY(largest > 0.0f);
    QVERIFY(reached > 0);
    QVERIFY2(asymmetry <= 1e-3f * largest,
             qPrintable(QString("asymmetry %1 of %2").arg(asymmetry).arg(largest)));
  }

  void everyBrushToThePlanesEdge_data() {
    QTest::addColumn<QString>("brush");
    QTest::addColumn<QString>("shape");
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("h");
    for (const auto& entry : std::filesystem::directory_iterator(kBuiltInBrushes)) {
      const QString id = QString::fromStdString(entry.path().filename().string());
      for (int n : {32, 128})
        QTest::addRow("%s square N=%d", entry.path().filename().c_str(), n)
            << id << "square" << n << n;
      QTest::addRow("%s disc N=64", entry.path().filename().c_str()) << id << "disc" << 64 << 64;
      QTest::addRow("%s 128x64", entry.path().filename().c_str()) << id << "wide" << 128 << 64;
    }
  }
  void everyBrushToThePlanesEdge() {
    QFETCH(QString, brush);
    QFETCH(QString, shape);
    QFETCH(int, n);
    QFETCH(int, h);
    GpuDocument document(core::makeDocument(
        shape == "wide"
            ? flatSheet(n, h)
            : core::makeSheet(shape == "disc" ? core::Sheet::Disc : core::Sheet::Square, n)));
    const auto before = snapshot(document);
    PathStroke stroke;
    stroke.brush = brush.toStdString();
    stroke.path = {{0.9f, 0.5f}, {1.0f, 0.5f}}; // to the edge at column N
    stroke.radius = 0.3f;
    stroke.strength = 0.5f;
    try {
      strokeAlongPath(*engine_, document, manifests_.at(stroke.brush), stroke);
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    const core::GeometryImage& after = document.document().positions;
    QVERIFY(allFinite(after));
    const auto now = snapshot(document);
    if (brush != "relax" && brush != "smooth" && brush != "flatten" && brush != "scrape")
      QVERIFY2(changedAt(before, now, n + 1, n, h / 2, h + 1), "the edge sample did not change");
    // The opposite edge is out of reach and untouched: no seam pass carried the dab across.
    for (int j = 0; j <= h; ++j)
      QVERIFY(!changedAt(before, now, n + 1, 0, j, h + 1));
    // One boundary loop: a connected manifold with Euler characteristic 1 (2 − 1 loop) whose
    // boundary is the image's rim.
    const core::TriangleMesh mesh = core::extractMesh(after);
    const core::MeshTopology topology = core::analyzeTopology(mesh);
    QCOMPARE(topology.euler, 1LL);
    QCOMPARE(topology.boundaryEdges, std::size_t(2 * (n + h)));
    QVERIFY(topology.manifold());
  }

  // A tile in the corner of a torus: its border samples and their twins across the image (column
  // and row 64 are column and row 0), the four corners together; a plane's: none.
  void seamRunsPairOppositeSides() {
    const std::vector<core::TexelRect> corner{{0, 0, 16, 16}};
    const std::vector<core::TexelRect> runs = seamRuns(corner, 65, core::Topology::Torus);
    const std::vector<core::TexelRect> expected{{0, 0, 16, 1},  {64, 0, 1, 1}, {0, 64, 16, 1},
                                                {64, 64, 1, 1}, {0, 1, 1, 15}, {64, 1, 1, 15}};
    QCOMPARE(runs.size(), expected.size());
    for (std::size_t k = 0; k < runs.size(); ++k)
      QVERIFY(runs[k] == expected[k]);
    QVERIFY(seamRuns(corner, 65, core::Topology::Plane).empty());
    QVERIFY(seamRuns({{16, 16, 16, 16}}, 65, core::Topology::Torus).empty()); // inside
  }

  // The same on a 128 × 64 image: row 64 is row 0, column 128 is column 0.
  void seamRunsPairOppositeSidesOfAWideTorus() {
    const std::vector<core::TexelRect> corner{{0, 0, 16, 16}};
    const std::vector<core::TexelRect> runs = seamRuns(corner, 129, 65, core::Topology::Torus);
    const std::vector<core::TexelRect> expected{{0, 0, 16, 1},   {128, 0, 1, 1}, {0, 64, 16, 1},
                                                {128, 64, 1, 1}, {0, 1, 1, 15},  {128, 1, 1, 15}};
    QCOMPARE(runs.size(), expected.size());
    for (std::size_t k = 0; k < runs.size(); ++k)
      QVERIFY(runs[k] == expected[k]);
    // A tile on the top row only: its samples and their twins on row 0.
    const std::vector<core::TexelRect> top =
        seamRuns({{32, 48, 16, 17}}, 129, 65, core::Topology::Torus);
    QCOMPARE(top.size(), std::size_t(2));
    QVERIFY((top[0] == core::TexelRect{32, 0, 16, 1}));
    QVERIFY((top[1] == core::TexelRect{32, 64, 16, 1}));
  }

  // A torus's pass writes column W and row H itself (no seaming pass after it): given tiles on
  // row 0 and column 0 only, as a caller may pass them, the dab still writes their twins on row H
  // and column W, bit for bit, for a brush written in place (push), one that reads neighbours
  // (smooth), one measured in the image (paint-uv) and a reparameterize one (relax: seamed by
  // the pass of its own).
  void aTorusPassWritesTheTwinsItsTilesMiss_data() {
    QTest::addColumn<QString>("brush");
    for (const char* brush : {"push", "smooth", "paint-uv", "relax", "inflate"})
      QTest::addRow("%s", brush) << QString(brush);
  }
  void aTorusPassWritesTheTwinsItsTilesMiss() {
    QFETCH(QString, brush);
    const int w = 128, h = 64;
    GpuDocument document(core::makeDocument(core::makeTorus(core::Torus{0.7f, 0.3f}, w, h)));
    const auto before = snapshot(document);
    Dab dab;
    dab.centreTexel = {0, 0};
    const core::GeometryImage& image = document.document().positions;
    dab.centre = image.at(dab.centreTexel).xyz();
    dab.centreNormal = core::normalize(dab.centre - core::Vec3f{0.7f, 0.0f, 0.0f});
    dab.radius = 0.15f;
    dab.strength = 0.5f;
    // The first 16 × 16 tile alone, and a strip along row 0: none holds row 64 or column 128.
    const std::vector<core::TexelRect> tiles{{0, 0, 16, 16}, {16, 0, 16, 16}, {112, 0, 16, 16}};
    try {
      engine_->dab(document, brush.toStdString(), dab, tiles);
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    const auto now = snapshot(document);
    QVERIFY(!sameBits(before, now));
    QVERIFY(torusSeamsExact(now, w, h));
    QCOMPARE(core::maxSeamGap(document.document().positions), 0.0f);
    // The twins changed with their samples: row 64 over the tiles' columns, column 128's rows.
    QVERIFY(changedAt(before, now, w + 1, 8, h, h + 1) ==
            changedAt(before, now, w + 1, 8, 0, h + 1));
    QVERIFY(changedAt(before, now, w + 1, w, 4, h + 1) ==
            changedAt(before, now, w + 1, 0, 4, h + 1));
  }

  // A dab centred on column 0 (= column W) of a 128 × 64 torus changes the samples on both sides
  // of the wrap exactly as the same dab half way round the ring (column W/2, away from the wrap)
  // changes the samples there: the torus of revolution is the same surface turned by π about z,
  // so the changes agree after the shift by W/2 and the turn (to float rounding: the turned
  // samples' angles round apart). A brush whose neighbour reads stopped at the wrap, or that
  // measured its footprint without the period, would change the two differently.
  void aDabOnTheWrapEqualsTheDabAwayFromIt_data() {
    QTest::addColumn<QString>("brush");
    for (const char* id : {"push", "inflate", "smooth", "flatten", "pinch", "crease", "layer",
                           "sphere-add", "sphere-subtract", "paint", "mask", "paint-uv", "relax"})
      QTest::addRow("%s", id) << QString(id);
  }
  void aDabOnTheWrapEqualsTheDabAwayFromIt() {
    QFETCH(QString, brush);
    const int n = 128, h = 64, side = n + 1;
    const core::GeometryImage torus = core::makeTorus(core::Torus{0.7f, 0.3f}, n, h);
    const auto changeOf = [&](core::Sample centre) {
      GpuDocument document(core::makeDocument(torus));
      const auto before = snapshot(document);
      Dab dab = dabAt(torus, centre, 0.25f, 0.4f);
      dab.centreNormal = core::gridNormal(torus, centre);
      engine_->dab(document, brush.toStdString(), dab);
      auto now = snapshot(document);
      for (std::size_t k = 0; k < now.size(); ++k)
        for (std::size_t t = 0; t < now[k].size(); ++t)
          now[k][t] -= before[k][t];
      return now;
    };
    std::vector<std::vector<float>> onWrap, away;
    try {
      onWrap = changeOf({0, h / 8});
      away = changeOf({n / 2, h / 8});
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    float largest = 0, difference = 0;
    int left = 0, right = 0; // changed samples just before the wrap (i near W) and after it
    for (std::size_t k = 0; k < onWrap.size(); ++k) {
      const std::size_t channels = onWrap[k].size() / (std::size_t(side) * (h + 1));
      for (int j = 0; j <= h; ++j)
        for (int i = 0; i <= n; ++i) {
          const int shifted = (i + n / 2) % n;
          bool changed = false;
          for (std::size_t c = 0; c < channels; ++c) {
            const float a = onWrap[k][(std::size_t(j) * side + i) * channels + c];
            float b = away[k][(std::size_t(j) * side + shifted) * channels + c];
            if (k == 0 && c < 2) b = -b; // positions: turned by π about z
            largest = std::max(largest, std::abs(a));
            difference = std::max(difference, std::abs(a - b));
            changed = changed || a != 0;
          }
          if (changed && i > n / 2 && i < n) ++left;
          if (changed && i > 0 && i < n / 2) ++right;
        }
    }
    qInfo("%s: largest change %g, difference %g, %d and %d samples changed on either side",
          qPrintable(brush), double(largest), double(difference), left, right);
    QVERIFY(largest > 0.0f);
    QVERIFY(left > 0);
    QVERIFY(right > 0);
    QVERIFY2(difference <= 1e-3f * largest,
             qPrintable(QString("difference %1 of %2").arg(difference).arg(largest)));
  }

  // A stroke across both wraps of a 128 × 64 torus, undone and redone through the edit history:
  // every layer comes back bit for bit, and the seams stay exact each way.
  void undoAndRedoOnAWideTorusAreBitExact_data() {
    QTest::addColumn<QString>("brush");
    for (const char* id : {"inflate", "smooth", "paint", "splat", "relax", "grab", "clay-strips"})
      QTest::addRow("%s", id) << QString(id);
  }
  void undoAndRedoOnAWideTorusAreBitExact() {
    QFETCH(QString, brush);
    const int n = 128, h = 64;
    core::GeometryImage torus = core::makeTorus(core::Torus{0.7f, 0.3f}, n, h);
    // Stretched a little on one side, so relax has something to even out.
    for (int j = 0; j <= h; ++j)
      for (int i = 0; i <= n / 16; ++i)
        torus.at(i, j).z *= 1.0f + 0.5f * float(n / 16 - i) / float(n / 16);
    for (int j = 0; j <= h; ++j)
      torus.at(n, j) = torus.at(0, j);
    GpuDocument document(core::makeDocument(torus));
    const auto before = snapshot(document);
    PathStroke stroke;
    stroke.brush = brush.toStdString();
    stroke.path = {{0.0f, 0.0f}, {0.04f, 0.06f}};
    stroke.radius = 0.3f;
    stroke.strength = 0.5f;
    core::EditHistory history(std::size_t(1) << 30);
    try {
      history.record(strokeAlongPath(*engine_, document, manifests_.at(stroke.brush), stroke).undo);
    } catch (const std::exception& e) {
      QFAIL(e.what());
    }
    const auto after = snapshot(document);
    QVERIFY(!sameBits(before, after));
    QVERIFY(torusSeamsExact(after, n, h));
    QVERIFY(history.undo(undoApplier(document), {}) != nullptr);
    QVERIFY(sameBits(before, snapshot(document)));
    QVERIFY(history.redo(undoApplier(document), {}) != nullptr);
    const auto redone = snapshot(document);
    QVERIFY(sameBits(after, redone));
    QVERIFY(torusSeamsExact(redone, n, h));
  }

private:
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

QTEST_GUILESS_MAIN(TopologyBrushesTest)
#include "topology_brushes_gltest.moc"
