// The stretch preview's GPU pass (gpu/shaders/stretch_map.glsl, run by ModelRenderer for
// Preview::Stretch) against the CPU definition (core::measureStretch): the same figure at every
// texel, seams and fold points included, after a full refresh and after a dab-sized one.
#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/measure/stretch.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"

#include <QtTest>
#include <epoxy/gl.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

using namespace octaclay;

namespace {

// stretch_test's limb: samples within 0.2 rad of `axis` moved out along it by 4.3 (1 − θ/0.2)².
core::GeometryImage limb(int n, core::Vec3f axis) {
  core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, n);
  for (core::Vec4f& t : image.texels()) {
    const double theta = std::acos(std::clamp(double(core::dot(t.xyz(), axis)), -1.0, 1.0));
    if (theta < 0.2) {
      const float lift = float(4.3 * (1.0 - theta / 0.2) * (1.0 - theta / 0.2));
      t.x += lift * axis.x;
      t.y += lift * axis.y;
      t.z += lift * axis.z;
    }
  }
  return image;
}

} // namespace

class StretchMapTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() {
    try {
      context_.emplace(gpu::GlContext::createHeadless());
    } catch (const gpu::GlError& e) {
      QFAIL(e.what());
    }
  }

  void matchesTheCpuMeasure_data() {
    QTest::addColumn<int>("n");
    QTest::addColumn<int>("shape"); // 0 blob, 1 limb at the pole +z, 2 limb across the fold
    QTest::newRow("blob 32") << 32 << 0;
    QTest::newRow("limb +z 64") << 64 << 1;
    QTest::newRow("limb +x 64") << 64 << 2;
  }

  // float against the CPU's double: measured ~1e-7 relative; 1e-4 leaves room for other
  // drivers and is far below what the colour scale shows (a factor 2 spans its range).
  void matchesTheCpuMeasure() {
    QFETCH(int, n);
    QFETCH(int, shape);
    const core::GeometryImage image = shape == 0   ? core::makeBaseShape(core::BaseShape::Blob, n)
                                      : shape == 1 ? limb(n, {0, 0, 1})
                                                   : limb(n, {1, 0, 0});
    gpu::GpuDocument document(core::makeDocument(image));
    gpu::ModelRenderer renderer;
    renderer.setLevel(n, 1);
    gpu::Texture target(64, 64, gpu::TextureFormat::Rgba8);
    const auto drawAndCompare = [&](const core::GeometryImage& expected, const char* when) {
      target.bindAsTarget();
      glViewport(0, 0, 64, 64);
      gpu::ModelView view;
      view.objectToClip = {0.1f, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 1};
      view.eye = {0, 0, 10};
      view.preview = gpu::ModelView::Preview::Stretch;
      renderer.draw(document, view);
      gpu::checkGlError("drawing the stretch preview");
      const int side = n + 1;
      const std::vector<float> gpu = renderer.stretchMap().read({0, 0, side, side});
      const core::StretchMap cpu = core::measureStretch(expected);
      const double mean = core::meanSpacing(expected);
      QVERIFY(std::abs(renderer.meanSpacing() - mean) < 1e-12 * mean);
      double worst = 0;
      std::size_t worstAt = 0;
      for (std::size_t k = 0; k < cpu.stretch.size(); ++k) {
        const double want = double(cpu.stretch[k]) * mean;
        const double error = std::abs(double(gpu[k]) - want) / want;
        if (error > worst) {
          worst = error;
          worstAt = k;
        }
      }
      qInfo("%s: largest relative difference %.2e at (%d, %d)", when, worst,
            int(worstAt % std::size_t(side)), int(worstAt / std::size_t(side)));
      QVERIFY2(worst < 1e-4, qPrintable(QString::number(worst)));
    };
    drawAndCompare(image, "full");

    // A dab-sized change: a lump pushed out over texels [n/4, n/4 + 6)², then the rect grown
    // by one texel (as the viewport's normalRectsAround does) given to refreshNormals.
    core::GeometryImage edited = image;
    const core::TexelRect rect{n / 4, n / 4, 6, 6};
    std::vector<float> texels;
    for (int j = rect.y; j < rect.y + rect.height; ++j)
      for (int i = rect.x; i < rect.x + rect.width; ++i) {
        core::Vec4f& t = edited.at(i, j);
        t = {t.x * 1.3f, t.y * 1.3f, t.z * 1.3f, t.w};
        texels.insert(texels.end(), {t.x, t.y, t.z, t.w});
      }
    document.restore(core::EditLayer::Positions, rect, texels);
    const core::TexelRect grown{rect.x - 1, rect.y - 1, rect.width + 2, rect.height + 2};
    renderer.refreshNormals(document, std::span(&grown, 1));
    drawAndCompare(edited, "after an edit");
  }

private:
  std::optional<gpu::GlContext> context_;
};

QTEST_GUILESS_MAIN(StretchMapTest)
#include "stretch_map_gltest.moc"
