#pragma once

#include "brush_settings.h"
#include "camera_control.h"
#include "camera_views.h"
#include "lod_display.h"
#include "saliency_keeper.h"
#include "sculpt_session.h"
#include "stroke_stabilizer.h"
#include "view_looks.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/edit_layer.h"
#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/material_catalog.h"
#include "octaclay/gpu/model_renderer.h"

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLContext>
#include <QWidget>
#include <vtkNew.h>

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <optional>

class QPainter;
class vtkGenericOpenGLRenderWindow;
class vtkObject;
class vtkRenderer;

namespace octaclay::gpu {
class BrushLibrary;
class GlContext;
class ModelRenderer;
} // namespace octaclay::gpu

namespace octaclay::app {

class ModelProp;
class ViewportOverlay;
class ViewportSurface;

/// Frame and stroke figures for the status bar.
struct ViewportStats {
  double framesPerSecond = 0; ///< frames painted over the last second
  double lastDabMs = 0;       ///< engine time per dab of the last frame that dabbed
  long long dabs = 0;         ///< dabs made since the viewport was created
  int n = 0;                  ///< the document's N
  long long displayedTriangles = 0, fullTriangles = 0; ///< displayed: the LOD's when shown alone
};

/// The 3D view: a native GL window (ViewportSurface) hosting a vtkGenericOpenGLRenderWindow (VTK's
/// Qt module is built for Qt5), whose GL context also runs the brush engine, so the full-resolution
/// image never crosses to the CPU per frame. Owns the edited document (GPU textures plus the
/// engine's CPU mirror), its brush library and its stroke history, sculpted through a
/// SculptSession. Left-drag sculpts (Ctrl inverts, Shift smooths), right- or middle-drag orbits,
/// Shift+middle or Ctrl+right pans, the wheel zooms; a left-drag that starts off the model orbits
/// too.
class ViewportWidget : public QWidget {
  Q_OBJECT
public:
  explicit ViewportWidget(QWidget* parent = nullptr);
  ~ViewportWidget() override;

  /// Asks for a frame (hides QWidget::update: the frames are the native window's).
  void update();
  /// The GL context (null before GL started) and making it current, as a QOpenGLWidget's.
  QOpenGLContext* context() const;
  void makeCurrent();
  void doneCurrent();
  /// The framebuffer frames are drawn into (the window's own: 0).
  GLuint defaultFramebufferObject() const;
  /// Draws a frame and returns its pixels without showing it.
  QImage grabFramebuffer();

  /// Replaces the document and clears the stroke history (uploaded now if GL is ready, else at
  /// GL start). Returns false with error() set if the upload failed; the previous document
  /// then stays. A new model is framed from the front; with keepView the camera stays where it
  /// is (Mesh ▸ Remesh and Resolution replace the document with the same surface).
  bool setDocument(core::Document document, bool keepView = false);
  bool hasDocument() const;
  /// The document as edited so far (the engine's CPU mirror). Only valid if hasDocument().
  const core::Document& document() const;

  /// The brush library (null until GL started). Scan and compile happen on the GL thread.
  gpu::BrushLibrary* library() { return library_.get(); }
  /// Polls the brush folders and reloads what changed or appeared; emits brushesChanged() if
  /// anything did. Returns the messages of failed reloads.
  QStringList reloadBrushes();

  void setBrushSettings(const BrushSettings& settings);
  const BrushSettings& brushSettings() const { return settings_; }
  /// The layer paint-category brushes write (diffuse, feature or mask).
  void setPaintTarget(core::EditLayer layer);
  void setShowDiffuse(bool show);
  void setShowMask(bool show);
  /// The shaded model, one layer channel alone, or the saliency (the positions' alpha) as a
  /// heat map.
  void setPreview(gpu::ModelView::Preview preview);
  /// The materials splat brushes can use (engine order) and those that failed to load.
  QStringList materialIds() const;
  QStringList materialErrors() const;
  /// Displays every divisor-th sample (N/divisor a side, clamped to at least 2).
  void setLevelDivisor(int divisor);
  int levelDivisor() const { return divisor_; }

  /// What the view shows: the full resolution, the level of detail setLodMesh gave (the full
  /// resolution until there is one), or both side by side (full resolution left, LOD right, one
  /// camera; either half sculpts).
  void setLodDisplay(LodDisplay display);
  LodDisplay lodDisplay() const { return lodDisplay_; }
  /// The LOD to show (uploaded at the next frame).
  void setLodMesh(std::shared_ptr<const core::LodMesh> lod);
  /// Triangles of the LOD the view draws (0 until one was uploaded).
  long long lodTriangles() const;
  /// A copy of the current positions (xyz and saliency), or null without a document.
  std::shared_ptr<const core::GeometryImage> positionsSnapshot() const;
  /// While wanted (the saliency heat map, a salient LOD), the positions' alpha holds the
  /// saliency of the current surface: recomputed if stale, and after each stroke, undo, redo and
  /// new document — on the GPU (gpu::SaliencyPass) at once, or with the CPU reference on a
  /// worker thread (see setSaliencyOnCpu), surfaceChanged() telling when it is in.
  void setSaliencyWanted(bool wanted);
  /// Whether the positions' alpha is the saliency of the current surface.
  bool saliencyCurrent() const { return saliency_.current(); }
  /// Computes the saliency with core::computeSaliency off the GUI thread instead of on the GPU.
  /// On by default where GL is a software rasterizer (llvmpipe): there the GPU pass is CPU work
  /// that would hold the GUI thread for seconds at N = 1024, the threaded CPU reference less and
  /// in the background.
  void setSaliencyOnCpu(bool onCpu) { saliency_.setOnCpu(onCpu); }
  bool saliencyOnCpu() const { return saliency_.onCpu(); }

