#include "file_suggestion.h"

#include <QDir>
#include <QFileInfo>

namespace octaclay::app {

QString suggestedSavePath(const QString& documentPath, const QString& importedFrom,
                          const QString& extension, const QString& fallbackFolder,
                          const QString& suffix) {
  const QString source = !documentPath.isEmpty() ? documentPath : importedFrom;
  const QString folder = source.isEmpty() ? fallbackFolder : QFileInfo(source).absolutePath();
  const QString base =
      source.isEmpty() ? QStringLiteral("untitled") : QFileInfo(source).completeBaseName();
  return QDir(folder).absoluteFilePath(base + suffix + QLatin1Char('.') + extension);
}

QString suggestedOpenFolder(const QString& documentPath, const QString& importedFrom,
                            const QString& fallbackFolder) {
  const QString source = !documentPath.isEmpty() ? documentPath : importedFrom;
  return source.isEmpty() ? fallbackFolder : QFileInfo(source).absolutePath();
}

} // namespace octaclay::app
