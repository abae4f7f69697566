// What a newcomer tripped over, in the real window (xcb under Xvfb, real GL strokes): an import
// is one undo step and undoing it brings the previous model back with its own strokes; File ▸
// Open on a mesh points to Import Mesh; an import error names the file once and fits the status
// bar; the Level of detail dock forgets the previous model's figures on File ▸ New; save and
// export dialogs suggest a name beside the document; File ▸ New says "Detail", not "Size N", and
// starts at the default display detail, whatever the imported model was shown at.
#include "brush_panel.h"
#include "lod_generator.h"
#include "lod_panel.h"
#include "main_window.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/geometry_image.h"
#include "octaclay/core/measure/stretch.h"

#include <QComboBox>
#include <QDialog>
#include <QFontMetrics>
#include <QLabel>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

#include <array>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <vector>

using namespace octaclay;
using app::MainWindow;
using app::testing::bitEqual;
using app::testing::positionsOf;

namespace {

// An icosphere (an icosahedron split twice, 162 vertices, 320 triangles) stretched to an egg, as
// an OBJ: a closed genus-0 mesh that imports in a moment.
void writeEgg(const QString& path) {
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  std::vector<std::array<float, 3>> v = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                                         {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                                         {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  std::vector<std::array<int, 3>> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int level = 0; level < 2; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      if (auto it = middle.find(key); it != middle.end()) return it->second;
      v.push_back({(v[a][0] + v[b][0]) / 2, (v[a][1] + v[b][1]) / 2, (v[a][2] + v[b][2]) / 2});
      return middle[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<std::array<int, 3>> finer;
    for (const auto& [a, b, c] : f) {
      const int ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
      finer.insert(finer.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    f = finer;
  }
  std::ofstream out(path.toStdString());
  for (auto& p : v) {
    const float r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    out << "v " << p[0] / r << ' ' << 1.5f * p[1] / r << ' ' << p[2] / r << '\n';
  }
  for (const auto& [a, b, c] : f)
    out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
}

} // namespace

class NewcomerRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void importIsOneUndoStepThatBringsThePreviousModelBack();
  void openOnAMeshPointsToImport();
  void importErrorNamesTheFileOnceAndFitsTheStatusBar();
  void lodFiguresGoWithFileNew();
  void saveAndExportSuggestANameBesideTheDocument();
  void newModelDialogSaysDetail();
  void fileNewGoesBackToTheDefaultDisplayDetail();
  void fileNewMakesACapsuleForALimb();

private:
  std::unique_ptr<MainWindow> makeWindow();

  QTemporaryDir dir_;
  QString egg_;
  std::unique_ptr<MainWindow> window_;
};

void NewcomerRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("newcomer_render_test");
  qputenv("OCTACLAY_PLUGIN_PATH", dir_.filePath("plugins").toUtf8());
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  QVERIFY(QDir().mkpath(dir_.filePath("meshes")));
  egg_ = dir_.filePath("meshes/egg.obj");
  writeEgg(egg_);
}

void NewcomerRenderTest::init() {
  QSettings().clear();
}

void NewcomerRenderTest::cleanup() {
  window_.reset();
}

std::unique_ptr<MainWindow> NewcomerRenderTest::makeWindow() {
  auto w = app::testing::openTestWindow(dir_.filePath("recovery"));
  if (w) w->brushState()->selectBrush("push");
  return w;
}

void NewcomerRenderTest::importIsOneUndoStepThatBringsThePreviousModelBack() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  const std::vector<float> sphere = positionsOf(*window_);
  app::testing::pushStrokeAcross(*window_, 0);
  const std::vector<float> stroked = positionsOf(*window_);
  QVERIFY(!bitEqual(sphere, stroked));
  QVERIFY(window_->saveDocument(dir_.filePath("ball.exr")));
  QVERIFY(!window_->isModified());

  QVERIFY(window_->importMesh(egg_, 64));
  QCOMPARE(window_->viewport()->modeller().document().size(), 64);
  QTRY_COMPARE(window_->undoStack()->count(), 2);
  QTRY_COMPARE(window_->undoStack()->text(1), QStringLiteral("Import egg.obj"));
  QVERIFY(window_->currentPath().isEmpty());
  QVERIFY(window_->isModified());
  QCOMPARE(window_->windowTitle(), QStringLiteral("egg[*] — Octaclay")); // the mesh's name
  const std::vector<float> imported = positionsOf(*window_);
  app::testing::pushStrokeAcross(*window_, 0);
  const std::vector<float> importedStroked = positionsOf(*window_);
  QVERIFY(!bitEqual(imported, importedStroked));
  QTRY_COMPARE(window_->undoStack()->count(), 3);

  // Back through the egg's stroke and the import to the saved ball, then its own stroke.
  QAction* undo = window_->action("actionUndo");
  QAction* redo = window_->action("actionRedo");
  undo->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), imported));
  undo->trigger();
  QCOMPARE(window_->viewport()->modeller().document().size(), 128);
  QVERIFY(bitEqual(positionsOf(*window_), stroked));
  QCOMPARE(window_->currentPath(), QFileInfo(dir_.filePath("ball.exr")).absoluteFilePath());
  QVERIFY(!window_->isModified()); // as saved
  QCOMPARE(window_->windowTitle(), QStringLiteral("ball.exr[*] — Octaclay"));
  QCOMPARE(window_->lodPanel()->documentSize(), 128);
  undo->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), sphere));
  // And forward again to the stroked egg.
  redo->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), stroked));
  redo->trigger();
  QCOMPARE(window_->viewport()->modeller().document().size(), 64);
  QVERIFY(bitEqual(positionsOf(*window_), imported));
  QVERIFY(window_->currentPath().isEmpty());
  QVERIFY(window_->isModified());
  QCOMPARE(window_->windowTitle(), QStringLiteral("egg[*] — Octaclay"));
  redo->trigger();
  QVERIFY(bitEqual(positionsOf(*window_), importedStroked));
  QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
}

