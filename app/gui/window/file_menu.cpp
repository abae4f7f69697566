// File ▸ New, Open, Import, Save, Export and Save Image: the questions each asks, then the
// window's document actions.

#include "file_menu.h"

#include "detail_levels.h"
#include "lod_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "save_compressed_dialog.h"
#include "save_image_dialog.h"
#include "viewport_widget.h"

#include <QComboBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFileDialog>
#include <QFileInfo>
#include <QFormLayout>
#include <QInputDialog>
#include <QLocale>
#include <QMenuBar>

#include <cmath>

namespace octaclay::app {
namespace {

QAction* add(QMenu* menu, const QString& text, const QString& name, QKeySequence shortcut = {}) {
  QAction* a = menu->addAction(text);
  a->setObjectName(name);
  if (!shortcut.isEmpty()) a->setShortcut(shortcut);
  return a;
}

void askAndSaveImage(MainWindow& window) {
  ViewportWidget& viewport = *window.viewport();
  const QSize viewSize = viewport.size() * viewport.devicePixelRatioF();
  ImageRequest request{viewSize, true};
  if (!window.hasFileChooser()) { // interactive: ask the size and background
    SaveImageDialog dialog(viewSize, viewport.maxImageSide(), &window);
    if (dialog.exec() != QDialog::Accepted) return;
    request = dialog.request();
  }
  QString path = window.choose(MainWindow::FileRequest::SaveImage);
  if (path.isEmpty()) return;
  if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".png");
  window.saveImage(path, request.size, request.background);
}

void askNewDocument(MainWindow& window) {
  QDialog dialog(&window);
  dialog.setWindowTitle(MainWindow::tr("New model"));
  auto* form = new QFormLayout(&dialog);
  auto* shape = new QComboBox(&dialog);
  shape->setObjectName("shapeCombo");
  for (const char* s : {"sphere", "cube", "cylinder", "blob", "capsule"})
    shape->addItem(MainWindow::tr(s), QString(s));
  // A limb to sculpt on, sampled evenly along it (core::makeCapsule).
  shape->setItemData(
      4, MainWindow::tr("A limb: a cylinder with round ends, its samples spread evenly along it"),
      Qt::ToolTipRole);
  auto* size = new QComboBox(&dialog);
  size->setObjectName("detailCombo");
  for (int n : {64, 128, 256, 512, 1024, 2048, 4096}) {
    size->addItem(detailLabel(n), n);
    size->setItemData(size->count() - 1, detailTooltip(n), Qt::ToolTipRole);
  }
  size->setCurrentIndex(size->findData(1024));
  form->addRow(MainWindow::tr("Shape"), shape);
  form->addRow(MainWindow::tr("Detail"), size);
  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
  form->addRow(buttons);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  if (dialog.exec() != QDialog::Accepted) return;
  window.newDocument(*core::parseBaseShape(shape->currentData().toString().toStdString()),
                     size->currentData().toInt());
}

void askImport(MainWindow& window) {
  if (!window.maybeSave()) return;
  const QString path = window.choose(MainWindow::FileRequest::Import);
  if (path.isEmpty()) return;
  int n = 512;
  if (!window.hasFileChooser()) { // interactive: ask the image size
    bool ok = false;
    const QList<int> sizes{128, 256, 512, 1024, 2048};
    QStringList labels;
    for (int s : sizes)
      labels << detailLabel(s);
    const QString size = QInputDialog::getItem(&window, MainWindow::tr("Import mesh"),
                                               MainWindow::tr("Detail"), labels, 2, false, &ok);
    if (!ok) return;
    n = sizes.value(static_cast<int>(labels.indexOf(size)), 512);
  }
  window.importMesh(path, n);
}

void askSaveCompressed(MainWindow& window) {
  if (!window.modeller()->hasDocument()) return;
  window.viewport()->endStroke();
  SaveCompressedDialog dialog(std::make_shared<const core::Document>(window.modeller()->document()),
                              &window);
  if (dialog.exec() != QDialog::Accepted) return;
  const QString path = window.choose(MainWindow::FileRequest::SaveCompressed);
  if (!path.isEmpty()) window.saveCompressed(path, dialog.options());
}

void askExport(MainWindow& window) {
  const QString path = window.choose(MainWindow::FileRequest::Export);
  if (path.isEmpty() || !window.modeller()->hasDocument()) return;
  int divisor = window.lodPanel()->divisor();
  if (!window.hasFileChooser()) { // interactive: ask which level, offering the displayed one
    const int n = window.modeller()->document().size();
    QStringList levels;
    for (int d = 1; n / d >= 2 && d <= 64; d *= 2)
      levels << (d == 1 ? MainWindow::tr("Full detail (%2 triangles)")
                        : MainWindow::tr("1/%1 of the detail (%2 triangles)").arg(d))
                    .arg(QLocale().toString(2LL * (n / d) * (n / d)));
    bool ok = false;
    const QString level =
        QInputDialog::getItem(&window, MainWindow::tr("Export mesh"), MainWindow::tr("Detail"),
                              levels, static_cast<int>(std::log2(divisor)), false, &ok);
    if (!ok) return;
    divisor = 1 << levels.indexOf(level);
  }
  window.exportMesh(path, divisor);
}

void save(MainWindow& window, bool askPath) {
  const QString path = askPath || window.currentPath().isEmpty()
                           ? window.choose(MainWindow::FileRequest::SaveAs)
                           : window.currentPath();
  if (!path.isEmpty()) window.saveDocument(path);
}

} // namespace

