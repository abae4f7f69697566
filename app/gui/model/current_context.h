#pragma once

#include "gl_host.h"

#include <QOpenGLContext>

namespace octaclay::app {

/// Makes a GlHost's context current for the scope of the guard and done again when the guard
/// goes, so an early return or an exception cannot leave the pair half done.
class CurrentContext {
public:
  /// Always: makeCurrent() now, doneCurrent() at the end. IfNotCurrent: only when the context
  /// was not current already (a call made from inside paintGL keeps it so).
  enum class Mode { Always, IfNotCurrent };

  explicit CurrentContext(GlHost& host, Mode mode = Mode::Always)
      : host_(host),
        owned_(mode == Mode::Always || QOpenGLContext::currentContext() != host.context()) {
    if (owned_) host_.makeCurrent();
  }
  ~CurrentContext() {
    if (owned_) host_.doneCurrent();
  }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

private:
  GlHost& host_;
  bool owned_;
};

} // namespace octaclay::app
