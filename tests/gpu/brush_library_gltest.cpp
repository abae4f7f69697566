// BrushLibrary: broken brushes are reported and skipped while the rest load, and edited brush
// files are recompiled on poll, keeping the previous program when the new one fails.

#include "octaclay/core/base_shapes.h"
#include "octaclay/gpu/brush_library.h"
#include "octaclay/gpu/gl_context.h"

#include <QtTest>
#include <fstream>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
namespace fs = std::filesystem;

namespace {

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

std::string manifest(const std::string& id) {
  return R"({"id": ")" + id + R"(", "name": "T", "api": 1, "shader": "brush.glsl",
             "writes": ["positions"], "area": "volume", "falloff": "constant"})";
}

const char* kRaise = "vec4 brush(vec4 value, BrushInput b) { return value + vec4(0, 0, 1, 0); }\n";

// Moves a file's time forward so the poll sees the edit without sleeping.
void touch(const fs::path& path, int seconds) {
  fs::last_write_time(path, fs::last_write_time(path) + std::chrono::seconds(seconds));
}

float raiseAtPole(BrushEngine& engine, const std::string& id) {
  const core::GeometryImage image = core::makeBaseShape(core::BaseShape::Sphere, 16);
  GpuDocument document(core::makeDocument(image));
  Dab dab;
  dab.centre = image.at(8, 8).xyz();
  dab.centreNormal = {0, 0, 1};
  dab.centreTexel = {8, 8};
  dab.radius = 0.1f;
  engine.dab(document, id, dab);
  return document.document().positions.at(8, 8).z - image.at(8, 8).z;
}

} // namespace

class BrushLibraryTest : public QObject {
  Q_OBJECT

private slots:
  void brokenBrushesAreSkipped();
  void editsAreReloadedAndFailuresKeepTheOldProgram();

private:
  std::optional<GlContext> context_ = GlContext::createHeadless();
};

void BrushLibraryTest::brokenBrushesAreSkipped() {
  QTemporaryDir dir;
  const fs::path root = dir.path().toStdString();
  write(root / "good/manifest.json", manifest("good"));
  write(root / "good/brush.glsl", kRaise);
  write(root / "bad-glsl/manifest.json", manifest("bad-glsl"));
  write(root / "bad-glsl/brush.glsl",
        "vec4 brush(vec4 value, BrushInput b) {\n  return missing;\n}\n");
  write(root / "bad-json/manifest.json", "{\"id\": ");
  BrushLibrary library({root});
  QCOMPARE(library.brushes().size(), std::size_t(1));
  QCOMPARE(library.brushes()[0]->id, std::string("good"));
  QCOMPARE(library.errors().size(), std::size_t(2));
  bool glsl = false, json = false;
  for (const std::string& e : library.errors()) {
    glsl = glsl || (e.find((root / "bad-glsl/brush.glsl").string() + ":2") != std::string::npos &&
                    e.find("missing") != std::string::npos);
    json = json || e.find((root / "bad-json/manifest.json").string()) != std::string::npos;
  }
  QVERIFY(glsl);
  QVERIFY(json);
  QVERIFY(std::abs(raiseAtPole(library.engine(), "good") - 1.0f) < 1e-6f);
}

void BrushLibraryTest::editsAreReloadedAndFailuresKeepTheOldProgram() {
  QTemporaryDir dir;
  const fs::path root = dir.path().toStdString();
  const fs::path shader = root / "edit/brush.glsl";
  write(root / "edit/manifest.json", manifest("edit"));
  write(shader, kRaise);
  BrushLibrary library({root});
  QVERIFY(library.reloadChanged().reloaded.empty()); // nothing changed yet

  write(shader, "vec4 brush(vec4 value, BrushInput b) {\n  return value +;\n}\n");
  touch(shader, 10);
  BrushLibrary::ReloadReport report = library.reloadChanged();
  QVERIFY(report.reloaded.empty());
  QCOMPARE(report.failed.size(), std::size_t(1));
  QVERIFY2(report.failed[0].find(shader.string() + ":2") != std::string::npos,
           report.failed[0].c_str());
  QVERIFY(std::abs(raiseAtPole(library.engine(), "edit") - 1.0f) < 1e-6f); // the old one still runs

  write(shader, "vec4 brush(vec4 value, BrushInput b) { return value + vec4(0, 0, 2, 0); }\n");
  touch(shader, 20);
  report = library.reloadChanged();
  QCOMPARE(report.reloaded, std::vector<std::string>{"edit"});
  QVERIFY(std::abs(raiseAtPole(library.engine(), "edit") - 2.0f) < 1e-6f);
}

QTEST_APPLESS_MAIN(BrushLibraryTest)
#include "brush_library_gltest.moc"
