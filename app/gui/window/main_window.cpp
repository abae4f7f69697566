#include "main_window.h"

#include "add_menu.h"
#include "brush_bars.h"
#include "brush_panel.h"
#include "document_actions.h"
#include "edit_menu.h"
#include "file_menu.h"
#include "file_suggestion.h"
#include "help_menu.h"
#include "history_list.h"
#include "image_output.h"
#include "layers_panel.h"
#include "lod_follow.h"
#include "lod_generator.h"
#include "lod_panel.h"
#include "modeller.h"
#include "object_transform_actions.h"
#include "objects_menu.h"
#include "objects_panel.h"
#include "sparse_sampling_hint.h"
#include "user_messages.h"
#include "view_actions.h"
#include "viewport_focus.h"
#include "viewport_widget.h"

#include "octaclay/gpu/brush_library.h"

#include <QApplication>
#include <QCloseEvent>
#include <QDockWidget>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTimer>

#include <algorithm>
#include <memory>
#include <tuple>

namespace octaclay::app {

MainWindow::MainWindow(Options options) : options_(std::move(options)) {
  setObjectName("MainWindow");
  modeller_ = new Modeller(this);
  history_ = new HistoryList(*modeller_, this);
  viewport_ = new ViewportWidget(*modeller_, this);
  setCentralWidget(viewport_);
  buildDocks();
  documents_ = new DocumentActions(
      {this, statusBar(), modeller_, viewport_, lodPanel_, history_},
      options_.recoveryFolder.isEmpty() ? RecoveryStore::defaultFolder() : options_.recoveryFolder,
      options_.sessionPid ? options_.sessionPid : QCoreApplication::applicationPid(), this);
  mesh_ = new MeshActions({this, statusBar(), modeller_, viewport_, documents_, history_,
                           [this](const QString& name) { return action(name); }},
                          this);
  connect(documents_, &DocumentActions::aboutToAdopt, this, [this] { lodFollower_.reset(); });
  connect(documents_, &DocumentActions::adopted, this, &MainWindow::updateStatus);
  connect(documents_, &DocumentActions::adopted, this, &MainWindow::applyUndoBudget);
  undoBudgetMiB_ = std::clamp(QSettings().value("undo/budgetMiB", kDefaultUndoMiB).toInt(),
                              kMinUndoMiB, kMaxUndoMiB);
  applyUndoBudget();
  connect(documents_, &DocumentActions::titleChanged, this, &MainWindow::updateTitle);
  connect(documents_, &DocumentActions::recentFilesChanged, this, &MainWindow::rebuildRecentMenu);
  connect(documents_, &DocumentActions::saliencyWishChanged, this,
          &MainWindow::updateSaliencyWanted);
  recentMenu_ = addFileMenu(*this);
  addEditMenu(*this);
  mesh_->addMenu(*menuBar());
  addAddMenu(*this);
  addViewMenu(*this, viewport_);
  addHelpMenu(*this);
  connectParts();
  addBrushBars(*this, *viewport_, modeller_->brushState());
  addObjectsMenu(*this); // between Add and View; its tool bar beside the brush header
  addObjectTransformActions(*this);
  qApp->installEventFilter(new ViewportFocusReturn(viewport_, this));
  new SparseSamplingHint(viewport_, statusBar(), action("actionRemesh"), this);

  fpsLabel_ = new QLabel(this);
  dabLabel_ = new QLabel(this);
  sizeLabel_ = new QLabel(this);
  trianglesLabel_ = new QLabel(this);
  for (QLabel* l : {fpsLabel_, dabLabel_, sizeLabel_, trianglesLabel_})
    statusBar()->addPermanentWidget(l);
  auto* statusTimer = new QTimer(this);
  connect(statusTimer, &QTimer::timeout, this, &MainWindow::updateStatus);
  statusTimer->start(500);

  autosaveTimer_ = new QTimer(this);
  connect(autosaveTimer_, &QTimer::timeout, this, [this] { autosaveNow(); });
  auto* brushPoll = new QTimer(this);
  connect(brushPoll, &QTimer::timeout, this, [this] {
    for (const QString& failure : modeller_->reloadBrushes())
      showStatusMessage(*statusBar(), failure, 8000);
  });
  brushPoll->start(1000);

  QSettings settings;
  resize(1280, 800);
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  rebuildRecentMenu();
  updateTitle();
}

MainWindow::~MainWindow() {
  delete viewport_; // its GL context goes first, taking the modeller's GL objects with it
}

QAction* MainWindow::action(const QString& objectName) const {
  return findChild<QAction*>(objectName);
}

void MainWindow::buildDocks() {
  brushPanel_ = new BrushPanel(modeller_->brushState(), this);
  layersPanel_ = new LayersPanel(this);
  lodPanel_ = new LodPanel(this);
  objectsPanel_ = new ObjectsPanel(*modeller_, this);
  auto addDock = [this](QWidget* panel, const QString& title, const QString& name,
                        Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(panel);
    addDockWidget(area, dock);
    return dock;
  };
  addDock(brushPanel_, tr("Brushes"), "BrushesDock", Qt::LeftDockWidgetArea);
  QDockWidget* layers = addDock(layersPanel_, tr("Layers"), "LayersDock", Qt::RightDockWidgetArea);
  tabifyDockWidget(layers, addDock(objectsPanel_, tr("Objects"), "ObjectsDock",
                                   Qt::RightDockWidgetArea)); // beside Layers, a tab
  layers->raise();
  addDock(lodPanel_, tr("Level of detail"), "LodDock", Qt::RightDockWidgetArea);
}

void MainWindow::connectParts() {
  // The first time the history's budget drops steps, the status bar says so (Edit ▸ History
  // then names its first row truthfully).
  connect(history_, &HistoryList::stepsStartedToDrop, this, [this] {
    const SceneHistory& h = modeller_->history();
    showStatusMessage(*statusBar(),
                      tr("Undo now keeps only the newest %1 steps: older ones no longer fit "
                         "its %2 MiB")
                          .arg(h.undoCount())
                          .arg(double(h.budget()) / double(1 << 20), 0, 'f', 0),
                      15000);
  });
  // Keep detail relaxes a released stroke beside the window: say so, and show the wait.
  connect(&modeller_->strokes(), &StrokeDriver::relaxingChanged, this, [this](bool relaxing) {
    const QString relaxingText = tr("Keeping detail: relaxing the stroke's samples…");
    if (relaxing) {
      viewport_->setCursor(Qt::BusyCursor);
      statusBar()->showMessage(relaxingText);
      return;
    }
    viewport_->unsetCursor();
    if (statusBar()->currentMessage() == relaxingText) statusBar()->clearMessage();
  });
  connect(history_, &HistoryList::cleanChanged, this, &MainWindow::updateTitle);
  connect(history_, &HistoryList::indexChanged, this, &MainWindow::updateTitle);
  const auto say = [this](const QString& message) {
    showStatusMessage(*statusBar(), message, 10000);
  };
  connect(modeller_, &Modeller::errorOccurred, this, say);
  connect(modeller_, &Modeller::refused, this, say);
  connect(objectsPanel_, &ObjectsPanel::message, this, say);
  connect(viewport_, &ViewportWidget::statsChanged, this, &MainWindow::updateStatus);
  auto applyLayers = [this] {
    viewport_->setShowDiffuse(layersPanel_->isVisible(core::EditLayer::Diffuse));
    viewport_->setShowMask(layersPanel_->isVisible(core::EditLayer::Mask));
    modeller_->brushState().setPaintTarget(layersPanel_->paintTarget());
  };
  connect(layersPanel_, &LayersPanel::visibilityChanged, this, applyLayers);
  connect(layersPanel_, &LayersPanel::paintTargetChanged, this, applyLayers);
  connect(layersPanel_, &LayersPanel::previewChanged, viewport_, &ViewportWidget::setPreview);
  applyLayers();
  connect(lodPanel_, &LodPanel::levelChanged, viewport_, &ViewportWidget::setLevelDivisor);
  viewport_->setLevelDivisor(lodPanel_->divisor());
  connectLod();
}

void MainWindow::connectLod() {
  lodGenerator_ = new LodGenerator([this] { return modeller_->positionsSnapshot(); }, this);
  lodGenerator_->setOptions(lodPanel_->liveLodOptions());
  const auto regenerate = [this] {
    if (lodPanel_->lodShown()) lodGenerator_->request();
  };
  // Each change of the surface: the shown LOD follows it at once (a frame's work), and a new one
  // is generated in the background.
  connect(modeller_, &Modeller::surfaceChanged, this, [this, regenerate] {
    if (lodPanel_->lodShown() && lodFollower_ && modeller_->hasDocument())
      viewport_->setLodMesh(std::make_shared<const core::LodMesh>(
          lodFollower_->follow(modeller_->document().positions)));
    regenerate();
  });
  connect(lodPanel_, &LodPanel::lodOptionsChanged, this, [this, regenerate] {
    lodGenerator_->setOptions(lodPanel_->liveLodOptions());
    updateSaliencyWanted();
    regenerate();
  });
  connect(lodPanel_, &LodPanel::displayChanged, this, [this, regenerate](LodPanel::Display d) {
    viewport_->setLodDisplay(d);
    updateSaliencyWanted();
    regenerate();
  });
  connect(layersPanel_, &LayersPanel::previewChanged, this, &MainWindow::updateSaliencyWanted);
  connect(lodPanel_, &LodPanel::exportRequested, this, [this] {
    const QString path = choose(FileRequest::ExportLod);
    if (!path.isEmpty()) exportLod(path);
  });
  connect(lodGenerator_, &LodGenerator::generated, this,
          [this](std::shared_ptr<const core::LodMesh> lod, double ms) {
            lodPanel_->setLodResult(static_cast<long long>(lod->mesh.triangles.size()), ms);
            lodFollower_ = std::make_unique<LodFollower>(*lod, *lodGenerator_->lodSource());
            // Made from a snapshot the stroke may have moved on from since.
            if (modeller_->hasDocument())
              lod = std::make_shared<const core::LodMesh>(
                  lodFollower_->follow(modeller_->document().positions));
            viewport_->setLodMesh(std::move(lod));
          });
  connect(lodGenerator_, &LodGenerator::measured, this,
          [this](const core::SurfaceDistance& error) { lodPanel_->setLodError(error); });
  connect(lodGenerator_, &LodGenerator::failed, this, [this](const QString& message) {
    statusBar()->showMessage(tr("Level of detail: %1").arg(message), 10000);
  });
  updateSaliencyWanted();
}

void MainWindow::updateSaliencyWanted() {
  const bool salientLod = lodPanel_->lodShown() && lodPanel_->liveLodReadsSaliency();
  modeller_->setSaliencyWanted(layersPanel_->preview() == LayersPanel::Preview::Saliency ||
                               salientLod);
}

BrushState* MainWindow::brushState() const {
  return &modeller_->brushState();
}

bool MainWindow::saveImage(const QString& path, QSize size, bool background) {
  return saveViewImage(*viewport_, *statusBar(), path, size, background);
}

void MainWindow::setAutosaveSeconds(int seconds) {
  options_.autosaveSeconds = std::max(0, seconds);
  QSettings().setValue("autosave/seconds", options_.autosaveSeconds);
  if (options_.autosaveSeconds > 0)
    autosaveTimer_->start(options_.autosaveSeconds * 1000);
  else
    autosaveTimer_->stop();
}

void MainWindow::updateStatus() {
  const ViewportStats s = viewport_->stats();
  const QLocale locale;
  // Idle, no frames were drawn: no figure rather than "0 frames/s".
  fpsLabel_->setText(s.framesPerSecond > 0 ? tr("%1 frames/s").arg(s.framesPerSecond, 0, 'f', 0)
                                           : QString());
  dabLabel_->setText(tr("dab %1 ms").arg(s.lastDabMs, 0, 'f', 2));
  sizeLabel_->setText(tr("N = %1").arg(s.n));
  trianglesLabel_->setText(
      tr("%1 / %2 triangles")
          .arg(locale.toString(s.displayedTriangles), locale.toString(s.fullTriangles)));
  lodPanel_->setTriangleCounts(s.displayedTriangles, s.fullTriangles);
  mesh_->updateActions();
  if (modeller_->hasDocument()) {
    const core::Document& d = modeller_->document();
    layersPanel_->setLayerState(core::EditLayer::Diffuse, !d.diffuse.uniform());
    layersPanel_->setLayerState(core::EditLayer::Feature, !d.feature.uniform());
    layersPanel_->setLayerState(core::EditLayer::Mask, !d.mask.uniform());
  }
}

void MainWindow::updateTitle() {
  // An imported model not saved yet goes by its mesh's name.
  const QString path = currentPath(), imported = documents_->importedFrom();
  const QString name = !path.isEmpty()       ? QFileInfo(path).fileName()
                       : !imported.isEmpty() ? QFileInfo(imported).completeBaseName()
                                             : tr("Untitled");
  setWindowTitle(QStringLiteral("%1[*] — Octaclay").arg(name));
  setWindowModified(isModified());
}

QString MainWindow::suggestedPath(FileRequest request) const {
  const QString documents = QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
  const QString path = currentPath(), imported = documents_->importedFrom();
  switch (request) {
  case FileRequest::Open:
  case FileRequest::Import:
    return suggestedOpenFolder(path, imported, documents);
  case FileRequest::SaveAs:
    return suggestedSavePath(path, imported, QStringLiteral("exr"), documents);
  case FileRequest::SaveCompressed:
    return suggestedSavePath(path, imported, QStringLiteral("ocz"), documents);
  case FileRequest::Export:
    return suggestedSavePath(path, imported, QStringLiteral("glb"), documents);
  case FileRequest::ExportLod:
    return suggestedSavePath(path, imported, QStringLiteral("glb"), documents,
                             QStringLiteral("_lod"));
  case FileRequest::SaveImage:
    return suggestedSavePath(path, {}, QStringLiteral("png"),
                             QStandardPaths::writableLocation(QStandardPaths::PicturesLocation));
  }
  return documents;
}

QString MainWindow::choose(FileRequest request) {
  return chooser_ ? chooser_(request) : askFilePath(*this, request, suggestedPath(request));
}

bool MainWindow::newDocument(core::BaseShape shape, int n, bool force) {
  if (!force && !maybeSave()) return false;
  return documents_->newDocument(shape, n);
}

void MainWindow::startSession() {
  documents_->findRecovery();
  const std::optional<RecoveryStore::Pending>& pending = documents_->pendingRecovery();
  if (pending && options_.askAboutRecovery) {
    const QString when = pending->savedAt.toLocalTime().toString(Qt::TextDate);
    const QString from =
        pending->originalPath.isEmpty() ? tr("an unsaved model") : pending->originalPath;
    const auto answer = QMessageBox::question(
        this, tr("Recover unsaved work?"),
        tr("Octaclay did not close properly last time. An autosave of %1 from %2 can be "
           "recovered.\n\nRecover it?")
            .arg(from, when),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    if (answer == QMessageBox::Yes)
      recover();
    else
      documents_->recovery().discard();
    documents_->forgetRecovery();
  }
  if (!documents_->recovery().beginSession())
    statusBar()->showMessage(tr("Another Octaclay is running: autosave is off here"), 10000);
  const int seconds = QSettings().value("autosave/seconds", options_.autosaveSeconds).toInt();
  options_.autosaveSeconds = seconds;
  if (seconds > 0) autosaveTimer_->start(seconds * 1000);
  if (options_.quickStartOnFirstRun) showQuickStartOnFirstRun(*this);
}

void MainWindow::applyUndoBudget() {
  modeller_->setHistoryBudget(static_cast<std::size_t>(undoBudgetMiB_) << 20);
}

void MainWindow::setUndoBudgetMiB(int mib) {
  undoBudgetMiB_ = std::clamp(mib, kMinUndoMiB, kMaxUndoMiB);
  QSettings().setValue("undo/budgetMiB", undoBudgetMiB_);
  const std::size_t before = modeller_->history().undoCount();
  applyUndoBudget();
  const std::size_t after = modeller_->history().undoCount();
  if (after == before) return;
  showStatusMessage(*statusBar(),
                    tr("Undo now keeps only the newest %1 steps: %2 older ones did not fit its "
                       "%3 MiB")
                        .arg(after)
                        .arg(before - after)
                        .arg(undoBudgetMiB_),
                    15000);
}

void MainWindow::rebuildRecentMenu() {
  recentMenu_->clear();
  const QStringList files = QSettings().value("recentFiles").toStringList();
  for (const QString& f : files)
    connect(recentMenu_->addAction(f), &QAction::triggered, this, [this, f] {
      if (maybeSave()) openDocument(f);
    });
  recentMenu_->setEnabled(!files.isEmpty());
}

bool MainWindow::maybeSave() {
  if (!isModified()) return true;
  const auto answer = QMessageBox::warning(
      this, tr("Unsaved changes"), tr("The model has unsaved changes. Save them first?"),
      QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
  if (answer == QMessageBox::Cancel) return false;
  if (answer == QMessageBox::Discard) return true;
  const QString path = currentPath().isEmpty() ? choose(FileRequest::SaveAs) : currentPath();
  return !path.isEmpty() && saveDocument(path);
}

void MainWindow::closeEvent(QCloseEvent* event) {
  if (!maybeSave()) {
    event->ignore();
    return;
  }
  QSettings settings;
  settings.setValue("window/geometry", saveGeometry());
  settings.setValue("window/state", saveState());
  documents_->recovery().endSession(); // a clean exit leaves nothing to recover
  event->accept();
}

} // namespace octaclay::app
