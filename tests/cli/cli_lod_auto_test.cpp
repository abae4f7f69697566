// octaclay-cli lod --method auto (issue 24), the default: the adaptive method on a sculpted
// sphere (its image samples the surface evenly), the full-resolution collapse on an imported mesh
// whose image stretches it, there no more than 0.3 dB below meshopt_simplify on the same
// full-resolution mesh and triangle count; either way a closed mesh of Euler characteristic 2,
// and --json says which method was used.

#include "../meshopt_reference.h"
#include "cli_support.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/measure/surface_distance.h"

#include <QFile>
#include <QTemporaryDir>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace {

struct ObjTopology {
  long long vertices = 0, faces = 0, edges = 0;
  bool closed = false; // every directed edge once, each with its reverse
};

// The welded positions ("v") and the triangles ("f a/ta b/tb c/tc") of an OBJ the LOD wrote.
ObjTopology objTopology(const QString& path) {
  ObjTopology out;
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return out;
  std::vector<std::uint64_t> directed;
  while (!f.atEnd()) {
    const QByteArray line = f.readLine().trimmed();
    if (line.startsWith("v ")) ++out.vertices;
    if (!line.startsWith("f ")) continue;
    const QList<QByteArray> corners = line.mid(2).split(' ');
    if (corners.size() != 3) return out;
    std::array<std::uint64_t, 3> v{};
    for (int k = 0; k < 3; ++k)
      v[k] = corners[k].split('/').front().toULongLong();
    for (int k = 0; k < 3; ++k)
      directed.push_back(v[k] << 32 | v[(k + 1) % 3]);
    ++out.faces;
  }
  std::sort(directed.begin(), directed.end());
  out.edges = static_cast<long long>(directed.size()) / 2;
  out.closed = std::adjacent_find(directed.begin(), directed.end()) == directed.end() &&
               std::all_of(directed.begin(), directed.end(), [&](std::uint64_t e) {
                 return std::binary_search(directed.begin(), directed.end(), e << 32 | e >> 32);
               });
  return out;
}

// meshopt_simplify on the document's full-resolution mesh down to `triangles`, measured as the
// CLI measures its LOD.
double meshoptPsnr(const QString& document, std::size_t triangles, std::size_t samples) {
  using namespace octaclay::core;
  const TriangleMesh full =
      extractMesh(readDocument(document.toStdString(), {.layers = false}).positions);
  const TriangleMesh compact = octaclay::testing::meshoptSimplified(full, triangles);
  return compareSurfaces(full, compact, {.samplesPerSurface = samples}).psnr;
}

} // namespace

class CliLodAutoTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void sculptedSphereGetsTheImageMethod();
  void stretchedImportGetsTheCollapse();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
};

void CliLodAutoTest::sculptedSphereGetsTheImageMethod() {
  const QString sphere = file("sphere.exr"), sculpted = file("sculpted.exr");
  RUN_JSON(created, "new", "--shape", "sphere", "--size", "128", "-o", sphere, "--json");
  // Keep-detail off: its local relaxation (issue 30) most likely leaves a step in the sample
  // spacing at its margin, which imageRoughness reads as bending (it does not tell tangential
  // spacing from the surface's own bend), so auto picks the collapse there: a known limit.
  RUN_JSON(stroked, "stroke", sphere, "--brush", "push", "--path", "0.3,0.4;0.5,0.5;0.6,0.7",
           "--radius", "0.1", "--strength", "0.5", "--keep-detail", "off", "-o", sculpted,
           "--json");
  const QString obj = file("sphere_lod.obj");
  RUN_JSON(lod, "lod", sculpted, "--triangles", "2000", "-o", obj, "--json"); // auto by default
  QCOMPARE(lod["method"].toString(), QString("auto"));
  QCOMPARE(lod["method_used"].toString(), QString("adaptive"));
  QCOMPARE(lod["saliency_computed"].toBool(), false); // adaptive does not read it
  QVERIFY(std::abs(lod["triangles"].toDouble() - 2000) <= 20);
  QVERIFY2(lod["psnr"].toDouble() > 60, qPrintable(QString::number(lod["psnr"].toDouble())));
  const ObjTopology topology = objTopology(obj);
  QVERIFY(topology.closed);
  QCOMPARE(topology.vertices - topology.edges + topology.faces, 2LL);
}

void CliLodAutoTest::stretchedImportGetsTheCollapse() {
  const QString document = file("bunny.exr");
  RUN_JSON(imported, "import",
           QStringLiteral(OCTACLAY_SHARED_DATA) + "/meshes/genus0/bunny_npm.obj", "--size", "64",
           "-o", document, "--json", "--quiet");
  for (const int triangles : {100, 400}) {
    const QString obj = file(QString("bunny_%1.obj").arg(triangles));
    RUN_JSON(lod, "lod", document, "--triangles", QString::number(triangles), "--samples", "20000",
             "-o", obj, "--json");
    QCOMPARE(lod["method_used"].toString(), QString("collapse"));
    const auto count = static_cast<std::size_t>(lod["triangles"].toDouble());
    QVERIFY(count <= std::size_t(triangles) && count + 2 >= std::size_t(triangles));
    const double ours = lod["psnr"].toDouble(), meshopt = meshoptPsnr(document, count, 20000);
    QVERIFY2(ours >= meshopt - 0.3,
             qPrintable(QString("%1 triangles: %2 dB, meshopt_simplify %3 dB")
                            .arg(triangles)
                            .arg(ours)
                            .arg(meshopt)));
    const ObjTopology topology = objTopology(obj);
    QVERIFY(topology.closed);
    QCOMPARE(topology.faces, static_cast<long long>(count));
    QCOMPARE(topology.vertices - topology.edges + topology.faces, 2LL);
  }
}

QTEST_GUILESS_MAIN(CliLodAutoTest)
#include "cli_lod_auto_test.moc"
