#pragma once

#include "viewport_widget.h"

#include <QOpenGLContext>

namespace octaclay::app {

/// Makes a ViewportWidget's context current for the scope of the guard and done again when the
/// guard goes, so an early return or an exception cannot leave the pair half done.
class CurrentContext {
public:
  /// Always: makeCurrent() now, doneCurrent() at the end. IfNotCurrent: only when the context
  /// was not current already (a call made from inside paintGL keeps it so).
  enum class Mode { Always, IfNotCurrent };

  explicit CurrentContext(ViewportWidget& widget, Mode mode = Mode::Always)
      : widget_(widget),
        owned_(mode == Mode::Always || QOpenGLContext::currentContext() != widget.context()) {
    if (owned_) widget_.makeCurrent();
  }
  ~CurrentContext() {
    if (owned_) widget_.doneCurrent();
  }
  CurrentContext(const CurrentContext&) = delete;
  CurrentContext& operator=(const CurrentContext&) = delete;

private:
  ViewportWidget& widget_;
  bool owned_;
};

} // namespace octaclay::app
