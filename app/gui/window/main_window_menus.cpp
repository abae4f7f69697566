// The main window's menus: File (document actions), Edit (undo, redo, preferences), Mesh
// (whole-model operations) and View.

#include "brush_panel.h"
#include "detail_levels.h"
#include "help_menu.h"
#include "history_list.h"
#include "lod_panel.h"
#include "looks_menu.h"
#include "main_window.h"
#include "modeller.h"
#include "save_compressed_dialog.h"
#include "shortcut_sheet.h"
#include "view_actions.h"
#include "viewport_widget.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QDockWidget>
#include <QFormLayout>
#include <QInputDialog>
#include <QLabel>
#include <QLocale>
#include <QMenuBar>
#include <QSettings>
#include <QSpinBox>
#include <QTimer>

#include <cmath>

namespace octaclay::app {
namespace {

QString mib(std::size_t bytes) {
  return QString::number(double(bytes) / (1 << 20), 'f', 1);
}

} // namespace

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
            shape->setObjectName("shapeCombo");
            for (const char* s : {"sphere", "cube", "cylinder", "blob", "capsule"})
              shape->addItem(tr(s), QString(s));
            // A limb to sculpt on, sampled evenly along it (core::makeCapsule).
            shape->setItemData(4,
                               tr("A limb: a cylinder with round ends, its samples spread "
                                  "evenly along it"),
                               Qt::ToolTipRole);
            auto* size = new QComboBox(&dialog);
            size->setObjectName("detailCombo");
            for (int n : {64, 128, 256, 512, 1024, 2048, 4096}) {
              size->addItem(detailLabel(n), n);
              size->setItemData(size->count() - 1, detailTooltip(n), Qt::ToolTipRole);
            }
            size->setCurrentIndex(size->findData(1024));
            form->addRow(tr("Shape"), shape);
            form->addRow(tr("Detail"), size);
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
              const QList<int> sizes{128, 256, 512, 1024, 2048};
              QStringList labels;
              for (int s : sizes)
                labels << detailLabel(s);
              const QString size = QInputDialog::getItem(this, tr("Import mesh"), tr("Detail"),
                                                         labels, 2, false, &ok);
              if (!ok) return;
              n = sizes.value(static_cast<int>(labels.indexOf(size)), 512);
            }
            importMesh(path, n);
          });
  recentMenu_ = file->addMenu(tr("Open &Recent"));
  connect(
      add(file, tr("&Save"), "actionSave", QKeySequence::Save), &QAction::triggered, this, [this] {
        const QString path = currentPath().isEmpty() ? choose(FileRequest::SaveAs) : currentPath();
        if (!path.isEmpty()) saveDocument(path);
      });
  connect(add(file, tr("Save &As…"), "actionSaveAs", QKeySequence(tr("Ctrl+Shift+S"))),
          &QAction::triggered, this, [this] {
            const QString path = choose(FileRequest::SaveAs);
            if (!path.isEmpty()) saveDocument(path);
          });
  connect(add(file, tr("Save &Compressed…"), "actionSaveCompressed"), &QAction::triggered, this,
          [this] {
            if (!viewport_->modeller().hasDocument()) return;
            viewport_->endStroke();
            SaveCompressedDialog dialog(
                std::make_shared<const core::Document>(viewport_->modeller().document()), this);
            if (dialog.exec() != QDialog::Accepted) return;
            const QString path = choose(FileRequest::SaveCompressed);
            if (!path.isEmpty()) saveCompressed(path, dialog.options());
          });
  connect(add(file, tr("&Export Mesh…"), "actionExport", QKeySequence(tr("Ctrl+E"))),
          &QAction::triggered, this, [this] {
            const QString path = choose(FileRequest::Export);
            if (path.isEmpty() || !viewport_->modeller().hasDocument()) return;
            int divisor = lodPanel_->divisor();
            if (!chooser_) { // interactive: ask which level, offering the displayed one
              const int n = viewport_->modeller().document().size();
              QStringList levels;
              for (int d = 1; n / d >= 2 && d <= 64; d *= 2)
                levels << (d == 1 ? tr("Full detail (%2 triangles)")
                                  : tr("1/%1 of the detail (%2 triangles)").arg(d))
                              .arg(QLocale().toString(2LL * (n / d) * (n / d)));
              bool ok = false;
              const QString level =
                  QInputDialog::getItem(this, tr("Export mesh"), tr("Detail"), levels,
                                        static_cast<int>(std::log2(divisor)), false, &ok);
              if (!ok) return;
              divisor = 1 << levels.indexOf(level);
            }
            exportMesh(path, divisor);
          });
  connect(add(file, tr("Save &Image…"), "actionSaveImage"), &QAction::triggered, this,
          &MainWindow::askAndSaveImage);
  file->addSeparator();
  connect(add(file, tr("&Quit"), "actionQuit", QKeySequence::Quit), &QAction::triggered, this,
          &QWidget::close);

  QMenu* edit = menuBar()->addMenu(tr("&Edit"));
  // Edit ▸ Undo and Redo name the step they would take (HistoryList: the modeller's history).
  QAction* undo = new QAction(tr("&Undo"), this);
  QAction* redo = new QAction(tr("&Redo"), this);
  const auto name = [this, undo, redo] {
    undo->setEnabled(history_->canUndo());
    undo->setText(history_->canUndo() ? tr("&Undo %1").arg(history_->undoText()) : tr("&Undo"));
    redo->setEnabled(history_->canRedo());
    redo->setText(history_->canRedo() ? tr("&Redo %1").arg(history_->redoText()) : tr("&Redo"));
  };
  name();
  connect(history_, &QAbstractItemModel::modelReset, this, name);
  connect(undo, &QAction::triggered, history_, &HistoryList::undo);
  connect(redo, &QAction::triggered, history_, &HistoryList::redo);
  undo->setObjectName("actionUndo");
  undo->setProperty(kSheetTextProperty, tr("Undo")); // its text names the step
  undo->setShortcut(QKeySequence::Undo);
  redo->setObjectName("actionRedo");
  redo->setProperty(kSheetTextProperty, tr("Redo"));
  // Both keys everywhere; QKeySequence::Redo is one of them on each platform, and an action
  // holding the same key twice makes Qt drop it as ambiguous.
  redo->setShortcuts({QKeySequence(tr("Ctrl+Shift+Z")), QKeySequence(tr("Ctrl+Y"))});
  edit->addAction(undo);
  edit->addAction(redo);
  addHistoryAction(*edit, *history_, *this);
  edit->addSeparator();
  connect(add(edit, tr("&Preferences…"), "actionPreferences"), &QAction::triggered, this, [this] {
    QDialog dialog(this);
    dialog.setWindowTitle(tr("Preferences"));
    auto* form = new QFormLayout(&dialog);
    const core::EditHistory& h = viewport_->modeller().history();
    auto* undoMemory = new QSpinBox(&dialog);
    undoMemory->setObjectName(QStringLiteral("undoMemory"));
    undoMemory->setRange(kMinUndoMiB, kMaxUndoMiB);
    undoMemory->setSingleStep(64);
    undoMemory->setSuffix(tr(" MiB"));
    undoMemory->setValue(undoBudgetMiB_);
    undoMemory->setToolTip(tr("How much memory Undo may hold: when strokes no longer fit, the "
                              "oldest can no longer be undone. A step at N = 1024 takes a few "
                              "MiB."));
    form->addRow(tr("Undo memory"), undoMemory);
    form->addRow(QString(), new QLabel(tr("%1 MiB in use now (%2 steps)")
                                           .arg(mib(h.bytes()))
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
    if (undoMemory->value() != undoBudgetMiB_) setUndoBudgetMiB(undoMemory->value());
    options_.autosaveSeconds = minutes->value() * 60;
    QSettings().setValue("autosave/seconds", options_.autosaveSeconds);
    if (options_.autosaveSeconds > 0)
      autosaveTimer_->start(options_.autosaveSeconds * 1000);
    else
      autosaveTimer_->stop();
  });

  // Mesh: whole-model operations, after Edit as in Blender.
  QMenu* mesh = menuBar()->addMenu(tr("&Mesh"));
  QAction* evenOut = add(mesh, tr("&Even Out Samples"), "actionEvenOutSamples");
  const QString evenOutTip =
      tr("Spread the samples evenly over the surface again, so stretched parts get detail back; "
         "the shape and paint stay put (if they would not, nothing changes and the status bar "
         "says why). Runs at once with progress and Cancel; one Undo brings the model back");
  evenOut->setToolTip(evenOutTip);
  evenOut->setStatusTip(evenOutTip);
  connect(evenOut, &QAction::triggered, this, [this] { evenOutSamples(); });
  QAction* remeshAction = add(mesh, tr("&Remesh…"), "actionRemesh");
  const QString remeshTip =
      tr("Give the surface a new, even sampling at a size you choose (the current one at "
         "first), every painted layer carried to the same surface points: for limbs pulled too "
         "far to even out. Asks first; progress and Cancel; one Undo brings the model back");
  remeshAction->setToolTip(remeshTip);
  remeshAction->setStatusTip(remeshTip);
  connect(remeshAction, &QAction::triggered, this, [this] { mesh_->openMeshSizeDialog(true); });
  QAction* resolution = add(mesh, tr("Re&solution…"), "actionResolution");
  const QString resolutionTip =
      tr("Resample every layer at a finer or coarser N with the same parameterization: block "
         "out coarse, detail fine. Asks first; one Undo brings the model back");
  resolution->setToolTip(resolutionTip);
  resolution->setStatusTip(resolutionTip);
  connect(resolution, &QAction::triggered, this, [this] { mesh_->openMeshSizeDialog(false); });
  mesh->setToolTipsVisible(true);
  connect(mesh, &QMenu::aboutToShow, mesh_, &MeshActions::updateActions);
  mesh_->updateActions();

  QMenu* view = menuBar()->addMenu(tr("&View"));
  for (QDockWidget* dock : findChildren<QDockWidget*>())
    view->addAction(dock->toggleViewAction());
  view->addSeparator();
  connect(add(view, tr("&Frame Model"), "actionFrameModel", QKeySequence(tr("Home"))),
          &QAction::triggered, viewport_, &ViewportWidget::frameModel);
  addViewActions(view, viewport_);
  addLookActions(view, viewport_);

  addHelpMenu(*this);
}

} // namespace octaclay::app
