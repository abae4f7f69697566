#pragma once

#include <QKeySequence>
#include <QString>

namespace octaclay::app {

/// The keys that pick the common built-in brushes (X push, S smooth, I inflate, T flatten,
/// R relax, P paint, M mask), empty for any other brush. The one table of them: the brush
/// actions take their shortcuts from here, and the shortcut sheet lists those actions. F and
/// Shift+F are the canvas radius and strength drags (canvas_brush_adjust.h).
QKeySequence brushShortcut(const QString& brushId);

} // namespace octaclay::app
