#pragma once

#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkRenderer;

namespace octaclay::app {

class Modeller;

/// The scene's other visible objects (every one but the edited one, which the ModelRenderer
/// draws from the GPU) as VTK actors in the same frame: each object's surface every
/// max(1, N/128)-th sample (core::extractMesh; at most 2 · 128² triangles an object), its
/// transform as the actor's user matrix, plain clay lit by VTK's headlight. Built from the CPU
/// documents the Modeller's scene holds, so nothing of theirs goes to the GPU as textures.
class SceneActors {
public:
  /// The most samples a side an inactive object is drawn with.
  static constexpr int kMaxSide = 128;

  /// Replaces the actors in renderer by those of modeller's scene as it is now.
  void rebuild(vtkRenderer& renderer, const Modeller& modeller);
  /// Removes them all from renderer.
  void clear(vtkRenderer& renderer);
  int count() const { return static_cast<int>(actors_.size()); }

private:
  std::vector<vtkSmartPointer<vtkActor>> actors_;
};

} // namespace octaclay::app
