#pragma once

#include "octaclay/gpu/brush_manifest.h"

#include <QColor>
#include <QIcon>
#include <QString>

namespace octaclay::app {

/// The colour of a brush category, shared by the generated icons and resources/icons/brushes
/// (tools/make_brush_icons.py): sculpt terracotta, paint blue, splat green.
QColor brushCategoryColour(gpu::Category category);

/// Up to two letters naming a brush on its generated icon: the initials of a name of several
/// words ("Sphere Add" → "SA"), else its first two letters ("Push" → "Pu").
QString brushInitials(const QString& name);

/// An icon drawn from the brush's name and category: its initials in white on a rounded square
/// of the category's colour.
QIcon generatedBrushIcon(const gpu::BrushManifest& brush);

/// The manifest's icon (SVG or PNG) rendered at 24, 32 and 48 pixels, or generatedBrushIcon when
/// the manifest names none or the file cannot be read (an SVG needs Qt's svg image plugin).
/// fromFile, when given, says which.
QIcon brushIcon(const gpu::BrushManifest& brush, bool* fromFile = nullptr);

} // namespace octaclay::app
