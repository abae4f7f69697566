// View ▸ Material, Wireframe and Background, the shading normals of an imported model, and the
// overlays that say what the pixels mean, drawn through the real viewport (xcb under Xvfb,
// llvmpipe) and read back.
#include "../core/shared_data.h"
#include "color_button.h"
#include "layers_panel.h"
#include "lod_panel.h"
#include "main_window.h"
#include "matcap_generator.h"
#include "modeller.h"
#include "test_window.h"
#include "viewport_overlay.h"
#include "viewport_widget.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/octahedral.h"

#include <QCheckBox>
#include <QDialog>
#include <QDialogButtonBox>
#include <QFile>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
#include <QPushButton>
#include <QScreen>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

using namespace octaclay;
using app::MainWindow;

namespace {

float luminance(QRgb c) {
  return static_cast<float>(0.299 * qRed(c) + 0.587 * qGreen(c) + 0.114 * qBlue(c));
}

// The model's pixels: those that differ from the top-left corner (the background).
std::vector<QPoint> modelPixels(const QImage& image) {
  std::vector<QPoint> out;
  const QRgb background = image.pixel(0, 0);
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.pixel(x, y) != background) out.emplace_back(x, y);
  return out;
}

// Mean absolute difference per channel (0–255) over the given pixels.
double meanDifference(const QImage& a, const QImage& b, const std::vector<QPoint>& pixels) {
  double sum = 0;
  for (const QPoint& p : pixels) {
    const QRgb x = a.pixel(p), y = b.pixel(p);
    sum += std::abs(qRed(x) - qRed(y)) + std::abs(qGreen(x) - qGreen(y)) +
           std::abs(qBlue(x) - qBlue(y));
  }
  return pixels.empty() ? 0 : sum / (3.0 * double(pixels.size()));
}

class LooksRenderTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void init();
  void cleanup();
  void committedMatcapsMatchTheGenerator();
  void eachMatcapChangesThePixelsDifferently();
  void wireframeOverlayAddsLinePixelsAlongTheLevel();
  void wireframeAtTheDefaultDetailLeavesTheSurfaceVisible();
  void backgroundChoiceChangesTheCornersAndIsRestored();
  void directFrameMatchesTheFrameVtkRenders();
  void importedModelHasNoUnlitSpecklesAtAnyLevel();
  void crumpledSamplesShadeAsTheSmoothSurface();
  void maskTintIsNotAPaintColour();
  void heatMapsShowALegendAndSideBySideIsLabelled();

private:
  std::unique_ptr<MainWindow> makeWindow();
  QImage grab();

  QTemporaryDir dir_;
  std::unique_ptr<MainWindow> window_;
};

void LooksRenderTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QStandardPaths::setTestModeEnabled(true);
  QCoreApplication::setOrganizationName("OctaclayTest");
  QCoreApplication::setApplicationName("looks_render_test");
  qputenv("XDG_DATA_HOME", dir_.filePath("data").toUtf8());
}

void LooksRenderTest::init() {
  QSettings().clear();
}
void LooksRenderTest::cleanup() {
  window_.reset();
}

std::unique_ptr<MainWindow> LooksRenderTest::makeWindow() {
  return app::testing::openTestWindow(dir_.filePath("recovery"));
}

// The viewport's pixels with no brush outline (a Leave event hides it).
QImage LooksRenderTest::grab() {
  QEvent leave(QEvent::Leave);
  QCoreApplication::sendEvent(window_->viewport(), &leave);
  return window_->viewport()->grabFramebuffer();
}

