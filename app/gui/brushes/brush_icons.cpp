#include "brush_icons.h"

#include <QFont>
#include <QImageReader>
#include <QPainter>
#include <QPixmap>

#include <array>

namespace octaclay::app {
namespace {

constexpr std::array kIconSizes{24, 32, 48};

} // namespace

QColor brushCategoryColour(gpu::Category category) {
  switch (category) {
  case gpu::Category::Sculpt:
    return QColor(0xb8, 0x67, 0x3f);
  case gpu::Category::Paint:
    return QColor(0x3f, 0x78, 0xb8);
  case gpu::Category::Splat:
    return QColor(0x4f, 0x9a, 0x57);
  }
  return Qt::gray;
}

QString brushInitials(const QString& name) {
  const QStringList words = name.simplified().split(u' ', Qt::SkipEmptyParts);
  if (words.size() >= 2) return (words[0].left(1) + words[1].left(1)).toUpper();
  if (words.isEmpty()) return QStringLiteral("?");
  return words[0].left(1).toUpper() + words[0].mid(1, 1).toLower();
}

QIcon generatedBrushIcon(const gpu::BrushManifest& brush) {
  const QString initials = brushInitials(QString::fromStdString(brush.name));
  QIcon icon;
  for (const int size : kIconSizes) {
    QPixmap pixmap(size, size);
    pixmap.fill(Qt::transparent);
    QPainter painter(&pixmap);
    painter.setRenderHint(QPainter::Antialiasing);
    painter.setPen(Qt::NoPen);
    painter.setBrush(brushCategoryColour(brush.category));
    painter.drawRoundedRect(QRectF(0, 0, size, size), size / 6.0, size / 6.0);
    QFont font = painter.font();
    font.setBold(true);
    font.setPixelSize(size * 9 / 20);
    painter.setFont(font);
    painter.setPen(Qt::white);
    painter.drawText(QRect(0, 0, size, size), Qt::AlignCenter, initials);
    painter.end();
    icon.addPixmap(pixmap);
  }
  return icon;
}

QIcon brushIcon(const gpu::BrushManifest& brush, bool* fromFile) {
  if (fromFile) *fromFile = false;
  const QString path = QString::fromStdString(brush.iconPath().string());
  if (path.isEmpty()) return generatedBrushIcon(brush);
  QIcon icon;
  for (const int size : kIconSizes) {
    QImageReader reader(path);
    const QSize natural = reader.size();
    if (natural.isValid()) reader.setScaledSize(natural.scaled(size, size, Qt::KeepAspectRatio));
    const QImage image = reader.read();
    if (image.isNull()) return generatedBrushIcon(brush);
    icon.addPixmap(QPixmap::fromImage(image));
  }
  if (fromFile) *fromFile = true;
  return icon;
}

} // namespace octaclay::app
