#pragma once

class QMainWindow;

namespace octaclay::app {

class BrushState;
class ViewportWidget;

/// Adds the brush tool bars above the viewport and the canvas's brush keys to window, each a view
/// of state that writes into it: the icons (one per brush, its shortcut picking it), the header
/// (radius, strength, symmetry), F / Shift+F (CanvasBrushAdjust: actionAdjustRadius,
/// actionAdjustStrength) and [ / ], Shift+[ / ] (the viewport's step requests). GUI thread.
void addBrushBars(QMainWindow& window, ViewportWidget& viewport, BrushState& state);

} // namespace octaclay::app
