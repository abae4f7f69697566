#pragma once

namespace octaclay::app {

class MainWindow;

/// The Objects menu (menuObjects, between Add and View) and the Objects tool bar
/// (objectsToolBar: Add ▾, Duplicate, Mirror X ▾), Blender's keys:
/// - Duplicate (actionDuplicateObject, Shift+D): a copy of the edited object made the edited one
///   (Modeller::duplicateActiveObject), named uniquely ("Body.001");
/// - Mirror Duplicate ▸ X / Y / Z (actionMirrorDuplicateX … Z): a copy mirrored across the
///   scene's plane through the origin (a pair of legs, ears or eyes);
/// - Delete Object (the Add menu's actionDeleteObject, the Delete key on the viewport);
/// - Hide (actionHideObject, H): the edited object; Hide Others (actionHideOthers, Shift+H);
///   Show All (actionShowAllObjects, Alt+H on the viewport: Alt+H elsewhere is Help's mnemonic);
/// - Frame Selected (actionFrameSelected, also in View; the numeric keypad's . or Delete with
///   NumLock off, taken from the viewport's key events as the keypad views are): the camera
///   frames the edited object's world box from where it looks;
/// - Merge (actionMergeObjects): ObjectMerge on the objects the Objects dock selects (two or
///   more), else every visible object.
/// Call once the Add and View menus exist.
void addObjectsMenu(MainWindow& window);

} // namespace octaclay::app
