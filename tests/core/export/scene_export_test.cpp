// A three-object scene exported: the GLB read back with tinygltf (a loader we did not write)
// shows three named nodes with the objects' transforms, each mesh closed once its seam copies
// are welded; the OBJ has three `o` groups, each closed in world space and facing outward; PLY
// holds every visible object in world space; a hidden object is left out.

#include "export_readback.h"

#include "octaclay/core/document/document_mirror.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/scene_export.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/capsule.h"

#include <QTemporaryDir>
#include <QtTest>
#include <tiny_gltf.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;
using namespace export_readback;

namespace {

Scene threeObjects() {
  Scene scene;
  scene.objects.push_back({"Body",
                           makeDocument(makeBaseShape(BaseShape::Sphere, 16)),
                           {{0, 0, 0}, {}, {1, 1, 1}},
                           true,
                           false});
  scene.objects.push_back({"Leg",
                           makeDocument(makeCapsule(8, Capsule{0.25f, 1.0f})),
                           {{0.6f, 0.1f, -1.0f}, {20, -10, 35}, {1, 2, 0.5f}},
                           true,
                           false});
  scene.objects.push_back({"Leg.001", mirrorDocument(scene.objects[1].document, 0),
                           mirroredTransform(scene.objects[1].transform, 0), true, false});
  return scene;
}

} // namespace

class SceneExportTest : public QObject {
  Q_OBJECT
private slots:
  void init() { QVERIFY(dir_.isValid()); }
  void glbHasANamedPlacedNodePerObject();
  void objHasAClosedGroupPerObject();
  void plyMergesTheVisibleObjectsInWorldSpace();
  void mirroringScaleKeepsTheWorldMeshOutward();

private:
  fs::path path(const std::string& name) const {
    return fs::path(dir_.path().toStdString()) / name;
  }
  QTemporaryDir dir_;
};

void SceneExportTest::glbHasANamedPlacedNodePerObject() {
  const Scene scene = threeObjects();
  writeSceneMeshes(scene, path("scene.glb"));
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  QVERIFY2(loader.LoadBinaryFromFile(&model, &err, &warn, path("scene.glb").string()), err.c_str());
  QCOMPARE(model.nodes.size(), std::size_t{3});
  QCOMPARE(model.scenes.at(0).nodes.size(), std::size_t{3});
  QCOMPARE(model.materials.size(), std::size_t{3});
  for (std::size_t k = 0; k < 3; ++k) {
    const SceneObject& object = scene.objects[k];
    const tinygltf::Node& node = model.nodes[k];
    QCOMPARE(node.name, object.name);
    QCOMPARE(
        model.materials[std::size_t(model.meshes[std::size_t(node.mesh)].primitives[0].material)]
            .name,
        object.name);
    // The transform, as floats: translation and scale exact, the rotation the same turn.
    QCOMPARE(float(node.translation.at(0)), object.transform.translation.x);
    QCOMPARE(float(node.translation.at(2)), object.transform.translation.z);
    QCOMPARE(float(node.scale.at(1)), object.transform.scale.y);
    const auto q = rotationQuaternion(object.transform);
    for (int c = 0; c < 4; ++c)
      QVERIFY(std::abs(node.rotation.at(std::size_t(c)) - q[std::size_t(c)]) < 1e-12);
    // Its mesh is the object's, in object space, and closed: Euler 2 once seams are welded.
    tinygltf::Model one = model;
    one.meshes = {model.meshes[std::size_t(node.mesh)]};
    const TriangleMesh mesh = weldByPosition(glbPositions(one));
    const MeshTopology topology = analyzeTopology(mesh);
    QVERIFY2(topology.closed() && topology.manifold(), object.name.c_str());
    QCOMPARE(topology.euler, 2LL);
    const int n = object.document.size();
    QCOMPARE(mesh.positions.size(), std::size_t(n) * n + 2);
    QVERIFY(signedVolume(mesh) > 0);
  }
}

void SceneExportTest::objHasAClosedGroupPerObject() {
  Scene scene = threeObjects();
  writeSceneMeshes(scene, path("scene.obj"));
  std::ifstream in(path("scene.obj"));
  std::vector<std::string> names;
  std::vector<TriangleMesh> groups;
  std::vector<Vec3f> all;
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "o") {
      names.push_back(line.substr(2));
      groups.emplace_back();
    } else if (tag == "v") {
      Vec3f p;
      words >> p.x >> p.y >> p.z;
      all.push_back(p);
    } else if (tag == "f") {
      std::array<std::uint32_t, 3> t{};
      for (auto& v : t)
        words >> v;
      for (auto& v : t)
        --v;
      groups.back().triangles.push_back(t);
    }
  }
  QCOMPARE(names, (std::vector<std::string>{"Body", "Leg", "Leg.001"}));
  for (std::size_t g = 0; g < 3; ++g) {
    TriangleMesh& mesh = groups[g];
    mesh.positions = all; // global indices, as OBJ counts them
    const MeshTopology topology = analyzeTopology(mesh);
    QVERIFY2(topology.closed() && topology.manifold(), names[g].c_str());
    QCOMPARE(topology.euler, 2LL);
    QVERIFY2(signedVolume(mesh) > 0, names[g].c_str()); // outward, in world space
    // Welded per object: each group has the object's N²+2 vertices.
    const int n = scene.objects[g].document.size();
    QCOMPARE(topology.vertices, std::size_t(n) * n + 2);
  }
  // The mirrored leg's world mesh is the leg's mirrored across x: same volume.
  QVERIFY(std::abs(signedVolume(groups[1]) - signedVolume(groups[2])) <
          1e-5 * signedVolume(groups[1]));
}

void SceneExportTest::plyMergesTheVisibleObjectsInWorldSpace() {
  Scene scene = threeObjects();
  scene.objects.push_back({"Hidden",
                           makeDocument(makeBaseShape(BaseShape::Cube, 8)),
                           {{50, 0, 0}, {}, {1, 1, 1}},
                           false,
                           false});
  writeSceneMeshes(scene, path("scene.ply"));
  const TriangleMesh mesh = readMesh(path("scene.ply"));
  std::size_t expected = 0;
  for (std::size_t k = 0; k < 3; ++k)
    expected +=
        2 * std::size_t(scene.objects[k].document.size()) * scene.objects[k].document.size();
  QCOMPARE(mesh.triangles.size(), expected);
  const BoundingBox box = boundingBox(mesh), visible = sceneBounds(scene, true);
  QVERIFY(length(box.min - visible.min) < 1e-5f && length(box.max - visible.max) < 1e-5f);
  QVERIFY(box.max.x < 10); // the hidden cube at x = 50 is not there
  QVERIFY(signedVolume(mesh) > 0);
}

void SceneExportTest::mirroringScaleKeepsTheWorldMeshOutward() {
  SceneObject object{"Flipped",
                     makeDocument(makeBaseShape(BaseShape::Blob, 16)),
                     {{1, 2, 3}, {0, 45, 0}, {-1, 1, 1}},
                     true,
                     false};
  QVERIFY(signedVolume(worldMesh(object)) > 0);
  object.transform.scale = {-1, -2, 0.5f}; // two negatives: no mirror
  QVERIFY(signedVolume(worldMesh(object)) > 0);
}

QTEST_APPLESS_MAIN(SceneExportTest)
#include "scene_export_test.moc"
