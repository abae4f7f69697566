#pragma once

#include "lod_display.h"
#include "scene_actors.h"
#include "view_looks.h"

#include "octaclay/core/geometry/vec.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/model_renderer.h"

#include <QImage>
#include <QSize>
#include <QString>
#include <vtkNew.h>

#include <array>
#include <functional>
#include <memory>
#include <optional>

class QPaintDevice;
class QPainter;
class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;

namespace octaclay::app {

class Modeller;
class ModelProp;
class ViewportWidget;

/// The brush ring drawn on the model under the pointer.
struct BrushRing {
  core::Vec3f centre;
  float radius = 0; ///< object units
  bool inverted = false;
};

/// The viewport's frames: the VTK render window and renderers (the LOD's right half side by
/// side), the model drawn with gpu::ModelRenderer from the document's textures, the looks, the
/// displayed level, the previews, Save Image's offscreen render, and the marks painted over each
/// frame. Follows the modeller's change feed: the normals and stretch map of what changed are
/// recomputed at once. Composed into ViewportWidget, whose GL context it draws in.
class ViewportFrames {
public:
  ViewportFrames(ViewportWidget& widget, Modeller& modeller);
  ~ViewportFrames();

  /// The widget's context is current and new: the renderer starts. Returns false with the
  /// reason in error.
  bool glStarted(QString& error);
  /// The context is current and about to go.
  void glStopping();
  bool ready() const { return model_ != nullptr; }
  void resize(int width, int height); ///< device pixels
  /// A new document is on the GPU: every normal, the displayed level, no LOD yet.
  void documentReplaced();
  /// The scene's objects changed (added, removed, shown, hidden): the others drawn anew.
  void objectsChanged() { others_.rebuild(*renderer_, modeller_); }
  /// Draws a frame into the widget's framebuffer (GL current).
  void paint(QSize size, const std::optional<BrushRing>& ring);
  /// The frame painter's marks over the frame just drawn.
  void paintMarks(QPaintDevice& device);
  void setFramePainter(std::function<void(QPainter&)> paint) { framePainter_ = std::move(paint); }
  void setGizmoPainter(std::function<void(QPainter&)> paint) { gizmoPainter_ = std::move(paint); }

  void setLooks(const ViewLooks& looks);
  const ViewLooks& looks() const { return looks_; }
  void setPreview(gpu::ModelView::Preview preview) { preview_ = preview; }
  gpu::ModelView::Preview preview() const { return preview_; }
  void setShowDiffuse(bool show) { showDiffuse_ = show; }
  void setShowMask(bool show) { showMask_ = show; }
  /// Displays every divisor-th sample (N/divisor a side, at least 2). Throws what the renderer
  /// throws.
  void setLevelDivisor(int divisor);
  int levelDivisor() const { return divisor_; }
  void setLodDisplay(LodDisplay display);
  LodDisplay lodDisplay() const { return lodDisplay_; }
  void setLodMesh(std::shared_ptr<const core::LodMesh> lod) { pendingLod_ = std::move(lod); }
  long long lodTriangles() const;
  long long displayedTriangles() const;
  /// Whether frames go straight into the window's framebuffer (the model alone, a plain
  /// background) rather than through VTK's.
  bool drawsDirectly() const;
  /// The view drawn offscreen at size without the brush ring (see ViewportWidget::renderImage).
  QImage renderImage(QSize size, bool background);
  int maxImageSide();

  vtkRenderer* renderer() const;
  vtkRenderer* lodRenderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;
  /// The scene's world bounds (xmin, xmax, ymin, …): the edited object's tile boxes under its
  /// transform and every other visible object.
  const std::array<double, 6>& updateBounds();
  const std::array<double, 6>& bounds() const;
  /// The renderer (null before GL started): its normal and stretch maps.
  const gpu::ModelRenderer* modelRenderer() const { return model_.get(); }
  /// The last drawing error, empty if none.
  QString error() const { return error_; }

private:
  void drawModel(vtkRenderer* renderer);
  void renderVtkFrame();
  void renderDirectFrame(QSize size);
  void applyLooks(gpu::ModelView& view, vtkRenderer* r);
  void follow(const gpu::DocumentChange& change);
  void onContextEvent(vtkObject* caller, unsigned long event, void* callData);

  ViewportWidget& widget_;
  Modeller& modeller_;
  vtkNew<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<ModelProp> prop_;
  vtkNew<vtkRenderer> lodRenderer_; // the right half, side by side
  vtkNew<ModelProp> lodProp_;
  std::unique_ptr<gpu::ModelRenderer> model_;
  SceneActors others_; // the scene's other visible objects, in renderer_
  std::shared_ptr<const core::LodMesh> pendingLod_; // uploaded at the next frame
  std::optional<BrushRing> ring_;                   // during paint()
  LodDisplay lodDisplay_ = LodDisplay::FullResolution;
  gpu::ModelView::Preview preview_ = gpu::ModelView::Preview::Shaded;
  bool showDiffuse_ = true, showMask_ = true;
  int divisor_ = 4;
  ViewLooks looks_;
  QString loadedMatcap_; // the matcap model_ holds, empty before the first
  QString error_;
  std::function<void(QPainter&)> framePainter_;
  std::function<void(QPainter&)> gizmoPainter_; // under framePainter_'s marks
};

} // namespace octaclay::app
