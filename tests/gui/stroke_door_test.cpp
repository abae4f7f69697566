// One stroke door (issue 31): a stroke made through SculptSession the way the viewport makes it
// (the Brushes panel's settings, the camera's eye, one queued move per pointer sample, the queue
// run once per frame) and the same stroke given to `octaclay-cli stroke` (the real program, its
// path and drag points played through the same door by playStroke) give the same document bit
// for bit, for every kind of brush: spaced (push), drag (snake hook), anchored (grab) and paint,
// with keep detail on and off. The two report the same dabs and the same undo step. One row
// proves the comparison can fail: a single pointer sample at pressure 0.99 gives other bits.

#include "../cli/cli_support.h"
#include "brush_setup.h"
#include "sculpt_session.h"

#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_engine.h"
#include "octaclay/gpu/gl_context.h"

#include <QTemporaryDir>
#include <QTest>

#include <array>
#include <cstring>
#include <limits>
#include <optional>
#include <vector>

using namespace octaclay;

namespace {

// A pointer's samples across the sphere's pole (the image's centre), unevenly spaced as a
// pointer's are and crossing cells in every direction.
const std::vector<std::array<float, 2>> kPointerSamples = {
    {0.42f, 0.47f}, {0.45f, 0.49f}, {0.47f, 0.5f}, {0.52f, 0.52f}, {0.56f, 0.51f}, {0.58f, 0.47f}};

// Drag points on the view plane through the pole, z = 1, seen from the eye (0, 0, 10).
const core::Vec3f kEye{0, 0, 10};
const std::vector<core::Vec3f> kDragPoints = {
    {0.0625f, 0.03125f, 1}, {0.125f, 0.0625f, 1}, {0.25f, 0.125f, 1}, {0.375f, 0.25f, 1}};

bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

bool sameBits(const core::Layer& a, const core::Layer& b) {
  return a.uniform() == b.uniform() &&
         std::memcmp(a.fill.data(), b.fill.data(), sizeof a.fill) == 0 &&
         sameBits(a.texels, b.texels);
}

std::vector<float> floatsOf(const core::GeometryImage& image) {
  std::vector<float> out;
  for (const core::Vec4f& t : image.texels())
    out.insert(out.end(), {t.x, t.y, t.z, t.w});
  return out;
}

QString joined(const std::vector<std::array<float, 2>>& path) {
  QStringList points;
  for (const auto& uv : path)
    points << QString::number(uv[0], 'g', 9) + "," + QString::number(uv[1], 'g', 9);
  return points.join(';');
}

QString joined(const std::vector<core::Vec3f>& points) {
  QStringList out;
  for (const core::Vec3f& p : points)
    out << QString("%1,%2,%3").arg(p.x, 0, 'g', 9).arg(p.y, 0, 'g', 9).arg(p.z, 0, 'g', 9);
  return out.join(';');
}

} // namespace

class StrokeDoorTest : public QObject {
  Q_OBJECT
private slots:
  void initTestCase();
  void sameStrokeThroughBothDoors_data();
  void sameStrokeThroughBothDoors();
  void anObjectRadiusOverridesTheFractionOfTheDiagonal();

private:
  QTemporaryDir dir_;
  QString sphere_;
  std::optional<gpu::GlContext> context_;
  std::optional<gpu::BrushEngine> engine_;
  gpu::BrushCatalog catalog_;
};

void StrokeDoorTest::initTestCase() {
  QVERIFY(dir_.isValid());
  sphere_ = dir_.filePath("sphere.exr");
  RUN_JSON(created, "new", "--shape", "sphere", "--size", "128", "-o", sphere_, "--json");
  context_.emplace(gpu::GlContext::createHeadless());
  engine_.emplace();
  catalog_ = app::scanBrushes(); // the brushes both doors find
  for (const char* id : {"push", "snake-hook", "grab", "paint"})
    QVERIFY2(catalog_.find(id) != nullptr, id);
}