  bool canUndo() const { return session_.history().canUndo(); }
  bool canRedo() const { return session_.history().canRedo(); }
  /// Reverts / reapplies the newest stroke on the GPU and the mirror; false if there is none.
  bool undoStroke();
  bool redoStroke();
  core::EditHistory& history() { return session_.history(); }
  /// Makes `after` (same size as the document) the document on the GPU and the mirror as one
  /// step of history() labelled label (SculptSession::applyChange), then refreshes what undo
  /// refreshes: the normals of the changed texels, the saliency and, through surfaceChanged(),
  /// the LOD. Returns whether a step was recorded (false: no document, a stroke is being made,
  /// or nothing differed). GL work on the GUI thread. Throws what the session throws; the
  /// normals are then redrawn from whatever the layers hold.
  bool applyChange(const core::Document& after, const std::string& label);
  /// Whether the session relaxes what sculpt strokes stretch: the brush settings' keepDetail as
  /// of the last stroke begun (StrokeStart::settings).
  bool keepsDetail() const { return session_.keepDetail(); }

  /// The front view, framing the model (a new document is shown so).
  void resetCamera();
  /// The model's bounding-box diagonal (1 without a document): the unit of the brush radius.
  float modelDiagonal() const { return session_.diagonal(); }
  /// Frames the model from the current direction (Home): its bounding sphere fills the view.
  void frameModel();
  /// Frames the model seen from towardEye (horizontal, unit) with +y up: an imported or opened
  /// model's first view, from the side core::guessFacing() takes for its front.
  void frameFrom(core::Vec3f towardEye);
  /// Turns the camera to a standard view about the focal point, keeping the zoom.
  void setView(ViewDirection direction);
  void setOrthographic(bool orthographic);
  bool orthographic() const;
  void setOrbitMode(OrbitMode mode) { orbitMode_ = mode; }
  OrbitMode orbitMode() const { return orbitMode_; }
  /// The view drawn offscreen at size (device pixels, up to maxImageSide() a side) without the
  /// brush outline; with background false the background is transparent (alpha 0) and the model
  /// opaque. Null when GL is not ready or the size is out of range. GL work on the GUI thread.
  QImage renderImage(QSize size, bool background);
  /// The largest side renderImage() draws (the GL framebuffer limit, 8192 at most).
  int maxImageSide();
  /// The surface point under widget position p (logical pixels), if any.
  std::optional<core::PickHit> pickAt(QPointF p) const;
  /// The surface point a press at p sculpts: the one under p, else the nearest within the brush
  /// ring's radius on screen (a press just off a thin limb or the silhouette sculpts there, as
  /// Blender's does); none: the press orbits.
  std::optional<core::PickHit> pressPick(QPointF p) const;
  /// Where object-space point p appears in the widget (logical pixels).
  QPointF project(core::Vec3f p) const;

  /// Feeds one point of a scripted stroke as the mouse would (begin, move…, end), for
  /// benchmarks and the screenshot script; positions in logical pixels.
  void beginStrokeAt(QPointF p, Qt::KeyboardModifiers modifiers = {});
  /// As above, at a point already picked (a press picks once).
  void beginStrokeAt(QPointF p, const core::PickHit& hit, Qt::KeyboardModifiers modifiers = {});
  void continueStrokeTo(QPointF p);
  void endStroke();
  bool stroking() const { return session_.stroking(); }

  ViewportStats stats() const;
  /// Why GL or a brush failed, empty if nothing did.
  QString error() const { return error_; }
  bool glReady() const { return model_ != nullptr; }
  /// Whether frames are the model alone on a plain background, drawn straight into the GL
  /// window's framebuffer; otherwise (side by side, a gradient, another prop in renderer()) VTK
  /// renders them into its own and they are copied over.
  bool drawsDirectly() const;

  vtkRenderer* renderer() const;
  vtkGenericOpenGLRenderWindow* renderWindow() const;

