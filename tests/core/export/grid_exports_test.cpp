// A torus's and a plane's textured exports arrive whole, as the ball's do: the OBJ and GLB at
// full resolution and at a level, read back by positions alone and welded by position, are a
// closed surface of Euler characteristic 0 (torus) or a sheet of Euler 1 with one boundary loop
// (plane); the OBJ holds each position once; every vertex's texture coordinate reads, in the
// (W+1)×(H+1) paint map, the paint of the very sample whose position it carries. A painted LOD
// of a W ≠ H torus reads its paint back where its texture coordinates point, and a scene GLB of
// a ball, a torus and a plane has the three named meshes.

#include "export_readback.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/scene_export.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sample_grid.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <set>

using namespace octaclay::core;
using namespace export_readback;

namespace {

// A 64 × 16 plane: a gentle hill over [-2, 2] × [-0.5, 0.5], so no two samples share a position.
GeometryImage hillPlane(int width, int height) {
  GeometryImage image(Topology::Plane, width, height);
  for (int j = 0; j <= height; ++j)
    for (int i = 0; i <= width; ++i) {
      const float x = 4.0f * float(i) / float(width) - 2.0f;
      const float y = float(j) / float(height) - 0.5f;
      image.at(i, j) = {x, y, 0.2f * std::exp(-(x * x + y * y)), 0};
    }
  return image;
}

GeometryImage shape(const QString& name) {
  if (name == "torus 64x16") return makeTorus({0.7f, 0.2f}, 64, 16);
  if (name == "torus 16x64") return makeTorus({0.7f, 0.3f}, 16, 64);
  if (name == "plane 64x16") return hillPlane(64, 16);
  return makeSheet(Sheet::Disc, 32);
}

// Red = x / W, green = y / H over the (W+1)×(H+1) samples, blue in stripes.
Document painted(GeometryImage image) {
  Document doc = makeDocument(std::move(image));
  const int w = doc.positions.width(), h = doc.positions.height();
  const std::size_t side = std::size_t(w) + 1, count = side * std::size_t(h + 1);
  doc.diffuse.texels.assign(count * 4, 1.0f);
  for (std::size_t t = 0; t < count; ++t) {
    doc.diffuse.texels[t * 4 + 0] = float(t % side) / float(w);
    doc.diffuse.texels[t * 4 + 1] = float(t / side) / float(h);
    doc.diffuse.texels[t * 4 + 2] = (t % side) * 4 / side % 2 == 0 ? 0.9f : 0.1f;
  }
  return doc;
}

// Empty when the welded mesh is the topology's surface: closed with Euler 0 for a torus, one
// boundary loop of 2(Mw + Mh) edges and Euler 1 for a plane; manifold, nothing unused.
QString surfaceProblem(const TriangleMesh& read, Topology topology, int mw, int mh) {
  const MeshTopology t = analyzeTopology(weldByPosition(read));
  const bool torus = topology == Topology::Torus;
  const std::size_t boundary = torus ? 0 : 2 * std::size_t(mw + mh);
  if (t.nonManifoldEdges || t.unusedVertices || t.boundaryEdges != boundary ||
      t.euler != (torus ? 0 : 1))
    return QString("%1 boundary edges (want %2), %3 non-manifold, Euler %4")
        .arg(t.boundaryEdges)
        .arg(boundary)
        .arg(t.nonManifoldEdges)
        .arg(t.euler);
  return {};
}

// The `vt` records of an OBJ.
std::vector<std::array<float, 2>> readObjTexcoords(const fs::path& path) {
  std::vector<std::array<float, 2>> texcoords;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("vt ", 0) == 0) {
      std::istringstream s(line.substr(3));
      std::array<float, 2> uv{};
      s >> uv[0] >> uv[1];
      texcoords.push_back(uv);
    }
  return texcoords;
}

} // namespace

class GridExportsTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void texturedExportsReadBackWhole_data();
  void texturedExportsReadBackWhole();
  void paintedLodOfANonSquareTorusReadsItsPaint();
  void sceneGlbHoldsABallATorusAndAPlane();
  void stepsLeavingTooFewCellsAreRefused();

private:
  fs::path file(const QString& name) const { return fs::path(dir_.filePath(name).toStdString()); }
  QTemporaryDir dir_;
};

