// What a newcomer reads, offscreen: an error names its file once and fits the status bar (the
// whole text in its tooltip), a mesh given to Open is recognised, save and export dialogs
// suggest a name beside the document, the Level of detail dock forgets the previous model's
// figures, and the README names the recovery folder the modeller really uses.
#include "detail_levels.h"
#include "file_suggestion.h"
#include "lod_panel.h"
#include "recovery_store.h"
#include "user_messages.h"

#include <QDir>
#include <QFile>
#include <QFontMetrics>
#include <QLabel>
#include <QLocale>
#include <QMainWindow>
#include <QStatusBar>
#include <QtTest>

using namespace octaclay;
using namespace octaclay::app;

class NewcomerMessagesTest : public QObject {
  Q_OBJECT

private slots:
  void failureNamesThePathOnce();
  void longMessagesAreElidedInTheStatusBarWithTheWholeTextInItsTooltip();
  void meshesAreToldFromModels();
  void saveAndExportSuggestANameBesideTheDocument();
  void lodFiguresAreClearedForANewDocument();
  void readmeNamesTheRecoveryFolder();
  void sizesAreSaidAsDetail();
};

void NewcomerMessagesTest::failureNamesThePathOnce() {
  const QString path = "/models/meshes/bob_genus1.obj";
  // core's reader errors start with the path.
  QCOMPARE(failureMessage("Could not import", path, path + ": genus 1 (needs genus 0)"),
           QStringLiteral("Could not import /models/meshes/bob_genus1.obj: genus 1 (needs genus "
                          "0)"));
  QCOMPARE(failureMessage("Could not import", path, "bob_genus1.obj: genus 1"),
           QStringLiteral("Could not import /models/meshes/bob_genus1.obj: genus 1"));
  // A reason that names the path elsewhere, or not at all, is kept whole.
  QCOMPARE(failureMessage("Could not save", path, "cannot write " + path + ": disk full"),
           QStringLiteral("Could not save %1: cannot write %1: disk full").arg(path));
  QCOMPARE(failureMessage("Could not open", "a.exr", "not an OpenEXR file"),
           QStringLiteral("Could not open a.exr: not an OpenEXR file"));
}

void NewcomerMessagesTest::longMessagesAreElidedInTheStatusBarWithTheWholeTextInItsTooltip() {
  QMainWindow window;
  window.resize(600, 300);
  auto* fps = new QLabel("60 frames/s");
  window.statusBar()->addPermanentWidget(fps);
  window.show();
  QVERIFY(QTest::qWaitForWindowExposed(&window));
  QStatusBar& bar = *window.statusBar();
  const QString message =
      failureMessage("Could not import", "/a/very/long/folder/name/" + QString(80, 'x') + ".obj",
                     "the spherical map folds over itself (12 flipped triangles): this mesh is "
                     "not supported yet") +
      "\nThe current model is unchanged.";
  showStatusMessage(bar, message, 0);
  const QString shown = bar.currentMessage();
  QVERIFY2(shown.contains(QChar(0x2026)), qPrintable(shown)); // elided
  QVERIFY(shown.startsWith("Could not import /a/"));
  QVERIFY(shown.endsWith("not supported yet"));
  QVERIFY(!shown.contains('\n'));
  const int room = bar.width() - fps->width();
  QVERIFY2(
      bar.fontMetrics().horizontalAdvance(shown) <= room,
      qPrintable(QString("%1 px in %2").arg(bar.fontMetrics().horizontalAdvance(shown)).arg(room)));
  QCOMPARE(bar.toolTip(), message);
  // A short one is shown whole; the tooltip leaves with its message.
  showStatusMessage(bar, "Saved", 0);
  QCOMPARE(bar.currentMessage(), QStringLiteral("Saved"));
  bar.clearMessage();
  QVERIFY(bar.toolTip().isEmpty());
}

void NewcomerMessagesTest::meshesAreToldFromModels() {
  for (const char* mesh : {"a.obj", "b.PLY", "/x/c.stl", "d.off"})
    QVERIFY2(isImportableMesh(mesh), mesh);
  for (const char* model : {"a.exr", "b.ocz", "c.glb", "objfile", ""})
    QVERIFY2(!isImportableMesh(model), model);
}

