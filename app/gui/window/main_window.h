#pragma once

#include "document_actions.h"
#include "history_list.h"
#include "mesh_actions.h"
#include "recovery_store.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QMainWindow>
#include <QPointer>

#include <functional>
#include <memory>
#include <optional>
#include <string>

class QAction;
class QLabel;
class QMenu;
class QTimer;

namespace octaclay::app {

class BrushPanel;
class BrushState;
class LayersPanel;
class LodFollower;
class HistoryList;
class LodGenerator;
class Modeller;
class LodPanel;
class ObjectsPanel;
class ViewportWidget;

/// The modeller's window: the viewport, the Brushes, Layers and Level of detail docks, the
/// File/Edit/Mesh/View/Help menus, undo, the status bar, autosave and crash recovery.
class MainWindow : public QMainWindow {
  Q_OBJECT
public:
  struct Options {
    QString recoveryFolder;           ///< empty: RecoveryStore::defaultFolder()
    qint64 sessionPid = 0;            ///< 0: this process (tests simulate other sessions)
    int autosaveSeconds = 120;        ///< 0 turns autosave off
    bool askAboutRecovery = true;     ///< false: pendingRecovery() is left for the caller
    bool quickStartOnFirstRun = true; ///< startSession() shows Help ▸ Quick Start once
  };
  /// What a file chooser is asked for.
  enum class FileRequest { Open, SaveAs, Export, Import, ExportLod, SaveCompressed, SaveImage };

  explicit MainWindow(Options options);
  MainWindow() : MainWindow(Options{}) {}
  ~MainWindow() override;

  /// Edit ▸ Preferences' undo memory, in MiB (kMinUndoMiB to kMaxUndoMiB): applied to the
  /// history now (while it does not fit, the oldest steps go and the status bar says so), to
  /// every document opened, made or replaced after, and kept in the settings for the next start.
  void setUndoBudgetMiB(int mib);
  int undoBudgetMiB() const { return undoBudgetMiB_; }
  /// Edit ▸ Preferences' autosave interval (0: off), kept in the settings and applied now.
  void setAutosaveSeconds(int seconds);
  int autosaveSeconds() const { return options_.autosaveSeconds; }
  static constexpr int kMinUndoMiB = 16, kMaxUndoMiB = 16384, kDefaultUndoMiB = 256;

  ViewportWidget* viewport() const { return viewport_; }
  /// The modeller the window's parts observe (document, brushes, strokes, history).
  Modeller* modeller() const { return modeller_; }
  BrushPanel* brushPanel() const { return brushPanel_; }
  LayersPanel* layersPanel() const { return layersPanel_; }
  LodPanel* lodPanel() const { return lodPanel_; }
  ObjectsPanel* objectsPanel() const { return objectsPanel_; }
  /// The one history as the window shows it (Edit ▸ Undo, Redo, History; the saved state).
  HistoryList* undoStack() const { return history_; }
  QAction* action(const QString& objectName) const;

  /// Where the file dialog for request opens: for a save or export, a name beside the document
  /// (its folder and base name, or the imported mesh's, with the right extension); for open and
  /// import, the document's folder (file_suggestion.h).
  QString suggestedPath(FileRequest request) const;
  /// Replaces the file dialogs (tests, scripts): returns the chosen path or empty to cancel.
  void setFileChooser(std::function<QString(FileRequest)> chooser) {
    chooser_ = std::move(chooser);
  }
  /// Whether a chooser replaces the dialogs: then the menus ask no other questions either.
  bool hasFileChooser() const { return bool(chooser_); }
  /// The path request is answered with: the chooser's, else a file dialog's; empty: cancelled.
  QString choose(FileRequest request);
  /// Asks whether to save unsaved changes first (Save, Discard, Cancel); false: cancelled or
  /// the save failed, so the model must stay.
  bool maybeSave();

