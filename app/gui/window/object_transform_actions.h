#pragma once

namespace octaclay::app {

class MainWindow;

/// Moving, rotating and scaling objects on the canvas (issue 33), as the window offers them:
///
/// - Object Mode (actionObjectMode; Tab on the viewport; the "Move Objects" tool-bar toggle):
///   shows the move gizmo (TransformGizmo) on the edited object and gives G, R and S to Move,
///   Rotate and Scale. Adding an object turns it on (the new object shows its arrows, as Nomad
///   shows a selection's); picking a brush (its icon or key) turns it off; off, G, R and S pick
///   the grab, relax and smooth brushes as before.
/// - Move, Rotate, Scale (actionMoveObject, actionRotateObject, actionScaleObject; G, R, S in
///   Object Mode) start ObjectTransformMode at the pointer; chosen from the menu they turn
///   Object Mode on first.
///
/// All of them go in the Add menu, after its shapes; the gesture's text ("Move X: 0.5") shows in
/// the status bar while it runs, a refusal (a locked object) as a status message.
void addObjectTransformActions(MainWindow& window);

} // namespace octaclay::app
