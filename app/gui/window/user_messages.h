#pragma once

#include <QString>

class QStatusBar;

namespace octaclay::app {

/// "<failed> <path>: <reason>" with the path said once: core's errors start with the file's
/// path ("<path>: genus 1…"), which failed (e.g. "Could not import") already names, so a reason
/// starting with path or its file name loses that prefix.
QString failureMessage(const QString& failed, const QString& path, const QString& reason);

/// Shows message's first line in bar for timeoutMs, elided in the middle to the bar's width,
/// with the whole message as the bar's tooltip while it shows (the message box has it too).
void showStatusMessage(QStatusBar& bar, const QString& message, int timeoutMs);

/// Whether path names a mesh File ▸ Import Mesh reads (.obj, .ply, .stl, .off), not a model.
bool isImportableMesh(const QString& path);

} // namespace octaclay::app
