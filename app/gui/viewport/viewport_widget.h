#pragma once

#include "camera_control.h"
#include "camera_views.h"
#include "gl_host.h"
#include "lod_display.h"
#include "object_pick.h"
#include "object_placement.h"
#include "stroke_input.h"
#include "view_looks.h"
#include "viewport_frames.h"

#include "octaclay/core/geometry/ray_pick.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/gpu/model_renderer.h"

#include <QElapsedTimer>
#include <QImage>
#include <QOpenGLContext>
#include <QWidget>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

class QPainter;
class vtkGenericOpenGLRenderWindow;
class vtkRenderer;

namespace octaclay::app {

class Modeller;
class ViewportOverlay;
class ViewportSurface;

/// Frame and stroke figures for the status bar.
struct ViewportStats {
  double framesPerSecond = 0; ///< frames painted over the last second
  double lastDabMs = 0;       ///< engine time per dab of the last run that dabbed
  long long dabs = 0;         ///< dabs made since the modeller was created
  int n = 0;                  ///< the document's N
  long long displayedTriangles = 0, fullTriangles = 0; ///< displayed: the LOD's when shown alone
};

/// The 3D view of a Modeller: a native GL window (ViewportSurface) whose context also holds the
/// modeller's document and runs its brush engine, the frames drawn in it (ViewportFrames), the
/// camera, and the input. Left-drag sculpts (StrokeInput; Ctrl inverts, Shift smooths),
/// right- or middle-drag orbits, Shift+middle or Ctrl+right pans, the wheel zooms; a left-drag
/// that starts off the model (beyond the brush ring) orbits too.
class ViewportWidget : public QWidget, public GlHost {
  Q_OBJECT
public:
  explicit ViewportWidget(Modeller& modeller, QWidget* parent = nullptr);
  ~ViewportWidget() override;

  Modeller& modeller() const { return modeller_; }
  ViewportFrames& frames() { return *frames_; }
  StrokeInput& strokes() { return strokes_; }

  // GlHost: the native window's context; update() asks for a frame (hides QWidget::update).
  QOpenGLContext* context() const override;
  void makeCurrent() override;
  void doneCurrent() override;
  void update() override;
  /// The framebuffer frames are drawn into (the window's own: 0).
  GLuint defaultFramebufferObject() const;
  /// Draws a frame and returns its pixels without showing it.
  QImage grabFramebuffer();
  bool glReady() const { return frames_->ready() && glOk_; }
  /// Why GL failed, else the modeller's last error.
  QString error() const;

  // What the frames show (ViewportFrames), each asking for a frame.
  void setLooks(const ViewLooks& looks);
  const ViewLooks& looks() const { return frames_->looks(); }
  void setPreview(gpu::ModelView::Preview preview);
  void setShowDiffuse(bool show);
  void setShowMask(bool show);
  void setLevelDivisor(int divisor);
  int levelDivisor() const { return frames_->levelDivisor(); }
  void setLodDisplay(LodDisplay display);
  LodDisplay lodDisplay() const { return frames_->lodDisplay(); }
  void setLodMesh(std::shared_ptr<const core::LodMesh> lod);
  long long lodTriangles() const { return frames_->lodTriangles(); }
  bool drawsDirectly() const { return frames_->drawsDirectly(); }
  /// The view drawn offscreen at size (device pixels, up to maxImageSide() a side) without the
  /// brush ring; with background false the background is transparent. Null when GL is not ready.
  QImage renderImage(QSize size, bool background) { return frames_->renderImage(size, background); }
  int maxImageSide() { return frames_->maxImageSide(); }
  vtkRenderer* renderer() const { return frames_->renderer(); }
  vtkGenericOpenGLRenderWindow* renderWindow() const { return frames_->renderWindow(); }
  /// 2D marks painted over every frame the GL window shows (the F / Shift+F ring and value): a
  /// widget over the native window would hide the model. Not in renderImage(). Empty: none.
  void setFramePainter(std::function<void(QPainter&)> paint);
  /// The object gizmo's arrows, painted under the frame painter's marks. Empty: none.
  void setGizmoPainter(std::function<void(QPainter&)> paint);
  /// The legend and half labels over the view.
  ViewportOverlay* overlay() const { return overlay_; }

