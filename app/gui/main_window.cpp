#include "main_window.h"

#include "brush_panel.h"
#include "layers_panel.h"
#include "lod_follow.h"
#include "lod_generator.h"
#include "lod_panel.h"
#include "save_compressed_dialog.h"
#include "stroke_command.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"
#include "octaclay/core/lod/lod_export.h"
#include "octaclay/gpu/brush_library.h"

#include <QApplication>
#include <QCloseEvent>
#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QFutureWatcher>
#include <QInputDialog>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSettings>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QUndoStack>
#include <QtConcurrent/QtConcurrentRun>

#include <cmath>
#include <memory>

namespace octaclay::app {
namespace {

constexpr int kMaxRecentFiles = 8;

std::filesystem::path toPath(const QString& path) {
  return std::filesystem::path(path.toStdString());
}

QString mib(std::size_t bytes) {
  return QString::number(double(bytes) / (1 << 20), 'f', 1);
}

} // namespace

MainWindow::MainWindow(Options options)
    : options_(std::move(options)),
      recovery_(options_.recoveryFolder.isEmpty() ? RecoveryStore::defaultFolder()
                                                  : options_.recoveryFolder,
                options_.sessionPid ? options_.sessionPid : QCoreApplication::applicationPid()) {
  setObjectName("MainWindow");
  undoStack_ = new QUndoStack(this);
  viewport_ = new ViewportWidget(this);
  setCentralWidget(viewport_);
  buildDocks();
  buildMenus();
  connectParts();

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
    for (const QString& failure : viewport_->reloadBrushes())
      statusBar()->showMessage(failure, 8000);
  });
  brushPoll->start(1000);

  QSettings settings;
  resize(1280, 800);
  restoreGeometry(settings.value("window/geometry").toByteArray());
  restoreState(settings.value("window/state").toByteArray());
  rebuildRecentMenu();
  updateTitle();
}

MainWindow::~MainWindow() = default;

QAction* MainWindow::action(const QString& objectName) const {
  return findChild<QAction*>(objectName);
}

void MainWindow::buildDocks() {
  brushPanel_ = new BrushPanel(this);
  layersPanel_ = new LayersPanel(this);
  lodPanel_ = new LodPanel(this);
  auto addDock = [this](QWidget* panel, const QString& title, const QString& name,
                        Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(name);
    dock->setWidget(panel);
    addDockWidget(area, dock);
    return dock;
  };
  addDock(brushPanel_, tr("Brushes"), "BrushesDock", Qt::LeftDockWidgetArea);
  addDock(layersPanel_, tr("Layers"), "LayersDock", Qt::RightDockWidgetArea);
  addDock(lodPanel_, tr("Level of detail"), "LodDock", Qt::RightDockWidgetArea);
}