void LooksRenderTest::committedMatcapsMatchTheGenerator() {
  const std::filesystem::path fresh = dir_.filePath("matcaps").toStdString();
  tools::writeMatcaps(fresh);
  QCOMPARE(app::matcapIds().size(), qsizetype(tools::generatedMatcapIds().size()));
  for (const std::string& id : tools::generatedMatcapIds()) {
    QVERIFY(app::matcapIds().contains(QString::fromStdString(id)));
    const core::RasterImage want = core::readImage(fresh / (id + ".png"), 3);
    const core::RasterImage have =
        core::readImage(app::matcapPath(QString::fromStdString(id)).toStdString(), 3);
    QCOMPARE(have.width, 256);
    QCOMPARE(have.height, 256);
    float worst = 0;
    for (std::size_t k = 0; k < want.pixels.size(); ++k)
      worst = std::max(worst, std::abs(want.pixels[k] - have.pixels[k]));
    // One 8-bit step: another libm may round pow or sqrt differently in the last bit.
    QVERIFY2(worst <= 1.01f / 255, (id + ": run make_resources (resources/README.md)").c_str());
  }
}

void LooksRenderTest::eachMatcapChangesThePixelsDifferently() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  QCOMPARE(window_->viewport()->looks().material, QString("lit"));
  QVERIFY(window_->action("actionMaterialLit")->isChecked());
  const QImage lit = grab();
  const std::vector<QPoint> model = modelPixels(lit);
  QVERIFY(model.size() > 50000);
  std::vector<QImage> looks;
  for (const char* name : {"Clay", "Redwax", "Chrome", "Skin"}) {
    QAction* a = window_->action(QStringLiteral("actionMaterial%1").arg(name));
    QVERIFY2(a, name);
    a->trigger();
    QVERIFY(a->isChecked());
    looks.push_back(grab());
    const double d = meanDifference(lit, looks.back(), model);
    QVERIFY2(d > 8, qPrintable(QStringLiteral("%1 vs lit: %2").arg(name).arg(d)));
    QVERIFY(window_->viewport()->error().isEmpty());
  }
  for (std::size_t a = 0; a < looks.size(); ++a)
    for (std::size_t b = a + 1; b < looks.size(); ++b) {
      const double d = meanDifference(looks[a], looks[b], model);
      QVERIFY2(d > 8, qPrintable(QStringLiteral("matcaps %1 and %2: %3").arg(a).arg(b).arg(d)));
    }
  // Red wax is red, chrome's lower half mirrors a dark floor under a bright sky.
  const QPoint centre = window_->viewport()->project({0, 0, 0}).toPoint();
  const QColor wax = looks[1].pixelColor(centre);
  QVERIFY2(wax.red() > 2 * wax.green() && wax.red() > 2 * wax.blue(), qPrintable(wax.name()));
  const int radius = int(window_->viewport()->project({0, 0.9f, 0}).y() - centre.y());
  const QPoint up = centre - QPoint(0, std::abs(radius) / 2),
               down = centre + QPoint(0, std::abs(radius) / 2);
  QVERIFY(luminance(looks[2].pixel(up)) > luminance(looks[2].pixel(down)) + 60);
  // Saved, and the next window starts with it.
  QCOMPARE(QSettings().value("view/material").toString(), QString("skin"));
  window_.reset();
  window_ = makeWindow();
  QVERIFY(window_);
  QCOMPARE(window_->viewport()->looks().material, QString("skin"));
  QVERIFY(window_->action("actionMaterialSkin")->isChecked());
  window_->action("actionMaterialLit")->trigger();
  QCOMPARE(QSettings().value("view/material").toString(), QString("lit"));
}

