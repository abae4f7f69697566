#pragma once

namespace octaclay::app {

class MainWindow;

/// The Add menu (menuAdd): a new object per base shape (Sphere, Cube, Cylinder, Blob, Capsule;
/// octahedral ones only), named by its shape (made unique: "Sphere.001"), at the active object's
/// N, at the view's focal point, about a quarter of the scene's size, made the edited one. Also
/// Delete Object (actionDeleteObject, the Delete key on the viewport): removes the edited one.
void addAddMenu(MainWindow& window);

} // namespace octaclay::app
