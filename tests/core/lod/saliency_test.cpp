// CPU saliency (saliency.h, computeSaliency): normalised to [0, 1], equal on identified samples,
// high around a sharp feature and low on the smooth sphere far from it.

#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/lod/saliency.h"

#include <QtTest>

#include <cmath>

using namespace octaclay::core;

namespace {

// The unit sphere with a narrow bump (angular radius ~0.1) around +z.
GeometryImage bumpedSphere(int n) {
  GeometryImage image = makeBaseShape(BaseShape::Sphere, n);
  for (Vec4f& t : image.texels()) {
    const Vec3f d = normalize(t.xyz());
    const float a = std::acos(std::clamp(d.z, -1.0f, 1.0f));
    const Vec3f p = d * (1 + 0.2f * std::exp(-(a * a) / 0.01f));
    t = {p.x, p.y, p.z, 0};
  }
  return image;
}

} // namespace

class SaliencyTest : public QObject {
  Q_OBJECT
private slots:
  void normalisedAndSeamed();
  void highAroundFeatureLowElsewhere();
  void customScales();
};

void SaliencyTest::normalisedAndSeamed() {
  GeometryImage image = bumpedSphere(64);
  computeSaliency(image);
  float lo = 1, hi = 0;
  for (const Vec4f& t : image.texels()) {
    lo = std::min(lo, t.w);
    hi = std::max(hi, t.w);
  }
  QVERIFY(lo >= 0);
  QCOMPARE(hi, 1.0f);
  const int n = image.size();
  std::array<Sample, 4> same;
  for (int k = 0; k <= n; ++k)
    for (const Sample s : {Sample{k, 0}, Sample{k, n}, Sample{0, k}, Sample{n, k}}) {
      const int count = identifiedSamples(n, s, same);
      for (int c = 1; c < count; ++c)
        QCOMPARE(image.at(same[c]).w, image.at(same[0]).w);
    }
}

void SaliencyTest::highAroundFeatureLowElsewhere() {
  GeometryImage image = bumpedSphere(128);
  computeSaliency(image);
  double near = 0, far = 0;
  int nearCount = 0, farCount = 0;
  for (const Vec4f& t : image.texels()) {
    const float z = normalize(t.xyz()).z;
    if (z > 0.97f) {
      near += t.w;
      ++nearCount;
    } else if (z < 0) {
      far += t.w;
      ++farCount;
    }
  }
  near /= nearCount;
  far /= farCount;
  qInfo("mean saliency near the bump %.3f, on the far half %.4f", near, far);
  QVERIFY(near > 0.05);
  QVERIFY(far < 0.05 * near);
}

void SaliencyTest::customScales() {
  GeometryImage a = bumpedSphere(64), b = bumpedSphere(64);
  computeSaliency(a, {{1.0f}});
  computeSaliency(b, {{4.0f}});
  // A single fine scale concentrates saliency on the bump's rim more tightly than a coarse one:
  // fewer samples above half the peak.
  const auto above = [](const GeometryImage& image) {
    int count = 0;
    for (const Vec4f& t : image.texels())
      count += t.w > 0.5f;
    return count;
  };
  qInfo("samples above 0.5: scale 1 %d, scale 4 %d", above(a), above(b));
  QVERIFY(above(a) < above(b));
}

QTEST_APPLESS_MAIN(SaliencyTest)
#include "saliency_test.moc"
