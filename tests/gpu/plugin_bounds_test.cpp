// Bounded plugin loading (issue 20), without GL: a manifest or shader that is a named pipe, a
// link to a device, a link loop or larger than 1 MB is listed as broken with a message naming
// the file, is never read and never blocks the scan; the manifest checks take linear time
// (10^5 parameters parse at once).

#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_manifest.h"
#include "octaclay/gpu/material_catalog.h"

#include <QTemporaryDir>
#include <QtTest>
#include <sys/stat.h>

#include <fstream>

using namespace octaclay;
using namespace octaclay::gpu;
namespace fs = std::filesystem;

namespace {

std::string manifest(const std::string& id) {
  return R"({"id": ")" + id + R"(", "name": "T", "api": 1, "shader": "brush.glsl",
             "writes": ["positions"], "area": "volume"})";
}

void writeFile(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
}

// A brush folder with a good shader whose manifest.json is made by makeManifest.
template <class Make>
fs::path brushFolder(const fs::path& root, const char* name, Make makeManifest) {
  const fs::path folder = root / name;
  writeFile(folder / "brush.glsl", "vec4 brush(vec4 value, BrushInput b) { return value; }\n");
  makeManifest(folder / "manifest.json");
  return folder;
}

// The catalog's error for the brush folder, or "" when it has none.
std::string errorOf(const BrushCatalog& catalog, const fs::path& folder) {
  for (const BrushCatalogError& e : catalog.errors())
    if (e.path.parent_path() == folder) return e.message;
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

} // namespace

class PluginBoundsTest : public QObject {
  Q_OBJECT

private slots:
  void unreadableManifestsAreListedAsBroken();
  void unreadableShadersAreRefused();
  void unreadableMaterialManifestsAreListedAsBroken();
  void parameterChecksAreLinear();
  void illFormedUtf8IsShownEscaped();
};

void PluginBoundsTest::unreadableManifestsAreListedAsBroken() {
  QTemporaryDir dir;
  const fs::path root = dir.path().toStdString();
  brushFolder(root, "good", [](const fs::path& m) { writeFile(m, manifest("good")); });
  const fs::path fifo = brushFolder(root, "fifo", [](const fs::path& m) {
    QCOMPARE(::mkfifo(m.c_str(), 0644), 0); // reading it would block until a writer comes
  });
  const fs::path zero = brushFolder(root, "zero", [](const fs::path& m) {
    fs::create_symlink("/dev/zero", m); // reading it would never end
  });
  const fs::path loop = brushFolder(root, "loop", [](const fs::path& m) {
    fs::create_symlink(m.filename(), m); // links to itself
  });
  const fs::path large = brushFolder(root, "large", [](const fs::path& m) {
    writeFile(m, manifest("large") + std::string((1u << 20) + 1, ' '));
  });

  BrushCatalog catalog;
  catalog.scan({root});
  QCOMPARE(catalog.brushes().size(), std::size_t(1));
  QCOMPARE(catalog.brushes()[0].id, std::string("good"));
  QCOMPARE(catalog.errors().size(), std::size_t(4));
  const std::string fifoError = errorOf(catalog, fifo);
  QVERIFY2(fifoError.starts_with((fifo / "manifest.json").string()) &&
               contains(fifoError, "named pipe"),
           fifoError.c_str());
  const std::string zeroError = errorOf(catalog, zero);
  QVERIFY2(contains(zeroError, (zero / "manifest.json").string()) &&
               contains(zeroError, "is a device"),
           zeroError.c_str());
  const std::string loopError = errorOf(catalog, loop);
  QVERIFY2(contains(loopError, (loop / "manifest.json").string()) &&
               contains(loopError, "symbolic link loop"),
           loopError.c_str());
  const std::string largeError = errorOf(catalog, large);
  QVERIFY2(contains(largeError, (large / "manifest.json").string()) &&
               contains(largeError, "more than the 1048576"),
           largeError.c_str());
  // Polling them only stats: it neither blocks nor reads.
  QVERIFY(!catalog.brushFoldersChanged());
}

