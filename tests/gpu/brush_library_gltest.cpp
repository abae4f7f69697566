// BrushLibrary: broken brushes are reported and skipped while the rest load, and edited brush
// files are recompiled on poll, keeping the previous program when the new one fails; brush folders
// dropped into or deleted from the search path while running appear and vanish on poll.

#include "octaclay/core/geometry/base_shapes.h"
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

// A copy of the shipped template brush under another id, as a plugin author would make it.
void copyTemplate(const fs::path& folder, const std::string& id) {
  const fs::path source = fs::path(OCTACLAY_SOURCE_DIR) / "plugins/examples/template-brush";
  std::ifstream in(source / "manifest.json");
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string from = R"("id": "template-brush")";
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::runtime_error("the template's id line changed");
  text.replace(at, from.size(), R"("id": ")" + id + R"(")");
  fs::create_directories(folder);
  fs::copy_file(source / "brush.glsl", folder / "brush.glsl");
  write(folder / "manifest.json", text);
}

std::vector<std::string> idsOf(const BrushLibrary& library) {
  std::vector<std::string> ids;
  for (const BrushManifest* brush : library.brushes())
    ids.push_back(brush->id);
  return ids;
}

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
  void droppedInBrushFoldersAppearAndVanish();

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

void BrushLibraryTest::droppedInBrushFoldersAppearAndVanish() {
  QTemporaryDir builtIn, plugins;
  const fs::path builtInRoot = builtIn.path().toStdString();
  const fs::path pluginRoot = plugins.path().toStdString();
  write(builtInRoot / "good/manifest.json", manifest("good"));
  write(builtInRoot / "good/brush.glsl", kRaise);
  BrushLibrary library({builtInRoot, pluginRoot});
  QVERIFY(library.errors().empty());
  BrushLibrary::ReloadReport report = library.reloadChanged();
  QVERIFY(report.added.empty() && report.removed.empty() && report.failed.empty());

  copyTemplate(pluginRoot / "dropped", "dropped-brush");
  report = library.reloadChanged();
  QCOMPARE(report.added, std::vector<std::string>{"dropped-brush"});
  QVERIFY(report.reloaded.empty() && report.removed.empty());
  QVERIFY2(report.failed.empty(), report.failed.empty() ? "" : report.failed[0].c_str());
  QCOMPARE(idsOf(library), (std::vector<std::string>{"dropped-brush", "good"}));
  QVERIFY(library.engine().has("dropped-brush"));
  QVERIFY(raiseAtPole(library.engine(), "dropped-brush") > 1e-3f); // the template raises
  QVERIFY(std::abs(raiseAtPole(library.engine(), "good") - 1.0f) < 1e-6f);
  report = library.reloadChanged();
  QVERIFY(report.added.empty() && report.reloaded.empty()); // reported once

  // A broken newcomer is reported; the others keep working.
  const fs::path broken = pluginRoot / "broken/manifest.json";
  write(broken, "{\"id\": \"broken\", ");
  report = library.reloadChanged();
  QVERIFY(report.added.empty() && report.removed.empty() && report.reloaded.empty());
  QCOMPARE(report.failed.size(), std::size_t(1));
  QVERIFY2(report.failed[0].starts_with(broken.string()), report.failed[0].c_str());
  QCOMPARE(library.errors().size(), std::size_t(1));
  QCOMPARE(library.errors()[0], report.failed[0]);
  QCOMPARE(idsOf(library), (std::vector<std::string>{"dropped-brush", "good"}));
  QVERIFY(std::abs(raiseAtPole(library.engine(), "good") - 1.0f) < 1e-6f);

  // A new brush whose GLSL does not compile: failed, not added, not listed.
  write(pluginRoot / "bad-glsl/manifest.json", manifest("bad-glsl"));
  write(pluginRoot / "bad-glsl/brush.glsl", "vec4 brush(vec4 value, BrushInput b) { oops }\n");
  report = library.reloadChanged();
  QVERIFY(report.added.empty());
  QCOMPARE(report.failed.size(), std::size_t(1));
  QVERIFY2(report.failed[0].find((pluginRoot / "bad-glsl/brush.glsl").string()) !=
               std::string::npos,
           report.failed[0].c_str());
  QCOMPARE(library.errors().size(), std::size_t(2));
  QCOMPARE(idsOf(library), (std::vector<std::string>{"dropped-brush", "good"}));

  fs::remove_all(pluginRoot / "dropped");
  report = library.reloadChanged();
  QCOMPARE(report.removed, std::vector<std::string>{"dropped-brush"});
  QVERIFY(report.added.empty() && report.reloaded.empty());
  QVERIFY(report.failed.empty()); // the broken ones were reported already
  QCOMPARE(idsOf(library), std::vector<std::string>{"good"});
  QVERIFY(!library.catalog().find("dropped-brush"));
  QVERIFY(std::abs(raiseAtPole(library.engine(), "good") - 1.0f) < 1e-6f);

  // Fixing the broken manifest in place loads it.
  write(broken, manifest("broken"));
  write(pluginRoot / "broken/brush.glsl", kRaise);
  report = library.reloadChanged();
  QCOMPARE(report.added, std::vector<std::string>{"broken"});
  QCOMPARE(library.errors().size(), std::size_t(1)); // bad-glsl still
  QCOMPARE(idsOf(library), (std::vector<std::string>{"broken", "good"}));
}

QTEST_APPLESS_MAIN(BrushLibraryTest)
#include "brush_library_gltest.moc"
