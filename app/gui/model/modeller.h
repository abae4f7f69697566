#pragma once

#include "brush_state.h"
#include "gl_host.h"
#include "saliency_keeper.h"
#include "scene_history.h"
#include "scene_step.h"
#include "sculpt_session.h"
#include "storage_ahead.h"
#include "stroke_driver.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/edit_history.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/gpu/gpu_document.h"
#include "octaclay/gpu/material_catalog.h"

#include <QObject>
#include <QStringList>

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace octaclay::gpu {
class BrushLibrary;
class GlContext;
} // namespace octaclay::gpu

namespace octaclay::app {

/// The modeller without its widgets: the scene of objects (core::Scene) and its active object,
/// whose document is the edited one (on the GPU, in a SculptSession); the
/// brushes and materials, the brush state, the strokes (StrokeDriver), the scene's one history
/// with undo and redo (SceneHistory: every object's strokes and operations and the scene's own
/// steps), and the followers of the document's one change feed (gpu::DocumentChange: the saliency
/// here, the renderer's normals and stretch map through followChanges, the live LOD through
/// surfaceChanged). The window, docks, tool bar, header and viewport observe it. GUI thread;
/// its GL work runs in the GlHost's context (the viewport's), made current by the modeller.
class Modeller : public QObject {
  Q_OBJECT
public:
  explicit Modeller(QObject* parent = nullptr);
  ~Modeller() override;

  /// The host's context is current and new: loads the brushes and materials, uploads a pending
  /// document. Returns false with error() set when GL cannot sculpt.
  bool glStarted(GlHost& host);
  /// The host's context is current and about to go: frees every GL object.
  void glStopping();
  bool glReady() const { return library_ != nullptr; }
  GlHost* glHost() const { return host_; }

  /// Replaces the scene by one object ("Model", identity transform) holding document and clears
  /// the history (uploaded now if GL is ready, else at GL start). Returns false with error() set
  /// if the upload failed; the previous scene then stays. documentReplaced(keepView) tells the
  /// viewport.
  bool setDocument(core::Document document, bool keepView = false);
  /// Replaces the scene (at least one object) and makes object `active` the edited one, the
  /// history cleared; as setDocument otherwise. sceneChanged() follows a success.
  bool setScene(core::Scene scene, int active = 0, bool keepView = false);
  bool hasDocument() const;
  /// The active object's document as edited so far (the CPU mirror): while a stroke's relaxation
  /// is being solved, the surface as shown, without it. Only valid if hasDocument().
  const core::Document& document() const;

  /// The whole scene, the active object holding its current document() (a copy of every
  /// object: for saving). Empty without a document.
  core::Scene scene() const;
  /// How many objects the scene holds (0 without a document) and which one is edited.
  int objectCount() const { return static_cast<int>(scene_.objects.size()); }
  int activeObject() const { return active_; }
  /// Object k's name, transform, visibility and lock, and for an inactive object its document.
  /// The active object's `document` is empty here: its current one is document().
  const core::SceneObject& objectAt(int k) const { return scene_.objects.at(std::size_t(k)); }
  /// Makes object k the edited one: the active object's current document goes back into the
  /// scene and object k's is uploaded, the camera kept. Not a step, and nothing is cleared: each
  /// object's document history goes with it (SceneHistory), so the steps of the object left
  /// stay in the one history (undoing one makes that object the edited one again). False, with
  /// nothing changed, for an index out of range, while a stroke is made or when the upload
  /// fails (error() set); true without work for the active object.
  bool setActiveObject(int k);
  /// Object k's visibility, lock and name (modeller_objects.cpp), each change one step of the
  /// history ("Hide Hat", "Lock Body", "Rename Ball → Head"): objectsChanged follows a change.
  /// renameObject returns why a name is refused (empty when it was taken).
  bool setObjectVisible(int k, bool visible);
  /// The same for several objects as one step named label (Show All, Hide Others): one undo
  /// brings them all back. No step when none changes.
  bool setObjectsVisible(const std::vector<int>& objects, bool visible, const std::string& label);
  bool setObjectLocked(int k, bool locked);
  QString renameObject(int k, const QString& name);
  /// Places object k (the door every move, rotation and scale goes through: the G/R/S mode's
  /// confirm, the CLI's transform), one step of the history ("Move Head", "Rotate …", "Scale …")
  /// from the transform before any preview to this one: returns why a transform is refused
  /// (transformProblem), empty when it was taken; objectsChanged follows a change.
  QString setObjectTransform(int k, const core::ObjectTransform& transform);
  /// Shows object k under transform while a G/R/S gesture runs, recording nothing and leaving
  /// the document unmodified (objectMoved follows); setObjectTransform or a preview of the
  /// transform before ends it. Returns false for an index out of range or a refused transform.
  bool previewObjectTransform(int k, const core::ObjectTransform& transform);
  /// Whether the edited object is shown (the Objects dock's eye): hidden, it is neither drawn
  /// nor picked. True without a scene.
  bool activeShown() const {
    return active_ < 0 || active_ >= objectCount() || objectAt(active_).visible;
  }
  /// Whether the edited object is locked: strokes on it are refused (refused() says so).
  bool activeLocked() const;
  /// Appends object (named uniquely from its name) and makes it the edited one, one step (label,
  /// by default "Add Sphere"). False, with nothing added, when setActiveObject refuses or fails.
  bool addObject(core::SceneObject object, const QString& label = {});
  /// Removes the edited object; the one before it (or the next) becomes the edited one. One step
  /// ("Delete Cube") that holds the removed object's document. Returns why it was refused (the
  /// last object, a stroke being made), empty on success.
  QString deleteActiveObject();
  /// Replaces the objects at `removed` (indices, at least one, the edited one may be among them)
  /// by `added` (named uniquely), appended and made the edited one: Objects ▸ Merge's door, one
  /// step labelled label. Returns why it was refused (an index out of range, a stroke being
  /// made, the upload failed), empty on success.
  QString replaceObjects(const std::vector<int>& removed, core::SceneObject added,
                         const QString& label);
  /// Moves object `from` to position `to` in the scene's order (the Objects dock's drag), one
  /// step ("Reorder Objects"): the edited object stays the edited one. False for an index out of
  /// range.
  bool moveObject(int from, int to);
  /// A copy of the current positions (xyz and saliency), or null without a document.
  std::shared_ptr<const core::GeometryImage> positionsSnapshot() const;
  /// The model's bounding-box diagonal (1 without a document): the unit of the brush radius.
  float modelDiagonal() const { return session_.diagonal(); }
  /// Whether a document is being uploaded (its bands let the event loop run: draw nothing).
  bool uploading() const { return uploading_; }