void StrokeDoorTest::sameStrokeThroughBothDoors_data() {
  QTest::addColumn<QString>("brush");
  QTest::addColumn<bool>("keepDetail");
  QTest::addColumn<float>("strength");
  QTest::addColumn<float>("pressure"); // of the viewport's third pointer sample; the CLI's is 1
  for (const bool keep : {false, true}) {
    const char* k = keep ? ", keep detail" : "";
    QTest::addRow("spaced: push%s", k) << "push" << keep << 2.0f << 1.0f;
    QTest::addRow("drag: snake-hook%s", k) << "snake-hook" << keep << 1.0f << 1.0f;
    QTest::addRow("anchored: grab%s", k) << "grab" << keep << 1.0f << 1.0f;
    QTest::addRow("paint%s", k) << "paint" << keep << 0.8f << 1.0f;
  }
  QTest::addRow("push, one sample pressed less: must differ") << "push" << false << 2.0f << 0.99f;
}

void StrokeDoorTest::sameStrokeThroughBothDoors() {
  QFETCH(QString, brush);
  QFETCH(bool, keepDetail);
  QFETCH(float, strength);
  QFETCH(float, pressure);
  const bool same = pressure == 1.0f;
  const std::string id = brush.toStdString();
  const gpu::BrushManifest& manifest = *catalog_.find(id);
  const bool drags =
      manifest.stroke == gpu::StrokeKind::Drag || manifest.stroke == gpu::StrokeKind::Anchored;
  const float radius = 0.08f; // of the diagonal
  // A dragging brush starts at the pole and follows the pointer off the surface.
  const std::vector<std::array<float, 2>> path =
      drags ? std::vector<std::array<float, 2>>{{0.5f, 0.5f}} : kPointerSamples;

  // The CLI's door: octaclay-cli stroke.
  const QString cliOut = dir_.filePath(brush + (keepDetail ? "-keep" : "") + "-cli.exr");
  QStringList args{"stroke",
                   sphere_,
                   "--brush",
                   brush,
                   "--path",
                   joined(path),
                   "--radius",
                   QString::number(radius, 'g', 9),
                   "--strength",
                   QString::number(strength, 'g', 9),
                   "--view",
                   "0,0,10",
                   "--keep-detail",
                   keepDetail ? "on" : "off",
                   "-o",
                   cliOut,
                   "--json"};
  if (drags) args << "--drag" << joined(kDragPoints);
  const Result r = runCli(args);
  QVERIFY2(!r.crashed && r.exitCode == kOk, qPrintable(describe(args, r)));
  const QJsonObject report = QJsonDocument::fromJson(r.out).object();

  // The viewport's door: the session as ViewportWidget::beginStrokeAt … endStroke drives it.
  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(manifest);
  session.setDocument(core::readDocument(sphere_.toStdString()));
  app::StrokeStart start;
  start.brushId = id;
  start.settings.brushId = id; // as the Brushes panel holds it for this brush
  start.settings.radius = radius;
  start.settings.strength = strength;
  start.settings.area = manifest.area;
  start.settings.falloff = manifest.falloff;
  for (const gpu::BrushParameter& p : manifest.parameters)
    start.settings.parameters[p.id] = p.defaultValue;
  start.settings.keepDetail = keepDetail;
  start.eye = kEye; // the camera's position
  session.beginStroke(start);
  QCOMPARE(session.strokeDrags(), drags);
  std::vector<app::StrokeMove> moves;
  for (const auto& uv : path) // a mouse: pressure 1
    moves.push_back(app::StrokeMove::toUv({uv[0], uv[1]}, moves.size() == 2 ? pressure : 1.0f));
  if (drags) // the pointer's rays, through the points the CLI drags to
    for (const core::Vec3f& p : kDragPoints)
      moves.push_back(app::StrokeMove::alongRay(kEye, p - kEye));
  int dabs = 0;
  for (std::size_t k = 0; k < moves.size(); ++k) {
    session.queueMove(moves[k]);
    if (k % 2 == 1 || k + 1 == moves.size()) { // a frame every two pointer samples
      const app::DabRun run = session.runQueuedMoves();
      QVERIFY2(run.error.empty(), run.error.c_str());
      dabs += run.made;
    }
  }
  const app::StrokeEnd end = session.finishStroke();
  QCOMPARE(end.label, id);
  QCOMPARE(session.history().undoCount(), std::size_t(1));
  const std::string viewportOut = dir_.filePath(brush + "-viewport.exr").toStdString();
  core::writeDocument(session.document(), viewportOut); // through the file, as the CLI's

  QCOMPARE(report["dabs"].toInt(), dabs);
  QCOMPARE(report["dabs"].toInt(), end.dabs);
  QCOMPARE(report["changed_tiles"].toInteger(), qint64(end.changedTiles));
  if (same) QCOMPARE(report["undo_bytes"].toInteger(), qint64(end.stepBytes));
  qInfo("%d dabs, %zu tiles changed, keep detail relaxed %zu tiles", dabs, end.changedTiles,
        session.lastRelaxation().tiles.size());

  const core::Document cli = core::readDocument(cliOut.toStdString());
  const core::Document viewport = core::readDocument(viewportOut);
  const core::Document before = core::readDocument(sphere_.toStdString());
  QVERIFY2(!sameBits(floatsOf(before.positions), floatsOf(viewport.positions)) ||
               !sameBits(before.diffuse, viewport.diffuse),
           "the stroke changed nothing: nothing compared");
  if (!same) {
    QVERIFY2(!sameBits(floatsOf(cli.positions), floatsOf(viewport.positions)),
             "a different stroke gave the same positions: the comparison sees nothing");
    return;
  }
  QVERIFY2(sameBits(floatsOf(cli.positions), floatsOf(viewport.positions)), "the positions differ");
  QVERIFY2(sameBits(cli.diffuse, viewport.diffuse), "the diffuse layer differs");
  QVERIFY2(sameBits(cli.feature, viewport.feature), "the feature layer differs");
  QVERIFY2(sameBits(cli.mask, viewport.mask), "the mask differs");
  QCOMPARE(cli.hasMask, viewport.hasMask);
}