void NewcomerRenderTest::openOnAMeshPointsToImport() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  const std::vector<float> before = positionsOf(*window_);
  window_->setFileChooser([&](MainWindow::FileRequest r) {
    return r == MainWindow::FileRequest::Open ? egg_ : QString();
  });
  window_->action("actionOpen")->trigger();
  const QString error = window_->lastError();
  QVERIFY2(error.contains("egg.obj is a mesh") && error.contains("File ▸ Import Mesh"),
           qPrintable(error));
  QVERIFY2(!error.contains("magic"), qPrintable(error));
  QVERIFY(bitEqual(positionsOf(*window_), before));
}

void NewcomerRenderTest::importErrorNamesTheFileOnceAndFitsTheStatusBar() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  const QString bad = QString(OCTACLAY_SHARED_DATA) + "/meshes/invalid/bob_genus1.obj";
  QVERIFY(!window_->importMesh(bad, 64));
  const QString error = window_->lastError();
  QVERIFY2(error.contains("genus 1"), qPrintable(error));
  QCOMPARE(error.count("bob_genus1.obj"), 1);
  QStatusBar* bar = window_->statusBar();
  const QString shown = bar->currentMessage();
  QVERIFY2(bar->fontMetrics().horizontalAdvance(shown) < bar->width(), qPrintable(shown));
  QVERIFY(shown.startsWith("Could not import"));
  QCOMPARE(bar->toolTip(), error);
}

void NewcomerRenderTest::lodFiguresGoWithFileNew() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Blob, 128, true));
  app::LodPanel* lod = window_->lodPanel();
  lod->setDisplay(app::LodPanel::Display::Lod);
  QVERIFY(QTest::qWaitFor(
      [&] { return lod->errorText() != "Error: —" && !window_->lodGenerator()->busy(); }, 60000));
  QVERIFY(lod->lodText().contains("triangles"));
  lod->setDisplay(app::LodPanel::Display::FullResolution);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  QCOMPARE(lod->lodText(), QStringLiteral("LOD: —"));
  QCOMPARE(lod->errorText(), QStringLiteral("Error: —"));
}

void NewcomerRenderTest::saveAndExportSuggestANameBesideTheDocument() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->importMesh(egg_, 64));
  const QString meshes = QFileInfo(egg_).absolutePath();
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::SaveAs), meshes + "/egg.exr");
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::Export), meshes + "/egg.glb");
  const QString saved = QFileInfo(dir_.filePath("clay/bust.exr")).absoluteFilePath();
  QVERIFY(QDir().mkpath(dir_.filePath("clay")));
  QVERIFY(window_->saveDocument(saved));
  const QString clay = QFileInfo(saved).absolutePath();
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::SaveAs), saved);
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::SaveCompressed), clay + "/bust.ocz");
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::Export), clay + "/bust.glb");
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::ExportLod), clay + "/bust_lod.glb");
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::Open), clay);
  QCOMPARE(window_->suggestedPath(MainWindow::FileRequest::Import), clay);
}

