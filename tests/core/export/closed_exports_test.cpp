// Every export arrives whole: each file the exports write (textured OBJ, GLB, PLY, STL, OFF and
// plain OBJ at full resolution and at a level, the LOD's OBJ and GLB) is read back by its
// positions alone, identical positions welded as a tool without our seams would, and is a
// closed, consistently oriented surface with Euler characteristic 2. The GLBs, read with
// tinygltf, carry their maps: base colour (the paint) and, for the LOD, normalTexture.

#include "export_readback.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <QTemporaryDir>
#include <QtTest>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;
using namespace export_readback;

namespace {

// Red grows to the right, green downwards (so a texture coordinate's colour can be checked),
// blue in stripes: a map that dropped the paint (uniform) shows.
Document paintedDocument(int n) {
  Document doc = makeDocument(makeBaseShape(BaseShape::Blob, n));
  const std::size_t side = std::size_t(n) + 1;
  doc.diffuse.texels.assign(side * side * 4, 1.0f);
  for (std::size_t t = 0; t < side * side; ++t) {
    doc.diffuse.texels[t * 4 + 0] = float(t % side) / float(n);
    doc.diffuse.texels[t * 4 + 1] = float(t / side) / float(n);
    doc.diffuse.texels[t * 4 + 2] = (t % side) * 4 / side % 2 == 0 ? 0.9f : 0.1f;
  }
  return doc;
}

// Empty when the welded surface is closed, manifold, oriented and of Euler characteristic 2.
QString wholeSurfaceProblem(const TriangleMesh& read) {
  if (read.triangles.empty()) return "no triangles";
  const TriangleMesh welded = weldByPosition(read);
  const MeshTopology topo = analyzeTopology(welded);
  if (topo.boundaryEdges || topo.nonManifoldEdges || topo.euler != 2 || topo.unusedVertices)
    return QString("%1 vertices (%2 unused), %3 boundary and %4 non-manifold edges, Euler %5")
        .arg(topo.vertices)
        .arg(topo.unusedVertices)
        .arg(topo.boundaryEdges)
        .arg(topo.nonManifoldEdges)
        .arg(topo.euler);
  if (!(signedVolume(welded) > 0)) return "turned inside out";
  return {};
}

} // namespace

class ClosedExportsTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void fullResolutionExportsReadBackClosed_data();
  void fullResolutionExportsReadBackClosed();
  void objWritesEachPositionOnce();
  void lodExportsReadBackClosedWithTheirMaps_data();
  void lodExportsReadBackClosedWithTheirMaps();

private:
  fs::path file(const QString& name) const { return fs::path(dir_.filePath(name).toStdString()); }
  QTemporaryDir dir_;
};

void ClosedExportsTest::fullResolutionExportsReadBackClosed_data() {
  QTest::addColumn<QString>("format");
  QTest::addColumn<int>("step");
  for (const char* format : {"textured.obj", "glb", "plain.obj", "ply", "stl", "off"})
    for (int step : {1, 4})
      QTest::newRow(qPrintable(QString("%1 step %2").arg(format).arg(step))) << format << step;
}

void ClosedExportsTest::fullResolutionExportsReadBackClosed() {
  QFETCH(QString, format);
  QFETCH(int, step);
  const int n = 32, m = n / step;
  const Document doc = paintedDocument(n);
  const fs::path path = file(QString("full-%1.%2").arg(step).arg(format));
  TriangleMesh read;
  if (format == "textured.obj") {
    writeTexturedObj(doc, step, path);
    read = readObjPositions(path);
  } else if (format == "glb") {
    writeGlb(doc, step, path);
    const tinygltf::Model model = readGlb(path);
    read = glbPositions(model);
    const tinygltf::Image* base = textureImage(model, materialTexture(model, false));
    QVERIFY2(base && base->width == n + 1, "no base colour texture");
    QVERIFY(colourCount(*base) >= 2); // the stripes
  } else {
    writeMesh(extractMesh(doc.positions, step), path);
    read = format == "plain.obj" ? readObjPositions(path) : readMesh(path);
  }
  const QString problem = wholeSurfaceProblem(read);
  QVERIFY2(problem.isEmpty(), qPrintable(format + ": " + problem));
  const std::size_t vertices = std::size_t(m) * std::size_t(m) + 2;
  QCOMPARE(weldByPosition(read).positions.size(), vertices);
  // Every indexed format but glTF (one texture coordinate per vertex) holds each position once,
  // so it is closed even for a reader that welds nothing (Blender's OBJ importer).
  if (format != "glb") QCOMPARE(read.positions.size(), vertices);
  QCOMPARE(read.triangles.size(), 2 * std::size_t(m) * std::size_t(m));
}