void LooksRenderTest::wireframeOverlayAddsLinePixelsAlongTheLevel() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  QVERIFY(window_->lodPanel()->setDivisor(8)); // 16 cells a side: lines far apart
  const QImage plain = grab();
  const std::vector<QPoint> model = modelPixels(plain);
  QAction* wireframe = window_->action("actionWireframe");
  QVERIFY(wireframe && wireframe->isCheckable());
  wireframe->trigger();
  QVERIFY(window_->viewport()->looks().wireframe);
  QVERIFY(QSettings().value("view/wireframe").toBool());
  const QImage wired = grab();
  int darker = 0;
  for (const QPoint& p : model)
    darker += luminance(wired.pixel(p)) < luminance(plain.pixel(p)) - 40;
  // Lines a pixel or two wide every few dozen pixels: some, but far from all.
  const double share = double(darker) / double(model.size());
  QVERIFY2(share > 0.03 && share < 0.5, qPrintable(QString::number(share)));
  // A row near the centre crosses lines: runs of line pixels separated by runs of surface. Not
  // the centre row itself: the equator is a grid line, which that row may run along.
  const QPoint centre = window_->viewport()->project({0, 0, 0}).toPoint();
  int runs = 0;
  for (int dy : {-5, 5}) {
    int rowRuns = 0;
    bool inLine = false;
    for (int x = centre.x() - 150; x <= centre.x() + 150; ++x) {
      const QPoint p(x, centre.y() + dy);
      const bool line = luminance(wired.pixel(p)) < luminance(plain.pixel(p)) - 40;
      rowRuns += line && !inLine;
      inLine = line;
    }
    runs = std::max(runs, rowRuns);
  }
  QVERIFY2(runs >= 4, qPrintable(QString::number(runs)));
  // Off again: the very same pixels as before.
  wireframe->trigger();
  QVERIFY(!window_->viewport()->looks().wireframe);
  const QImage off = grab();
  QCOMPARE(meanDifference(off, plain, model), 0.0);
}

// Issue 31: at the default display detail (256 samples a side) the wireframe drew a line every
// two or three pixels and only darkened the model. Now its lines are a coarser level's where the
// displayed cells are narrow on screen: lines cross the model, and most of it is surface.
void LooksRenderTest::wireframeAtTheDefaultDetailLeavesTheSurfaceVisible() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 512, true));
  QCOMPARE(window_->lodPanel()->displayedSize(), app::LodPanel::kDefaultDisplaySize);
  const QImage plain = grab();
  const std::vector<QPoint> model = modelPixels(plain);
  window_->action("actionWireframe")->trigger();
  QVERIFY(window_->viewport()->looks().wireframe);
  const QImage wired = grab();
  const auto isLine = [&](QPoint p) {
    return luminance(wired.pixel(p)) < luminance(plain.pixel(p)) - 40;
  };
  int lines = 0;
  for (const QPoint& p : model)
    lines += isLine(p);
  const double share = double(lines) / double(model.size());
  // Rows a little above and below the centre: runs of line pixels between runs of surface.
  const QPoint centre = window_->viewport()->project({0, 0, 0}).toPoint();
  int runs = 0, longestSurface = 0;
  for (int dy : {-7, 7}) {
    int rowRuns = 0, surface = 0;
    bool inLine = false;
    for (int x = centre.x() - 150; x <= centre.x() + 150; ++x) {
      const bool line = isLine({x, centre.y() + dy});
      rowRuns += line && !inLine;
      surface = line ? 0 : surface + 1;
      longestSurface = std::max(longestSurface, surface);
      inLine = line;
    }
    runs = std::max(runs, rowRuns);
  }
  qInfo("wireframe at %d samples a side: %.1f %% of %zu model pixels are line pixels; %d lines "
        "across 300 px, the widest gap %d px",
        window_->lodPanel()->displayedSize(), 100.0 * share, model.size(), runs, longestSurface);
  // Lines about 2 px wide, the displayed cells' or a coarser level's at least 24 px apart
  // (kMinCellPixels), three families (the grid's two and the diagonals): a fifth of the model
  // or so (94 % when every displayed edge was drawn); the surface shows between them.
  QVERIFY2(share > 0.05 && share < 0.3, qPrintable(QString::number(share)));
  QVERIFY2(runs >= 6, qPrintable(QString::number(runs)));
  QVERIFY2(longestSurface >= 8, qPrintable(QString::number(longestSurface)));
}