// The viewport's view radius reaches the session as StrokeStart::objectRadius (object units):
// the fraction × the diagonal given that way strokes bit for bit as the fraction does, whatever
// settings.radius then says; twice that radius strokes differently; a radius that is not finite
// and positive is refused before the stroke begins.
void StrokeDoorTest::anObjectRadiusOverridesTheFractionOfTheDiagonal() {
  const gpu::BrushManifest& manifest = *catalog_.find("push");
  const auto strokeWith = [&](float fraction, std::optional<float> objectRadius) {
    app::SculptSession session;
    session.setBrushes(*engine_, catalog_);
    session.loadBrush(manifest);
    session.setDocument(core::readDocument(sphere_.toStdString()));
    app::StrokeStart start;
    start.brushId = start.settings.brushId = "push";
    start.settings.radius = fraction;
    start.settings.strength = 1.0f;
    start.settings.keepDetail = false;
    if (objectRadius)
      start.objectRadius = *objectRadius * session.gpuDocument().bounds().diagonal();
    session.beginStroke(start);
    for (const auto& uv : {std::array<float, 2>{0.3f, 0.4f}, std::array<float, 2>{0.36f, 0.42f}})
      session.moveTo(app::StrokeMove::toUv({uv[0], uv[1]}));
    session.finishStroke();
    return floatsOf(session.document().positions);
  };
  const std::vector<float> scene = strokeWith(0.05f, std::nullopt);
  QVERIFY(sameBits(scene, strokeWith(0.9f, 0.05f)));
  QVERIFY(!sameBits(scene, strokeWith(0.05f, 0.1f)));

  app::SculptSession session;
  session.setBrushes(*engine_, catalog_);
  session.loadBrush(manifest);
  session.setDocument(core::readDocument(sphere_.toStdString()));
  for (const float bad : {0.0f, -0.1f, std::numeric_limits<float>::quiet_NaN(),
                          std::numeric_limits<float>::infinity()}) {
    app::StrokeStart start;
    start.brushId = start.settings.brushId = "push";
    start.objectRadius = bad;
    try {
      session.beginStroke(start);
      QFAIL(qPrintable(QString("radius %1 accepted").arg(bad)));
    } catch (const core::Error& e) {
      QCOMPARE(e.kind(), core::ErrorKind::InvalidArgument);
      QVERIFY2(QString(e.what()).contains("brush radius"), e.what());
    }
    QVERIFY(!session.stroking());
  }
}

QTEST_GUILESS_MAIN(StrokeDoorTest)
#include "stroke_door_test.moc"
