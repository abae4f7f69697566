#pragma once

#include "autosaver.h"
#include "background_task.h"
#include "recovery_store.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document.h"
#include "octaclay/core/document/scene.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QObject>
#include <QString>

#include <cstdint>
#include <map>
#include <optional>
#include <utility>

class QStatusBar;
class QWidget;

namespace octaclay::core {
struct EditStep;
}

namespace octaclay::app {

class HistoryList;
class LodPanel;
class Modeller;
class ViewportWidget;

/// What the modeller does with document files: new, open, save, save compressed, import,
/// export, export the LOD, autosave and recovery. Each reads or writes off the GUI thread
/// (BackgroundTaskRunner), reports failures (a message box and the status bar, kept in
/// lastError()) and keeps the document's path and saved state. GUI thread.
class DocumentActions : public QObject {
  Q_OBJECT
public:
  /// What the actions work on; all must outlive this object.
  struct Parts {
    QWidget* window = nullptr; ///< parent of dialogs
    QStatusBar* statusBar = nullptr;
    Modeller* modeller = nullptr;       ///< the document the actions read and replace
    ViewportWidget* viewport = nullptr; ///< its camera and the stroke under way
    LodPanel* lodPanel = nullptr;
    HistoryList* history = nullptr; ///< its clean state is the document's saved state
  };
  /// recoveryFolder and sessionPid as RecoveryStore's.
  DocumentActions(Parts parts, const QString& recoveryFolder, qint64 sessionPid,
                  QObject* parent = nullptr);

  /// A new document of this shape and size (made off the GUI thread).
  bool newDocument(core::BaseShape shape, int n);
  /// Reads path (.exr: every object of its scene, core::readScene; or .ocz as an untitled
  /// one-object model); on failure reports why and keeps the current document. A mesh (.obj,
  /// .ply, .stl, .off) is refused with a pointer to Import Mesh.
  bool openDocument(const QString& path);
  /// Saves the whole scene (core::writeScene: every object, its name, transform, visibility and
  /// lock) atomically off the GUI thread; the document stays editable meanwhile.
  bool saveDocument(const QString& path);
  /// Writes the document compressed (.ocz). The document keeps its path and unsaved state. A
  /// scene of several objects is refused (reported, nothing written): .ocz holds one.
  bool saveCompressed(const QString& path, const core::CompressOptions& options);
  /// Imports a closed genus-0 mesh (OBJ, PLY, STL, OFF) as a new N document, with a
  /// cancellable progress dialog; on failure or cancel the current document stays. The import
  /// is one step of the modeller's history ("Import <name>", the previous document held by it):
  /// undo brings the previous document back, its path and saved state too, with its strokes
  /// still undoable.
  bool importMesh(const QString& path, int n);
  /// Writes the mesh at level N/divisor (OBJ, GLB, PLY, STL or OFF by extension). A scene of
  /// several objects writes every visible one at full resolution (core::writeSceneMeshes: GLB
  /// nodes with their transforms, OBJ groups, one world-space PLY/STL/OFF).
  bool exportMesh(const QString& path, int divisor);
  /// Writes the Level of detail dock's LOD of the current surface (OBJ + MTL or GLB) with the
  /// painted layers, as exportMesh writes them, and a tangent-space normal map baked from the
  /// full resolution (glTF's normalTexture).
  bool exportLod(const QString& path);

  /// Makes document (the same surface resampled: Mesh ▸ Remesh, Mesh ▸ Resolution) the current
  /// one as one step of the modeller's history labelled label (Modeller::replaceDocument),
  /// keeping the path, the camera and what the model was imported from; undo brings the replaced
  /// document back bit for bit. False (reported; nothing changes) if the upload failed.
  bool replaceDocument(core::Document document, const QString& label);

  QString currentPath() const { return path_; }
  /// The mesh the current document was imported from (absolute), empty if it was not.
  QString importedFrom() const { return importedFrom_; }
  bool isModified() const;
  /// The scene changed outside the history: modified until saved. (Object edits are steps of
  /// the history, whose clean state says whether they were saved.)
  void markModified() {
    forceModified_ = true;
    emit titleChanged();
  }
  QString lastError() const { return lastError_; }

  /// Autosaves now if the document changed since the last autosave: a snapshot copied here, the
  /// file encoded and written on a worker (Autosaver). True when one started or none was
  /// needed; false when there is no document, other file work or an autosave runs, or a stroke is
  /// being made (then it tries again two seconds later). A failure shows in the status bar.
  bool autosaveNow();
  /// The recovery store, once no autosave is writing to it.
  RecoveryStore& recovery() {
    autosaver_.wait();
    return recovery_;
  }
  /// Whether an autosave is being written (on a worker).
  bool autosaving() const { return autosaver_.busy(); }
  /// Waits for an autosave in flight to end (tests; quitting waits by itself).
  void waitForAutosave() { autosaver_.wait(); }
  /// The one runner every long task of the window shares, so that no two run at once.
  BackgroundTaskRunner& runner() { return runner_; }
  /// The recovery left by a crashed session (set by findRecovery()).
  const std::optional<RecoveryStore::Pending>& pendingRecovery() const { return pending_; }
  void findRecovery() { pending_ = recovery().pending(); }
  void forgetRecovery() { pending_.reset(); }
  /// Loads the pending recovery as the current (modified) document.
  bool recover();

signals:
  /// A document is about to replace the current one.
  void aboutToAdopt();
  /// A new document is in the viewport.
  void adopted();
  /// The path or the saved state changed.
  void titleChanged();
  /// A file was opened or saved: the recent files list changed.
  void recentFilesChanged();
  /// exportLod changed what saliency the viewport computes: the window restores its wish.
  void saliencyWishChanged();

private:
  void showError(const QString& message);
  /// exportMesh for a scene of several objects.
  bool exportScene(const QString& path);
  /// Shows scene as the current one (its first visible object active), its history empty and saved;
  /// false if the viewport refused it (reported; the current document stays).
  bool adoptScene(core::Scene scene, const QString& path);
  /// The modeller switched its active object (not a step: the history and its saved state stay).
  void activeObjectChanged(int k);
  /// The LOD panel's levels of the edited object (a torus's or plane's W/d × H/d) and the
  /// viewport at the chosen one.
  void listLevels();
  /// The file state (path, import, forced modified) a replacing step leaves, and the one before.
  struct FileState {
    QString path, importedFrom;
    bool forceModified = false;
  };
  /// Replaces the document as one history step, the file state becoming `after`.
  bool replaceWith(core::Document document, const QString& label, const FileState& after);
  /// The history's entry `serial` was undone or redone; a replacing step's file state comes back,
  /// the panels told of the size.
  void stepped(std::uint64_t serial, bool replacedDocument, bool undo);
  void shownReplaced();
  FileState fileState() const { return {path_, importedFrom_, forceModified_}; }
  void addRecentFile(const QString& path);

  Parts parts_;
  BackgroundTaskRunner runner_;
  RecoveryStore recovery_;
  Autosaver autosaver_{recovery_}; // after recovery_: destroyed (waiting for its save) first
  std::optional<std::uint64_t> autosaving_; // the history position of the autosave in flight
  std::optional<RecoveryStore::Pending> pending_;
  QString path_;
  QString importedFrom_;
  QString lastError_;
  std::optional<std::uint64_t> autosaved_; // the history position at the last autosave
  /// The file states around each replacing step (by its SceneHistory serial): before, after.
  std::map<std::uint64_t, std::pair<FileState, FileState>> replacedStates_;
  bool forceModified_ = false; // a recovered or imported document differs from any file
};

} // namespace octaclay::app