  /// A new document of this shape and size (made off the GUI thread). Asks about unsaved
  /// changes first unless force.
  bool newDocument(core::BaseShape shape, int n, bool force = false);
  /// Reads path (.exr, or .ocz as an untitled model) off the GUI thread with progress; on failure
  /// reports why and keeps the current document. Does not ask about unsaved changes (the File menu
  /// does).
  bool openDocument(const QString& path) { return documents_->openDocument(path); }
  /// Saves atomically off the GUI thread; the document stays editable meanwhile.
  bool saveDocument(const QString& path) { return documents_->saveDocument(path); }
  /// Writes the document compressed (.ocz) atomically off the GUI thread with progress. The
  /// document keeps its path and unsaved state: a lossy .ocz is not the model itself.
  bool saveCompressed(const QString& path, const core::CompressOptions& options) {
    return documents_->saveCompressed(path, options);
  }
  /// Imports a closed genus-0 mesh (OBJ, PLY, STL, OFF) as a new N document, off the GUI thread
  /// with a cancellable progress dialog; on failure or cancel the current document stays.
  bool importMesh(const QString& path, int n) { return documents_->importMesh(path, n); }
  /// Writes the mesh at level N/divisor (OBJ, PLY, STL or OFF by extension).
  bool exportMesh(const QString& path, int divisor) {
    return documents_->exportMesh(path, divisor);
  }
  /// Writes the Level of detail dock's LOD (its method and target) of the current surface as
  /// OBJ + MTL or GLB with an object-space normal map baked from the full resolution, off the
  /// GUI thread with progress.
  bool exportLod(const QString& path) { return documents_->exportLod(path); }
  /// Mesh ▸ Even Out Samples: core::evenOut on a copy of the document, off the GUI
  /// thread behind a progress dialog with Cancel (control: the task's progress and cancel flag,
  /// new if null; tests pass one already cancelled), the menu item showing how far it is. On
  /// success the result becomes the document as one undo step ("Even Out Samples" on the undo
  /// stack) and the document is modified; when the even-out's own check leaves the model
  /// unchanged, the status bar says why and no step is pushed; on cancel nothing changes and the
  /// status bar says so; on an error a message box says why and nothing changes. Returns whether
  /// a step was made. Refused (false) without a document, during a stroke or while another task
  /// runs.
  bool evenOutSamples(std::shared_ptr<TaskControl> control = nullptr) {
    return mesh_->evenOutSamples(std::move(control));
  }
  /// Mesh ▸ Remesh…: core::remeshDocument at size n (0: the current N) as evenOutSamples runs
  /// core::evenOut. The result replaces the document as one undo step ("Remesh", or "Remesh at
  /// N = n"; a step of the one history holding the replaced document, its strokes before it, so
  /// undo brings it back bit for bit); the path, the camera and the saved file stay. When the
  /// remesh's own check leaves the model unchanged the status bar says why and no step is made.
  bool remesh(int n = 0, std::shared_ptr<TaskControl> control = nullptr) {
    return mesh_->remesh(n, std::move(control));
  }
  /// Mesh ▸ Resolution…: core::resizeAndCheck to n (unchanged, with the reason, when the result
  /// would be worse), run and applied as remesh() is ("Resolution N → n"). n equal to the current N
  /// changes nothing and says so.
  bool changeResolution(int n, std::shared_ptr<TaskControl> control = nullptr) {
    return mesh_->changeResolution(n, std::move(control));
  }
  /// Draws the viewport offscreen at size (device pixels) with or without its background
  /// (transparent) and writes it to path as PNG; the status bar says what happened.
  bool saveImage(const QString& path, QSize size, bool background);
  /// The brush as the user set it (the modeller's): what the Brushes dock, the tool bars and
  /// the canvas's keys edit.
  BrushState* brushState() const;
  /// Regenerates the live LOD in the background (while the dock shows it).
  LodGenerator* lodGenerator() const { return lodGenerator_; }

  QString currentPath() const { return documents_->currentPath(); }
  bool isModified() const { return documents_->isModified(); }
  /// The last error shown to the user (tests read it), empty if none since the last success.
  QString lastError() const { return documents_->lastError(); }

  /// Writes the recovery file now (the autosave timer calls this). Returns false on failure.
  bool autosaveNow() { return documents_->autosaveNow(); }
  /// A recovery left by a session that crashed, found at start.
  const std::optional<RecoveryStore::Pending>& pendingRecovery() const {
    return documents_->pendingRecovery();
  }
  /// Loads the pending recovery as the current (modified) document.
  bool recover() { return documents_->recover(); }
  /// Checks for a crashed session's recovery (asking the user when options say so) and starts
  /// this session's autosave; on a first start, opens Help ▸ Quick Start once (see
  /// Options::quickStartOnFirstRun). Call once after show().
  void startSession();

protected:
  void closeEvent(QCloseEvent* event) override;

private:
  // The history's budget on the document shown now (a replaced document's history comes with
  // the default).
  void applyUndoBudget();
  int undoBudgetMiB_ = kDefaultUndoMiB;
  void buildDocks();
  void connectParts();
  void updateStatus();
  void updateTitle();
  void rebuildRecentMenu();
  void connectLod();
  /// Saliency is computed while the heat map or a salient LOD method needs it.
  void updateSaliencyWanted();

  Options options_;
  DocumentActions* documents_ = nullptr;
  Modeller* modeller_ = nullptr;
  ViewportWidget* viewport_ = nullptr;
  BrushPanel* brushPanel_ = nullptr;
  LayersPanel* layersPanel_ = nullptr;
  LodPanel* lodPanel_ = nullptr;
  ObjectsPanel* objectsPanel_ = nullptr;
  LodGenerator* lodGenerator_ = nullptr;
  std::unique_ptr<LodFollower> lodFollower_; // the newest LOD, moved with the surface each frame
  HistoryList* history_ = nullptr;
  MeshActions* mesh_ = nullptr; // the Mesh menu's operations
  QMenu* recentMenu_ = nullptr;
  QLabel* fpsLabel_ = nullptr;
  QLabel* dabLabel_ = nullptr;
  QLabel* sizeLabel_ = nullptr;
  QLabel* trianglesLabel_ = nullptr;
  QTimer* autosaveTimer_ = nullptr;
  std::function<QString(FileRequest)> chooser_;
};

} // namespace octaclay::app