void PluginBoundsTest::unreadableShadersAreRefused() {
  QTemporaryDir dir;
  const fs::path root = dir.path().toStdString();
  // A shader that is a link to a device is refused by the manifest's check (a stat).
  const fs::path device = root / "device";
  writeFile(device / "manifest.json", manifest("device"));
  fs::create_symlink("/dev/zero", device / "brush.glsl");
  try {
    parseBrushManifest(device / "manifest.json");
    QFAIL("a shader linked to /dev/zero was accepted");
  } catch (const BrushLoadError& e) {
    QVERIFY2(contains(e.what(), "brush.glsl") && contains(e.what(), "not a regular file"),
             e.what());
  }
  // One over 1 MB parses (the manifest is fine) but is not read.
  const fs::path large = root / "large";
  writeFile(large / "manifest.json", manifest("large"));
  writeFile(large / "brush.glsl", std::string((1u << 20) + 1, '\n'));
  const BrushManifest brush = parseBrushManifest(large / "manifest.json");
  try {
    BrushCatalog::shaderSource(brush);
    QFAIL("a shader over 1 MB was read");
  } catch (const BrushLoadError& e) {
    QVERIFY2(std::string(e.what()).starts_with((large / "brush.glsl").string()) &&
                 contains(e.what(), "more than"),
             e.what());
  }
  // One swapped for a pipe after the manifest was parsed is refused when read, at once.
  fs::remove(large / "brush.glsl");
  QCOMPARE(::mkfifo((large / "brush.glsl").c_str(), 0644), 0);
  try {
    BrushCatalog::shaderSource(brush);
    QFAIL("a shader that is a named pipe was read");
  } catch (const BrushLoadError& e) {
    QVERIFY2(contains(e.what(), "named pipe"), e.what());
  }
}

void PluginBoundsTest::unreadableMaterialManifestsAreListedAsBroken() {
  QTemporaryDir dir;
  const fs::path root = dir.path().toStdString();
  fs::create_directories(root / "fifo");
  QCOMPARE(::mkfifo((root / "fifo" / "material.json").c_str(), 0644), 0);
  fs::create_directories(root / "loop");
  fs::create_symlink("material.json", root / "loop" / "material.json");
  MaterialCatalog catalog;
  catalog.scan({root});
  QCOMPARE(catalog.materials().size(), std::size_t(0));
  QCOMPARE(catalog.errors().size(), std::size_t(2));
  for (const std::string& e : catalog.errors())
    QVERIFY2(contains(e, "named pipe") || contains(e, "symbolic link loop"), e.c_str());
}

void PluginBoundsTest::parameterChecksAreLinear() {
  // 10^5 parameters, and a duplicate of the first as the last: a quadratic check would take
  // seconds (the issue measured 10 s); this must finish, and name both.
  constexpr int kCount = 100000;
  std::string text = R"({"id": "many", "name": "Many", "api": 1, "shader": "brush.glsl",
                         "writes": ["positions"], "area": "volume", "parameters": [)";
  for (int k = 0; k < kCount; ++k)
    text += R"({"id": "p)" + std::to_string(k) + R"(", "type": "float"},)";
  QTemporaryDir dir;
  const fs::path file = fs::path(dir.path().toStdString()) / "manifest.json";
  writeFile(file.parent_path() / "brush.glsl", "vec4 brush(vec4 v, BrushInput b) { return v; }\n");
  const BrushManifest many = parseBrushManifestText(text.substr(0, text.size() - 1) + "]}", file);
  QCOMPARE(many.parameters.size(), std::size_t(kCount));
  try {
    parseBrushManifestText(text + R"({"id": "p0", "type": "float"}]})", file);
    QFAIL("a duplicate parameter id was accepted");
  } catch (const BrushLoadError& e) {
    QVERIFY2(contains(e.what(), "parameters[100000].id: \"p0\" is already used by parameters[0]"),
             e.what());
  }
}

void PluginBoundsTest::illFormedUtf8IsShownEscaped() {
  // nlohmann refuses the byte and quotes it; the message must stay UTF-8 (brushes --json).
  QTemporaryDir dir;
  const fs::path file = fs::path(dir.path().toStdString()) / "manifest.json";
  try {
    parseBrushManifestText("{\"id\": \"b\", \"name\": \"T\xff\"}", file);
    QFAIL("a manifest with a stray byte was accepted");
  } catch (const BrushLoadError& e) {
    const std::string message = e.what();
    QVERIFY2(contains(message, "\\xFF"), e.what());
    for (const char c : message)
      QVERIFY2(static_cast<unsigned char>(c) < 0x80, e.what());
  }
}

QTEST_APPLESS_MAIN(PluginBoundsTest)
#include "plugin_bounds_test.moc"
