#pragma once

namespace octaclay::app {

class MainWindow;

/// The Add menu (menuAdd): a new object per shape (Sphere, Cube, Cylinder, Blob, Capsule, Torus,
/// Plane, Disc), named by its shape (made unique: "Sphere.001"), at the active object's
/// N, about a quarter of the scene's size, made the edited one: upright (its z along the scene's
/// up, as Blender adds) at the view's focal point, or, from Shift+A in the view
/// (actionAddAtPointer: the menu pops up at the pointer), centred on the surface under the
/// pointer and standing on it (its z along the normal there). Also
/// Delete Object (actionDeleteObject, the Delete key on the viewport): removes the edited one.
void addAddMenu(MainWindow& window);

} // namespace octaclay::app
