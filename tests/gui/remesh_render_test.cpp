// Mesh ▸ Remesh… and Mesh ▸ Resolution… in the modeller, through the real VTK viewport (xcb
// under Xvfb, llvmpipe): a sphere with a pulled limb and a painted cap gets a new, even sampling
// as one undo step that brings the original back bit for bit, a run twice by accident is one
// Undo away, a cancelled run changes neither the model nor its history, the resolution goes up
// and down as one step, and the dialogs say what they will do.
#include "limb_document.h"
#include "main_window.h"
#include "mesh_size_dialog.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_widget.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/measure/stretch.h"

#include <QAction>
#include <QComboBox>
#include <QMenuBar>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>
#include <vtkCamera.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

using namespace octaclay;
using app::MainWindow;
using app::MeshSizeDialog;
using testing::bitsOf;

namespace {

// A unit sphere with a thin limb 3 long pulled out of the +z pole (few samples spread over a
// long spike, as a far push leaves them) and a red cap painted on its -x side (away from the
// limb and off the image's centre).
core::Document paintedLimb(int n) {
  core::Document d = testing::limbDocument(n);
  const std::size_t side = static_cast<std::size_t>(n + 1);
  d.diffuse.texels.resize(side * side * 4);
  for (std::size_t t = 0; t < side * side; ++t) {
    const core::Vec4f& p = d.positions.texels()[t];
    const bool red = p.x < -0.6f;
    const std::array<float, 4> c = red ? std::array<float, 4>{0.9f, 0.1f, 0.1f, 1} : d.diffuse.fill;
    std::copy(c.begin(), c.end(), d.diffuse.texels.begin() + std::ptrdiff_t(t * 4));
  }
  return d;
}

// Share of the samples with |P| > 1.6 (the limb) over the share of the area there: 1 when the
// limb has its fair share of samples.
double limbFairShare(const core::Document& d) {
  return core::regionSampling(d.positions,
                              [](const core::Vec3f& p) { return core::length(p) > 1.6f; })
      .fairShare;
}

// The red cap's share of the diffuse samples (red over 0.5), the cap's area being the same.
double redShare(const core::Document& d) {
  if (d.diffuse.uniform()) return 0;
  std::size_t red = 0;
  const std::size_t count = d.diffuse.texels.size() / 4;
  for (std::size_t t = 0; t < count; ++t)
    red += d.diffuse.texels[t * 4] > 0.5f && d.diffuse.texels[t * 4 + 1] < 0.5f;
  return double(red) / double(count);
}

std::array<double, 3> eyeOf(const MainWindow& w) {
  std::array<double, 3> eye{};
  w.viewport()->renderer()->GetActiveCamera()->GetPosition(eye.data());
  return eye;
}

class RemeshRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void menuItemsSayWhatTheyWillDo();
  void remeshFromTheMenuIsOneUndoStepBackToTheOriginalBitForBit();
  void remeshTwiceByAccidentIsOneUndoAway();
  void cancelledRemeshAndResolutionChangeNothing();
  void resolutionUpAndDownAreOneStepEach();
  void unchangedRemeshSaysWhyAndPushesNoStep();

private:
  bool openLimb(MainWindow& w);

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void RemeshRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("remesh_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
  core::writeDocument(paintedLimb(64), dir_.filePath("limb.exr").toStdString());
}

void RemeshRenderTest::init() {
  QSettings().clear();
  window_ = app::testing::openTestWindow(dir_.filePath("recovery"));
}

void RemeshRenderTest::cleanup() {
  window_.reset();
}

bool RemeshRenderTest::openLimb(MainWindow& w) {
  return w.openDocument(dir_.filePath("limb.exr")) &&
         w.viewport()->modeller().document().size() == 64;
}

void RemeshRenderTest::menuItemsSayWhatTheyWillDo() {
  QVERIFY(window_);
  QMenu* mesh = nullptr;
  for (QAction* a : window_->menuBar()->actions())
    if (a->text().remove('&') == "Mesh") mesh = a->menu();
  QVERIFY(mesh);
  QStringList items;
  for (QAction* a : mesh->actions())
    items << a->text().remove('&');
  QCOMPARE(items, QStringList({"Even Out Samples", "Remesh…", "Resolution…"}));
  for (const char* name : {"actionEvenOutSamples", "actionRemesh", "actionResolution"}) {
    QAction* a = window_->action(name);
    QVERIFY(a);
    QVERIFY(!a->isEnabled()); // nothing to work on yet
    QVERIFY2(a->statusTip().contains("one Undo brings the model back"), name);
  }
  QVERIFY(window_->action("actionRemesh")->statusTip().contains("every painted layer carried"));

  QVERIFY(openLimb(*window_));
  for (const char* name : {"actionEvenOutSamples", "actionRemesh", "actionResolution"})
    QVERIFY2(window_->action(name)->isEnabled(), name);
  // The dialogs: the current N chosen at first, powers of two within eight times it.
  MeshSizeDialog remesh(MeshSizeDialog::Kind::Remesh, 64, window_.get());
  QCOMPARE(remesh.size(), 64);
  QCOMPARE(remesh.sizes(), QList<int>({8, 16, 32, 64, 128, 256, 512}));
  QVERIFY(remesh.description().contains("resampled at N = 64"));
  QVERIFY(remesh.description().contains("Every painted layer (colour, feature, mask) is carried"));
  QVERIFY(remesh.description().contains("one undo step"));
  QVERIFY(remesh.setSize(256));
  QVERIFY(remesh.description().contains("resampled at N = 256"));
  QVERIFY(!remesh.setSize(1024));
  MeshSizeDialog resolution(MeshSizeDialog::Kind::Resolution, 4096, window_.get());
  QCOMPARE(resolution.sizes(), QList<int>({512, 1024, 2048, 4096, 8192}));
  QVERIFY(resolution.setSize(8192));
  QVERIFY(resolution.description().contains("from N = 4096 up to N = 8192"));
  QVERIFY(resolution.setSize(1024));
  QVERIFY(resolution.description().contains("from N = 4096 down to N = 1024"));
  QCOMPARE(MeshSizeDialog(MeshSizeDialog::Kind::Resolution, 2).sizes(), QList<int>({2, 4, 8, 16}));
}

void RemeshRenderTest::remeshFromTheMenuIsOneUndoStepBackToTheOriginalBitForBit() {
  QVERIFY(window_);
  QVERIFY(openLimb(*window_));
  const QString path = window_->currentPath();
  const core::Document original = window_->viewport()->modeller().document();
  const std::vector<unsigned char> before = bitsOf(original);
  const double shareBefore = limbFairShare(original);
  const double ratioBefore = core::summarizeStretch(original.positions).longestOverMedian;
  const double redBefore = redShare(original);
  window_->viewport()->setView(app::ViewDirection::Right);
  const std::array<double, 3> eye = eyeOf(*window_);

  // The menu item opens the dialog; its Remesh button (the current N) runs the remesh.
  bool sawDialog = false;
  QTimer::singleShot(0, window_.get(), [&] {
    auto* dialog = window_->findChild<MeshSizeDialog*>("remeshDialog");
    if (!dialog) return;
    sawDialog = dialog->size() == 64;
    dialog->accept();
  });
  // While it runs, the menu item says how far it is (and cannot be run again).
  QStringList itemTexts;
  QTimer watch;
  connect(&watch, &QTimer::timeout, window_.get(), [&] {
    QAction* a = window_->action("actionRemesh");
    if (!a->isEnabled()) itemTexts << a->text();
  });
  watch.start(20);
  window_->action("actionRemesh")->trigger(); // runs to the end: the task's loop waits for it
  watch.stop();
  QVERIFY(sawDialog);
  QVERIFY(!itemTexts.isEmpty());
  QVERIFY2(itemTexts.first().startsWith("Remeshing… ") && itemTexts.first().endsWith(" %"),
           qPrintable(itemTexts.join(", ")));
  QTRY_COMPARE(window_->undoStack()->count(), 1);
  QCOMPARE(window_->undoStack()->undoText(), QString("Remesh"));
  QVERIFY(window_->isModified());
  QCOMPARE(window_->currentPath(), path); // the same model, still saved where it was
  QVERIFY(window_->viewport()->error().isEmpty());
  QVERIFY2(window_->statusBar()->currentMessage().startsWith("Remeshed at N = 64: longest edge"),
           qPrintable(window_->statusBar()->currentMessage()));
  QVERIFY(window_->action("actionRemesh")->isEnabled());
  QCOMPARE(window_->action("actionRemesh")->text(), QString("&Remesh…"));
  QVERIFY(eyeOf(*window_) == eye); // the camera stays: the same surface

  const core::Document remeshed = window_->viewport()->modeller().document();
  const std::vector<unsigned char> after = bitsOf(remeshed);
  const double shareAfter = limbFairShare(remeshed);
  const double ratioAfter = core::summarizeStretch(remeshed.positions).longestOverMedian;
  const double redAfter = redShare(remeshed);
  qInfo("limb fair share %.3f -> %.3f, longest ÷ median edge %.1f -> %.1f, red cap %.3f -> %.3f",
        shareBefore, shareAfter, ratioBefore, ratioAfter, redBefore, redAfter);
  QVERIFY2(shareAfter > 2 * shareBefore, qPrintable(QString::number(shareAfter)));
  QVERIFY2(ratioAfter < ratioBefore / 2, qPrintable(QString::number(ratioAfter)));
  // The paint is carried: the cap keeps about its share of the samples (the cap's samples per
  // area change little, the limb's grow, so the share may shrink a little, never vanish).
  QVERIFY2(redAfter > 0.6 * redBefore && redAfter < 1.2 * redBefore,
           qPrintable(QString::number(redAfter)));

  window_->action("actionUndo")->trigger();
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == before);
  QVERIFY(!window_->isModified());
  QVERIFY(eyeOf(*window_) == eye);
  window_->action("actionRedo")->trigger();
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == after);
  QVERIFY(window_->isModified());
}

