#pragma once

#include <QString>

namespace octaclay::app {

class MainWindow;

/// The whole-model operation a stretch picture shows.
enum class StretchOperation {
  EvenOut, ///< Mesh ▸ Even Out Samples (docs/stretch.png: issue 21's pulled limb)
  Remesh,  ///< Mesh ▸ Remesh… at the current N (docs/remesh.png: the snake-hooked creature)
};

/// A README picture: the window's document with Layers ▸ Preview ▸ Stretch, before and after
/// the operation, side by side in one image, each half captioned with its longest grid edge
/// over the median (core::summarizeStretch). The limb (EvenOut) is seen from the side, the
/// creature (Remesh) from the front right. Changes the window's camera, preview and document;
/// needs the viewport's GL started (waits up to 10 s). Returns false with a message on stderr
/// if GL, the operation or the save failed.
bool makeStretchScreenshot(MainWindow& window, const QString& imagePath,
                           StretchOperation operation = StretchOperation::EvenOut);

} // namespace octaclay::app