void LooksRenderTest::backgroundChoiceChangesTheCornersAndIsRestored() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  const QImage before = grab();
  bool edited = false;
  QTimer::singleShot(0, [&] {
    auto* dialog = window_->findChild<QDialog*>("backgroundDialog");
    if (!dialog) return;
    dialog->findChild<QCheckBox*>("gradient")->setChecked(true);
    dialog->findChild<app::ColorButton*>("top")->setColor(QColor(200, 40, 30));
    dialog->findChild<app::ColorButton*>("bottom")->setColor(QColor(20, 40, 210));
    edited = true;
    dialog->accept();
  });
  window_->action("actionBackground")->trigger();
  QVERIFY(edited);
  const QImage after = grab();
  const QColor top = after.pixelColor(2, 2), bottom = after.pixelColor(2, after.height() - 3);
  QVERIFY2(top.red() > 170 && top.blue() < 70, qPrintable(top.name()));
  QVERIFY2(bottom.blue() > 170 && bottom.red() < 50, qPrintable(bottom.name()));
  QVERIFY(before.pixel(2, 2) != after.pixel(2, 2));
  // Cancel puts the previous background back.
  QTimer::singleShot(0, [&] {
    auto* dialog = window_->findChild<QDialog*>("backgroundDialog");
    if (!dialog) return;
    dialog->findChild<QCheckBox*>("gradient")->setChecked(false);
    dialog->reject();
  });
  window_->action("actionBackground")->trigger();
  QCOMPARE(grab().pixel(2, 2), after.pixel(2, 2));
  // Restored at start.
  window_.reset();
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->viewport()->looks().gradient);
  QCOMPARE(window_->viewport()->looks().backgroundTop, QColor(200, 40, 30));
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  QCOMPARE(grab().pixel(2, 2), after.pixel(2, 2));
}

// The model alone on a plain background skips VTK's framebuffer; the same view through VTK (a
// "gradient" of one colour) must give the same pixels.
void LooksRenderTest::directFrameMatchesTheFrameVtkRenders() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 128, true));
  app::ViewportWidget* viewport = window_->viewport();
  app::ViewLooks looks = viewport->looks();
  looks.material = "clay";
  looks.backgroundTop = QColor(60, 90, 40);
  viewport->setLooks(looks);
  QVERIFY(viewport->drawsDirectly());
  const QImage direct = grab();
  const std::vector<QPoint> model = modelPixels(direct);
  QVERIFY2(model.size() > 20000, qPrintable(QString::number(model.size())));
  QCOMPARE(direct.pixelColor(2, 2), QColor(60, 90, 40));

  looks.gradient = true;
  looks.backgroundBottom = looks.backgroundTop;
  viewport->setLooks(looks);
  QVERIFY(!viewport->drawsDirectly());
  const QImage throughVtk = grab();
  QCOMPARE(throughVtk.size(), direct.size());
  const app::testing::PixelDifference d = app::testing::comparePixels(direct, throughVtk);
  // Equal but where the shader's 2×2 derivative quads pair other pixels in VTK's framebuffer than
  // in the window's top-down rows: a few pixels at most, a little.
  QVERIFY2(
      d.differing * 200 <= int(model.size()) && d.worst <= 40,
      qPrintable(QString("%1 of %2, worst %3").arg(d.differing).arg(model.size()).arg(d.worst)));

  // Side by side is always VTK's (two renderers).
  looks.gradient = false;
  viewport->setLooks(looks);
  QVERIFY(viewport->drawsDirectly());
  viewport->setLodDisplay(app::LodDisplay::SideBySide);
  QVERIFY(!viewport->drawsDirectly());
}

// A closed lat-long ellipsoid with semi-axes (a, b, c), as OBJ text.
QByteArray ellipsoidObj(float a, float b, float c, int rings, int segments) {
  QByteArray obj;
  const auto vertex = [&](float x, float y, float z) {
    obj += QByteArray("v ") + QByteArray::number(x) + ' ' + QByteArray::number(y) + ' ' +
           QByteArray::number(z) + '\n';
  };
  vertex(0, b, 0);
  for (int r = 1; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = M_PI * r / rings, phi = 2 * M_PI * s / segments;
      vertex(float(a * std::sin(theta) * std::cos(phi)), float(b * std::cos(theta)),
             float(c * std::sin(theta) * std::sin(phi)));
    }
  vertex(0, -b, 0);
  const auto at = [&](int r, int s) { return 2 + (r - 1) * segments + (s % segments); };
  const int last = 2 + (rings - 1) * segments;
  const auto face = [&](int i, int j, int k) {
    obj += "f " + QByteArray::number(i) + ' ' + QByteArray::number(j) + ' ' +
           QByteArray::number(k) + '\n';
  };
  for (int s = 0; s < segments; ++s) {
    face(1, at(1, s + 1), at(1, s));
    face(last, at(rings - 1, s), at(rings - 1, s + 1));
    for (int r = 1; r + 1 < rings; ++r) {
      face(at(r, s), at(r, s + 1), at(r + 1, s + 1));
      face(at(r, s), at(r + 1, s + 1), at(r + 1, s));
    }
  }
  return obj;
}