void MainWindow::buildMenus() {
  auto add = [this](QMenu* menu, const QString& text, const QString& name,
                    QKeySequence shortcut = {}) {
    QAction* a = menu->addAction(text);
    a->setObjectName(name);
    if (!shortcut.isEmpty()) a->setShortcut(shortcut);
    return a;
  };
  QMenu* file = menuBar()->addMenu(tr("&File"));
  connect(add(file, tr("&New…"), "actionNew", QKeySequence::New), &QAction::triggered, this,
          [this] {
            QDialog dialog(this);
            dialog.setWindowTitle(tr("New model"));
            auto* form = new QFormLayout(&dialog);
            auto* shape = new QComboBox(&dialog);
            for (const char* s : {"sphere", "cube", "cylinder", "blob"})
              shape->addItem(tr(s), QString(s));
            auto* size = new QComboBox(&dialog);
            for (int n : {64, 128, 256, 512, 1024, 2048, 4096})
              size->addItem(QString::number(n), n);
            size->setCurrentText("1024");
            form->addRow(tr("Shape"), shape);
            form->addRow(tr("Size N"), size);
            auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
            form->addRow(buttons);
            connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
            connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
            if (dialog.exec() != QDialog::Accepted) return;
            newDocument(*core::parseBaseShape(shape->currentData().toString().toStdString()),
                        size->currentData().toInt());
          });
  connect(add(file, tr("&Open…"), "actionOpen", QKeySequence::Open), &QAction::triggered, this,
          [this] {
            if (!maybeSave()) return;
            const QString path = choose(FileRequest::Open);
            if (!path.isEmpty()) openDocument(path);
          });
  connect(add(file, tr("&Import Mesh…"), "actionImport", QKeySequence(tr("Ctrl+I"))),
          &QAction::triggered, this, [this] {
            if (!maybeSave()) return;
            const QString path = choose(FileRequest::Import);
            if (path.isEmpty()) return;
            int n = 512;
            if (!chooser_) { // interactive: ask the image size
              bool ok = false;
              const QString size =
                  QInputDialog::getItem(this, tr("Import mesh"), tr("Geometry image size N"),
                                        {"128", "256", "512", "1024", "2048"}, 2, false, &ok);
              if (!ok) return;
              n = size.toInt();
            }
            importMesh(path, n);
          });
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  connect(add(file, tr("&Save"), "actionSave", QKeySequence::Save), &QAction::triggered, this,
          [this] {
            const QString path = path_.isEmpty() ? choose(FileRequest::SaveAs) : path_;
            if (!path.isEmpty()) saveDocument(path);
          });
  connect(add(file, tr("Save &As…"), "actionSaveAs", QKeySequence::SaveAs), &QAction::triggered,
          this, [this] {
            const QString path = choose(FileRequest::SaveAs);
            if (!path.isEmpty()) saveDocument(path);
          });
  connect(add(file, tr("Save &Compressed…"), "actionSaveCompressed"), &QAction::triggered, this,
          [this] {
            if (!viewport_->hasDocument()) return;
            viewport_->endStroke();
            SaveCompressedDialog dialog(
                std::make_shared<const core::Document>(viewport_->document()), this);
            if (dialog.exec() != QDialog::Accepted) return;
            const QString path = choose(FileRequest::SaveCompressed);
            if (!path.isEmpty()) saveCompressed(path, dialog.options());
          });
  connect(
      add(file, tr("&Export Mesh…"), "actionExport", QKeySequence(tr("Ctrl+E"))),
      &QAction::triggered, this, [this] {
        const QString path = choose(FileRequest::Export);
        if (path.isEmpty() || !viewport_->hasDocument()) return;
        int divisor = lodPanel_->divisor();
        if (!chooser_) { // interactive: ask which level, offering the displayed one
          const int n = viewport_->document().size();
          QStringList levels;
          for (int d = 1; n / d >= 2 && d <= 64; d *= 2)
            levels << tr("N/%1 (%2, %3 triangles)").arg(d).arg(n / d).arg(2LL * (n / d) * (n / d));
          bool ok = false;
          const QString level =
              QInputDialog::getItem(this, tr("Export mesh"), tr("Level of detail"), levels,
                                    static_cast<int>(std::log2(divisor)), false, &ok);
          if (!ok) return;
          divisor = 1 << levels.indexOf(level);
        }
        exportMesh(path, divisor);
      });
  file->addSeparator();
  connect(add(file, tr("&Quit"), "actionQuit", QKeySequence::Quit), &QAction::triggered, this,
          &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  QAction* undo = undoStack_->createUndoAction(this, tr("&Undo"));
  undo->setObjectName("actionUndo");
  undo->setShortcut(QKeySequence::Undo);
  QAction* redo = undoStack_->createRedoAction(this, tr("&Redo"));
  redo->setObjectName("actionRedo");
  redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence::Redo});
  edit->addAction(undo);
  edit->addAction(redo);
  edit->addSeparator();
  connect(add(edit, tr("&Preferences…"), "actionPreferences"), &QAction::triggered, this, [this] {
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout(&dialog);
    const core::EditHistory& h = viewport_->history();
    form->addRow(tr("Undo history"), new QLabel(tr("%1 MiB used of a %2 MiB budget (%3 steps)")
                                                    .arg(mib(h.bytes()), mib(h.budget()))
                                                    .arg(h.undoCount() + h.redoCount())));
    auto* minutes = new QSpinBox(&dialog);
    minutes->setRange(0, 60);
    minutes->setSuffix(tr(" min"));
    minutes->setSpecialValueText(tr("off"));
    minutes->setValue(options_.autosaveSeconds / 60);
    form->addRow(tr("Autosave every"), minutes);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
    if (dialog.exec() != QDialog::Accepted) return;
    options_.autosaveSeconds = minutes->value() * 60;
    QSettings().setValue("autosave/seconds", options_.autosaveSeconds);
    if (options_.autosaveSeconds > 0)
      autosaveTimer_->start(options_.autosaveSeconds * 1000);
    else
      autosaveTimer_->stop();
  });

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    view->addAction(dock->toggleViewAction());
  view->addSeparator();
  connect(add(view, tr("&Reset Camera"), "actionResetCamera", QKeySequence(tr("Home"))),
          &QAction::triggered, viewport_, &ViewportWidget::resetCamera);
}

