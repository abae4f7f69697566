#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

namespace octaclay::gpu {
namespace {

const char* glErrorName(GLenum error) {
  switch (error) {
  case GL_INVALID_ENUM:
    return "GL_INVALID_ENUM";
  case GL_INVALID_VALUE:
    return "GL_INVALID_VALUE";
  case GL_INVALID_OPERATION:
    return "GL_INVALID_OPERATION";
  case GL_INVALID_FRAMEBUFFER_OPERATION:
    return "GL_INVALID_FRAMEBUFFER_OPERATION";
  case GL_OUT_OF_MEMORY:
    return "GL_OUT_OF_MEMORY";
  default:
    return "unknown GL error";
  }
}

} // namespace

void checkGlError(const std::string& what) {
  const GLenum error = glGetError();
  if (error == GL_NO_ERROR) return;
  // Drain the queue so the next check reports only its own step.
  while (glGetError() != GL_NO_ERROR) {
  }
  throw GlError(what + " failed: " + glErrorName(error));
}

} // namespace octaclay::gpu
