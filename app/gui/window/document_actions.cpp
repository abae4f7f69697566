#include "document_actions.h"

#include "file_work.h"
#include "history_list.h"
#include "lod_panel.h"
#include "modeller.h"
#include "save_compressed_dialog.h"
#include "user_messages.h"
#include "viewport_widget.h"

#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/document/scene_io.h"
#include "octaclay/core/export/scene_export.h"
#include "octaclay/core/lod/facing.h"

#include <QFileInfo>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <memory>

namespace octaclay::app {
namespace {

constexpr int kMaxRecentFiles = 8;

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdString());
}

} // namespace

DocumentActions::DocumentActions(Parts parts, const QString& recoveryFolder, qint64 sessionPid,
                                 QObject* parent)
    : QObject(parent), parts_(parts), runner_(parts.window), recovery_(recoveryFolder, sessionPid) {
  connect(&autosaver_, &Autosaver::finished, this, [this](const QString& error) {
    if (!error.isEmpty()) {
      parts_.statusBar->showMessage(tr("Autosave failed: %1").arg(error), 10000);
      return;
    }
    autosaved_ = autosaving_;
  });
  connect(parts_.modeller, &Modeller::historyStepped, this, &DocumentActions::stepped);
  connect(parts_.modeller, &Modeller::activeObjectAboutToChange, this,
          [this] { emit aboutToAdopt(); }); // another document is about to be shown
  connect(parts_.modeller, &Modeller::activeObjectChanged, this,
          &DocumentActions::activeObjectChanged);
}

// The LOD panel's levels of the edited object: N/d of a ball, W/d × H/d of a torus or plane
// (a torus keeping its 4 cells around the tube), and the viewport drawn at the level chosen.
void DocumentActions::listLevels() {
  const core::GeometryImage& p = parts_.modeller->document().positions;
  const bool ball = p.topology() == core::Topology::Octahedral;
  parts_.lodPanel->setDocumentSize(p.width(), ball ? 0 : p.height(),
                                   p.topology() == core::Topology::Torus ? core::kMinTorusSize
                                                                         : core::kMinSize);
  parts_.viewport->setLevelDivisor(parts_.lodPanel->divisor());
}

void DocumentActions::activeObjectChanged(int k) {
  // Not a step: the one history, its saved state and the autosave's position stay.
  listLevels();
  emit titleChanged();
  emit adopted();
  parts_.statusBar->showMessage(
      tr("Editing %1").arg(QString::fromStdString(parts_.modeller->objectAt(k).name)), 8000);
}

bool DocumentActions::isModified() const {
  return forceModified_ || !parts_.history->isClean();
}

void DocumentActions::showError(const QString& message) {
  lastError_ = message;
  showStatusMessage(*parts_.statusBar, message, 15000);
  auto* box = new QMessageBox(QMessageBox::Critical, tr("Octaclay"), message, QMessageBox::Ok,
                              parts_.window);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open(); // window-modal, does not block the caller
}

bool DocumentActions::importMesh(const QString& path, int n) {
  auto control = std::make_shared<TaskControl>();
  auto imported = std::make_shared<ImportedMesh>();
  const QString error = runner_.run(tr("Importing %1…").arg(QFileInfo(path).fileName()),
                                    importWork(path, n, control, imported), control);
  if (control->cancel) {
    parts_.statusBar->showMessage(tr("Import cancelled; the current model is unchanged"), 8000);
    return false;
  }
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not import"), path, error) +
              tr("\nThe current model is unchanged."));
    return false;
  }
  // One step of the history: the replaced document (its strokes before it) is held by the step.
  const QString name = QFileInfo(path).fileName();
  const FileState state{{}, QFileInfo(path).absoluteFilePath(), true}; // not saved anywhere yet
  if (parts_.modeller->hasDocument()) {
    if (!replaceWith(std::move(imported->document), tr("Import %1").arg(name), state)) return false;
  } else {
    if (!adoptScene(core::sceneOf(std::move(imported->document)), {})) return false;
    importedFrom_ = state.importedFrom;
    forceModified_ = true;
  }
  parts_.viewport->frameFrom(imported->facing);
  emit titleChanged();
  lastError_.clear();
  parts_.statusBar->showMessage(
      tr("Imported %1 (%2)").arg(QFileInfo(path).fileName(), imported->report), 8000);
  return true;
}

bool DocumentActions::adoptScene(core::Scene scene, const QString& path) {
  emit aboutToAdopt(); // before the new document's surfaceChanged
  // The first visible object is the one edited (a hidden one would still be drawn as edited).
  const auto visible = std::find_if(scene.objects.begin(), scene.objects.end(),
                                    [](const core::SceneObject& o) { return o.visible; });
  const int active =
      visible == scene.objects.end() ? 0 : static_cast<int>(visible - scene.objects.begin());
  if (!parts_.modeller->setScene(std::move(scene), active)) {
    showError(parts_.viewport->error());
    return false;
  }
  parts_.history->setClean(); // setDocument cleared the history: as opened or made
  replacedStates_.clear();
  path_ = path;
  importedFrom_.clear();
  forceModified_ = false;
  autosaved_.reset();
  autosaving_.reset(); // an autosave in flight was of the document before
  listLevels();
  emit titleChanged();
  emit adopted();
  return true;
}

