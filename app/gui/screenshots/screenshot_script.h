#pragma once

#include <QString>

namespace octaclay::app {

class MainWindow;

/// Makes a few strokes on the window's model (a pulled ridge, inflated bumps, painted colour),
/// then saves the whole window as an image: the README's picture. Returns false with a message
/// on stderr if a stroke or the save failed.
bool makeScreenshot(MainWindow& window, const QString& imagePath);

} // namespace octaclay::app