// Issue 22: black speckles and stripes where the image stretches. With a headlight a pixel of
// a smooth surface is lit by its normal's cosine to the eye: none may be darker than the unlit
// ambient (0.18 × the clay colour), and on a convex model none away from its outline may fall
// to that ambient at all (every normal there faces the eye). On the armadillo (its sides and
// armpits stretch the image most) no unlit pixel may sit between lit ones on one continuous
// surface: a visible surface faces the eye, so only an outline, where the depth jumps, is unlit.
void LooksRenderTest::importedModelHasNoUnlitSpecklesAtAnyLevel() {
  const QString folder = QString(OCTACLAY_SHARED_DATA) + "/meshes/genus0/";
  const QString armadillo = folder + "armadillo.obj", bust = folder + "max_planck_decimated.obj";
  if (!QFileInfo::exists(armadillo)) OCTACLAY_MISSING_SHARED_DATA("armadillo.obj");
  if (!QFileInfo::exists(bust)) OCTACLAY_MISSING_SHARED_DATA("max_planck_decimated.obj");
  // An ellipsoid eight times longer than wide: the octahedral image stretches along it.
  const QString ellipsoid = dir_.filePath("ellipsoid.obj");
  {
    QFile file(ellipsoid);
    QVERIFY(file.open(QIODevice::WriteOnly));
    file.write(ellipsoidObj(1.0f, 0.125f, 0.125f, 24, 48));
  }
  window_ = makeWindow();
  QVERIFY(window_);
  window_->layersPanel()->setVisible(core::EditLayer::Diffuse, false); // plain clay
  app::ViewportWidget* view = window_->viewport();
  const float ambient = 0.18f * luminance(qRgb(204, 199, 189)); // clay (0.8, 0.78, 0.74)
  const float unlitAbove = 4, litAbove = 40; // luminance over the ambient: cosine ≈ 0.025, 0.25
  QString speckled;                          // every level's speckles, reported together
  for (const auto& [mesh, size] : {std::pair{armadillo, 256}, {bust, 128}, {ellipsoid, 128}}) {
    const bool convex = mesh == ellipsoid;
    QVERIFY(window_->importMesh(mesh, size));
    QVERIFY2(window_->lastError().isEmpty(), qPrintable(window_->lastError()));
    for (int divisor : {1, 2, 4, 8}) {
      QVERIFY(window_->lodPanel()->setDivisor(divisor));
      const QImage image = grab();
      const QRgb background = image.pixel(0, 0);
      const auto onModel = [&](int x, int y) {
        return x >= 0 && y >= 0 && x < image.width() && y < image.height() &&
               image.pixel(x, y) != background;
      };
      const auto above = [&](QPoint p) { return luminance(image.pixel(p)) - ambient; };
      // Whether the pixels a and b, on either side of p, lie on p's surface: no depth jump.
      const float jump = 0.02f * view->modeller().modelDiagonal();
      const auto continuous = [&](QPoint a, QPoint p, QPoint b) {
        const auto ha = view->pickAt(a), hp = view->pickAt(p), hb = view->pickAt(b);
        return ha && hp && hb && std::abs(ha->distance - hp->distance) < jump &&
               std::abs(hb->distance - hp->distance) < jump;
      };
      int model = 0, unlitInside = 0, speckles = 0;
      float darkest = 255;
      QString where;
      for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
          if (!onModel(x, y)) continue;
          ++model;
          const QPoint p(x, y);
          darkest = std::min(darkest, luminance(image.pixel(p)));
          bool inside = true; // 3 px or more from the outline
          for (int dy = -3; dy <= 3 && inside; ++dy)
            for (int dx = -3; dx <= 3 && inside; ++dx)
              inside = onModel(x + dx, y + dy);
          if (!inside || above(p) > unlitAbove) continue;
          ++unlitInside;
          for (const QPoint step : {QPoint(2, 0), QPoint(0, 2)})
            if (above(p - step) > litAbove && above(p + step) > litAbove &&
                continuous(p - step, p, p + step)) {
              ++speckles;
              where += QStringLiteral(" (%1, %2)").arg(x).arg(y);
              break;
            }
        }
      const QString what =
          QStringLiteral("%1 at N/%2").arg(QFileInfo(mesh).fileName()).arg(divisor);
      QVERIFY2(model > 5000, qPrintable(what));
      QVERIFY2(darkest >= ambient - 1.5f,
               qPrintable(QStringLiteral("%1: a pixel at %2, the ambient is %3")
                              .arg(what)
                              .arg(darkest)
                              .arg(ambient)));
      if (speckles > 0)
        speckled += QStringLiteral("\n%1: %2 unlit pixels between lit ones:%3")
                        .arg(what)
                        .arg(speckles)
                        .arg(where.left(120));
      if (convex)
        QVERIFY2(unlitInside == 0, qPrintable(QStringLiteral("%1: %2 unlit pixels inside %3")
                                                  .arg(what)
                                                  .arg(unlitInside)
                                                  .arg(model)));
    }
  }
  QVERIFY2(speckled.isEmpty(), qPrintable(speckled));
}