void RemeshRenderTest::remeshTwiceByAccidentIsOneUndoAway() {
  QVERIFY(window_);
  QVERIFY(openLimb(*window_));
  const std::vector<unsigned char> original = bitsOf(window_->viewport()->modeller().document());
  QVERIFY(window_->remesh());
  const std::vector<unsigned char> once = bitsOf(window_->viewport()->modeller().document());
  QVERIFY(once != original);
  // The second run either changes the model again (a step of its own) or says why not.
  const bool again = window_->remesh();
  QTRY_COMPARE(window_->undoStack()->count(), again ? 2 : 1);
  if (again) {
    window_->action("actionUndo")->trigger();
    QVERIFY(bitsOf(window_->viewport()->modeller().document()) == once);
  }
  window_->action("actionUndo")->trigger();
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == original);
  QVERIFY(!window_->isModified());

  // Even Out twice: each run is one step or none (its own check may refuse this limb, saying
  // why), so as many Undos as steps bring the original back.
  std::vector<unsigned char> previous = original;
  for (int run = 0; run < 2; ++run) {
    const int steps = window_->undoStack()->count();
    if (window_->evenOutSamples()) {
      QTRY_COMPARE(window_->undoStack()->count(), steps + 1);
      window_->action("actionUndo")->trigger();
      QVERIFY(bitsOf(window_->viewport()->modeller().document()) == previous);
      window_->action("actionRedo")->trigger();
      previous = bitsOf(window_->viewport()->modeller().document());
    } else {
      QTRY_COMPARE(window_->undoStack()->count(), steps);
      QVERIFY(bitsOf(window_->viewport()->modeller().document()) == previous);
      QVERIFY2(window_->statusBar()->currentMessage().startsWith("Even Out left the model"),
               qPrintable(window_->statusBar()->currentMessage()));
    }
  }
  while (window_->undoStack()->canUndo())
    window_->action("actionUndo")->trigger();
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == original);
}

