// describeDocument's facts on the ball against their definitions, sample by sample: the box over
// the finite samples in the order BoundingBox::extend takes them (between 0 and -0 the first one
// met stays, so the bits are compared), the non-finite samples and the cells' zero-area
// triangles. Rows of every kind: all finite (the vector path), some not finite, bounds at
// exactly ±0, flat rows, rows shorter than a vector step.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/document_info.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/octahedral.h"

#include <QtTest>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>

using namespace octaclay::core;

namespace {

std::uint32_t bitsOf(float v) {
  std::uint32_t b;
  std::memcpy(&b, &v, 4);
  return b;
}

struct Expected {
  BoundingBox box;
  std::uint64_t nonFinite = 0, degenerate = 0;
};

Expected byDefinition(const GeometryImage& image) {
  Expected e;
  const int n = image.size();
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Vec3f p = image.at(i, j).xyz();
      if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
        e.box.extend(p);
      else
        ++e.nonFinite;
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (const auto& t : cellTriangles(n, i, j)) {
        const Vec3f a = image.at(t[0]).xyz();
        const Vec3f normal = cross(image.at(t[1]).xyz() - a, image.at(t[2]).xyz() - a);
        e.degenerate += dot(normal, normal) == 0.0f ? 1 : 0;
      }
  return e;
}

} // namespace

class DocumentInfoTest : public QObject {
  Q_OBJECT

private slots:
  void factsMatchTheirDefinitions() {
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, 9);
    for (const int n : {2, 4, 8, 64, 128}) {
      for (int variant = 0; variant < 6; ++variant) {
        Document document = makeDocument(makeBaseShape(BaseShape::Sphere, n));
        GeometryImage& image = document.positions;
        for (int j = 0; j <= n; ++j)
          for (int i = 0; i <= n; ++i) {
            Vec4f& t = image.at(i, j);
            switch (variant) {
            case 0:
              break; // the sphere as made
            case 1:  // non-negative z with zeros of both signs: the row's low bound is ±0
              t.z = std::abs(t.z);
              if (pick(random) < 3) t.z = pick(random) < 5 ? 0.0f : -0.0f;
              break;
            case 2: // flat rows of ±0 and non-positive x: the high bound is ±0
              t.x = -std::abs(t.x);
              if (j % 3 == 0 || pick(random) < 2) t.x = pick(random) < 5 ? -0.0f : 0.0f;
              break;
            case 3: // a few samples not finite, some rows wholly so
              if (pick(random) == 0 || j == n / 2)
                t.y = pick(random) < 5 ? std::numeric_limits<float>::quiet_NaN()
                                       : -std::numeric_limits<float>::infinity();
              break;
            case 4: // random positions, repeated ones making zero-area triangles
              t = {unit(random), unit(random), unit(random), 0.0f};
              if (i > 0 && pick(random) < 3) t = image.at(i - 1, j);
              break;
            default: // every sample at the origin, half of them -0
              t = pick(random) < 5 ? Vec4f{0.0f, 0.0f, 0.0f, 0.0f}
                                   : Vec4f{-0.0f, -0.0f, -0.0f, 0.0f};
            }
          }
        const DocumentInfo info = describeDocument(document);
        const Expected e = byDefinition(image);
        const QString where = QString("N = %1, variant %2").arg(n).arg(variant);
        QVERIFY2(info.nonFinite == e.nonFinite, qPrintable(where));
        QVERIFY2(info.degenerateTriangles == e.degenerate, qPrintable(where));
        QVERIFY2(info.bbox.empty() == e.box.empty(), qPrintable(where));
        if (e.box.empty()) continue;
        const float got[6] = {info.bbox.min.x, info.bbox.min.y, info.bbox.min.z,
                              info.bbox.max.x, info.bbox.max.y, info.bbox.max.z};
        const float want[6] = {e.box.min.x, e.box.min.y, e.box.min.z,
                               e.box.max.x, e.box.max.y, e.box.max.z};
        for (int c = 0; c < 6; ++c)
          QVERIFY2(bitsOf(got[c]) == bitsOf(want[c]),
                   qPrintable(where + QString(", bound %1: %2 against %3")
                                          .arg(c)
                                          .arg(double(got[c]))
                                          .arg(double(want[c]))));
      }
    }
  }
};

QTEST_GUILESS_MAIN(DocumentInfoTest)
#include "document_info_test.moc"
