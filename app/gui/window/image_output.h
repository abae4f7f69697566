#pragma once

#include <QImage>
#include <QString>

namespace octaclay::app {

/// Writes image as a PNG through the one output writer (core::OutputSet: all or nothing).
/// Returns false with a message on stderr when it cannot.
bool saveImagePng(const QImage& image, const QString& path);

} // namespace octaclay::app
