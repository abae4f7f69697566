#pragma once

#include <stdexcept>
#include <string>

namespace octaclay::gpu {

/// A GL or EGL failure: no usable context, a GL error after a call, an incomplete framebuffer,
/// a shader that did not compile (the message carries the driver's log).
class GlError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// Throws GlError naming `what` and the pending GL error, if there is one. Needs a current context.
void checkGlError(const std::string& what);

} // namespace octaclay::gpu
