// Every built-in brush on a torus across its wrap and on a plane to its edge: the prelude's
// neighbour reads and the seaming pass go through the topology, so the torus's seams stay exact
// (column and row N equal column and row 0 bit for bit), its mesh closed with Euler
// characteristic 0, the plane's one boundary loop with Euler characteristic 1.

#include "brush_test_support.h"
#include "path_stroke.h"

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
#include <map>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;

namespace {

// Whether any layer differs at texel (i, j) between two snapshots.
bool changedAt(const std::vector<std::vector<float>>& a, const std::vector<std::vector<float>>& b,
               int side, int i, int j) {
  for (std::size_t k = 0; k < a.size(); ++k) {
    const std::size_t channels = a[k].size() / (std::size_t(side) * side);
    for (std::size_t c = 0; c < channels; ++c) {
      const std::size_t at = (std::size_t(j) * side + i) * channels + c;
      if (a[k][at] != b[k][at]) return true;
    }
  }
  return false;
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
    for (const auto& entry : std::filesystem::directory_iterator(kBuiltInBrushes))
      for (int n : {64, 128}) // at 32 a ring cell (0.2) is wider than sphere-add's cap
        QTest::addRow("%s N=%d", entry.path().filename().c_str(), n)
            << QString::fromStdString(entry.path().filename().string()) << n;
  }
  void everyBrushAcrossTheTorusWrap() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    GpuDocument document(core::makeDocument(core::makeTorus(core::Torus{0.7f, 0.3f}, n, n)));
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
    const int side = n + 1;
    const auto now = snapshot(document);
    for (std::size_t k = 0; k < now.size(); ++k) { // every layer seamed: column N is column 0
      const std::size_t channels = now[k].size() / (std::size_t(side) * side);
      for (int j = 0; j <= n; ++j)
        for (std::size_t c = 0; c < channels; ++c)
          QCOMPARE(now[k][(std::size_t(j) * side + n) * channels + c],
                   now[k][(std::size_t(j) * side) * channels + c]);
      for (int i = 0; i <= n; ++i)
        for (std::size_t c = 0; c < channels; ++c)
          QCOMPARE(now[k][(std::size_t(n) * side + i) * channels + c],
                   now[k][std::size_t(i) * channels + c]);
    }
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
    QTest::addColumn<bool>("acrossColumns");
    for (const char* id : {"push", "inflate", "smooth", "flatten", "pinch", "crease", "layer",
                           "sphere-add", "sphere-subtract", "paint", "mask", "paint-uv"})
      for (int n : {64, 256})
        for (bool columns : {true, false})
          QTest::addRow("%s N=%d %s", id, n, columns ? "column 0" : "row 0")
              << QString(id) << n << columns;
  }
  void aDabOnBothWrapsIsMirrorSymmetric() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    QFETCH(bool, acrossColumns);
    const core::GeometryImage torus = core::makeTorus(core::Torus{0.7f, 0.3f}, n, n);
    GpuDocument document(core::makeDocument(torus));
    const auto before = snapshot(document);
    const float radius = 0.25f;
    const core::Sample centre = acrossColumns ? core::Sample{0, n / 8} : core::Sample{n / 8, 0};
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
      const std::size_t channels = now[layer].size() / (std::size_t(side) * side);
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
      for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
          const auto d = change(layer, i, j, false, false);
          const auto m = acrossColumns ? change(layer, n - i, j, true, false)
                                       : change(layer, i, n - j, false, true);
          for (int c = 0; c < 4; ++c) {
            largest = std::max(largest, std::abs(d[c]));
            asymmetry = std::max(asymmetry, std::abs(d[c] - m[c]));
          }
          const bool farSide = acrossColumns ? 2 * i > n && i < n : 2 * j > n && j < n;
          if (farSide && d != std::array<float, 4>{}) ++reached;
        }
    qInfo("%s N=%d: largest change %g, asymmetry %g, %d samples changed past the wraps",
          qPrintable(brush), n, double(largest), double(asymmetry), reached);
    QVERIFY(largest > 0.0f);
    QVERIFY(reached > 0);
    QVERIFY2(asymmetry <= 1e-3f * largest,
             qPrintable(QString("asymmetry %1 of %2").arg(asymmetry).arg(largest)));
  }

  void everyBrushToThePlanesEdge_data() {
    QTest::addColumn<QString>("brush");
    QTest::addColumn<int>("n");
    for (const auto& entry : std::filesystem::directory_iterator(kBuiltInBrushes))
      for (int n : {32, 128})
        QTest::addRow("%s N=%d", entry.path().filename().c_str(), n)
            << QString::fromStdString(entry.path().filename().string()) << n;
  }
  void everyBrushToThePlanesEdge() {
    QFETCH(QString, brush);
    QFETCH(int, n);
    GpuDocument document(core::makeDocument(core::makeSheet(core::Sheet::Square, n)));
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
      QVERIFY2(changedAt(before, now, n + 1, n, n / 2), "the edge sample did not change");
    // The opposite edge is out of reach and untouched: no seam pass carried the dab across.
    for (int j = 0; j <= n; ++j)
      QVERIFY(!changedAt(before, now, n + 1, 0, j));
    const core::TriangleMesh mesh = core::extractMesh(after);
    const core::MeshTopology topology = core::analyzeTopology(mesh);
    QCOMPARE(topology.euler, 1LL);
    QCOMPARE(topology.boundaryEdges, std::size_t(4 * n));
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

  void aTorusWiderThanHighIsRefusedByTheGpu() {
    try {
      GpuDocument wide(core::makeDocument(core::makeTorus({}, 64, 16)));
      QFAIL("a 64x16 torus went onto the GPU");
    } catch (const std::exception& e) {
      QVERIFY2(std::string(e.what()).find("square images only") != std::string::npos, e.what());
    }
  }

private:
  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::map<std::string, BrushManifest> manifests_;
};

QTEST_GUILESS_MAIN(TopologyBrushesTest)
#include "topology_brushes_gltest.moc"