void RemeshRenderTest::cancelledRemeshAndResolutionChangeNothing() {
  QVERIFY(window_);
  QVERIFY(openLimb(*window_));
  // Twice: on the document as opened (unmodified, no history), and after one remesh
  // (modified, one step, the history held by it).
  for (int round = 0; round < 2; ++round) {
    const std::vector<unsigned char> before = bitsOf(window_->viewport()->modeller().document());
    const int steps = window_->undoStack()->count();
    const int index = window_->undoStack()->index();
    const std::size_t undoable = window_->viewport()->modeller().history().undoCount();
    const bool modified = window_->isModified();
    for (const bool remeshing : {true, false}) {
      auto control = std::make_shared<app::TaskControl>();
      control->cancel = true; // as if Cancel were pressed at once
      QVERIFY(remeshing ? !window_->remesh(128, control)
                        : !window_->changeResolution(128, control));
      QVERIFY(bitsOf(window_->viewport()->modeller().document()) == before);
      QTRY_COMPARE(window_->undoStack()->count(), steps);
      QTRY_COMPARE(window_->undoStack()->index(), index);
      QCOMPARE(window_->viewport()->modeller().history().undoCount(), undoable);
      QCOMPARE(window_->isModified(), modified);
      QCOMPARE(window_->statusBar()->currentMessage(),
               remeshing ? QString("Remesh cancelled; the model is unchanged")
                         : QString("Resolution change cancelled; the model is unchanged"));
      QVERIFY(window_->action("actionRemesh")->isEnabled());
      QVERIFY(window_->action("actionResolution")->isEnabled());
    }
    if (round == 0) QVERIFY(window_->remesh());
  }
}