void NewcomerMessagesTest::saveAndExportSuggestANameBesideTheDocument() {
  const QString docs = "/home/u/Documents";
  // A saved document: its folder and name with the right extension.
  QCOMPARE(suggestedSavePath("/work/clay/bust.exr", {}, "glb", docs),
           QStringLiteral("/work/clay/bust.glb"));
  QCOMPARE(suggestedSavePath("/work/clay/bust.exr", "/meshes/spot.obj", "ocz", docs),
           QStringLiteral("/work/clay/bust.ocz"));
  QCOMPARE(suggestedSavePath("/work/clay/bust.v2.exr", {}, "glb", docs, "_lod"),
           QStringLiteral("/work/clay/bust.v2_lod.glb"));
  // An imported, never saved model: beside the mesh it came from.
  QCOMPARE(suggestedSavePath({}, "/meshes/spot.obj", "exr", docs),
           QStringLiteral("/meshes/spot.exr"));
  // A new model: "untitled" in the documents folder.
  QCOMPARE(suggestedSavePath({}, {}, "exr", docs),
           QStringLiteral("/home/u/Documents/untitled.exr"));
  QCOMPARE(suggestedOpenFolder("/work/clay/bust.exr", "/meshes/spot.obj", docs),
           QStringLiteral("/work/clay"));
  QCOMPARE(suggestedOpenFolder({}, "/meshes/spot.obj", docs), QStringLiteral("/meshes"));
  QCOMPARE(suggestedOpenFolder({}, {}, docs), docs);
}

void NewcomerMessagesTest::lodFiguresAreClearedForANewDocument() {
  LodPanel panel;
  panel.setDocumentSize(1024);
  panel.setLodResult(19998, 12.3);
  core::SurfaceDistance error;
  error.rms = 0.00123;
  error.hausdorff = 0.0101;
  error.psnr = 58.2;
  panel.setLodError(error);
  QVERIFY(panel.lodText() != QStringLiteral("LOD: —"));
  QVERIFY(panel.errorText() != QStringLiteral("Error: —"));
  panel.setDocumentSize(256); // File ▸ New
  QCOMPARE(panel.lodText(), QStringLiteral("LOD: —"));
  QCOMPARE(panel.errorText(), QStringLiteral("Error: —"));
}

void NewcomerMessagesTest::readmeNamesTheRecoveryFolder() {
  // The modeller's names (app/gui/window/main.cpp) and the default data home.
  qunsetenv("XDG_DATA_HOME");
  QCoreApplication::setOrganizationName("Octaclay");
  QCoreApplication::setApplicationName("octaclay");
  QString folder = RecoveryStore::defaultFolder();
  QVERIFY2(folder.startsWith(QDir::homePath() + "/"), qPrintable(folder));
  folder.replace(0, QDir::homePath().size(), "~");
  QFile readme(QStringLiteral(OCTACLAY_SOURCE_DIR) + "/README.md");
  QVERIFY(readme.open(QIODevice::ReadOnly));
  const QString text = QString::fromUtf8(readme.readAll());
  QVERIFY2(text.contains("(to `" + folder + "`)"), qPrintable(folder));
}

void NewcomerMessagesTest::sizesAreSaidAsDetail() {
  QCOMPARE(detailLabel(64), QStringLiteral("Very coarse (64)"));
  QCOMPARE(detailLabel(512), QStringLiteral("Fine (512)"));
  QCOMPARE(detailLabel(1024), QStringLiteral("Very fine (1024)"));
  QCOMPARE(detailLabel(4096), QStringLiteral("Finest (4096)"));
  QCOMPARE(detailLabel(96), QStringLiteral("96")); // not offered: the number alone
  const QString tip = detailTooltip(512);
  QVERIFY2(tip.startsWith("N = 512: 512 × 512 samples"), qPrintable(tip));
  QVERIFY2(tip.contains(QLocale().toString(2LL * 512 * 512)), qPrintable(tip));
}

QTEST_MAIN(NewcomerMessagesTest)
#include "newcomer_messages_test.moc"
