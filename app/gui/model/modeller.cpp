#include "modeller.h"

#include "brush_setup.h"
#include "current_context.h"
#include "data_folders.h"

#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QOpenGLContext>
#include <QOpenGLFunctions>

#include <utility>

namespace octaclay::app {

Modeller::Modeller(QObject* parent) : QObject(parent), strokes_(*this) {
  session_.setChangeFollower([this](const gpu::DocumentChange& c) { documentChanged(c); });
  connect(&saliency_, &SaliencyKeeper::jobFinished, this, &Modeller::cpuSaliencyFinished);
  connect(&saliency_, &SaliencyKeeper::failed, this, &Modeller::fail);
}

Modeller::~Modeller() {
  strokes_.settle();
  saliency_.waitForJob();
}

bool Modeller::glStarted(GlHost& host) {
  host_ = &host;
  try {
    context_ = std::make_unique<gpu::GlContext>(gpu::GlContext::adoptCurrent());
    library_ = std::make_unique<gpu::BrushLibrary>(
        gpu::BrushCatalog::defaultSearchPath(builtInBrushFolder()));
    const QString renderer = QString::fromLatin1(
        reinterpret_cast<const char*>(host.context()->functions()->glGetString(GL_RENDERER)));
    // On a software rasterizer the GPU pass is CPU work that would hold the GUI thread for
    // seconds at N = 1024; the threaded CPU reference takes less, in the background.
    saliency_.setOnCpu(renderer.contains("llvmpipe") || renderer.contains("softpipe") ||
                       renderer.contains("SwiftShader"));
    materials_.scan(gpu::MaterialCatalog::defaultSearchPath(builtInMaterialFolder()));
    library_->engine().setMaterials(materials_);
  } catch (const std::exception& e) {
    library_.reset();
    fail(QStringLiteral("OpenGL 4.3 core is needed for sculpting: %1").arg(e.what()));
    return false;
  }
  session_.setBrushes(library_->engine(), library_->catalog());
  offerBrushes();
  if (pending_) {
    core::Document document = std::move(*pending_);
    pending_.reset();
    uploadDocument(std::move(document), false);
  }
  return true;
}

void Modeller::glStopping() {
  strokes_.settle();
  saliency_.waitForJob();
  session_.releaseGpu();
  saliency_.releaseGpu();
  library_.reset();
  context_.reset();
  host_ = nullptr;
}

bool Modeller::setDocument(core::Document document, bool keepView) {
  return setScene(core::sceneOf(std::move(document)), 0, keepView);
}

bool Modeller::setScene(core::Scene scene, int active, bool keepView) {
  if (scene.objects.empty() || active < 0 || active >= static_cast<int>(scene.objects.size())) {
    fail(QStringLiteral("A scene needs an object to edit"));
    return false;
  }
  strokes_.settle();
  core::Document document = std::move(scene.objects[std::size_t(active)].document);
  scene.objects[std::size_t(active)].document = {};
  std::vector<ObjectId> ids;
  for (std::size_t k = 0; k < scene.objects.size(); ++k)
    ids.push_back(newObjectId());
  previewed_.clear();
  if (!host_ || !host_->context()) {
    pending_ = std::move(document);
    scene_ = std::move(scene);
    ids_ = std::move(ids);
    active_ = active;
    history_.restart(ids_[std::size_t(active_)]);
    emit historyChanged();
    emit sceneChanged();
    return true;
  }
  CurrentContext current(*host_);
  // The scene is taken before the upload, whose documentReplaced lets the viewport read it.
  core::Scene before = std::exchange(scene_, std::move(scene));
  std::vector<ObjectId> idsBefore = std::exchange(ids_, std::move(ids));
  const int activeBefore = std::exchange(active_, active);
  const bool ok = uploadDocument(std::move(document), keepView);
  if (!ok && session_.hasDocument()) { // the session kept the previous document
    scene_ = std::move(before);
    ids_ = std::move(idsBefore);
    active_ = activeBefore;
  } else {
    history_.restart(ids_[std::size_t(active_)]);
  }
  emit historyChanged();
  if (ok) emit sceneChanged();
  return ok;
}

core::Scene Modeller::scene() const {
  core::Scene whole;
  if (!hasDocument()) return whole;
  whole.objects = scene_.objects; // the active object's slot is empty: cheap
  whole.objects[std::size_t(active_)].document = document();
  return whole;
}

bool Modeller::setActiveObject(int k) {
  if (k < 0 || k >= objectCount() || !hasDocument()) return false;
  if (k == active_) return true;
  strokes_.settle();
  if (session_.stroking()) return false;
  emit activeObjectAboutToChange();
  const int before = active_;
  // The edited document goes back first, so that documentReplaced's followers see the scene
  // as it now is.
  scene_.objects[std::size_t(before)].document = document();
  if (!enterObject(k)) {
    active_ = before;
    scene_.objects[std::size_t(before)].document = {};
    return false;
  }
  emit historyChanged();
  emit activeObjectChanged(k);
  return true;
}

bool Modeller::enterObject(int k) {
  const int before = active_;
  const ObjectId leaving = history_.liveObject();
  core::SceneObject& next = scene_.objects[std::size_t(k)];
  history_.leave(); // the upload clears the session's history: the object left keeps its own
  active_ = k;
  if (!host_ || !host_->context() || !session_.hasDocument()) {
    pending_ = std::exchange(next.document, {});
  } else {
    CurrentContext current(*host_);
    // A copy goes up: if the upload throws, the object keeps its document.
    if (!uploadDocument(core::Document(next.document), true)) {
      active_ = before;
      history_.enter(leaving);
      return false;
    }
    next.document = {};
  }
  history_.enter(ids_[std::size_t(k)]);
  return true;
}

bool Modeller::replaceDocument(core::Document after, const QString& label) {
  strokes_.settle();
  if (!session_.hasDocument() || !host_ || session_.stroking()) return false;
  {
    CurrentContext current(*host_);
    try {
      drainGlErrors();
      session_.replaceDocument(std::move(after), label.toStdString());
    } catch (const std::exception& e) {
      fail(QStringLiteral("Could not load the model onto the GPU: %1").arg(e.what()));
      return false;
    }
  }
  history_.noteLiveStep();
  emit documentReplaced(true);
  emit historyChanged();
  emit surfaceChanged();
  return true;
}

void Modeller::setHistoryBudget(std::size_t bytes) {
  history_.setBudget(bytes);
  emit historyChanged();
}

bool Modeller::uploadDocument(core::Document document, bool keepView) {
  if (!library_) {
    pending_ = std::move(document); // kept so it can still be saved
    return false;
  }
  try {
    drainGlErrors();
    // The upload is GL work, so it stays on this thread; between its bands the event loop runs
    // (timers, repaints, the progress dialog) but no user input: nothing may edit meanwhile.
    QElapsedTimer sinceEvents;
    sinceEvents.start();
    const auto events = [&] {
      uploading_ = true;
      QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
      uploading_ = false;
    };
    // The textures first, on a worker with a shared context, the event loop running meanwhile.
    gpu::GpuDocument::Storage storage =
        storageAhead_.make(host_->context(), document.positions.grid(), events);
    host_->makeCurrent();
    session_.setDocument(
        std::move(document),
        [&](float) {
          if (sinceEvents.elapsed() < 30) return;
          events();
          host_->makeCurrent(); // a repaint in between may have left another context current
          sinceEvents.restart();
        },
        std::move(storage));
  } catch (const std::exception& e) {
    uploading_ = false;
    fail(QStringLiteral("Could not load the model onto the GPU: %1").arg(e.what()));
    return false;
  }
  emit documentReplaced(keepView);
  host_->update();
  return true;
}

bool Modeller::hasDocument() const {
  return session_.hasDocument() || pending_.has_value();
}

const core::Document& Modeller::document() const {
  if (!session_.hasDocument()) return *pending_;
  // While a stroke's relaxation is solved beside the GUI this is the surface as shown (both only
  // read it); its step is recorded, and the document written, when it is in.
  if (!session_.gpuDocument().mirrorStale()) return session_.document();
  // Mid-stroke (picking, autosave, save): the session reads back what the stroke deferred (paint;
  // positions too on a GPU), which is GL work.
  CurrentContext current(*host_, CurrentContext::Mode::IfNotCurrent);
  return session_.document();
}

std::shared_ptr<const core::GeometryImage> Modeller::positionsSnapshot() const {
  if (!hasDocument()) return nullptr;
  return std::make_shared<const core::GeometryImage>(document().positions);
}

QStringList Modeller::reloadBrushes() {
  QStringList failed;
  if (!library_) return failed;
  gpu::BrushLibrary::ReloadReport report;
  {
    CurrentContext current(*host_);
    report = library_->reloadChanged();
  }
  for (const std::string& f : report.failed)
    failed << QString::fromStdString(f);
  session_.brushesReloaded(report.reloaded);
  if (!report.reloaded.empty() || !report.failed.empty() || !report.added.empty() ||
      !report.removed.empty())
    offerBrushes();
  return failed;
}

void Modeller::offerBrushes() {
  std::vector<gpu::BrushManifest> brushes;
  for (const gpu::BrushManifest* b : library_->brushes())
    brushes.push_back(*b);
  std::vector<std::string> errors = library_->errors();
  for (const std::string& e : materials_.errors())
    errors.push_back(e);
  brushState_.setMaterials(materialIds());
  brushState_.setBrushes(std::move(brushes), std::move(errors));
}

QStringList Modeller::materialIds() const {
  QStringList ids;
  for (const gpu::Material& m : materials_.materials())
    ids << QString::fromStdString(m.id);
  return ids;
}

QStringList Modeller::materialErrors() const {
  QStringList errors;
  for (const std::string& e : materials_.errors())
    errors << QString::fromStdString(e);
  return errors;
}

void Modeller::documentChanged(const gpu::DocumentChange& change) {
  if (change.layer == core::EditLayer::Positions) saliency_.surfaceEdited();
  for (const auto& follow : followers_)
    follow(change);
  switch (change.kind) {
  case gpu::ChangeKind::Dabs:
    break; // the stroke goes on: its end settles (strokeSettled)
  default:
    if (change.layer == core::EditLayer::Positions) refreshSaliency();
    break;
  }
}

void Modeller::followChanges(std::function<void(const gpu::DocumentChange&)> follower) {
  followers_.push_back(std::move(follower));
}

void Modeller::strokeSettled(const QString& label) {
  refreshSaliency(); // at stroke end: the whole image's normalisation may have changed
  history_.noteLiveStep();
  if (!label.isEmpty()) emit strokeFinished(label);
  if (!label.isEmpty()) emit historyChanged();
  emit surfaceChanged();
}

void Modeller::setSaliencyWanted(bool wanted) {
  saliency_.setWanted(wanted);
  if (!wanted || !saliency_.stale() || !session_.hasDocument() || !host_) return;
  {
    CurrentContext current(*host_);
    refreshSaliency();
  }
  host_->update();
  emit surfaceChanged();
}

void Modeller::refreshSaliency() {
  // Not while a relaxation reads the mirror beside the GUI: its end refreshes.
  if (session_.hasDocument() && library_ && !strokes_.relaxing())
    saliency_.refresh(session_.gpuDocument());
}

void Modeller::cpuSaliencyFinished() {
  if (!session_.hasDocument() || strokes_.relaxing()) return; // the stroke's end starts anew
  {
    CurrentContext current(*host_);
    // The surface changed meanwhile: again (a stroke's end starts its own).
    if (saliency_.storeJob(session_.gpuDocument()) && !session_.stroking()) refreshSaliency();
  }
  if (saliency_.current()) {
    host_->update();
    emit surfaceChanged(); // a salient LOD is regenerated with it
  }
}

bool Modeller::undoStroke() {
  return stepHistory(true);
}

bool Modeller::redoStroke() {
  return stepHistory(false);
}

bool Modeller::stepHistory(bool undo) {
  strokes_.settle();
  if (!session_.hasDocument() || !host_ || session_.stroking()) return false;
  history_.noteLiveStep();
  SceneHistory::Entry* entry = undo ? history_.nextUndoEntry() : history_.nextRedoEntry();
  if (!entry) return false;
  const std::uint64_t serial = entry->serial;
  cancelPreviews(); // a G/R/S preview does not outlive an undo
  if (entry->scene) {
    const QString why = showStep(*entry->scene, undo);
    if (!why.isEmpty()) {
      emit refused(why);
      return false;
    }
    history_.stepped(undo);
    host_->update();
    emit historyStepped(serial, false, undo);
    emit historyChanged();
    return true;
  }
  // A step of another object's document: that object is edited again first (Nomad's way).
  const int k = indexOf(entry->object);
  if (k < 0 || (k != active_ && !setActiveObject(k))) return false;
  const core::EditStep* s = nullptr;
  {
    CurrentContext current(*host_);
    try {
      s = undo ? session_.undo() : session_.redo(); // the feed redraws and refreshes
    } catch (const std::exception& e) {
      fail(QString::fromUtf8(e.what()));
    }
  }
  host_->update();
  if (!s) return false;
  history_.stepped(undo);
  if (s->replacesDocument()) emit documentReplaced(true);
  emit historyStepped(serial, s->replacesDocument(), undo);
  emit historyChanged();
  emit surfaceChanged();
  return true;
}

bool Modeller::applyChange(const core::Document& after, const std::string& label) {
  strokes_.settle();
  if (!session_.hasDocument() || !host_ || session_.stroking()) return false;
  bool recorded = false;
  {
    CurrentContext current(*host_);
    drainGlErrors();
    try {
      recorded = session_.applyChange(after, label);
    } catch (const std::exception&) { // what was written reached the feed
      host_->update();
      emit surfaceChanged();
      throw;
    }
  }
  host_->update();
  if (recorded) history_.noteLiveStep();
  if (recorded) emit historyChanged();
  if (recorded) emit surfaceChanged();
  return recorded;
}

void Modeller::fail(const QString& message) {
  error_ = message;
  emit errorOccurred(message);
}

void Modeller::drainGlErrors() {
  // Qt and VTK may leave an error pending; the engine checks errors after its own calls.
  if (!host_ || !host_->context()) return;
  QOpenGLFunctions* gl = host_->context()->functions();
  for (int k = 0; k < 16 && gl->glGetError() != GL_NO_ERROR; ++k) {
  }
}

} // namespace octaclay::app