void MainWindow::connectParts() {
  connect(viewport_, &ViewportWidget::strokeFinished, this,
          [this](const QString& label) { undoStack_->push(new StrokeCommand(viewport_, label)); });
  connect(undoStack_, &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
  connect(undoStack_, &QUndoStack::indexChanged, this, &MainWindow::updateTitle);
  connect(viewport_, &ViewportWidget::brushesChanged, this, &MainWindow::refreshBrushes);
  connect(viewport_, &ViewportWidget::errorOccurred, this,
          [this](const QString& message) { statusBar()->showMessage(message, 10000); });
  connect(viewport_, &ViewportWidget::statsChanged, this, &MainWindow::updateStatus);
  connect(brushPanel_, &BrushPanel::settingsChanged, this,
          [this] { viewport_->setBrushSettings(brushPanel_->settings()); });
  connect(viewport_, &ViewportWidget::radiusStepRequested, this,
          [this](float f) { brushPanel_->setRadius(brushPanel_->radius() * f); });
  connect(viewport_, &ViewportWidget::strengthStepRequested, this,
          [this](float f) { brushPanel_->setStrength(brushPanel_->strength() * f); });
  auto applyLayers = [this] {
    viewport_->setShowDiffuse(layersPanel_->isVisible(core::EditLayer::Diffuse));
    viewport_->setShowMask(layersPanel_->isVisible(core::EditLayer::Mask));
    viewport_->setPaintTarget(layersPanel_->paintTarget());
  };
  connect(layersPanel_, &LayersPanel::visibilityChanged, this, applyLayers);
  connect(layersPanel_, &LayersPanel::paintTargetChanged, this, applyLayers);
  connect(layersPanel_, &LayersPanel::previewChanged, viewport_, &ViewportWidget::setPreview);
  applyLayers();
  connect(lodPanel_, &LodPanel::levelChanged, viewport_, &ViewportWidget::setLevelDivisor);
  viewport_->setLevelDivisor(lodPanel_->divisor());
  viewport_->setBrushSettings(brushPanel_->settings());
  connectLod();
}

void MainWindow::connectLod() {
  lodGenerator_ = new LodGenerator([this] { return viewport_->positionsSnapshot(); }, this);
  lodGenerator_->setOptions(lodPanel_->lodOptions());
  const auto regenerate = [this] {
    if (lodPanel_->lodShown()) lodGenerator_->request();
  };
  // Each change of the surface: the shown LOD follows it at once (a frame's work), and a new one
  // is generated in the background.
  connect(viewport_, &ViewportWidget::surfaceChanged, this, [this, regenerate] {
    if (lodPanel_->lodShown() && lodFollower_ && viewport_->hasDocument())
      viewport_->setLodMesh(std::make_shared<const core::LodMesh>(
          lodFollower_->follow(viewport_->document().positions)));
    regenerate();
  });
  connect(lodPanel_, &LodPanel::lodOptionsChanged, this, [this, regenerate] {
    lodGenerator_->setOptions(lodPanel_->lodOptions());
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
            if (viewport_->hasDocument())
              lod = std::make_shared<const core::LodMesh>(
                  lodFollower_->follow(viewport_->document().positions));
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
  const core::ResampleMethod m = lodPanel_->method();
  const bool salientLod = lodPanel_->lodShown() && (m == core::ResampleMethod::SalientPoint ||
                                                    m == core::ResampleMethod::SalientAverage);
  viewport_->setSaliencyWanted(layersPanel_->preview() == LayersPanel::Preview::Saliency ||
                               salientLod);
}

void MainWindow::refreshBrushes() {
  gpu::BrushLibrary* library = viewport_->library();
  if (!library) return;
  std::vector<gpu::BrushManifest> brushes;
  for (const gpu::BrushManifest* b : library->brushes())
    brushes.push_back(*b);
  std::vector<std::string> errors = library->errors();
  for (const QString& e : viewport_->materialErrors())
    errors.push_back(e.toStdString());
  brushPanel_->setMaterials(viewport_->materialIds());
  brushPanel_->setBrushes(std::move(brushes), std::move(errors));
  viewport_->setBrushSettings(brushPanel_->settings());
}

void MainWindow::updateStatus() {
  const ViewportStats s = viewport_->stats();
  const QLocale locale;
  fpsLabel_->setText(tr("%1 frames/s").arg(s.framesPerSecond, 0, 'f', 0));
  dabLabel_->setText(tr("dab %1 ms").arg(s.lastDabMs, 0, 'f', 2));
  sizeLabel_->setText(tr("N = %1").arg(s.n));
  trianglesLabel_->setText(
      tr("%1 / %2 triangles")
          .arg(locale.toString(s.displayedTriangles), locale.toString(s.fullTriangles)));
  lodPanel_->setTriangleCounts(s.displayedTriangles, s.fullTriangles);
  if (viewport_->hasDocument()) {
    const core::Document& d = viewport_->document();
    layersPanel_->setLayerState(core::EditLayer::Diffuse, !d.diffuse.uniform());
    layersPanel_->setLayerState(core::EditLayer::Feature, !d.feature.uniform());
    layersPanel_->setLayerState(core::EditLayer::Mask, !d.mask.uniform());
  }
}

bool MainWindow::isModified() const {
  return forceModified_ || !undoStack_->isClean();
}

void MainWindow::updateTitle() {
  const QString name = path_.isEmpty() ? tr("Untitled") : QFileInfo(path_).fileName();
  setWindowTitle(QStringLiteral("%1[*] — Octaclay").arg(name));
  setWindowModified(isModified());
}

void MainWindow::showError(const QString& message) {
  lastError_ = message;
  statusBar()->showMessage(message, 15000);
  auto* box =
      new QMessageBox(QMessageBox::Critical, tr("Octaclay"), message, QMessageBox::Ok, this);
  box->setAttribute(Qt::WA_DeleteOnClose);
  box->open(); // window-modal, does not block the caller
}

QString MainWindow::choose(FileRequest request) {
  if (chooser_) return chooser_(request);
  const QString dir = QFileInfo(path_).absolutePath();
  switch (request) {
  case FileRequest::Open:
    return QFileDialog::getOpenFileName(this, tr("Open model"), dir,
                                        tr("Octaclay documents (*.exr *.ocz)"));
  case FileRequest::SaveCompressed:
    return QFileDialog::getSaveFileName(this, tr("Save compressed model"), dir,
                                        tr("Compressed Octaclay documents (*.ocz)"));
  case FileRequest::SaveAs:
    return QFileDialog::getSaveFileName(this, tr("Save model"), dir,
                                        tr("Octaclay documents (*.exr)"));
  case FileRequest::Import:
    return QFileDialog::getOpenFileName(this, tr("Import mesh"), dir,
                                        tr("Meshes (*.obj *.ply *.stl *.off)"));
  case FileRequest::Export:
    return QFileDialog::getSaveFileName(this, tr("Export mesh"), dir,
                                        tr("Meshes (*.obj *.glb *.ply *.stl *.off)"));
  case FileRequest::ExportLod:
    return QFileDialog::getSaveFileName(this, tr("Export level of detail"), dir,
                                        tr("Meshes with a normal map (*.obj *.glb)"));
  }
  return {};
}

QString MainWindow::runInBackground(const QString& label, const std::function<void()>& work,
                                    std::shared_ptr<TaskControl> control) {
  if (busy_) return tr("Another file operation is still running");
  busy_ = true;
  auto error = std::make_shared<QString>();
  QFutureWatcher<void> watcher;
  QEventLoop loop;
  connect(&watcher, &QFutureWatcher<void>::finished, &loop, &QEventLoop::quit);
  QProgressDialog progress(label, control ? tr("Cancel") : QString(), 0, control ? 100 : 0, this);
  progress.setWindowModality(Qt::WindowModal); // no edits while the document is in flight
  progress.setMinimumDuration(0);
  progress.cancel(); // QProgressDialog shows itself at construction otherwise: wait as below
  QTimer poll;
  if (control) {
    connect(&progress, &QProgressDialog::canceled, this, [control] { control->cancel = true; });
    connect(&poll, &QTimer::timeout, &progress, [&progress, control] {
      progress.setValue(static_cast<int>(control->fraction.load() * 100));
    });
    poll.start(100);
  }
  watcher.setFuture(QtConcurrent::run([work, error] {
    try {
      work();
    } catch (const std::exception& e) {
      *error = QString::fromUtf8(e.what());
    }
  }));
  // Work a person would notice (over 100 ms) gets the dialog; quick work never flashes it.
  QTimer::singleShot(100, &progress, [&progress, &watcher] {
    if (!watcher.isFinished()) progress.show();
  });
  if (!watcher.isFinished()) loop.exec();
  busy_ = false;
  return *error;
}

bool MainWindow::importMesh(const QString& path, int n) {
  auto control = std::make_shared<TaskControl>();
  auto made = std::make_shared<core::Document>();
  auto report = std::make_shared<QString>();
  const QString error = runInBackground(
      tr("Importing %1…").arg(QFileInfo(path).fileName()),
      [made, report, control, path, n] {
        const core::ValidatedMesh mesh = core::loadGenus0Mesh(toPath(path));
        const core::SphericalMap map = core::parameterizeOnSphere(mesh.mesh, [control](float f) {
          control->fraction = 0.9f * f;
          return !control->cancel.load();
        });
        if (map.flipped > 0)
          throw core::Error(core::ErrorKind::InvalidInput,
                            "the spherical map folds over itself (" + std::to_string(map.flipped) +
                                " flipped triangles): this mesh is not supported yet");
        core::ImportedDiffuse diffuse;
        *made = core::importValidatedMesh(mesh, map, n, &diffuse);
        control->fraction = 1.0f;
        QString colour = QObject::tr("no colour");
        if (diffuse.source == core::DiffuseSource::VertexColours)
          colour = QObject::tr("vertex colours");
        else if (diffuse.source == core::DiffuseSource::Texture)
          colour = QObject::tr("texture %1")
                       .arg(QString::fromStdString(diffuse.texture.filename().string()));
        *report = QObject::tr("stretch %1, %2 flipped triangles, %3")
                      .arg(static_cast<double>(map.stretchL2), 0, 'f', 2)
                      .arg(map.flipped)
                      .arg(colour);
        // Attributes the file names but the import could not use (a missing .mtl or texture).
        for (const std::string& note : diffuse.notes)
          *report += QStringLiteral("; ") + QString::fromStdString(note);
      },
      control);
  if (control->cancel) {
    statusBar()->showMessage(tr("Import cancelled; the current model is unchanged"), 8000);
    return false;
  }
  if (!error.isEmpty()) {
    showError(tr("Could not import %1: %2\nThe current model is unchanged.").arg(path, error));
    return false;
  }
  adoptDocument(std::move(*made), {});
  forceModified_ = true; // not saved anywhere yet
  updateTitle();
  lastError_.clear();
  statusBar()->showMessage(tr("Imported %1 (%2)").arg(QFileInfo(path).fileName(), *report), 8000);
  return true;
}

void MainWindow::adoptDocument(core::Document document, const QString& path) {
  lodFollower_.reset(); // before the new document's surfaceChanged
  if (!viewport_->setDocument(std::move(document))) {
    showError(viewport_->error());
    return;
  }
  undoStack_->clear();
  path_ = path;
  forceModified_ = false;
  autosavedIndex_ = -1;
  lodPanel_->setDocumentSize(viewport_->document().size());
  viewport_->setLevelDivisor(lodPanel_->divisor());
  updateTitle();
  updateStatus();
}

bool MainWindow::newDocument(core::BaseShape shape, int n, bool force) {
  if (!force && !maybeSave()) return false;
  auto made = std::make_shared<core::Document>();
  const QString error =
      runInBackground(tr("Creating a model of size %1…").arg(n), [made, shape, n] {
        *made = core::makeDocument(core::makeBaseShape(shape, n));
      });
  if (!error.isEmpty()) {
    showError(tr("Could not create the model: %1").arg(error));
    return false;
  }
  adoptDocument(std::move(*made), {});
  lastError_.clear();
  return true;
}

bool MainWindow::openDocument(const QString& path) {
  auto read = std::make_shared<core::Document>();
  const QString error = runInBackground(tr("Opening %1…").arg(QFileInfo(path).fileName()),
                                        [read, path] { *read = readModelFile(path); });
  if (!error.isEmpty()) {
    showError(tr("Could not open %1: %2\nThe current model is unchanged.").arg(path, error));
    return false;
  }
  // A compressed model opens untitled, so Save asks for an .exr instead of overwriting it.
  const bool compressed = QFileInfo(path).suffix().compare("ocz", Qt::CaseInsensitive) == 0;
  adoptDocument(std::move(*read), compressed ? QString() : QFileInfo(path).absoluteFilePath());
  addRecentFile(QFileInfo(path).absoluteFilePath());
  lastError_.clear();
  return true;
}

bool MainWindow::saveDocument(const QString& path) {
  if (!viewport_->hasDocument()) return false;
  viewport_->endStroke();
  // A snapshot: the save runs while the user may keep sculpting.
  auto snapshot = std::make_shared<core::Document>(viewport_->document());
  const QString error =
      runInBackground(tr("Saving %1…").arg(QFileInfo(path).fileName()),
                      [snapshot, path] { core::writeDocument(*snapshot, toPath(path)); });
  if (!error.isEmpty()) {
    showError(tr("Could not save %1: %2").arg(path, error));
    return false;
  }
  path_ = QFileInfo(path).absoluteFilePath();
  undoStack_->setClean();
  forceModified_ = false;
  recovery_.discard(); // the file now holds everything the recovery did
  addRecentFile(path_);
  updateTitle();
  lastError_.clear();
  statusBar()->showMessage(tr("Saved %1").arg(path_), 5000);
  return true;
}

bool MainWindow::saveCompressed(const QString& path, const core::CompressOptions& options) {
  if (!viewport_->hasDocument()) return false;
  viewport_->endStroke();
  auto snapshot = std::make_shared<core::Document>(viewport_->document());
  const QString error =
      runInBackground(tr("Saving %1…").arg(QFileInfo(path).fileName()), [snapshot, path, options] {
        core::writeCompressedDocument(*snapshot, options, toPath(path));
      });
  if (!error.isEmpty()) {
    showError(tr("Could not save %1: %2").arg(path, error));
    return false;
  }
  lastError_.clear();
  statusBar()->showMessage(tr("Saved compressed %1").arg(path), 5000);
  return true;
}

bool MainWindow::exportMesh(const QString& path, int divisor) {
  if (!viewport_->hasDocument()) return false;
  // .obj and .glb carry the painted layers (maps beside the OBJ, textures inside the GLB).
  const QString suffix = QFileInfo(path).suffix().toLower();
  const bool obj = suffix == "obj", glb = suffix == "glb";
  if (!obj && !glb && !core::meshFormatFromPath(toPath(path))) {
    showError(tr("Cannot export %1: use .obj, .glb, .ply, .stl or .off").arg(path));
    return false;
  }
  std::function<void()> work;
  if (obj || glb) {
    viewport_->endStroke();
    auto snapshot = std::make_shared<core::Document>(viewport_->document());
    work = [snapshot, path, divisor, obj] {
      if (obj)
        core::writeTexturedObj(*snapshot, divisor, toPath(path));
      else
        core::writeGlb(*snapshot, divisor, toPath(path));
    };
  } else {
    auto snapshot = std::make_shared<core::GeometryImage>(viewport_->document().positions);
    work = [snapshot, path, divisor] {
      core::writeMesh(core::extractMesh(*snapshot, divisor), toPath(path));
    };
  }
  const QString error = runInBackground(tr("Exporting %1…").arg(QFileInfo(path).fileName()), work);
  if (!error.isEmpty()) {
    showError(tr("Could not export %1: %2").arg(path, error));
    return false;
  }
  lastError_.clear();
  statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

bool MainWindow::exportLod(const QString& path) {
  if (!viewport_->hasDocument()) return false;
  const QString suffix = QFileInfo(path).suffix().toLower();
  if (suffix != "obj" && suffix != "glb") {
    showError(tr("Cannot export the level of detail to %1: use .obj or .glb").arg(path));
    return false;
  }
  viewport_->endStroke();
  // Salient methods read the saliency in alpha: the current surface's, from the viewport when it
  // has it at once (GPU), else computed by the export's worker on its copy.
  const core::ResampleMethod m = lodPanel_->method();
  const bool salient =
      m == core::ResampleMethod::SalientPoint || m == core::ResampleMethod::SalientAverage;
  if (salient) viewport_->setSaliencyWanted(true);
  const bool computeSaliency = salient && !viewport_->saliencyCurrent();
  auto snapshot = std::make_shared<core::GeometryImage>(viewport_->document().positions);
  const core::LodOptions options = lodPanel_->lodOptions();
  auto control = std::make_shared<TaskControl>();
  const QString error = runInBackground(
      tr("Exporting %1…").arg(QFileInfo(path).fileName()),
      [snapshot, options, path, control, computeSaliency] {
        if (computeSaliency) core::computeSaliency(*snapshot);
        const core::LodMesh lod = core::generateLod(*snapshot, options);
        control->fraction = 0.3f;
        if (control->cancel) return; // between steps: nothing written yet
        // One map texel per full-resolution sample (up to 4096²): the map carries all the detail
        // the LOD's triangles dropped.
        const int resolution = std::clamp(snapshot->size(), 2, 4096);
        const core::NormalMap map =
            core::bakeNormalMap(*snapshot, lod, core::NormalMapSpace::Object, resolution);
        control->fraction = 0.8f;
        if (control->cancel) return;
        core::writeLodMesh(lod, map, toPath(path));
        control->fraction = 1.0f;
      },
      control);
  updateSaliencyWanted();
  if (!error.isEmpty()) {
    showError(tr("Could not export %1: %2").arg(path, error));
    return false;
  }
  if (control->cancel) {
    statusBar()->showMessage(tr("Export cancelled; nothing was written"), 8000);
    return false;
  }
  lastError_.clear();
  statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
  return true;
}

bool MainWindow::autosaveNow() {
  if (!viewport_->hasDocument() || busy_) return false;
  if (!isModified() || undoStack_->index() == autosavedIndex_) return true;
  viewport_->endStroke();
  auto snapshot = std::make_shared<core::Document>(viewport_->document());
  const QString original = path_;
  RecoveryStore* store = &recovery_;
  const QString error = runInBackground(
      tr("Autosaving…"), [snapshot, original, store] { store->save(*snapshot, original); });
  if (!error.isEmpty()) {
    statusBar()->showMessage(tr("Autosave failed: %1").arg(error), 10000);
    return false;
  }
  autosavedIndex_ = undoStack_->index();
  return true;
}

void MainWindow::startSession() {
  pending_ = recovery_.pending();
  if (pending_ && options_.askAboutRecovery) {
    const QString when = pending_->savedAt.toLocalTime().toString(Qt::TextDate);
    const QString from =
        pending_->originalPath.isEmpty() ? tr("an unsaved model") : pending_->originalPath;
    const auto answer = QMessageBox::question(
        this, tr("Recover unsaved work?"),
        tr("Octaclay did not close properly last time. An autosave of %1 from %2 can be "
           "recovered.\n\nRecover it?")
            .arg(from, when),
        QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
    if (answer == QMessageBox::Yes)
      recover();
    else
      recovery_.discard();
    pending_.reset();
  }
  if (!recovery_.beginSession())
    statusBar()->showMessage(tr("Another Octaclay is running: autosave is off here"), 10000);
  const int seconds = QSettings().value("autosave/seconds", options_.autosaveSeconds).toInt();
  options_.autosaveSeconds = seconds;
  if (seconds > 0) autosaveTimer_->start(seconds * 1000);
}

bool MainWindow::recover() {
  if (!pending_) return false;
  core::Document document;
  const RecoveryStore::Pending pending = *pending_;
  RecoveryStore* store = &recovery_;
  const QString error = runInBackground(
      tr("Recovering…"), [&document, pending, store] { document = store->load(pending); });
  if (!error.isEmpty()) {
    showError(tr("Could not recover the autosave: %1").arg(error));
    return false;
  }
  adoptDocument(std::move(document), pending.originalPath);
  forceModified_ = true; // it differs from the file on disk until saved
  pending_.reset();
  updateTitle();
  return true;
}

void MainWindow::addRecentFile(const QString& path) {
  QSettings settings;
  QStringList files = settings.value("recentFiles").toStringList();
  files.removeAll(path);
  files.prepend(path);
  while (files.size() > kMaxRecentFiles)
    files.removeLast();
  settings.setValue("recentFiles", files);
  rebuildRecentMenu();
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
  const QString path = path_.isEmpty() ? choose(FileRequest::SaveAs) : path_;
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
  recovery_.endSession(); // a clean exit leaves nothing to recover
  event->accept();
}

} // namespace octaclay::app
