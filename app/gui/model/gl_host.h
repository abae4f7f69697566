#pragma once

class QOpenGLContext;

namespace octaclay::app {

/// Whoever owns the GL context the document's textures live in (the viewport's native window):
/// the modeller makes it current around its GL work (CurrentContext).
class GlHost {
public:
  virtual ~GlHost() = default;
  /// The context (null before GL started).
  virtual QOpenGLContext* context() const = 0;
  virtual void makeCurrent() = 0;
  virtual void doneCurrent() = 0;
  /// Asks for a frame showing the document as it is now.
  virtual void update() = 0;
};

} // namespace octaclay::app
