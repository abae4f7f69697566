// Texture::fill, the GPU clear GpuDocument gives an unpainted layer on a real GPU: it writes its
// region and nothing else, in every layer format (half floats as the texture rounds them), and
// leaves the caller's framebuffer and scissor test as they were.
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gl_objects.h"

#include <QtTest>
#include <epoxy/gl.h>

#include <optional>

using namespace octaclay;

class TextureFillTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void fillsItsRegionOnlyInEveryFormat();
  void leavesTheCallersStateAsItWas();

private:
  std::optional<gpu::GlContext> context_;
};

void TextureFillTest::initTestCase() {
  try {
    context_.emplace(gpu::GlContext::createHeadless());
  } catch (const gpu::GlError& e) {
    QFAIL(e.what());
  }
}

void TextureFillTest::fillsItsRegionOnlyInEveryFormat() {
  for (const gpu::TextureFormat format :
       {gpu::TextureFormat::Rgba32f, gpu::TextureFormat::Rgba16f, gpu::TextureFormat::R32f}) {
    gpu::Texture texture(33, 17, format);
    const int c = texture.channels();
    texture.fill({0.25f, 0.5f, 0.75f, 1.0f}, {0, 0, 33, 17});
    texture.fill({0.8f, -2.0f, 3.5f, 0.0f}, {4, 3, 10, 5}); // 0.8 is not a half float
    const std::vector<float> texels = texture.read({0, 0, 33, 17});
    const std::vector<float> inside = texture.read({4, 3, 1, 1});
    const bool half = format == gpu::TextureFormat::Rgba16f;
    QVERIFY(half ? inside[0] != 0.8f && std::abs(inside[0] - 0.8f) < 1e-3f : inside[0] == 0.8f);
    int changed = 0;
    for (int y = 0; y < 17; ++y)
      for (int x = 0; x < 33; ++x) {
        const bool in = x >= 4 && x < 14 && y >= 3 && y < 8;
        const float* t = &texels[static_cast<std::size_t>((y * 33 + x) * c)];
        const std::array<float, 4> want = in ? std::array<float, 4>{inside[0], -2.0f, 3.5f, 0.0f}
                                             : std::array<float, 4>{0.25f, 0.5f, 0.75f, 1.0f};
        for (int k = 0; k < c; ++k)
          QCOMPARE(t[k], want[static_cast<std::size_t>(k)]);
        changed += in;
      }
    QCOMPARE(changed, 50);
  }
}

void TextureFillTest::leavesTheCallersStateAsItWas() {
  gpu::Texture target(8, 8, gpu::TextureFormat::Rgba32f), other(8, 8, gpu::TextureFormat::R32f);
  target.bindAsTarget();
  GLint bound = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glEnable(GL_SCISSOR_TEST);
  glScissor(1, 2, 3, 4);
  other.fill({1, 0, 0, 0}, {0, 0, 8, 8});
  GLint after = 0;
  std::array<GLint, 4> box{};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &after);
  glGetIntegerv(GL_SCISSOR_BOX, box.data());
  QCOMPARE(after, bound);
  QVERIFY(glIsEnabled(GL_SCISSOR_TEST));
  QCOMPARE(box, (std::array<GLint, 4>{1, 2, 3, 4}));
  glDisable(GL_SCISSOR_TEST);
  other.fill({2, 0, 0, 0}, {0, 0, 8, 8});
  QVERIFY(!glIsEnabled(GL_SCISSOR_TEST));
  QCOMPARE(other.read({7, 7, 1, 1})[0], 2.0f);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

QTEST_GUILESS_MAIN(TextureFillTest)
#include "texture_fill_gltest.moc"
