#pragma once

#include <QString>

namespace octaclay::app {

class MainWindow;

/// The README's picture of issue 21 (docs/stretch.png): the window's document (a pulled limb)
/// seen from the side with Layers ▸ Preview ▸ Stretch, before and after Mesh ▸ Even Out Samples,
/// side by side in one image, each half captioned with its longest grid edge over the median
/// (core::summarizeStretch). Changes the window's camera, preview and document; needs the
/// viewport's GL started (waits up to 10 s). Returns false with a message on stderr if GL, the
/// even-out or the save failed.
bool makeStretchScreenshot(MainWindow& window, const QString& imagePath);

} // namespace octaclay::app
