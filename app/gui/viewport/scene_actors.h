#pragma once

#include <vtkSmartPointer.h>

#include <vector>

class vtkActor;
class vtkPolyDataMapper;
class vtkRenderer;

namespace octaclay::app {

class Modeller;

/// The scene's other visible objects (every one but the edited one, which the ModelRenderer
/// draws from the GPU) as VTK actors in the same frame: each object's surface every
/// max(1, N/128)-th sample (core::extractMesh; at most 2 · 128² triangles an object) and coarser
/// levels down to 16 a side, each level a mapper of its own built once (its buffers stay on the
/// GPU between frames); before each frame the renderer draws (its StartEvent), each actor takes
/// the coarsest level whose outline segments stay within kOutlineSegmentPixels at the object's
/// size on screen. Its transform is the actor's user matrix, plain clay lit by VTK's headlight.
/// Built from the CPU documents the Modeller's scene holds, so nothing of theirs goes to the GPU as
/// textures. Called on the GUI thread.
class SceneActors {
public:
  /// The most samples a side an inactive object is drawn with.
  static constexpr int kMaxSide = 128;
  /// The fewest: a ball of 16 × 16 cells still reads as a ball.
  static constexpr int kMinSide = 16;
  /// Screen pixels a segment of an object's outline may span before a finer level is taken: a
  /// ball of side N has about 2N edges around its equator, so one d pixels across is drawn with
  /// side ≥ π·d / (2 · 10 px) (at 100 px: 16). 10 px, not 5: sixteen objects of N = 512 draw at
  /// 33 frames/s while one is stroked, not 24 (bench_viewport --scenes, llvmpipe, quiet).
  static constexpr double kOutlineSegmentPixels = 10;

  SceneActors() = default;
  SceneActors(const SceneActors&) = delete;
  SceneActors& operator=(const SceneActors&) = delete;
  ~SceneActors();

  /// Replaces the actors in renderer by those of modeller's scene as it is now.
  void rebuild(vtkRenderer& renderer, const Modeller& modeller);
  /// Removes them all from renderer.
  void clear(vtkRenderer& renderer);
  int count() const { return static_cast<int>(objects_.size()); }
  /// The cells a side actor k draws with now (after the last frame's choice).
  int shownSide(int k) const;
  /// Picks each actor's level for the renderer's camera and size (what each frame's StartEvent
  /// does).
  void chooseLevels(vtkRenderer& renderer);

private:
  struct Object {
    vtkSmartPointer<vtkActor> actor;
    std::vector<vtkSmartPointer<vtkPolyDataMapper>> levels; ///< finest first
    std::vector<int> sides;                                 ///< cells a side of each level
    double centre[3] = {0, 0, 0};                           ///< world bounding sphere
    double radius = 0;                                      ///< of the sphere around its box
    double breadth = 0; ///< its box's largest side: the outline's size on screen
    int shown = 0;      ///< index into levels
  };
  std::vector<Object> objects_;
  vtkSmartPointer<vtkRenderer> observed_;
  unsigned long observer_ = 0;
};

} // namespace octaclay::app
