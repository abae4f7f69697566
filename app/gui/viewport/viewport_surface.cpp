#include "viewport_surface.h"

#include "viewport_widget.h"

namespace octaclay::app {

ViewportSurface::ViewportSurface(ViewportWidget& owner)
    : QOpenGLWindow(QOpenGLWindow::NoPartialUpdate), owner_(owner) {
  // Input passes through to the widget beneath, so the mouse, the keyboard focus and shortcuts
  // follow Qt's widget rules as they did for a QOpenGLWidget.
  setFlags(flags() | Qt::WindowTransparentForInput | Qt::WindowDoesNotAcceptFocus);
}

void ViewportSurface::initializeGL() {
  owner_.initializeGL();
}

void ViewportSurface::resizeGL(int width, int height) {
  owner_.resizeGL(width, height);
}

void ViewportSurface::paintGL() {
  owner_.paintGL();
  owner_.paintMarks(*this);
}

} // namespace octaclay::app
