#pragma once

#include <memory>
#include <string>

namespace octaclay::gpu {

/// An OpenGL 4.3 core context the gpu module runs in: its own headless EGL context (Mesa's
/// surfaceless platform; the EGL device platform on NVIDIA), or the caller's current one.
class GlContext {
public:
  /// Creates and makes current a headless 4.3 core context. Throws GlError with what is missing
  /// (no libEGL, no platform, no 4.3 core context) when none can be made; never aborts.
  static GlContext createHeadless();
  /// Uses the context current on this thread (the modeller's viewport); does not own it.
  /// Throws GlError when none is current or it is older than 4.3.
  static GlContext adoptCurrent();

  GlContext(GlContext&&) noexcept;
  GlContext& operator=(GlContext&&) noexcept;
  ~GlContext();

  /// Makes this context current on the calling thread (a no-op for an adopted context).
  void makeCurrent() const;
  std::string renderer() const;
  std::string version() const;
  /// "surfaceless", "device" or "adopted".
  const std::string& platform() const;

private:
  struct State;
  explicit GlContext(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

} // namespace octaclay::gpu
