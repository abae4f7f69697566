#pragma once

#include <QOpenGLWindow>

namespace octaclay::app {

class ViewportWidget;

/// The viewport's native GL window, embedded in its ViewportWidget. A QOpenGLWidget draws into a
/// framebuffer that Qt then composes with the rest of the window, two more full-window passes a
/// frame that a software rasterizer pays for; this window's frames go to the screen directly. It
/// draws what the widget says and takes no input: the widget beneath it gets the mouse and keys.
class ViewportSurface : public QOpenGLWindow {
  Q_OBJECT
public:
  explicit ViewportSurface(ViewportWidget& owner);

protected:
  void initializeGL() override;
  void resizeGL(int width, int height) override;
  void paintGL() override;

private:
  ViewportWidget& owner_;
};

} // namespace octaclay::app
