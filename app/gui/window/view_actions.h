#pragma once

class QMainWindow;
class QMenu;

namespace octaclay::app {

class ViewportWidget;

/// Adds to the View menu: a Views submenu with the six standard views on the numeric keypad
/// (Blender's keys: 1 front, Ctrl+1 back, 3 right, Ctrl+3 left, 7 top, Ctrl+7 bottom),
/// Orthographic (keypad 5, checkable) and an Orbit submenu, Turntable (the default) or Free
/// Trackball, remembered in QSettings under "view/orbit". Actions are named actionViewFront …
/// actionViewBottom, actionOrthographic, actionOrbitTurntable and actionOrbitTrackball.
void addViewActions(QMenu* view, ViewportWidget* viewport);

/// Adds the View menu to window's menu bar: its docks' toggles, Frame Model (Home), the views
/// (addViewActions) and the looks (addLookActions).
void addViewMenu(QMainWindow& window, ViewportWidget* viewport);

} // namespace octaclay::app
