#include "pass_watchdog.h"

#include "octaclay/gpu/gl_error.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <charconv>

namespace octaclay::gpu::detail {

PassWatchdog::~PassWatchdog() {
  clear();
}

void PassWatchdog::submitted(std::chrono::nanoseconds limit, const std::string& owner) {
  if (limit.count() <= 0) return;
  // The GPU's clock as the pass is submitted, and as it completes (a timestamp query): a pass
  // whose fence the check finds signalled may still have overrun, when something in between
  // waited for it (a driver that copies textures on the CPU).
  GLint64 at = 0;
  glGetInteger64v(GL_TIMESTAMP, &at);
  GLuint query = 0;
  glGenQueries(1, &query);
  glQueryCounter(query, GL_TIMESTAMP);
  GLsync fence = glFenceSync(GL_SYNC_GPU_COMMANDS_COMPLETE, 0);
  if (!fence) {
    glDeleteQueries(1, &query);
    throw GlError("the brush watchdog cannot create a GL fence");
  }
  pending_.push_back({fence, query, at, std::chrono::steady_clock::now(), owner});
}

const std::string* PassWatchdog::keepWithin(std::size_t ahead, std::chrono::nanoseconds limit) {
  while (pending_.size() > ahead) {
    Pending& oldest = pending_.front();
    const auto left = limit - (std::chrono::steady_clock::now() - oldest.submitted);
    // The flush bit: the fence must reach the GPU, or a wait with a limit may expire on a pass
    // that was never submitted. A limit already spent still polls once.
    const GLenum waited = glClientWaitSync(
        static_cast<GLsync>(oldest.fence), GL_SYNC_FLUSH_COMMANDS_BIT,
        static_cast<GLuint64>(std::max<std::int64_t>(
            0, std::chrono::duration_cast<std::chrono::nanoseconds>(left).count())));
    if (waited == GL_WAIT_FAILED) throw GlError("the brush watchdog cannot wait for a GL fence");
    bool overran = waited == GL_TIMEOUT_EXPIRED;
    if (!overran) { // finished: the query's result is there, no wait
      GLuint64 done = 0;
      glGetQueryObjectui64v(oldest.query, GL_QUERY_RESULT, &done);
      overran = done > static_cast<GLuint64>(oldest.gpuSubmitted) &&
                done - static_cast<GLuint64>(oldest.gpuSubmitted) >
                    static_cast<GLuint64>(std::max<std::int64_t>(0, limit.count()));
    }
    if (overran) {
      overran_ = oldest.owner;
      clear();
      return &overran_;
    }
    glDeleteSync(static_cast<GLsync>(oldest.fence));
    glDeleteQueries(1, &oldest.query);
    pending_.pop_front();
  }
  return nullptr;
}

void PassWatchdog::clear() {
  for (const Pending& p : pending_) {
    glDeleteSync(static_cast<GLsync>(p.fence));
    glDeleteQueries(1, &p.query);
  }
  pending_.clear();
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