// The sphere sampled with its odd rows and columns scrambled along the surface: every sample
// lies on the sphere and the even ones are where they belong, so from N/2 on the displayed
// triangles are the smooth sphere's, but neighbouring full-resolution cells fold against each
// other, as where an imported image stretches. No pixel away from the outline may fall to the
// unlit ambient.
void LooksRenderTest::crumpledSamplesShadeAsTheSmoothSurface() {
  constexpr int n = 128;
  core::GeometryImage image(n);
  std::uint32_t state = 12345;
  const auto jitter = [&] {
    state = state * 1664525u + 1013904223u;
    return int(state >> 30) - 1; // -1, 0, 1, 2
  };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      int si = i, sj = j;
      const bool interior = i > 2 && j > 2 && i < n - 2 && j < n - 2;
      if (interior && (i % 2 || j % 2)) {
        si += jitter();
        sj += jitter();
      }
      const core::Vec3f d = core::octahedralDirection(n, si, sj);
      image.at(i, j) = {d.x, d.y, d.z, 0};
    }
  window_ = makeWindow();
  QVERIFY(window_);
  window_->layersPanel()->setVisible(core::EditLayer::Diffuse, false);
  QVERIFY(window_->viewport()->modeller().setDocument(core::makeDocument(std::move(image))));
  const float ambient = 0.18f * luminance(qRgb(204, 199, 189));
  for (int divisor : {2, 4}) {
    QVERIFY(window_->lodPanel()->setDivisor(divisor));
    const QImage shot = grab();
    const QPoint centre = window_->viewport()->project({0, 0, 0}).toPoint();
    const int radius = int(std::abs(window_->viewport()->project({0, 1, 0}).y() - centre.y()));
    int unlit = 0, inside = 0;
    for (int y = centre.y() - radius; y <= centre.y() + radius; ++y)
      for (int x = centre.x() - radius; x <= centre.x() + radius; ++x) {
        if (std::hypot(x - centre.x(), y - centre.y()) > 0.9 * radius) continue;
        ++inside;
        unlit += luminance(shot.pixel(x, y)) <= ambient + 4;
      }
    QVERIFY(inside > 10000);
    QVERIFY2(
        unlit == 0,
        qPrintable(
            QStringLiteral("N/%1: %2 unlit of %3 pixels").arg(divisor).arg(unlit).arg(inside)));
  }
}

