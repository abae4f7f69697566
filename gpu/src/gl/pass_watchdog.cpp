#include "pass_watchdog.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <charconv>

namespace octaclay::gpu::detail {

bool finishedWithin(std::chrono::nanoseconds limit) {
  if (limit.count() <= 0) return true;
  GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (!fence) throw GlError("the brush watchdog cannot create a GL fence");
  // The flush bit: the fence must reach the GPU, or a wait with a limit may expire on a
  // pass that was never submitted.
  const GLenum waited =
      glClientWaitSync(fence, GL_SYNC_FLUSH_COMMANDS_BIT, static_cast<GLuint64>(limit.count()));
  glDeleteSync(fence);
  if (waited == GL_WAIT_FAILED) throw GlError("the brush watchdog cannot wait for a GL fence");
  return waited != GL_TIMEOUT_EXPIRED;
}

std::string describeLimit(std::chrono::nanoseconds limit) {
  const double ns = static_cast<double>(limit.count());
  const auto format = [](double value, const char* unit) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
    return std::string(buffer, end) + " " + unit;
  };
  if (ns >= 1e9) return format(ns / 1e9, "s");
  if (ns >= 1e6) return format(ns / 1e6, "ms");
  if (ns >= 1e3) return format(ns / 1e3, "µs");
  return format(ns, "ns");
}

} // namespace octaclay::gpu::detail
