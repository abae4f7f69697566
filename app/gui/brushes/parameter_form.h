#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <QPointer>
#include <QString>
#include <QStringList>
#include <QWidget>

#include <array>
#include <functional>
#include <map>
#include <string>

class QComboBox;
class QFormLayout;

namespace octaclay::app {

/// Called with a parameter's id and the value the user just set.
using ParameterEdited = std::function<void(const std::string& id, std::array<float, 4> value)>;

/// Adds to layout one labelled row per parameter of brush, generated from its manifest: Float →
/// QDoubleSpinBox, Int → QSpinBox, Bool → QCheckBox, Color → ColorButton, Enum → QComboBox of
/// the options, Material → QComboBox of materials; each named "parameter-<id>", with the
/// manifest's range, step and tooltip, showing its entry in values (the default where there is
/// none). edited is called on each change the user makes. Returns the widgets by parameter id.
std::map<QString, QPointer<QWidget>>
addParameterRows(QFormLayout& layout, const gpu::BrushManifest& brush,
                 const std::map<std::string, std::array<float, 4>>& values,
                 const QStringList& materials, const ParameterEdited& edited);

/// A combo box that can be narrower than its longest item, so a narrow dock stays usable.
QComboBox* makeNarrowCombo();

} // namespace octaclay::app