QString askFilePath(MainWindow& window, MainWindow::FileRequest request, const QString& dir) {
  using FileRequest = MainWindow::FileRequest;
  switch (request) {
  case FileRequest::Open:
    return QFileDialog::getOpenFileName(&window, MainWindow::tr("Open model"), dir,
                                        MainWindow::tr("Octaclay documents (*.exr *.ocz)"));
  case FileRequest::SaveCompressed:
    return QFileDialog::getSaveFileName(&window, MainWindow::tr("Save compressed model"), dir,
                                        MainWindow::tr("Compressed Octaclay documents (*.ocz)"));
  case FileRequest::SaveAs:
    return QFileDialog::getSaveFileName(&window, MainWindow::tr("Save model"), dir,
                                        MainWindow::tr("Octaclay documents (*.exr)"));
  case FileRequest::Import:
    return QFileDialog::getOpenFileName(&window, MainWindow::tr("Import mesh"), dir,
                                        MainWindow::tr("Meshes (*.obj *.ply *.stl *.off)"));
  case FileRequest::Export:
    return QFileDialog::getSaveFileName(&window, MainWindow::tr("Export mesh"), dir,
                                        MainWindow::tr("Meshes (*.glb *.obj *.ply *.stl *.off)"));
  case FileRequest::ExportLod:
    return QFileDialog::getSaveFileName(&window, MainWindow::tr("Export level of detail"), dir,
                                        MainWindow::tr("Meshes with a normal map (*.glb *.obj)"));
  case FileRequest::SaveImage:
    return QFileDialog::getSaveFileName(&window, MainWindow::tr("Save image"), dir,
                                        MainWindow::tr("PNG images (*.png)"));
  }
  return {};
}

QMenu* addFileMenu(MainWindow& window) {
  QMenu* file = window.menuBar()->addMenu(MainWindow::tr("&File"));
  const auto item = [file, &window](const QString& text, const QString& name, QKeySequence shortcut,
                                    auto run) {
    QObject::connect(add(file, text, name, shortcut), &QAction::triggered, &window,
                     [&window, run] { run(window); });
  };
  item(MainWindow::tr("&New…"), "actionNew", QKeySequence::New, askNewDocument);
  item(MainWindow::tr("&Open…"), "actionOpen", QKeySequence::Open, [](MainWindow& w) {
    if (!w.maybeSave()) return;
    const QString path = w.choose(MainWindow::FileRequest::Open);
    if (!path.isEmpty()) w.openDocument(path);
  });
  item(MainWindow::tr("&Import Mesh…"), "actionImport", QKeySequence(MainWindow::tr("Ctrl+I")),
       askImport);
  QMenu* recent = file->addMenu(MainWindow::tr("Open &Recent"));
  item(MainWindow::tr("&Save"), "actionSave", QKeySequence::Save,
       [](MainWindow& w) { save(w, false); });
  item(MainWindow::tr("Save &As…"), "actionSaveAs", QKeySequence(MainWindow::tr("Ctrl+Shift+S")),
       [](MainWindow& w) { save(w, true); });
  item(MainWindow::tr("Save &Compressed…"), "actionSaveCompressed", {}, askSaveCompressed);
  item(MainWindow::tr("&Export Mesh…"), "actionExport", QKeySequence(MainWindow::tr("Ctrl+E")),
       askExport);
  item(MainWindow::tr("Save &Image…"), "actionSaveImage", {}, askAndSaveImage);
  file->addSeparator();
  QObject::connect(add(file, MainWindow::tr("&Quit"), "actionQuit", QKeySequence::Quit),
                   &QAction::triggered, &window, &QWidget::close);
  return recent;
}

} // namespace octaclay::app
