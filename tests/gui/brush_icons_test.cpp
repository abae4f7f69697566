// Brush icons and the tool bar's pieces without GL: every built-in brush names its committed
// SVG (the same bytes as resources/icons/brushes) and it renders; a brush without one, or with
// one that cannot be read, gets its initials on the category's colour; the tool bar groups by
// category and reports picks; the header's radius scale round-trips.
#include "brush_header.h"
#include "brush_icons.h"
#include "brush_shortcuts.h"
#include "brush_toolbar.h"

#include "octaclay/gpu/brush_manifest.h"

#include <QAction>
#include <QFile>
#include <QImage>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>

using namespace octaclay;
namespace fs = std::filesystem;

namespace {

const fs::path kSource = OCTACLAY_SOURCE_DIR;

QByteArray bytesOf(const fs::path& file) {
  QFile f(QString::fromStdString(file.string()));
  return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
}

// Whether colour c is within 12 of colour want in each channel.
bool near(QColor c, QColor want) {
  return std::abs(c.red() - want.red()) <= 12 && std::abs(c.green() - want.green()) <= 12 &&
         std::abs(c.blue() - want.blue()) <= 12;
}

gpu::BrushManifest fake(const std::string& id, const std::string& name, gpu::Category category) {
  gpu::BrushManifest m;
  m.id = id;
  m.name = name;
  m.category = category;
  return m;
}

int whitePixels(const QImage& image) {
  int n = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      n += near(image.pixelColor(x, y), Qt::white);
  return n;
}

} // namespace

class BrushIconsTest : public QObject {
  Q_OBJECT

private slots:
  void builtInBrushesNameTheirCommittedIcons();
  void withoutAnIconTheInitialsShowOnTheCategoryColour();
  void toolBarGroupsByCategoryAndReportsPicks();
  void headerRadiusScaleRoundTrips();
};

void BrushIconsTest::builtInBrushesNameTheirCommittedIcons() {
  int brushes = 0;
  for (const fs::directory_entry& entry : fs::directory_iterator(kSource / "plugins" / "brushes")) {
    const gpu::BrushManifest m = gpu::parseBrushManifest(entry.path() / "manifest.json");
    ++brushes;
    QCOMPARE(m.iconFile, std::string("icon.svg"));
    const QByteArray mine = bytesOf(m.iconPath());
    QVERIFY2(!mine.isEmpty() &&
                 mine == bytesOf(kSource / "resources" / "icons" / "brushes" / (m.id + ".svg")),
             m.id.c_str());
    bool fromFile = false;
    const QIcon icon = app::brushIcon(m, &fromFile);
    QVERIFY2(fromFile, m.id.c_str()); // needs Qt's svg image plugin (libqt6svg6)
    const QImage image = icon.pixmap(48, 48).toImage();
    QCOMPARE(image.size(), QSize(48, 48));
    // The category's colour behind a white pictogram.
    QVERIFY2(near(image.pixelColor(24, 2), app::brushCategoryColour(m.category)), m.id.c_str());
    QVERIFY2(whitePixels(image) > 60, m.id.c_str());
  }
  // One committed icon per built-in brush, none left over.
  int icons = 0;
  for (const fs::directory_entry& entry :
       fs::directory_iterator(kSource / "resources" / "icons" / "brushes"))
    icons += entry.path().extension() == ".svg" ? 1 : 0;
  QVERIFY(brushes >= 12);
  QCOMPARE(icons, brushes);
}

