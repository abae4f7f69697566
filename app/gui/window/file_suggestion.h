#pragma once

#include <QString>

namespace octaclay::app {

/// Where a save or export dialog opens, and the name it offers: beside the document, with its
/// base name and `extension` (e.g. "exr", "glb") and `suffix` before it ("_lod"). The document
/// is documentPath when it has one, else the mesh it was imported from (importedFrom), else
/// "untitled" in fallbackFolder (the user's documents folder). Returns an absolute path.
QString suggestedSavePath(const QString& documentPath, const QString& importedFrom,
                          const QString& extension, const QString& fallbackFolder,
                          const QString& suffix = {});

/// The folder an open or import dialog starts in: the document's folder, else the folder of
/// the mesh it was imported from, else fallbackFolder.
QString suggestedOpenFolder(const QString& documentPath, const QString& importedFrom,
                            const QString& fallbackFolder);

} // namespace octaclay::app
