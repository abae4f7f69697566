#include "image_output.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"

#include <QBuffer>
#include <QFile>

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

} // namespace octaclay::app