void BrushIconsTest::withoutAnIconTheInitialsShowOnTheCategoryColour() {
  QCOMPARE(app::brushInitials(QStringLiteral("Sphere Add")), QStringLiteral("SA"));
  QCOMPARE(app::brushInitials(QStringLiteral("push")), QStringLiteral("Pu"));
  QCOMPARE(app::brushInitials(QStringLiteral("  ")), QStringLiteral("?"));
  for (const gpu::Category category :
       {gpu::Category::Sculpt, gpu::Category::Paint, gpu::Category::Splat}) {
    bool fromFile = true;
    const QImage image =
        app::brushIcon(fake("blob", "Blob Paint", category), &fromFile).pixmap(48, 48).toImage();
    QVERIFY(!fromFile);
    QVERIFY(near(image.pixelColor(24, 2), app::brushCategoryColour(category)));
    QVERIFY(near(image.pixelColor(2, 24), app::brushCategoryColour(category)));
    QVERIFY(whitePixels(image) > 20); // the letters
  }
  // An icon that passed the parser but does not decode falls back too.
  QTemporaryDir dir;
  QVERIFY(dir.isValid());
  gpu::BrushManifest broken = fake("broken", "Broken", gpu::Category::Paint);
  broken.folder = dir.path().toStdString();
  broken.iconFile = "icon.png";
  std::ofstream(broken.iconPath()) << "not a png";
  bool fromFile = true;
  const QImage image = app::brushIcon(broken, &fromFile).pixmap(32, 32).toImage();
  QVERIFY(!fromFile);
  QVERIFY(near(image.pixelColor(16, 2), app::brushCategoryColour(gpu::Category::Paint)));
}

void BrushIconsTest::toolBarGroupsByCategoryAndReportsPicks() {
  QWidget host;
  app::BrushToolBar bar(&host);
  bar.setBrushes(
      {fake("splat", "Splat", gpu::Category::Splat), fake("paint", "Paint", gpu::Category::Paint),
       fake("push", "Push", gpu::Category::Sculpt), fake("smooth", "Smooth", gpu::Category::Sculpt),
       fake("push", "Push again", gpu::Category::Paint)});
  QCOMPARE(bar.brushIds(),
           (QStringList{"push", "smooth", "paint", "splat"})); // the first of an id wins
  QStringList layout; // the bar's own order, separators as "|"
  for (QAction* a : bar.actions())
    layout << (a->isSeparator() ? QStringLiteral("|") : a->data().toString());
  QCOMPARE(layout, (QStringList{"push", "smooth", "|", "paint", "|", "splat"}));
  QAction* smooth = bar.brushAction(QStringLiteral("smooth"));
  QCOMPARE(smooth->parent(), &host);
  QVERIFY(host.actions().contains(smooth));
  QCOMPARE(smooth->shortcut(), QKeySequence(QStringLiteral("S")));
  QCOMPARE(smooth->toolTip(), QStringLiteral("Smooth (S)"));
  QVERIFY(bar.brushAction(QStringLiteral("splat"))->shortcut().isEmpty());

  QSignalSpy chosen(&bar, &app::BrushToolBar::brushChosen);
  smooth->trigger();
  QCOMPARE(chosen.count(), 1);
  QCOMPARE(chosen.front().front().toString(), QStringLiteral("smooth"));
  bar.setCurrentBrush(QStringLiteral("paint"));
  QVERIFY(bar.brushAction(QStringLiteral("paint"))->isChecked());
  QVERIFY(!smooth->isChecked());
  QCOMPARE(chosen.count(), 1); // setCurrentBrush reports nothing
  // Rebuilt: the current brush stays checked; the old actions are gone from the host.
  bar.setBrushes({fake("paint", "Paint", gpu::Category::Paint)});
  QVERIFY(bar.brushAction(QStringLiteral("paint"))->isChecked());
  QCOMPARE(host.actions().size(), 1);
}

void BrushIconsTest::headerRadiusScaleRoundTrips() {
  using app::BrushHeader;
  QCOMPARE(BrushHeader::radiusToPosition(0.001f), 0);
  QCOMPARE(BrushHeader::radiusToPosition(1.0f), BrushHeader::kRadiusSteps);
  QCOMPARE(BrushHeader::positionToRadius(BrushHeader::kRadiusSteps), 1.0f);
  for (const float r : {0.002f, 0.01f, 0.05f, 0.3f}) {
    const float back = BrushHeader::positionToRadius(BrushHeader::radiusToPosition(r));
    QVERIFY2(std::abs(back - r) <= r * 0.0035f, qPrintable(QString("%1 -> %2").arg(r).arg(back)));
  }
}

QTEST_MAIN(BrushIconsTest)
#include "brush_icons_test.moc"
