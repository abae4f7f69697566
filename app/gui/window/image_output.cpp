#include "image_output.h"

#include "viewport_widget.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <QBuffer>
#include <QFile>
#include <QFileInfo>
#include <QStatusBar>

#include <cstdint>
#include <cstdio>
#include <span>

namespace octaclay::app {

bool saveImagePng(const QImage& image, const QString& path) {
  QByteArray bytes;
  QBuffer buffer(&bytes);
  if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) {
    std::fprintf(stderr, "octaclay: cannot encode %s as PNG\n", qPrintable(path));
    return false;
  }
  try {
    core::writeBytesAtomically(QFile::encodeName(path).toStdString(),
                               std::span(reinterpret_cast<const std::uint8_t*>(bytes.constData()),
                                         static_cast<std::size_t>(bytes.size())));
  } catch (const core::Error& e) {
    std::fprintf(stderr, "octaclay: %s\n", e.what());
    return false;
  }
  return true;
}

bool saveViewImage(ViewportWidget& viewport, QStatusBar& statusBar, const QString& path, QSize size,
                   bool background) {
  const QImage image = viewport.renderImage(size, background);
  if (image.isNull()) {
    statusBar.showMessage(QStatusBar::tr("Could not draw a %1 × %2 picture (at most %3 a side)")
                              .arg(size.width())
                              .arg(size.height())
                              .arg(viewport.maxImageSide()),
                          10000);
    return false;
  }
  if (!saveImagePng(image, path)) {
    statusBar.showMessage(QStatusBar::tr("Could not write %1").arg(path), 10000);
    return false;
  }
  statusBar.showMessage(QStatusBar::tr("Saved %1 (%2 × %3)")
                            .arg(QFileInfo(path).fileName())
                            .arg(size.width())
                            .arg(size.height()),
                        5000);
  return true;
}

} // namespace octaclay::app
