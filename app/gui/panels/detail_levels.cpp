#include "detail_levels.h"

#include <QCoreApplication>
#include <QLocale>

namespace octaclay::app {

QString detailLabel(int n) {
  const auto tr = [](const char* text) {
    return QCoreApplication::translate("octaclay::app::Detail", text);
  };
  QString word;
  switch (n) {
  case 64:
    word = tr("Very coarse");
    break;
  case 128:
    word = tr("Coarse");
    break;
  case 256:
    word = tr("Medium");
    break;
  case 512:
    word = tr("Fine");
    break;
  case 1024:
    word = tr("Very fine");
    break;
  case 2048:
    word = tr("Extra fine");
    break;
  case 4096:
    word = tr("Finest");
    break;
  default:
    return QString::number(n);
  }
  return QStringLiteral("%1 (%2)").arg(word).arg(n);
}

QString detailTooltip(int n) {
  return QCoreApplication::translate("octaclay::app::Detail",
                                     "N = %1: %1 × %1 samples, %2 triangles; more detail "
                                     "sculpts finer and needs more memory")
      .arg(n)
      .arg(QLocale().toString(2LL * n * n));
}

} // namespace octaclay::app