void GridExportsTest::texturedExportsReadBackWhole_data() {
  QTest::addColumn<QString>("shape");
  QTest::addColumn<QString>("format");
  QTest::addColumn<int>("step");
  for (const char* s : {"torus 64x16", "torus 16x64", "plane 64x16", "disc 32"})
    for (const char* format : {"obj", "glb"})
      for (int step : {1, 4})
        QTest::newRow(qPrintable(QString("%1 %2 step %3").arg(s, format).arg(step)))
            << s << format << step;
}

void GridExportsTest::texturedExportsReadBackWhole() {
  QFETCH(QString, shape);
  QFETCH(QString, format);
  QFETCH(int, step);
  const Document doc = painted(::shape(shape));
  const int w = doc.positions.width(), h = doc.positions.height();
  const int mw = w / step, mh = h / step;
  const Topology topology = doc.positions.topology();
  const fs::path path = file(QString("%1-%2.%3").arg(shape, QString::number(step), format));
  const std::size_t welded = std::size_t(vertexCount(topology, mw, mh));

  TriangleMesh read;
  std::vector<std::array<float, 2>> uvs; // per read vertex (GLB) or per `vt` (OBJ)
  RasterImage base;
  if (format == "obj") {
    writeTexturedObj(doc, step, path);
    read = readObjPositions(path);
    QCOMPARE(read.positions.size(), welded); // each position once, as the ball's OBJ
    uvs = readObjTexcoords(path);
    QCOMPARE(uvs.size(), std::size_t(mw + 1) * std::size_t(mh + 1));
    for (auto& uv : uvs)
      uv[1] = 1.0f - uv[1]; // OBJ's v points up
    base = readImage(texturedObjFiles(path)[2], 4);
  } else {
    writeGlb(doc, step, path);
    const tinygltf::Model model = readGlb(path);
    read = glbPositions(model);
    QCOMPARE(read.positions.size(), std::size_t(mw + 1) * std::size_t(mh + 1));
    const auto uv = accessorData<float>(
        model, model.meshes.at(0).primitives.at(0).attributes.at("TEXCOORD_0"), 2);
    for (std::size_t k = 0; k + 1 < uv.size(); k += 2)
      uvs.push_back({uv[k], uv[k + 1]});
    const tinygltf::Image* image = textureImage(model, materialTexture(model, false));
    QVERIFY2(image, "no base colour texture");
    base.width = image->width;
    base.height = image->height;
    base.channels = image->component;
    for (unsigned char byte : image->image)
      base.pixels.push_back(float(byte) / 255.0f);
  }
  QCOMPARE(base.width, w + 1);
  QCOMPARE(base.height, h + 1);
  QCOMPARE(read.triangles.size(), 2 * std::size_t(mw) * std::size_t(mh));
  const QString problem = surfaceProblem(read, topology, mw, mh);
  QVERIFY2(problem.isEmpty(), qPrintable(shape + " " + format + ": " + problem));
  QCOMPARE(weldByPosition(read).positions.size(), welded);

  // Each texture coordinate is a texel centre whose paint is that of its own sample; in the
  // GLB, whose vertices carry one coordinate each, that sample's position is the vertex's.
  for (std::size_t k = 0; k < uvs.size(); ++k) {
    const int x = int(std::lround(uvs[k][0] * float(w + 1) - 0.5f));
    const int y = int(std::lround(uvs[k][1] * float(h + 1) - 0.5f));
    QVERIFY(x >= 0 && x <= w && y >= 0 && y <= h);
    QCOMPARE(x % step, 0);
    QCOMPARE(y % step, 0);
    QVERIFY2(std::abs(base.at(x, y, 0) - float(x) / float(w)) <= 1.0f / 255 &&
                 std::abs(base.at(x, y, 1) - float(y) / float(h)) <= 1.0f / 255,
             qPrintable(QString("texel (%1, %2)").arg(x).arg(y)));
    if (format == "glb") {
      const Vec3f p = read.positions[k], q = doc.positions.positionWrapped({x, y});
      QVERIFY2(p.x == q.x && p.y == q.y && p.z == q.z,
               qPrintable(QString("vertex %1 is not sample (%2, %3)").arg(k).arg(x).arg(y)));
    }
  }
}

