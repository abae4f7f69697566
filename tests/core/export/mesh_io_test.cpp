// Mesh export and import through OpenMesh: OBJ, PLY, STL and OFF round trips of extracted meshes,
// and the errors for unknown extensions and unwritable paths.

#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

std::set<std::string> listDir(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    names.insert(e.path().filename().string());
  return names;
}

QString expectError(const std::function<void()>& f, ErrorKind kind) {
  try {
    f();
  } catch (const Error& e) {
    if (e.kind() != kind)
      return QString("wrong ErrorKind %1 (expected %2): %3")
          .arg(int(e.kind()))
          .arg(int(kind))
          .arg(e.what());
    if (QByteArray(e.what()).isEmpty()) return "empty message";
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  }
  return "did not throw";
}

#define EXPECT_ERROR(call, kind)                                                                   \
  do {                                                                                             \
    const QString why_ = expectError([&] { call; }, kind);                                         \
    QVERIFY2(why_.isEmpty(), qPrintable(why_));                                                    \
  } while (false)

#define NO_THROW(call)                                                                             \
  do {                                                                                             \
    try {                                                                                          \
      call;                                                                                        \
    } catch (const std::exception& e_) {                                                           \
      QFAIL(qPrintable(QString(#call " threw: ") + e_.what()));                                    \
    }                                                                                              \
  } while (false)

using Tri = std::array<std::uint32_t, 3>;
Tri rotated(Tri t) {
  while (t[0] > t[1] || t[0] > t[2])
    t = {t[1], t[2], t[0]};
  return t;
}

} // namespace

class MeshIoTest : public QObject {
  Q_OBJECT

private slots:
  void formatFromPath();
  void roundTrip_data();
  void roundTrip();
  void unknownExtension();
  void unwritablePath();
  void unreadable();

private:
  QTemporaryDir dir_;
};

void MeshIoTest::formatFromPath() {
  QCOMPARE(meshFormatFromPath("a.obj"), std::optional(MeshFormat::Obj));
  QCOMPARE(meshFormatFromPath("dir.x/b.PLY"), std::optional(MeshFormat::Ply));
  QCOMPARE(meshFormatFromPath("c.Stl"), std::optional(MeshFormat::Stl));
  QCOMPARE(meshFormatFromPath("/tmp/d.off"), std::optional(MeshFormat::Off));
  QVERIFY(!meshFormatFromPath("e.exr").has_value());
  QVERIFY(!meshFormatFromPath("obj").has_value());
  QVERIFY(!meshFormatFromPath("f.obj.txt").has_value());
}

void MeshIoTest::roundTrip_data() {
  QTest::addColumn<QString>("extension");
  QTest::addColumn<int>("step");
  for (const char* ext : {"obj", "ply", "stl", "off"})
    for (int step : {1, 4})
      QTest::newRow(qPrintable(QString("%1/step%2").arg(ext).arg(step))) << QString(ext) << step;
}

void MeshIoTest::roundTrip() {
  QFETCH(QString, extension);
  QFETCH(int, step);
  const int n = 32, m = n / step;
  const TriangleMesh mesh = extractMesh(makeBaseShape(BaseShape::Blob, n), step);
  const fs::path p = fs::path(dir_.path().toStdString()) / ("mesh." + extension.toStdString());
  NO_THROW(writeMesh(mesh, p));
  QVERIFY(fs::exists(p));
  TriangleMesh back;
  NO_THROW(back = readMesh(p));

  const std::size_t v = std::size_t(m) * m + 2, t = std::size_t(2) * m * m;
  QCOMPARE(back.positions.size(), v);
  QCOMPARE(back.triangles.size(), t);
  const MeshTopology topo = analyzeTopology(back);
  QCOMPARE(topo.vertices, v);
  QCOMPARE(topo.boundaryEdges, std::size_t{0});
  QCOMPARE(topo.nonManifoldEdges, std::size_t{0});
  QCOMPARE(topo.euler, 2LL);
  const double volume = signedVolume(mesh), backVolume = signedVolume(back);
  QVERIFY(volume > 0);
  QVERIFY2(std::abs(backVolume - volume) <= 1e-4 * volume,
           qPrintable(QString("%1 vs %2").arg(backVolume).arg(volume)));

  if (extension != "stl") {
    // Indexed formats keep the vertex order and the triangles.
    for (std::size_t k = 0; k < v; ++k)
      if (length(back.positions[k] - mesh.positions[k]) > 1e-5f)
        QFAIL(qPrintable(QString("vertex %1 moved by %2")
                             .arg(k)
                             .arg(length(back.positions[k] - mesh.positions[k]))));
    std::vector<Tri> a, b;
    for (const auto& tri : mesh.triangles)
      a.push_back(rotated(tri));
    for (const auto& tri : back.triangles)
      b.push_back(rotated(tri));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    QVERIFY2(a == b, "triangles differ");
  } else {
    // STL is a triangle soup: every re-read vertex is an original one and vice versa, one to one.
    std::vector<std::size_t> match(v, v);
    std::vector<char> used(v, 0);
    for (std::size_t k = 0; k < v; ++k) {
      for (std::size_t o = 0; o < v; ++o)
        if (!used[o] && length(back.positions[k] - mesh.positions[o]) <= 1e-5f) {
          match[k] = o;
          used[o] = 1;
          break;
        }
      if (match[k] == v) QFAIL(qPrintable(QString("re-read vertex %1 matches no original").arg(k)));
    }
    // And the triangles are the same, with the same orientation.
    std::vector<Tri> a, b;
    for (const auto& tri : mesh.triangles)
      a.push_back(rotated(tri));
    for (const auto& tri : back.triangles)
      b.push_back(rotated({std::uint32_t(match[tri[0]]), std::uint32_t(match[tri[1]]),
                           std::uint32_t(match[tri[2]])}));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    QVERIFY2(a == b, "triangles differ");
  }
}

void MeshIoTest::unknownExtension() {
  const TriangleMesh mesh = extractMesh(makeBaseShape(BaseShape::Sphere, 4));
  const fs::path root(dir_.path().toStdString());
  const auto before = listDir(root);
  for (const char* name : {"mesh.xyz", "mesh", "mesh.exr", "mesh.glb2"})
    EXPECT_ERROR(writeMesh(mesh, root / name), ErrorKind::InvalidArgument);
  QVERIFY(listDir(root) == before);
}

void MeshIoTest::unwritablePath() {
  const TriangleMesh mesh = extractMesh(makeBaseShape(BaseShape::Sphere, 8));
  const fs::path root(dir_.path().toStdString());
  const auto before = listDir(root);
  for (const char* ext : {"obj", "ply", "stl", "off"}) {
    const fs::path missingDir = root / "no-such-dir" / (std::string("mesh.") + ext);
    EXPECT_ERROR(writeMesh(mesh, missingDir), ErrorKind::Io);
    QVERIFY(!fs::exists(missingDir.parent_path()));
    const fs::path isDir = root / (std::string("folder.") + ext);
    fs::create_directory(isDir);
    EXPECT_ERROR(writeMesh(mesh, isDir), ErrorKind::Io);
    QVERIFY(fs::is_directory(isDir) && fs::is_empty(isDir));
    fs::remove(isDir);
  }
  QVERIFY2(listDir(root) == before, "a failed write left a file behind");
}

void MeshIoTest::unreadable() {
  const fs::path root(dir_.path().toStdString());
  EXPECT_ERROR(readMesh(root / "missing.obj"), ErrorKind::Io);
  { std::ofstream(root / "empty.obj") << "# nothing here\n"; }
  EXPECT_ERROR(readMesh(root / "empty.obj"), ErrorKind::InvalidInput);
}

QTEST_APPLESS_MAIN(MeshIoTest)
#include "mesh_io_test.moc"
