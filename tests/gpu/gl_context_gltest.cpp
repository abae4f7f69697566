// The headless context and the GL object wrappers: a 4.3 core context exists without a display,
// float textures round-trip bit-exactly, a scissored render-to-texture pass changes exactly the
// texels inside the scissor, and a broken shader reports its name and the compiler's log.

#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/gl_error.h"
#include "octaclay/gpu/gl_objects.h"

#include <QtTest>
#include <epoxy/gl.h>

#include <cstring>
#include <optional>
#include <utility>

using namespace octaclay::gpu;

class GlContextTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void contextIsCore43();
  void rgba32fRoundTripIsBitExact();
  void scissoredPassTouchesOnlyItsRegion();
  void brokenShaderReportsNameAndLog();
  void adoptCurrentUsesTheSameContext();
  void adoptOwnsAndWrapDoesNot();
  void vertexArrayIsDeletedWithItsOwner();

private:
  std::optional<GlContext> context_;
};

void GlContextTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
  } catch (const GlError& e) {
    QFAIL(e.what());
  }
  qInfo("%s: %s, %s", context_->platform().c_str(), context_->renderer().c_str(),
        context_->version().c_str());
}

// Texture::adopt takes ownership of a GL id; Texture::wrap only stands for it.
void GlContextTest::adoptOwnsAndWrapDoesNot() {
  Texture owner(4, 4, TextureFormat::Rgba32f);
  const unsigned id = owner.id();
  {
    const Texture wrapped = Texture::wrap(id, 4, 4, TextureFormat::Rgba32f);
    QCOMPARE(wrapped.id(), id);
  }
  QVERIFY(glIsTexture(id)); // the wrapper left it to its owner
  Texture adopted = Texture::adopt(owner.release(), 4, 4, TextureFormat::Rgba32f);
  QCOMPARE(adopted.id(), id);
  adopted = Texture();
  QVERIFY(!glIsTexture(id)); // the adopter deleted it
}

void GlContextTest::vertexArrayIsDeletedWithItsOwner() {
  VertexArray array = VertexArray::create();
  array.bind();
  glBindVertexArray(0);
  const unsigned id = array.id();
  QVERIFY(glIsVertexArray(id));
  VertexArray moved = std::move(array);
  QCOMPARE(moved.id(), id);
  QCOMPARE(array.id(), 0u);
  moved = VertexArray();
  QVERIFY(!glIsVertexArray(id));
}

void GlContextTest::contextIsCore43() {
  GLint major = 0, minor = 0, profile = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
  QVERIFY(major * 10 + minor >= 43);
  QVERIFY(profile & GL_CONTEXT_CORE_PROFILE_BIT);
}

void GlContextTest::rgba32fRoundTripIsBitExact() {
  const int side = 65;
  std::vector<float> texels(static_cast<std::size_t>(side) * side * 4);
  for (std::size_t k = 0; k < texels.size(); ++k)
    texels[k] = std::nextafter(static_cast<float>(k) * 1e-3f, 1e9f) * ((k % 3) ? 1.0f : -1.0f);
  Texture texture(side, side, TextureFormat::Rgba32f);
  texture.upload({0, 0, side, side}, texels);
  const std::vector<float> back = texture.read({0, 0, side, side});
  QCOMPARE(back.size(), texels.size());
  QVERIFY(std::memcmp(back.data(), texels.data(), texels.size() * sizeof(float)) == 0);

  // A sub-region reads back the matching rows and columns.
  const std::vector<float> part = texture.read({10, 20, 3, 2});
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int c = 0; c < 4; ++c)
        QCOMPARE(part[(y * 3 + x) * 4 + c], texels[((20 + y) * side + 10 + x) * 4 + c]);
}

void GlContextTest::scissoredPassTouchesOnlyItsRegion() {
  const int side = 33;
  std::vector<float> zeros(static_cast<std::size_t>(side) * side * 4, 0.0f);
  Texture source(side, side, TextureFormat::Rgba32f), target(side, side, TextureFormat::Rgba32f);
  for (std::size_t k = 0; k < zeros.size(); ++k)
    zeros[k] = static_cast<float>(k);
  source.upload({0, 0, side, side}, zeros);
  target.upload({0, 0, side, side}, zeros);

  const Program add("add-one", fullscreenVertexShader(), R"(#version 430 core
uniform sampler2D u_source;
out vec4 color;
void main() { color = texelFetch(u_source, ivec2(gl_FragCoord.xy), 0) + vec4(1.0); }
)");
  const Framebuffer framebuffer(target);
  framebuffer.bind();
  glViewport(0, 0, side, side);
  glEnable(GL_SCISSOR_TEST);
  glScissor(5, 7, 10, 4);
  add.use();
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, source.id());
  glUniform1i(add.uniform("u_source"), 0);
  drawFullscreenPass();
  glDisable(GL_SCISSOR_TEST);

  const std::vector<float> result = target.read({0, 0, side, side});
  int changed = 0;
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const bool inside = x >= 5 && x < 15 && y >= 7 && y < 11;
      const std::size_t k = (static_cast<std::size_t>(y) * side + x) * 4;
      QCOMPARE(result[k], zeros[k] + (inside ? 1.0f : 0.0f));
      changed += inside;
    }
  QCOMPARE(changed, 40);
}

void GlContextTest::brokenShaderReportsNameAndLog() {
  try {
    Program broken("plugins/brushes/broken/brush.glsl", fullscreenVertexShader(),
                   "#version 430 core\nout vec4 color;\nvoid main() { color = undefinedThing; }\n");
    QFAIL("a broken shader compiled");
  } catch (const GlError& e) {
    const QString message = e.what();
    QVERIFY2(message.contains("plugins/brushes/broken/brush.glsl"), qPrintable(message));
    QVERIFY2(message.contains("fragment"), qPrintable(message));
    QVERIFY2(message.contains("undefinedThing"), qPrintable(message));
  }
  // A failed compile leaves no GL error behind for the next step.
  QCOMPARE(glGetError(), GLenum(GL_NO_ERROR));
}

void GlContextTest::adoptCurrentUsesTheSameContext() {
  const GlContext adopted = GlContext::adoptCurrent();
  QCOMPARE(adopted.platform(), std::string("adopted"));
  QCOMPARE(adopted.renderer(), context_->renderer());
}

QTEST_APPLESS_MAIN(GlContextTest)
#include "gl_context_gltest.moc"