bool DocumentActions::replaceDocument(core::Document document, const QString& label) {
  if (!parts_.modeller->hasDocument()) return false;
  if (!replaceWith(std::move(document), label, fileState())) return false;
  lastError_.clear();
  return true;
}

bool DocumentActions::replaceWith(core::Document document, const QString& label,
                                  const FileState& after) {
  parts_.viewport->endStroke();
  const FileState before = fileState();
  emit aboutToAdopt();
  Modeller& modeller = *parts_.modeller;
  if (!modeller.replaceDocument(std::move(document), label)) {
    showError(parts_.viewport->error());
    return false;
  }
  if (modeller.history().canUndo())
    replacedStates_[modeller.history().position()] = {before, after};
  path_ = after.path;
  importedFrom_ = after.importedFrom;
  forceModified_ = after.forceModified;
  shownReplaced();
  return true;
}

void DocumentActions::stepped(std::uint64_t serial, bool replacedDocument, bool undo) {
  const auto states = replacedStates_.find(serial);
  if (!replacedDocument) return;
  if (states != replacedStates_.end()) {
    const FileState& state = undo ? states->second.first : states->second.second;
    path_ = state.path;
    importedFrom_ = state.importedFrom;
    forceModified_ = state.forceModified;
  }
  shownReplaced();
}

void DocumentActions::shownReplaced() {
  autosaved_.reset();
  autosaving_.reset(); // an autosave in flight was of the document before
  listLevels();
  emit titleChanged();
  emit adopted();
}

bool DocumentActions::newDocument(core::BaseShape shape, int n) {
  auto made = std::make_shared<core::Document>();
  const QString error = runner_.run(tr("Creating a model of size %1…").arg(n), [made, shape, n] {
    *made = core::makeDocument(core::makeBaseShape(shape, n));
  });
  if (!error.isEmpty()) {
    showError(tr("Could not create the model: %1").arg(error));
    return false;
  }
  // A new model starts from the default display detail, whatever the last one was shown at.
  parts_.lodPanel->forgetDisplayChoice();
  adoptScene(core::sceneOf(std::move(*made)), {});
  lastError_.clear();
  return true;
}

bool DocumentActions::openDocument(const QString& path) {
  if (isImportableMesh(path)) {
    showError(tr("%1 is a mesh, not an Octaclay model: use File ▸ Import Mesh… (Ctrl+I) to turn "
                 "it into one.\nThe current model is unchanged.")
                  .arg(QFileInfo(path).fileName()));
    return false;
  }
  auto read = std::make_shared<core::Scene>();
  auto facing = std::make_shared<core::Vec3f>();
  const QString error =
      runner_.run(tr("Opening %1…").arg(QFileInfo(path).fileName()), [read, facing, path] {
        *read = readSceneFile(path);
        *facing = core::guessFacing(read->objects.front().document.positions);
      });
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not open"), path, error) +
              tr("\nThe current model is unchanged."));
    return false;
  }
  // A compressed model opens untitled, so Save asks for an .exr instead of overwriting it.
  const bool compressed = QFileInfo(path).suffix().compare("ocz", Qt::CaseInsensitive) == 0;
  if (adoptScene(std::move(*read), compressed ? QString() : QFileInfo(path).absoluteFilePath()))
    parts_.viewport->frameFrom(*facing);
  addRecentFile(QFileInfo(path).absoluteFilePath());
  lastError_.clear();
  return true;
}

bool DocumentActions::saveDocument(const QString& path) {
  if (!parts_.modeller->hasDocument()) return false;
  parts_.viewport->endStroke();
  // A snapshot: the save runs while the user may keep sculpting.
  auto snapshot = std::make_shared<core::Scene>(parts_.modeller->scene());
  const QString error =
      runner_.run(tr("Saving %1…").arg(QFileInfo(path).fileName()),
                  [snapshot, path] { core::writeScene(*snapshot, toPath(path)); });
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not save"), path, error));
    return false;
  }
  path_ = QFileInfo(path).absoluteFilePath();
  parts_.history->setClean();
  forceModified_ = false;
  recovery().discard(); // the file now holds everything the recovery did
  addRecentFile(path_);
  emit titleChanged();
  lastError_.clear();
  parts_.statusBar->showMessage(tr("Saved %1").arg(path_), 5000);
  return true;
}

bool DocumentActions::saveCompressed(const QString& path, const core::CompressOptions& options) {
  if (!parts_.modeller->hasDocument()) return false;
  parts_.viewport->endStroke();
  // Every object (.ocz version 2); a lone object at the identity keeps today's format.
  auto snapshot = std::make_shared<core::Scene>(parts_.modeller->scene());
  const QString error =
      runner_.run(tr("Saving %1…").arg(QFileInfo(path).fileName()), [snapshot, path, options] {
        core::writeCompressedModel(*snapshot, options, toPath(path));
      });
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not save"), path, error));
    return false;
  }
  lastError_.clear();
  parts_.statusBar->showMessage(tr("Saved compressed %1").arg(path), 5000);
  return true;
}