  /// The front view, framing the model (a new document is shown so).
  void resetCamera();
  /// Frames the model from the current direction (Home).
  void frameModel();
  /// Frames the model seen from towardEye (horizontal, unit) with +y up.
  void frameFrom(core::Vec3f towardEye);
  /// Turns the camera to a standard view about the focal point, keeping the zoom.
  void setView(ViewDirection direction);
  void setOrthographic(bool orthographic);
  bool orthographic() const;
  void setOrbitMode(OrbitMode mode) { orbitMode_ = mode; }
  OrbitMode orbitMode() const { return orbitMode_; }

  /// The surface point under widget position p (logical pixels), if any, in the active
  /// object's space (the pointer's ray carried there by placement()).
  std::optional<core::PickHit> pickAt(QPointF p) const;
  /// The visible surface of any object under widget position p, in world space, its normal
  /// turned towards the viewer (Shift+A adds there); nothing over the background.
  std::optional<SurfacePick> surfaceAt(QPointF p) const;
  /// Where point p of the active object's space appears in the widget (logical pixels; the
  /// left half side by side).
  QPointF project(core::Vec3f p) const;
  /// Where the active object sits (its transform): the camera is in world space, the document,
  /// its picks and the brush in the object's.
  ObjectPlacement placement() const;
  /// The part of the widget one model is drawn in (logical pixels): the left half side by side.
  QRectF modelRect() const;

  /// A scripted stroke fed as the mouse would (StrokeInput), for benchmarks, tests and the
  /// screenshot script; positions in logical pixels. endStroke waits for the stroke's step.
  void beginStrokeAt(QPointF p, Qt::KeyboardModifiers modifiers = {});
  void continueStrokeTo(QPointF p) { strokes_.moveTo(p); }
  void endStroke() { strokes_.end(StrokeDriver::Relax::Wait); }
  bool stroking() const;
  /// The surface point a press at p sculpts (StrokeInput::pressPick).
  std::optional<core::PickHit> pressPick(QPointF p) const { return strokes_.pressPick(p); }

  ViewportStats stats() const;

signals:
  void statsChanged();
  /// [ / ] (radius) and Shift+[ / ] (strength): factor > 1 grows.
  void radiusStepRequested(float factor);
  void strengthStepRequested(float factor);
  /// A frame showing the document was drawn.
  void framePainted();
  /// A left press is about to begin a stroke at the image point uv (the press's one pick).
  void strokePressed(core::Vec2f uv);
  /// A frame reached the screen.
  void frameSwapped();

protected:
  friend class ViewportSurface;
  void initializeGL();
  void resizeGL(int width, int height);
  void paintGL();
  void paintMarks(QPaintDevice& device) { frames_->paintMarks(device); }
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void wheelEvent(QWheelEvent* event) override;
  void tabletEvent(QTabletEvent* event) override;
  void keyPressEvent(QKeyEvent* event) override;
  void leaveEvent(QEvent* event) override;
  void resizeEvent(QResizeEvent* event) override;

private:
  // ObjectClick: an Alt+left press that selects the object under it at its release, or orbits
  // (as an Alt+left drag always did) once the pointer moves more than a few pixels.
  enum class Drag { None, Sculpt, Orbit, Pan, ObjectClick };

  void documentReplaced(bool keepView);
  // Object k moved (-1: objects changed): the other objects' actors are rebuilt, then a frame.
  void objectMoved(int k);
  /// The brush ring at the hovered point, if one is shown.
  std::optional<BrushRing> ring() const;
  /// Alt+click: makes the visible object under widget position p the edited one
  /// (Modeller::setActiveObject); nothing when none is there.
  void selectObjectAt(QPointF p);

  Modeller& modeller_;
  ViewportSurface* surface_ = nullptr; // owned by its container, a child of this widget
  QWidget* container_ = nullptr;
  std::unique_ptr<ViewportFrames> frames_;
  StrokeInput strokes_;
  Drag drag_ = Drag::None;
  OrbitMode orbitMode_ = OrbitMode::Turntable;
  Qt::MouseButton dragButton_ = Qt::NoButton; ///< the button whose release ends drag_
  QPointF lastPos_;
  QPointF pressPos_; // where the current drag's button went down
  bool glStarted_ = false, glOk_ = false;
  QString glError_;
  QElapsedTimer clock_;
  std::deque<qint64> frameTimes_;
  ViewportOverlay* overlay_ = nullptr;
};

} // namespace octaclay::app
