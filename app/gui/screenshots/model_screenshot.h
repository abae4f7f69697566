#pragma once

#include <QString>

namespace octaclay::app {

class MainWindow;

/// Shows the window's document in the clay matcap from the front right (a little above), with
/// the brush `brushId` chosen in the tool bar, then saves the whole window as an image: the
/// README's picture of a model (docs/creature.png, scripts/creature-screenshot). Returns false
/// with a message on stderr if there is no GL context or document, or the save failed.
bool makeModelScreenshot(MainWindow& window, const QString& brushId, const QString& imagePath);

} // namespace octaclay::app