bool DocumentActions::exportMesh(const QString& path, int divisor) {
  if (!parts_.modeller->hasDocument()) return false;
  parts_.viewport->endStroke();
  if (parts_.modeller->objectCount() > 1) return exportScene(path);
  // .obj and .glb carry the painted layers (maps beside the OBJ, textures inside the GLB).
  const std::function<void()> work = meshExportWork(parts_.modeller->document(), path, divisor);
  if (!work) {
    showError(tr("Cannot export %1: use .obj, .glb, .ply, .stl or .off").arg(path));
    return false;
  }
  const QString error = runner_.run(tr("Exporting %1…").arg(QFileInfo(path).fileName()), work);
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not export"), path, error));
    return false;
  }
  lastError_.clear();
  parts_.statusBar->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

bool DocumentActions::exportScene(const QString& path) {
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (!QStringList{"obj", "glb", "ply", "stl", "off"}.contains(suffix)) {
    showError(tr("Cannot export %1: use .obj, .glb, .ply, .stl or .off").arg(path));
    return false;
  }
  auto snapshot = std::make_shared<const core::Scene>(parts_.modeller->scene());
  const QString error =
      runner_.run(tr("Exporting %1…").arg(QFileInfo(path).fileName()),
                  [snapshot, path] { core::writeSceneMeshes(*snapshot, toPath(path)); });
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not export"), path, error));
    return false;
  }
  lastError_.clear();
  const auto visible = std::count_if(snapshot->objects.begin(), snapshot->objects.end(),
                                     [](const core::SceneObject& o) { return o.visible; });
  parts_.statusBar->showMessage(
      tr("Exported %1: %2 visible objects at full resolution").arg(path).arg(visible), 5000);
  return true;
}

bool DocumentActions::exportLod(const QString& path) {
  if (!parts_.modeller->hasDocument()) return false;
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix != "obj" && suffix != "glb") {
    showError(tr("Cannot export the level of detail to %1: use .obj or .glb").arg(path));
    return false;
  }
  parts_.viewport->endStroke();
  // Salient methods read the saliency in alpha: the current surface's, from the viewport when it
  // has it at once (GPU), else computed by the export's worker on its copy.
  const core::ResampleMethod m = parts_.lodPanel->method();
  const bool salient =
      m == core::ResampleMethod::SalientPoint || m == core::ResampleMethod::SalientAverage;
  if (salient) parts_.modeller->setSaliencyWanted(true);
  const bool computeSaliency = salient && !parts_.modeller->saliencyCurrent();
  // The whole document: the LOD carries the paint as File ▸ Export Mesh does.
  auto snapshot = std::make_shared<core::Document>(parts_.modeller->document());
  const core::LodOptions options = parts_.lodPanel->lodOptions();
  auto control = std::make_shared<TaskControl>();
  const QString error =
      runner_.run(tr("Exporting %1…").arg(QFileInfo(path).fileName()),
                  lodExportWork(snapshot, options, path, control, computeSaliency), control);
  emit saliencyWishChanged();
  if (!error.isEmpty()) {
    showError(failureMessage(tr("Could not export"), path, error));
    return false;
  }
  if (control->cancel) {
    parts_.statusBar->showMessage(tr("Export cancelled; nothing was written"), 8000);
    return false;
  }
  lastError_.clear();
  parts_.statusBar->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

bool DocumentActions::autosaveNow() {
  if (!parts_.modeller->hasDocument() || runner_.busy() || autosaver_.busy()) return false;
  if (!isModified() || parts_.history->position() == autosaved_) return true;
  if (parts_.viewport->stroking()) { // the stroke's end makes the next step: save after it
    QTimer::singleShot(2000, this, [this] { autosaveNow(); });
    return false;
  }
  // The GUI thread only copies the document; encoding and writing run on a worker while the
  // window goes on (the finished signal records the undo index saved, or says what failed).
  auto snapshot = std::make_shared<const core::Scene>(parts_.modeller->scene());
  autosaving_ = parts_.history->position();
  return autosaver_.start(std::move(snapshot), path_);
}

bool DocumentActions::recover() {
  if (!pending_) return false;
  core::Scene scene;
  const RecoveryStore::Pending pending = *pending_;
  RecoveryStore* store = &recovery();
  const QString error =
      runner_.run(tr("Recovering…"), [&scene, pending, store] { scene = store->load(pending); });
  if (!error.isEmpty()) {
    showError(tr("Could not recover the autosave: %1").arg(error));
    return false;
  }
  adoptScene(std::move(scene), pending.originalPath);
  forceModified_ = true; // it differs from the file on disk until saved
  pending_.reset();
  emit titleChanged();
  return true;
}

void DocumentActions::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList files = settings.value("recentFiles").toStringList();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > kMaxRecentFiles)
    files.removeLast();
  settings.setValue("recentFiles", files);
  emit recentFilesChanged();
}

} // namespace octaclay::app
