#pragma once

#include <QImage>
#include <QSize>
#include <QString>

class QStatusBar;

namespace octaclay::app {

/// Writes image as a PNG through the one output writer (core::OutputSet: all or nothing).
/// Returns false with a message on stderr when it cannot.
bool saveImagePng(const QImage& image, const QString& path);

class ViewportWidget;

/// File ▸ Save Image: viewport drawn offscreen at size (device pixels) with or without its
/// background (transparent), written to path as PNG; statusBar says what happened.
bool saveViewImage(ViewportWidget& viewport, QStatusBar& statusBar, const QString& path, QSize size,
                   bool background);

} // namespace octaclay::app