void GridExportsTest::paintedLodOfANonSquareTorusReadsItsPaint() {
  Document doc = painted(makeTorus({0.7f, 0.2f}, 128, 32));
  computeSaliency(doc.positions);
  LodOptions options;
  options.targetTriangles = 800;
  const LodMesh lod = generateLod(doc.positions, options);
  const NormalMap map = bakeNormalMap(doc.positions, lod, NormalMapSpace::Tangent, 128);
  const fs::path path = file("torus-lod.glb");
  writeLodMesh(lod, map, doc, path);
  const tinygltf::Model model = readGlb(path);
  const tinygltf::Image* base = textureImage(model, materialTexture(model, false));
  QVERIFY2(base && base->width == 128 && base->height == 128, "no 128² base colour texture");
  // At every vertex the base colour is the paint at its image coordinate: red = u, green = v
  // (within the 8-bit map and half a texel).
  const auto uv = accessorData<float>(
      model, model.meshes.at(0).primitives.at(0).attributes.at("TEXCOORD_0"), 2);
  QVERIFY(uv.size() >= 2 * 100);
  float worst = 0;
  for (std::size_t k = 0; k + 1 < uv.size(); k += 2)
    worst = std::max({worst, std::abs(sampleLinear(*base, uv[k], uv[k + 1], 0) - uv[k]),
                      std::abs(sampleLinear(*base, uv[k], uv[k + 1], 1) - uv[k + 1])});
  QVERIFY2(worst <= 0.5f / 32 + 2.0f / 255, qPrintable(QString::number(worst)));
  const QString problem =
      analyzeTopology(weldByPosition(glbPositions(model))).euler == 0 ? QString() : "not Euler 0";
  QVERIFY2(problem.isEmpty(), qPrintable(problem));
}

void GridExportsTest::sceneGlbHoldsABallATorusAndAPlane() {
  Scene scene;
  scene.objects.push_back({"Ball", painted(makeBaseShape(BaseShape::Sphere, 16)), {}, true, false});
  scene.objects.push_back({"Ring",
                           painted(makeTorus({0.7f, 0.2f}, 32, 8)),
                           {{2, 0, 0}, {90, 0, 0}, {1, 1, 1}},
                           true,
                           false});
  scene.objects.push_back(
      {"Ground", painted(hillPlane(16, 8)), {{0, -1, 0}, {}, {3, 1, 3}}, true, false});
  const fs::path path = file("scene.glb");
  writeSceneMeshes(scene, path);
  const tinygltf::Model model = readGlb(path);
  QCOMPARE(model.nodes.size(), std::size_t{3});
  const long long euler[] = {2, 0, 1};
  const std::size_t vertices[] = {16 * 16 + 2, 32 * 8, 17 * 9};
  for (std::size_t k = 0; k < 3; ++k) {
    const tinygltf::Node& node = model.nodes[k];
    QCOMPARE(node.name, scene.objects[k].name);
    tinygltf::Model one = model;
    one.meshes = {model.meshes[std::size_t(node.mesh)]};
    const TriangleMesh mesh = weldByPosition(glbPositions(one));
    QCOMPARE(analyzeTopology(mesh).euler, euler[k]);
    QCOMPARE(mesh.positions.size(), vertices[k]);
    const tinygltf::Material& material = model.materials.at(
        std::size_t(model.meshes[std::size_t(node.mesh)].primitives[0].material));
    const tinygltf::Image* base =
        textureImage(model, material.pbrMetallicRoughness.baseColorTexture.index);
    QVERIFY(base);
    QCOMPARE(base->width, scene.objects[k].document.positions.width() + 1);
    QCOMPARE(base->height, scene.objects[k].document.positions.height() + 1);
  }
}

void GridExportsTest::stepsLeavingTooFewCellsAreRefused() {
  const Document doc = painted(makeTorus({0.7f, 0.2f}, 64, 16));
  const fs::path path = file("too-coarse.obj");
  bool refused = false;
  try {
    writeTexturedObj(doc, 8, path); // 8 × 2 cells: a torus keeps 4 around its tube
  } catch (const Error& e) {
    refused = e.kind() == ErrorKind::InvalidArgument &&
              std::string(e.what()).find("at least 4") != std::string::npos;
  }
  QVERIFY(refused);
  QVERIFY(!fs::exists(path));
  writeTexturedObj(doc, 4, path); // 16 × 4 cells
  QCOMPARE(readObjPositions(path).positions.size(), std::size_t(16 * 4));
}

QTEST_APPLESS_MAIN(GridExportsTest)
#include "grid_exports_test.moc"
