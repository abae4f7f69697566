#include "octaclay/gpu/gl_context.h"

#include "octaclay/gpu/gl_error.h"

#include <dlfcn.h>
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <cstdio>
#include <vector>

namespace octaclay::gpu {

struct GlContext::State {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  bool owned = false;
  std::string platform;
};

namespace {

// libepoxy aborts the process when it cannot load libEGL, so look for it first.
void requireLibEgl() {
  void* lib = dlopen("libEGL.so.1", RTLD_LAZY | RTLD_LOCAL);
  if (!lib)
    throw GlError("no OpenGL available: libEGL.so.1 cannot be loaded (install libegl1 and "
                  "libegl-mesa0 / libgl1-mesa-dri, or a GPU driver)");
  dlclose(lib);
}

std::string eglErrorText(const char* step) {
  const EGLint error = eglGetError();
  if (error == EGL_SUCCESS) return std::string(step) + " found no EGL driver";
  char hex[16];
  std::snprintf(hex, sizeof hex, "0x%04x", static_cast<unsigned>(error));
  return std::string(step) + " failed (EGL error " + hex + ")";
}

// Surfaceless (Mesa, llvmpipe here) first, then the first EGL device (NVIDIA without X).
EGLDisplay openDisplay(std::string& platform) {
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_MESA_platform_surfaceless")) {
    EGLDisplay display =
        eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) {
      platform = "surfaceless";
      return display;
    }
  }
  if (epoxy_has_egl_extension(EGL_NO_DISPLAY, "EGL_EXT_platform_device")) {
    EGLDeviceEXT devices[8];
    EGLint count = 0;
    if (eglQueryDevicesEXT(8, devices, &count))
      for (EGLint k = 0; k < count; ++k) {
        EGLDisplay display = eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT, devices[k], nullptr);
        if (display != EGL_NO_DISPLAY && eglInitialize(display, nullptr, nullptr)) {
          platform = "device";
          return display;
        }
      }
  }
  throw GlError("no headless OpenGL: neither EGL's surfaceless platform nor an EGL device "
                "could be opened (" +
                eglErrorText("eglInitialize") +
                "); install Mesa (libegl-mesa0, libgl1-mesa-dri) or a GPU driver");
}

void requireVersion43(const std::string& platform) {
  GLint major = 0, minor = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetIntegerv(GL_MINOR_VERSION, &minor);
  if (major * 10 + minor < 43)
    throw GlError("OpenGL " + std::to_string(major) + "." + std::to_string(minor) + " (" +
                  platform + ") is too old: Octaclay needs OpenGL 4.3 core");
}

} // namespace

GlContext GlContext::createHeadless() {
  requireLibEgl();
  auto state = std::make_unique<State>();
  state->display = openDisplay(state->platform);
  if (!eglBindAPI(EGL_OPENGL_API)) throw GlError(eglErrorText("eglBindAPI(EGL_OPENGL_API)"));

  EGLConfig config = EGL_NO_CONFIG_KHR;
  if (!epoxy_has_egl_extension(state->display, "EGL_KHR_no_config_context")) {
    const EGLint attributes[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
    EGLint count = 0;
    if (!eglChooseConfig(state->display, attributes, &config, 1, &count) || count == 0)
      throw GlError("no EGL config with OpenGL support");
  }
  const EGLint contextAttributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                      4,
                                      EGL_CONTEXT_MINOR_VERSION,
                                      3,
                                      EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                      EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                      EGL_NONE};
  state->context = eglCreateContext(state->display, config, EGL_NO_CONTEXT, contextAttributes);
  if (state->context == EGL_NO_CONTEXT)
    throw GlError("no OpenGL 4.3 core context on the " + state->platform + " platform (" +
                  eglErrorText("eglCreateContext") + ")");
  state->owned = true;
  GlContext context(std::move(state));
  context.makeCurrent();
  requireVersion43(context.platform());
  return context;
}

GlContext GlContext::adoptCurrent() {
  auto state = std::make_unique<State>();
  state->platform = "adopted";
  GLint major = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  if (major == 0) throw GlError("no OpenGL context is current on this thread");
  requireVersion43(state->platform);
  return GlContext(std::move(state));
}

GlContext::GlContext(std::unique_ptr<State> state) : state_(std::move(state)) {}
GlContext::GlContext(GlContext&&) noexcept = default;
GlContext& GlContext::operator=(GlContext&&) noexcept = default;

GlContext::~GlContext() {
  if (!state_ || !state_->owned) return;
  if (eglGetCurrentContext() == state_->context)
    eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  eglDestroyContext(state_->display, state_->context);
}

void GlContext::makeCurrent() const {
  if (!state_->owned) return;
  if (!eglMakeCurrent(state_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, state_->context))
    throw GlError(eglErrorText("eglMakeCurrent"));
}

std::string GlContext::renderer() const {
  return reinterpret_cast<const char*>(glGetString(GL_RENDERER));
}

std::string GlContext::version() const {
  return reinterpret_cast<const char*>(glGetString(GL_VERSION));
}

const std::string& GlContext::platform() const {
  return state_->platform;
}

} // namespace octaclay::gpu
