// Checks every LOD test makes of a generated LOD: closed genus 0, seam-consistent corners.
#pragma once

#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/lod/lod.h"

#include <QtTest>

#include <cmath>

namespace octaclay::core::testing {

inline void checkClosedGenus0(const TriangleMesh& mesh) {
  const MeshTopology t = analyzeTopology(mesh);
  QVERIFY(t.closed());
  QVERIFY(t.manifold());
  QCOMPARE(t.euler, 2LL);
  QCOMPARE(t.unusedVertices, std::size_t(0));
  QVERIFY(signedVolume(mesh) > 0);
}

// No triangle spans a seam in the image: every triangle's corner coordinates are
// counter-clockwise in the image (as the mesh is outward) and lie in [0, 1]², and together they
// cover the image square once (total area 1). A triangle spanning a seam would be inverted or
// cover the square a second time.
inline void checkCornerUv(const LodMesh& lod) {
  QCOMPARE(lod.cornerUv.size(), lod.mesh.triangles.size());
  double total = 0;
  int inverted = 0;
  for (const auto& c : lod.cornerUv) {
    for (int k = 0; k < 3; ++k)
      QVERIFY(c[k].x >= 0 && c[k].x <= 1 && c[k].y >= 0 && c[k].y <= 1);
    const double area = 0.5 * ((double(c[1].x) - c[0].x) * (double(c[2].y) - c[0].y) -
                               (double(c[2].x) - c[0].x) * (double(c[1].y) - c[0].y));
    total += area;
    inverted += area < -1e-9;
  }
  QVERIFY2(inverted == 0, qPrintable(QString("%1 inverted corner triangles").arg(inverted)));
  QVERIFY2(std::abs(total - 1) < 1e-4, qPrintable(QString("corner area %1").arg(total)));
}

} // namespace octaclay::core::testing