void LooksRenderTest::maskTintIsNotAPaintColour() {
  window_ = makeWindow();
  QVERIFY(window_);
  core::Document d = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 64));
  d.mask.texels.assign(65 * 65, 0.0f); // masked everywhere
  QVERIFY(window_->viewport()->modeller().setDocument(std::move(d)));
  const QImage image = grab();
  const QPoint centre = window_->viewport()->project({0, 0, 0}).toPoint();
  // Orange, hatched: red over blue, and neighbouring diagonals differ.
  int hatched = 0;
  for (int k = 0; k < 8; ++k) {
    const QColor c = image.pixelColor(centre + QPoint(k, 0));
    QVERIFY2(c.red() > c.blue() + 60, qPrintable(c.name()));
    hatched += image.pixel(centre + QPoint(k, 0)) != image.pixel(centre + QPoint(k + 1, 0));
  }
  QVERIFY(hatched >= 1);
}

void LooksRenderTest::heatMapsShowALegendAndSideBySideIsLabelled() {
  window_ = makeWindow();
  QVERIFY(window_);
  QVERIFY(window_->newDocument(core::BaseShape::Sphere, 64, true));
  app::ViewportOverlay* overlay = window_->viewport()->overlay();
  QVERIFY(!overlay->legend()->isVisible());
  window_->layersPanel()->setPreview(app::LayersPanel::Preview::Saliency);
  QVERIFY(overlay->legend()->isVisible());
  // Inside the viewport, and its bar runs from the heat map's blue to its red.
  QVERIFY(window_->viewport()->rect().contains(overlay->legend()->geometry()));
  const QImage legend = overlay->legend()->grab().toImage();
  const int y = 30 * legend.height() / overlay->legend()->height();
  const QColor low = legend.pixelColor(legend.width() / 20, y),
               high = legend.pixelColor(legend.width() * 19 / 20, y);
  QVERIFY2(low.blue() > 200 && low.red() < 60, qPrintable(low.name()));
  QVERIFY2(high.red() > 200 && high.blue() < 60, qPrintable(high.name()));
  window_->layersPanel()->setPreview(app::LayersPanel::Preview::Shaded);
  QVERIFY(!overlay->legend()->isVisible());

  QVERIFY(!overlay->leftLabel()->isVisible());
  window_->viewport()->setLodDisplay(app::LodDisplay::SideBySide);
  QVERIFY(overlay->leftLabel()->isVisible() && overlay->rightLabel()->isVisible());
  QCOMPARE(overlay->leftLabel()->text(), QString("Full resolution"));
  QCOMPARE(overlay->rightLabel()->text(), QString("Level of detail"));
  const int half = window_->viewport()->width() / 2;
  QVERIFY(overlay->leftLabel()->geometry().right() < half);
  QVERIFY(overlay->rightLabel()->geometry().left() > half);
  // On the screen, over the GL window's frame: the labels' dark box with white text in it.
  for (QLabel* label : {overlay->leftLabel(), overlay->rightLabel()}) {
    QVERIFY(QTest::qWaitFor(
        [&] {
          const QPoint at = label->mapToGlobal(QPoint(0, 0));
          const QImage screen = QGuiApplication::primaryScreen()
                                    ->grabWindow(0, at.x(), at.y(), label->width(), label->height())
                                    .toImage();
          int dark = 0, white = 0;
          for (int row = 0; row < screen.height(); ++row)
            for (int column = 0; column < screen.width(); ++column) {
              const float l = luminance(screen.pixel(column, row));
              dark += l < 30;
              white += l > 200;
            }
          const int all = screen.width() * screen.height();
          return all > 0 && dark * 2 > all && white > 10;
        },
        3000));
  }
  window_->viewport()->setLodDisplay(app::LodDisplay::FullResolution);
  QVERIFY(!overlay->leftLabel()->isVisible());
}

} // namespace

QTEST_MAIN(LooksRenderTest)
#include "looks_render_test.moc"
