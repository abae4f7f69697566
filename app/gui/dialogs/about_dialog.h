#pragma once

#include <QString>

class QWidget;

namespace octaclay::app {

/// Help ▸ About's text (HTML): Octaclay's version and every library it is built on with its
/// licence (Qt LGPL-3, VTK BSD-3, OpenEXR BSD-3, OpenCV Apache-2, OpenMesh BSD-3, Eigen MPL-2,
/// tinygltf MIT, CLI11 BSD-3, nlohmann-json MIT, libepoxy MIT).
QString aboutText();

/// Opens Help ▸ About over parent (window-modal, returns at once).
void showAbout(QWidget* parent);

} // namespace octaclay::app