  /// The session the document lives in (for drawing it: gpuDocument()).
  SculptSession& session() { return session_; }
  const SculptSession& session() const { return session_; }
  BrushState& brushState() { return brushState_; }
  StrokeDriver& strokes() { return strokes_; }
  const StrokeDriver& strokes() const { return strokes_; }

  /// The brush library (null until GL started).
  gpu::BrushLibrary* library() { return library_.get(); }
  /// Polls the brush folders and reloads what changed or appeared; the brush state gets the new
  /// list if anything did. Returns the messages of failed reloads.
  QStringList reloadBrushes();
  /// The materials splat brushes can use (engine order) and those that failed to load.
  QStringList materialIds() const;
  QStringList materialErrors() const;

  /// While wanted (the saliency heat map, a salient LOD), the positions' alpha holds the saliency
  /// of the current surface: recomputed when an edit settles, on the GPU or (setSaliencyOnCpu,
  /// the default on a software rasterizer) with the CPU reference on a worker thread.
  void setSaliencyWanted(bool wanted);
  bool saliencyCurrent() const { return saliency_.current(); }
  void setSaliencyOnCpu(bool onCpu) { saliency_.setOnCpu(onCpu); }
  bool saliencyOnCpu() const { return saliency_.onCpu(); }

  /// The scene's one history (every object's document steps and the scene's steps).
  SceneHistory& history() { return history_; }
  const SceneHistory& history() const { return history_; }
  bool canUndo() const { return history_.canUndo(); }
  bool canRedo() const { return history_.canRedo(); }
  /// Reverts / reapplies the newest step of the one history, whichever object it belongs to (a
  /// document step of another object makes that object the edited one first, uploading its
  /// document); false if there is none, a stroke is being made or the upload failed.
  bool undoStroke();
  bool redoStroke();
  /// Makes `after` (same size) the document as one history step labelled label
  /// (SculptSession::applyChange). Returns whether a step was recorded. Throws what the session
  /// throws.
  bool applyChange(const core::Document& after, const std::string& label);
  /// Makes `after` (any N) the document as one history step labelled label (Remesh,
  /// Resolution, Import), the view kept (documentReplaced(true)); undo brings the one before
  /// back bit for bit. Returns false with error() set if the upload failed (nothing changed).
  bool replaceDocument(core::Document after, const QString& label);
  /// The history's memory budget (Edit ▸ Preferences): older steps that no longer fit drop.
  void setHistoryBudget(std::size_t bytes);
  /// Whether the last stroke begun relaxed what it stretched (keep detail).
  bool keepsDetail() const { return session_.keepDetail(); }

  /// follower is told of every change of the document (after the saliency is), GL current.
  void followChanges(std::function<void(const gpu::DocumentChange&)> follower);

