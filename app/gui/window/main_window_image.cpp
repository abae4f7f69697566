// File ▸ Save Image: the viewport drawn offscreen at the view's or a chosen size, written as PNG
// through the one output writer.

#include "image_output.h"
#include "main_window.h"
#include "save_image_dialog.h"
#include "viewport_widget.h"

#include <QFileInfo>
#include <QStatusBar>

namespace octaclay::app {

bool MainWindow::saveImage(const QString& path, QSize size, bool background) {
  const QImage image = viewport_->renderImage(size, background);
  if (image.isNull()) {
    statusBar()->showMessage(tr("Could not draw a %1 × %2 picture (at most %3 a side)")
                                 .arg(size.width())
                                 .arg(size.height())
                                 .arg(viewport_->maxImageSide()),
                             10000);
    return false;
  }
  if (!saveImagePng(image, path)) {
    statusBar()->showMessage(tr("Could not write %1").arg(path), 10000);
    return false;
  }
  statusBar()->showMessage(
      tr("Saved %1 (%2 × %3)").arg(QFileInfo(path).fileName()).arg(size.width()).arg(size.height()),
      5000);
  return true;
}

void MainWindow::askAndSaveImage() {
  const QSize viewSize = viewport_->size() * viewport_->devicePixelRatioF();
  ImageRequest request{viewSize, true};
  if (!chooser_) { // interactive: ask the size and background (tests call saveImage directly)
    SaveImageDialog dialog(viewSize, viewport_->maxImageSide(), this);
    if (dialog.exec() != QDialog::Accepted) return;
    request = dialog.request();
  }
  QString path = choose(FileRequest::SaveImage);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".png");
  saveImage(path, request.size, request.background);
}

} // namespace octaclay::app