void ClosedExportsTest::objWritesEachPositionOnce() {
  // The figures: at N = 16 the OBJ has the surface's 258 vertices, not 289 samples, and
  // the seams split only the 289 texture coordinates.
  const fs::path path = file("sixteen.obj");
  writeTexturedObj(paintedDocument(16), 1, path);
  std::ifstream in(path);
  std::string line;
  int v = 0, vt = 0, vn = 0;
  while (std::getline(in, line)) {
    v += line.rfind("v ", 0) == 0;
    vt += line.rfind("vt ", 0) == 0;
    vn += line.rfind("vn ", 0) == 0;
  }
  QCOMPARE(v, 16 * 16 + 2);
  QCOMPARE(vn, 16 * 16 + 2);
  QCOMPARE(vt, 17 * 17);
  QVERIFY(readObjPositions(path).positions.size() ==
          weldByPosition(readObjPositions(path)).positions.size());
}

void ClosedExportsTest::lodExportsReadBackClosedWithTheirMaps_data() {
  QTest::addColumn<QString>("extension");
  QTest::addColumn<bool>("painted");
  QTest::newRow("obj painted") << "obj" << true;
  QTest::newRow("glb painted") << "glb" << true;
  QTest::newRow("obj") << "obj" << false;
  QTest::newRow("glb") << "glb" << false;
}

void ClosedExportsTest::lodExportsReadBackClosedWithTheirMaps() {
  QFETCH(QString, extension);
  QFETCH(bool, painted);
  const int n = 64;
  Document doc = paintedDocument(n);
  computeSaliency(doc.positions);
  LodOptions options;
  options.targetTriangles = 600;
  const LodMesh lod = generateLod(doc.positions, options);
  const NormalMap map = bakeNormalMap(doc.positions, lod, NormalMapSpace::Tangent, n);
  const fs::path path =
      file(QString("lod-%1.%2").arg(painted ? "painted" : "plain").arg(extension));
  const std::vector<fs::path> files =
      painted ? writeLodMesh(lod, map, doc, path) : writeLodMesh(lod, map, path);
  for (const fs::path& f : files)
    QVERIFY2(fs::is_regular_file(f), f.string().c_str());

  TriangleMesh read;
  if (extension == "obj") {
    read = readObjPositions(path);
    QCOMPARE(read.positions.size(), lod.mesh.positions.size()); // each position once
    QCOMPARE(files.size(), std::size_t(painted ? 6 : 3));
    std::ifstream mtl(files[1]);
    const std::string text((std::istreambuf_iterator<char>(mtl)), {});
    QVERIFY2(text.find("map_Bump " + files[2].filename().string()) != std::string::npos,
             text.c_str());
    QCOMPARE(text.find("map_Kd ") != std::string::npos, painted);
    if (painted)
      QVERIFY2(text.find("map_Kd " + files[3].filename().string()) != std::string::npos,
               text.c_str());
  } else {
    QCOMPARE(files.size(), std::size_t(1));
    const tinygltf::Model model = readGlb(path);
    read = glbPositions(model);
    const tinygltf::Image* normal = textureImage(model, materialTexture(model, true));
    QVERIFY2(normal && normal->width == n, "no normalTexture");
    const tinygltf::Image* base = textureImage(model, materialTexture(model, false));
    QCOMPARE(base != nullptr, painted);
    if (painted) {
      QCOMPARE(base->width, n);
      QVERIFY(colourCount(*base) >= 2);
      QVERIFY(model.materials[0].pbrMetallicRoughness.metallicRoughnessTexture.index >= 0);
      // At every vertex the base colour is the paint where the vertex came from: red = x / N,
      // green = y / N (within the 8-bit map and half a texel of clamping at the border).
      const tinygltf::Primitive& p = model.meshes[0].primitives[0];
      const auto uv = accessorData<float>(model, p.attributes.at("TEXCOORD_0"), 2);
      float worst = 0;
      for (std::size_t k = 0; k + 1 < uv.size(); k += 2)
        worst = std::max({worst, std::abs(sampleLinear(*base, uv[k], uv[k + 1], 0) - uv[k]),
                          std::abs(sampleLinear(*base, uv[k], uv[k + 1], 1) - uv[k + 1])});
      QVERIFY2(worst <= 0.5f / float(n) + 2.0f / 255, qPrintable(QString::number(worst)));
    }
  }
  const QString problem = wholeSurfaceProblem(read);
  QVERIFY2(problem.isEmpty(), qPrintable(extension + ": " + problem));
  QCOMPARE(weldByPosition(read).positions.size(), lod.mesh.positions.size());
}

QTEST_APPLESS_MAIN(ClosedExportsTest)
#include "closed_exports_test.moc"