void NewcomerRenderTest::newModelDialogSaysDetail() {
  window_ = makeWindow();
  QVERIFY(window_);
  QStringList labels, items;
  QString chosen;
  // File ▸ New is modal: read it once it is up, then cancel.
  QTimer::singleShot(0, window_.get(), [&] {
    QWidget* dialog = QApplication::activeModalWidget();
    if (!dialog) return;
    for (QLabel* l : dialog->findChildren<QLabel*>())
      labels << l->text();
    if (auto* detail = dialog->findChild<QComboBox*>("detailCombo")) {
      for (int k = 0; k < detail->count(); ++k)
        items << detail->itemText(k);
      chosen = detail->currentText();
    }
    static_cast<QDialog*>(dialog)->reject();
  });
  window_->action("actionNew")->trigger();
  QVERIFY2(labels.contains("Detail"), qPrintable(labels.join(", ")));
  QVERIFY(!labels.join(" ").contains("Size N"));
  QCOMPARE(items.size(), 7);
  QCOMPARE(items.front(), QStringLiteral("Very coarse (64)"));
  QCOMPARE(chosen, QStringLiteral("Very fine (1024)"));
}

void NewcomerRenderTest::fileNewGoesBackToTheDefaultDisplayDetail() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->importMesh(egg_, 64));
  app::LodPanel* lod = window_->lodPanel();
  // The imported model shown at Full detail, by choice, and its LOD beside it.
  QVERIFY(lod->setDivisor(1));
  lod->setDisplay(app::LodPanel::Display::SideBySide);
  QCOMPARE(window_->viewport()->levelDivisor(), 1);
  QVERIFY(window_->saveDocument(dir_.filePath("egg.exr"))); // File ▸ New asks no question

  // File ▸ New through its menu item, a Fine (512) sphere chosen in its dialog.
  bool accepted = false;
  QTimer::singleShot(0, window_.get(), [&] {
    auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    auto* detail = dialog->findChild<QComboBox*>("detailCombo");
    if (!detail) { // not the New dialog: refuse it rather than wait forever
      dialog->reject();
      return;
    }
    detail->setCurrentIndex(detail->findData(512));
    accepted = true;
    dialog->accept();
  });
  window_->action("actionNew")->trigger();
  QVERIFY(accepted);
  QCOMPARE(window_->viewport()->modeller().document().size(), 512);
  // The default level: the largest of at most LodPanel::kDefaultDisplaySize samples a side.
  const int expected = 512 / app::LodPanel::kDefaultDisplaySize;
  QCOMPARE(lod->divisor(), expected);
  QCOMPARE(window_->viewport()->levelDivisor(), expected);
  QCOMPARE(lod->display(), app::LodPanel::Display::FullResolution);
  QCOMPARE(window_->viewport()->lodDisplay(), app::LodDisplay::FullResolution);
}

// Issue 33: a capsule from File ▸ New, chosen in its dialog: twice as long as it is wide, its
// edges no longer than a sphere's of the same N (merge_test measures its even sampling).
void NewcomerRenderTest::fileNewMakesACapsuleForALimb() {
  window_ = makeWindow();
  QVERIFY(window_);
  bool accepted = false;
  QTimer::singleShot(0, window_.get(), [&] {
    auto* dialog = qobject_cast<QDialog*>(QApplication::activeModalWidget());
    if (!dialog) return;
    auto* shape = dialog->findChild<QComboBox*>("shapeCombo");
    auto* detail = dialog->findChild<QComboBox*>("detailCombo");
    if (!shape || !detail || shape->findData("capsule") < 0) {
      dialog->reject();
      return;
    }
    shape->setCurrentIndex(shape->findData("capsule"));
    detail->setCurrentIndex(detail->findData(256));
    accepted = true;
    dialog->accept();
  });
  window_->action("actionNew")->trigger();
  QVERIFY2(accepted, "the New dialog offers no capsule");
  const core::Document& made = window_->modeller()->document();
  QCOMPARE(made.size(), 256);
  const core::BoundingBox box = core::boundingBox(made.positions);
  const core::Vec3f extent = box.max - box.min;
  qInfo("capsule extent %.3f x %.3f x %.3f", double(extent.x), double(extent.y), double(extent.z));
  QVERIFY(std::abs(extent.z / extent.x - 2.0f) < 0.05f);
  QVERIFY(std::abs(extent.x - extent.y) < 1e-3f);
  // No long edges: the longest over the median within 10 % of a sphere's.
  const double capsule = core::summarizeStretch(made.positions).longestOverMedian;
  const double sphere =
      core::summarizeStretch(
          core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 256)).positions)
          .longestOverMedian;
  qInfo("longest edge / median: capsule %.2f, sphere %.2f", capsule, sphere);
  QVERIFY(capsule <= sphere * 1.1);
}

QTEST_MAIN(NewcomerRenderTest)
#include "newcomer_render_test.moc"