void RemeshRenderTest::resolutionUpAndDownAreOneStepEach() {
  QVERIFY(window_);
  QVERIFY(openLimb(*window_));
  const std::vector<unsigned char> original = bitsOf(window_->viewport()->modeller().document());
  const double redBefore = redShare(window_->viewport()->modeller().document());
  QVERIFY(!window_->changeResolution(64)); // the current N: nothing to do
  QCOMPARE(window_->statusBar()->currentMessage(),
           QString("The model is already N = 64: nothing to resample"));
  QTRY_COMPARE(window_->undoStack()->count(), 0);

  QVERIFY(window_->changeResolution(128));
  QCOMPARE(window_->viewport()->modeller().document().size(), 128);
  QCOMPARE(window_->undoStack()->undoText(), QString("Resolution 64 → 128"));
  QCOMPARE(window_->statusBar()->currentMessage(), QString("Resampled from N = 64 to N = 128"));
  QCOMPARE(window_->viewport()->stats().n, 128);
  const double redUp = redShare(window_->viewport()->modeller().document());
  QVERIFY2(std::abs(redUp - redBefore) < 0.1 * redBefore, qPrintable(QString::number(redUp)));
  QVERIFY(window_->changeResolution(32));
  QCOMPARE(window_->viewport()->modeller().document().size(), 32);
  QTRY_COMPARE(window_->undoStack()->count(), 2);

  window_->action("actionUndo")->trigger();
  QCOMPARE(window_->viewport()->modeller().document().size(), 128);
  window_->action("actionUndo")->trigger();
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == original);
  QCOMPARE(window_->viewport()->stats().n, 64);
  QVERIFY(!window_->isModified());

  // Through the menu: the dialog offers the sizes around 64 and Resample runs the choice.
  QTimer::singleShot(0, window_.get(), [&] {
    if (auto* dialog = window_->findChild<MeshSizeDialog*>("resolutionDialog")) {
      dialog->setSize(256);
      dialog->accept();
    }
  });
  window_->action("actionResolution")->trigger();
  QCOMPARE(window_->viewport()->modeller().document().size(), 256);
  QCOMPARE(window_->undoStack()->undoText(), QString("Resolution 64 → 256"));
}

void RemeshRenderTest::unchangedRemeshSaysWhyAndPushesNoStep() {
  QVERIFY(window_);
  // One sample pulled far out of a sphere: a needle no new sampling keeps, so the surface
  // would move by far more than the remesh's tolerance and its own check refuses.
  core::Document needle = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64));
  needle.positions.at(40, 20).x *= 6, needle.positions.at(40, 20).y *= 6,
      needle.positions.at(40, 20).z *= 6;
  QVERIFY(window_->viewport()->modeller().setDocument(needle));
  const std::vector<unsigned char> before = bitsOf(window_->viewport()->modeller().document());
  QVERIFY(!window_->remesh());
  QVERIFY(bitsOf(window_->viewport()->modeller().document()) == before);
  QTRY_COMPARE(window_->undoStack()->count(), 0);
  QVERIFY(!window_->isModified());
  const QString message = window_->statusBar()->currentMessage();
  QVERIFY2(message.startsWith("Remesh left the model unchanged: the surface would move by"),
           qPrintable(message));
}

} // namespace

QTEST_MAIN(RemeshRenderTest)
#include "remesh_render_test.moc"