  /// Why GL or a brush failed, empty if nothing did.
  QString error() const { return error_; }
  /// Reports a failure (errorOccurred).
  void fail(const QString& message);
  /// Drops GL errors Qt or VTK left pending (GL current): the engine checks its own.
  void drainGlErrors();
  /// A stroke ended (StrokeDriver): label names the step recorded, empty when none was.
  void strokeSettled(const QString& label);

  /// Objects ▸ Duplicate and Mirror Duplicate (modeller_object_commands.cpp): a copy of the
  /// edited object, its document as edited so far, named from its name ("Body" → "Body.001"),
  /// shown and unlocked, appended through addObject and made the edited one. mirrorAxis 0, 1 or
  /// 2: mirrored across the scene's plane through the origin normal to x, y or z
  /// (core::mirrorDocument with core::mirroredTransform, exact); -1: in place, bit for bit.
  /// Returns why it was refused (no document, a stroke being made, the scene full, the upload
  /// failed), empty on success.
  QString duplicateActiveObject(int mirrorAxis = -1);
  /// The edited object's samples in world space, boxed (Frame Selected); empty without a
  /// document.
  core::BoundingBox activeWorldBounds() const;

signals:
  /// A step was recorded by a stroke (labelled with its brush).
  void strokeFinished(const QString& label);
  void errorOccurred(const QString& message);
  /// A new document was uploaded; keepView: the camera should stay.
  void documentReplaced(bool keepView);
  /// The scene was replaced (setDocument, setScene): its objects, their transforms, which is
  /// active.
  void sceneChanged();
  /// Objects were added, removed, renamed, moved, shown, hidden, locked, unlocked, merged or
  /// reordered, by the user or by undo and redo (each a step of the history, whose saved state
  /// says whether the scene differs from its file).
  void objectsChanged();
  /// Object k is shown under a previewed transform (previewObjectTransform): redraw only.
  void objectMoved(int k);
  /// Something asked for was refused (a stroke on a locked object): why, for the status bar.
  void refused(const QString& why);
  /// Another object is about to become the edited one (setActiveObject, or an undo or redo that
  /// goes to another object's step).
  void activeObjectAboutToChange();
  /// Object k became the edited one (after documentReplaced(true)).
  void activeObjectChanged(int k);
  /// The surface changed (dabs, a finished stroke, undo, redo, a new document, the saliency in).
  void surfaceChanged();
  /// The history changed: a step recorded, undone or redone, steps dropped, or all cleared.
  void historyChanged();
  /// undo or redo stepped through the entry with this serial (SceneHistory::Entry);
  /// replacedDocument: a replacing step showed another document.
  void historyStepped(std::uint64_t serial, bool replacedDocument, bool undo);

private:
  // Hands the library's brushes, their load errors and the materials to brushState_.
  void offerBrushes();
  bool uploadDocument(core::Document document, bool keepView);
  void documentChanged(const gpu::DocumentChange& change);
  void refreshSaliency();
  void cpuSaliencyFinished();
  bool stepHistory(bool undo);
  // Makes object k (its document in its slot) the edited one, the history of the object left
  // (history_.liveObject()) parked; false with the histories as they were if the upload failed.
  bool enterObject(int k);
  // Shows one side of step on the scene (modeller_objects.cpp), switching the edited object
  // when the step says so; why it could not, empty on success.
  QString showStep(SceneStep& step, bool before);
  // Makes step (its after side) and records it; why not, empty on success.
  QString doStep(SceneStep step);
  // Object k's look changed as one step; placing: a transform that ends a preview.
  QString changeLook(int k, const ObjectLook& after, std::string label, bool placing = false);
  // Previewed objects back where their previews began (an undo or redo ends a G/R/S gesture).
  void cancelPreviews();
  int indexOf(ObjectId id) const;
  ObjectId newObjectId() { return ++objectIds_; }

  GlHost* host_ = nullptr;
  SculptSession session_;
  SceneHistory history_{session_.history()};
  BrushState brushState_;
  StrokeDriver strokes_;
  SaliencyKeeper saliency_;
  std::unique_ptr<gpu::GlContext> context_;
  std::unique_ptr<gpu::BrushLibrary> library_;
  gpu::MaterialCatalog materials_;
  std::optional<core::Document> pending_; // set before GL started (or when it failed)
  // Every object; the active one's document lives in session_ (or pending_), its slot here empty.
  core::Scene scene_;
  std::vector<ObjectId> ids_; // scene_'s objects' ids, in order
  ObjectId objectIds_ = 0;    // the last id given
  // Transforms of objects under a G/R/S preview, as they were before it.
  std::map<ObjectId, core::ObjectTransform> previewed_;
  int active_ = 0;
  std::vector<std::function<void(const gpu::DocumentChange&)>> followers_;
  bool uploading_ = false;
  StorageAhead storageAhead_; // a new document's textures made beside the GUI thread
  QString error_;
};

} // namespace octaclay::app