  /// The material (lit or a matcap), wireframe overlay and background (viewport_looks.cpp).
  void setLooks(const ViewLooks& looks);
  const ViewLooks& looks() const { return looks_; }
  /// 2D marks painted over every frame the GL window shows, after the model (logical pixels;
  /// the F / Shift+F ring and value): a widget over the GL window would hide the model, since a
  /// native window shows nothing through it. Not in renderImage() or grabFramebuffer(). Empty:
  /// none. Asks for a frame.
  void setFramePainter(std::function<void(QPainter&)> paint);
  /// The legend and half labels over the view.
  ViewportOverlay* overlay() const { return overlay_; }

signals:
  /// A stroke was recorded in history() (push an undo command labelled so).
  void strokeFinished(const QString& label);
  void brushesChanged();
  void statsChanged();
  /// [ / ] (radius) and Shift+[ / ] (strength): factor > 1 grows.
  void radiusStepRequested(float factor);
  void strengthStepRequested(float factor);
  void errorOccurred(const QString& message);
  /// A frame showing the document was drawn.
  void framePainted();
  /// A left press is about to begin a stroke at the image point uv (the press's one pick).
  void strokePressed(core::Vec2f uv);
  /// The surface changed (dabs, a finished stroke, undo, redo, a new document).
  void surfaceChanged();

  /// A frame reached the screen.
  void frameSwapped();

protected:
  friend class ViewportSurface;
  void initializeGL();
  void resizeGL(int width, int height);
  void paintGL();
  /// The frame painter's marks over the frame just drawn (ViewportSurface::paintGL).
  void paintMarks(QPaintDevice& device);
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void tabletEvent(QTabletEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  enum class Drag { None, Sculpt, Orbit, Pan };

  bool uploadDocument(core::Document document, bool keepView = false);
  void onRenderWindowEvent(vtkObject* caller, unsigned long event, void* callData);
  void drainGlErrors();
  void drawModel(vtkRenderer* renderer);
  void queueStrokePoint(QPointF p);
  /// Runs the queued dabs (GL current). Returns how many were made.
  int runQueuedDabs();
  void finishStroke();
  /// Recomputes the normals the touched texels' neighbourhoods read.
  void refreshNormalsAround(std::vector<core::TexelRect> touched);
  /// Redraws every normal and the picking bounds after the layers were put back wholesale.
  void refreshAllNormals();
  /// Undo or redo on the GPU and the mirror, then the normals of what changed.
  bool stepHistory(bool undo);
  /// Recomputes the saliency if wanted and stale (GL current), or starts the CPU job.
  void refreshSaliency();
  void cpuSaliencyFinished();
  /// The surface changed: the saliency is stale.
  void surfaceEdited();
  /// The part of the widget one model is drawn in (logical pixels): the left half side by side.
  QRectF modelRect() const;
  void applyLodDisplay();
  void updateClipping();
  /// VTK's frame (both renderers) into its framebuffers, GL state cache reset around it.
  void renderVtkFrame();
  void renderDirectFrame(QSize size);
  /// The model's bounds from the document's tile boxes, for framing and clipping.
  void updateBounds();
  void fail(const QString& message);
  /// Fills view's material and wireframe fields, loading the matcap on first use (GL current).
  void applyLooks(gpu::ModelView& view, vtkRenderer* r);

  ViewportSurface* surface_ = nullptr; // owned by its container, a child of this widget
  QWidget* container_ = nullptr;
  vtkNew<vtkGenericOpenGLRenderWindow> renderWindow_;
  vtkNew<vtkRenderer> renderer_;
  vtkNew<ModelProp> prop_;
  vtkNew<vtkRenderer> lodRenderer_; // the right half, side by side
  vtkNew<ModelProp> lodProp_;

  std::unique_ptr<gpu::GlContext> context_;
  std::unique_ptr<gpu::BrushLibrary> library_;
  std::unique_ptr<gpu::ModelRenderer> model_;
  SaliencyKeeper saliency_;
  LodDisplay lodDisplay_ = LodDisplay::FullResolution;
  std::shared_ptr<const core::LodMesh> pendingLod_; // uploaded at the next frame
  SculptSession session_;
  std::optional<core::Document> pending_; // set before GL started (or when it failed)

  BrushSettings settings_;
  core::EditLayer paintTarget_ = core::EditLayer::Diffuse;
  bool showDiffuse_ = true, showMask_ = true;
  gpu::ModelView::Preview preview_ = gpu::ModelView::Preview::Shaded;
  gpu::MaterialCatalog materials_;
  QStringList materialErrors_;
  int divisor_ = 4;

  StrokeStabilizer stabilizer_;
  std::optional<core::PickHit> hover_;
  Drag drag_ = Drag::None;
  OrbitMode orbitMode_ = OrbitMode::Turntable;
  Qt::MouseButton dragButton_ = Qt::NoButton; ///< the button whose release ends drag_
  QPointF lastPos_;
  float tabletPressure_ = 1.0f;
  bool tabletDown_ = false;

  bool glStarted_ = false;
  bool uploading_ = false;
  QString error_;
  QElapsedTimer clock_;
  std::deque<qint64> frameTimes_;
  ViewLooks looks_;
  QString loadedMatcap_; // the matcap model_ holds, empty before the first
  ViewportOverlay* overlay_ = nullptr;
  std::function<void(QPainter&)> framePainter_;
};

} // namespace octaclay::app
