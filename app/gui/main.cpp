#include "viewport_widget.h"

#include "octaclay/core/base_shapes.h"

#include <QApplication>
#include <QTimer>

int main(int argc, char** argv) {
  QApplication app(argc, argv);
  octaclay::app::ViewportWidget view;
  view.resize(640, 480);
  view.setDocument(octaclay::core::makeDocument(
      octaclay::core::makeBaseShape(octaclay::core::BaseShape::Sphere, 256)));
  view.show();
  QTimer::singleShot(1500, [&] {
    view.grabFramebuffer().save("/tmp/viewport.png");
    qInfo("error: %s", qPrintable(view.error()));
    app.quit();
  });
  return app.exec();
}
