// Materials for the splat brush, without GL: the five shipped materials load with 256² maps whose
// values look like what they claim to be, every map and the environment map tile seamlessly, a
// broken material folder is reported (the message starts with its file and names the field) and
// skipped while the others load, a later folder overrides an id, $OCTACLAY_MATERIAL_PATH and XDG
// are searched, and the generator (tools/material_generator.cpp, linked in by tools/CMakeLists.txt)
// writes the same bytes on every run and what is committed under resources/.

#include "material_generator.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/gpu/material_catalog.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

using namespace octaclay;
using namespace octaclay::gpu;
namespace fs = std::filesystem;

namespace {

const fs::path kResources = fs::path(OCTACLAY_SOURCE_DIR) / "resources";
// One 8-bit step: what rounding to a PNG may add to any difference.
constexpr float kQuantum = 1.0f / 255.0f;

const char* const kGoodManifest = R"({
  "id": "test-material",
  "name": "Test material",
  "source": "tests/gpu/material_catalog_test.cpp",
  "license": "CC0-1.0",
  "tileSize": 0.05,
  "heightScale": 0.1,
  "maps": {"height": "height.png", "colour": "colour.png", "specular": "specular.png",
           "reflectivity": "reflectivity.png"}
})";

void writeFile(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  QVERIFY2(out.good(), file.c_str());
}

std::string readFile(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

core::RasterImage flatImage(int size, int channels, float value) {
  core::RasterImage image;
  image.width = image.height = size;
  image.channels = channels;
  image.pixels.assign(static_cast<std::size_t>(size) * size * channels, value);
  return image;
}

// kGoodManifest with the top-level fields of patch replaced (a null value removes the field).
std::string patched(const QJsonObject& patch) {
  QJsonObject object = QJsonDocument::fromJson(kGoodManifest).object();
  for (auto it = patch.begin(); it != patch.end(); ++it) {
    if (it.value().isNull())
      object.remove(it.key());
    else
      object.insert(it.key(), it.value());
  }
  return QJsonDocument(object).toJson().toStdString();
}

// A complete material folder: manifest text and four flat size² maps.
void writeMaterial(const fs::path& folder, const std::string& manifest, int size = 16) {
  writeFile(folder / "material.json", manifest);
  core::writePng(flatImage(size, 1, 0.5f), folder / "height.png");
  core::writePng(flatImage(size, 3, 0.8f), folder / "colour.png");
  core::writePng(flatImage(size, 1, 0.3f), folder / "specular.png");
  core::writePng(flatImage(size, 1, 0.1f), folder / "reflectivity.png");
}

std::string withId(const std::string& id, const std::string& name = "Test material") {
  return patched({{"id", QString::fromStdString(id)}, {"name", QString::fromStdString(name)}});
}

// The message loadMaterial throws, or "loaded" when it does not.
std::string errorOf(const fs::path& folder) {
  try {
    loadMaterial(folder);
    return "loaded";
  } catch (const MaterialLoadError& e) {
    return e.what();
  }
}

// Values of channel c, sorted.
std::vector<float> sortedValues(const core::RasterImage& image, int c) {
  std::vector<float> values;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      values.push_back(image.at(x, y, c));
  std::sort(values.begin(), values.end());
  return values;
}

float percentile(const std::vector<float>& sorted, double p) {
  return sorted[static_cast<std::size_t>(p * static_cast<double>(sorted.size() - 1))];
}

float mean(const core::RasterImage& image, int c) {
  double sum = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      sum += image.at(x, y, c);
  return static_cast<float>(sum / (static_cast<double>(image.width) * image.height));
}

// Mean |a - b| over channel c between column (or row, when rows) i and j.
double lineDifference(const core::RasterImage& image, int c, bool rows, int i, int j) {
  const int length = rows ? image.width : image.height;
  double sum = 0.0;
  for (int k = 0; k < length; ++k)
    sum += rows ? std::abs(image.at(k, i, c) - image.at(k, j, c))
                : std::abs(image.at(i, k, c) - image.at(j, k, c));
  return sum / length;
}

// A seamless map differs across its wrap (last line to first) no more than twice as much as
// neighbouring lines do on average inside it, plus one 8-bit step for rounding. A map whose
// pattern were cut off at the edge would jump there like a step edge across the whole line.
void verifyTiles(const core::RasterImage& image, const std::string& what, bool checkRows = true) {
  for (int c = 0; c < image.channels; ++c)
    for (const bool rows : {false, true}) {
      if (rows && !checkRows) continue;
      const int count = rows ? image.height : image.width;
      double interior = 0.0;
      for (int i = 0; i + 1 < count; ++i)
        interior += lineDifference(image, c, rows, i, i + 1);
      interior /= count - 1;
      const double seam = lineDifference(image, c, rows, count - 1, 0);
      QVERIFY2(seam <= 2.0 * interior + kQuantum,
               (what + " channel " + std::to_string(c) + (rows ? " rows" : " columns") + ": seam " +
                std::to_string(seam) + " vs interior " + std::to_string(interior))
                   .c_str());
    }
}

// Every file under folder, relative to it, sorted.
std::vector<fs::path> filesUnder(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), folder));
  std::sort(files.begin(), files.end());
  return files;
}

enum class Breakage { None, RemoveSpecular, SmallerSpecular, TextAsColour, NonSquare, NotPow2 };

} // namespace

class MaterialCatalogTest : public QObject {
  Q_OBJECT

private slots:
  void shippedMaterialsLoad();
  void shippedMaterialsLookRight();
  void shippedMapsTile();
  void environmentMapTiles();
  void goodManifestLoads();
  void badMaterialIsRefused_data();
  void badMaterialIsRefused();
  void scanSkipsBrokenFoldersAndLoadsTheRest();
  void laterFolderReplacesId();
  void defaultSearchPathOrder();
  void materialPathIsScanned();
  void generatorIsDeterministic();
  void committedResourcesMatchGenerator();

private:
  QTemporaryDir dir_;
  fs::path root() const { return fs::path(dir_.path().toStdString()); }
};

void MaterialCatalogTest::shippedMaterialsLoad() {
  MaterialCatalog catalog;
  catalog.scan({kResources / "materials"});
  for (const std::string& error : catalog.errors())
    qWarning("%s", error.c_str());
  QVERIFY(catalog.errors().empty());
  QCOMPARE(catalog.materials().size(), std::size_t(5));
  for (const char* id : {"brick", "stone", "wood", "red-plastic", "mirror"}) {
    const Material* m = catalog.find(id);
    QVERIFY2(m, id);
    QCOMPARE(m->id, std::string(id));
    QVERIFY(!m->name.empty());
    QVERIFY(m->license.starts_with("CC0-1.0"));
    QVERIFY(m->tileSize > 0.0f);
    QVERIFY(m->heightScale >= 0.0f);
    QCOMPARE(m->folder, kResources / "materials" / id);
    for (const auto& [image, channels] :
         {std::pair{&m->height, 1}, {&m->colour, 4}, {&m->specular, 1}, {&m->reflectivity, 1}}) {
      QCOMPARE(image->width, 256);
      QCOMPARE(image->height, 256);
      QCOMPARE(image->channels, channels);
      QVERIFY(std::all_of(image->pixels.begin(), image->pixels.end(),
                          [](float v) { return v >= 0.0f && v <= 1.0f; }));
    }
    // The generator writes RGB; a missing alpha is full coverage.
    QCOMPARE(sortedValues(m->colour, 3).front(), 1.0f);
  }
  QVERIFY(!catalog.find("granite"));
}

void MaterialCatalogTest::shippedMaterialsLookRight() {
  MaterialCatalog catalog;
  catalog.scan({kResources / "materials"});
  QCOMPARE(catalog.materials().size(), std::size_t(5));

  // Brick: mortar grooves low, brick faces high; the top row lies in a bed joint.
  const Material& brick = *catalog.find("brick");
  const auto brickHeights = sortedValues(brick.height, 0);
  QVERIFY(percentile(brickHeights, 0.1) < 0.25f);
  QVERIFY(percentile(brickHeights, 0.9) > 0.65f);
  double topRow = 0.0;
  for (int x = 0; x < 256; ++x)
    topRow += brick.height.at(x, 0, 0);
  QVERIFY(topRow / 256.0 < 0.3);
  QVERIFY(brick.height.at(128 / 3, 16, 0) > 0.6f);               // middle of the first brick
  QVERIFY(mean(brick.colour, 0) > mean(brick.colour, 1) + 0.1f); // red-brown
  QVERIFY(mean(brick.specular, 0) < 0.2f);
  QCOMPARE(sortedValues(brick.reflectivity, 0).back(), 0.0f);

  // Stone: grey (channels close), some specular.
  const Material& stone = *catalog.find("stone");
  QVERIFY(std::abs(mean(stone.colour, 0) - mean(stone.colour, 2)) < 0.05f);
  QVERIFY(mean(stone.specular, 0) > 0.1f && mean(stone.specular, 0) < 0.5f);
  const auto stoneHeights = sortedValues(stone.height, 0);
  QVERIFY(percentile(stoneHeights, 0.9) - percentile(stoneHeights, 0.1) > 0.4f);

  // Wood: brown (r > g > b), medium specular.
  const Material& wood = *catalog.find("wood");
  QVERIFY(mean(wood.colour, 0) > mean(wood.colour, 1) &&
          mean(wood.colour, 1) > mean(wood.colour, 2));
  QVERIFY(mean(wood.specular, 0) > 0.25f && mean(wood.specular, 0) < 0.6f);

  // Red plastic: red everywhere, flat with faint noise, glossy, hardly reflective.
  const Material& plastic = *catalog.find("red-plastic");
  for (int y = 0; y < 256; ++y)
    for (int x = 0; x < 256; ++x) {
      QVERIFY(plastic.colour.at(x, y, 0) > plastic.colour.at(x, y, 1) + 0.4f);
      QVERIFY(std::abs(plastic.height.at(x, y, 0) - 0.5f) <= 0.015f);
    }
  QVERIFY(mean(plastic.specular, 0) > 0.7f);
  QVERIFY(sortedValues(plastic.reflectivity, 0).back() < 0.2f);

  // Mirror: flat, near-white, reflects almost everything.
  const Material& mirror = *catalog.find("mirror");
  QVERIFY(sortedValues(mirror.reflectivity, 0).front() > 0.9f);
  QVERIFY(sortedValues(mirror.specular, 0).front() > 0.9f);
  QVERIFY(mean(mirror.colour, 1) > 0.8f);
  const auto mirrorHeights = sortedValues(mirror.height, 0);
  QVERIFY(mirrorHeights.back() - mirrorHeights.front() < kQuantum / 2);
}

void MaterialCatalogTest::shippedMapsTile() {
  MaterialCatalog catalog;
  catalog.scan({kResources / "materials"});
  QCOMPARE(catalog.materials().size(), std::size_t(5));
  for (const Material& m : catalog.materials()) {
    verifyTiles(m.height, m.id + " height");
    verifyTiles(m.colour, m.id + " colour");
    verifyTiles(m.specular, m.id + " specular");
    verifyTiles(m.reflectivity, m.id + " reflectivity");
  }
}

void MaterialCatalogTest::environmentMapTiles() {
  const core::RasterImage studio = core::readImage(kResources / "environment" / "studio.png", 3);
  QCOMPARE(studio.width, 512);
  QCOMPARE(studio.height, 256);
  // Equirectangular: only the azimuth (x) wraps; the top and bottom rows are the poles.
  verifyTiles(studio, "studio.png", false);
  // Bright softboxes somewhere, a sky lighter than the floor.
  QVERIFY(sortedValues(studio, 1).back() > 0.95f);
  double sky = 0.0, floor = 0.0;
  for (int x = 0; x < 512; ++x) {
    sky += studio.at(x, 8, 1);
    floor += studio.at(x, 247, 1);
  }
  QVERIFY(sky > floor + 0.3 * 512);
}

void MaterialCatalogTest::goodManifestLoads() {
  const fs::path folder = root() / "good";
  writeMaterial(folder, patched({{"x-note", "own fields are allowed"}}), 32);
  Material m;
  try {
    m = loadMaterial(folder);
  } catch (const MaterialLoadError& e) {
    QFAIL(e.what());
  }
  QCOMPARE(m.id, std::string("test-material"));
  QCOMPARE(m.name, std::string("Test material"));
  QCOMPARE(m.license, std::string("CC0-1.0"));
  QCOMPARE(m.tileSize, 0.05f);
  QCOMPARE(m.heightScale, 0.1f);
  QCOMPARE(m.folder, folder);
  QCOMPARE(m.height.width, 32);
  QCOMPARE(m.colour.channels, 4);
  QVERIFY(std::abs(m.specular.at(3, 3, 0) - 0.3f) <= kQuantum);

  // source, license, tileSize and heightScale are optional.
  writeMaterial(folder, patched({{"source", QJsonValue::Null},
                                 {"license", QJsonValue::Null},
                                 {"tileSize", QJsonValue::Null},
                                 {"heightScale", QJsonValue::Null}}));
  QCOMPARE(errorOf(folder), std::string("loaded"));
}

void MaterialCatalogTest::badMaterialIsRefused_data() {
  QTest::addColumn<QString>("manifest");
  QTest::addColumn<int>("breakage");
  QTest::addColumn<QString>("expected"); // after "<folder>/material.json: "

  const auto manifest = [](const QJsonObject& patch) {
    return QString::fromStdString(patched(patch));
  };
  const int none = static_cast<int>(Breakage::None);
  QTest::newRow("bad JSON") << QString("{\"id\": \"x\",") << none << "invalid JSON at byte";
  QTest::newRow("not an object") << QString("[1, 2]") << none
                                 << "expected a JSON object { ... }, got an array";
  QTest::newRow("duplicate key") << QString(R"({"id": "a", "id": "b"})") << none
                                 << "id: appears twice in the same object";
  QTest::newRow("unknown field") << manifest({{"tilesize", 1}}) << none
                                 << "tilesize: unknown field (did you mean \"tileSize\"?)";
  QTest::newRow("unknown field, no hint")
      << manifest({{"glow", 1}}) << none << "glow: unknown field (prefix your own fields with x-)";
  QTest::newRow("unknown map") << manifest({{"maps", QJsonObject{{"height", "height.png"},
                                                                 {"colour", "colour.png"},
                                                                 {"specular", "specular.png"},
                                                                 {"reflectivity", "r.png"},
                                                                 {"normal", "n.png"}}}})
                               << none << "maps.normal: unknown field";
  QTest::newRow("missing id") << manifest({{"id", QJsonValue::Null}}) << none
                              << "id: missing required field";
  QTest::newRow("bad id") << manifest({{"id", "Brick"}}) << none
                          << "id: \"Brick\" is not a valid material id";
  QTest::newRow("empty name") << manifest({{"name", ""}}) << none << "name: must not be empty";
  QTest::newRow("number name") << manifest({{"name", 3}}) << none
                               << "name: expected a string, got 3";
  QTest::newRow("tileSize 0") << manifest({{"tileSize", 0}}) << none
                              << "tileSize: 0 is outside (0, 10]";
  QTest::newRow("tileSize negative")
      << manifest({{"tileSize", -0.5}}) << none << "tileSize: -0.5 is outside (0, 10]";
  QTest::newRow("tileSize string")
      << manifest({{"tileSize", "big"}}) << none << "tileSize: expected a number, got \"big\"";
  QTest::newRow("heightScale negative")
      << manifest({{"heightScale", -1}}) << none << "heightScale: -1 is outside [0, 10]";
  QTest::newRow("missing maps") << manifest({{"maps", QJsonValue::Null}}) << none
                                << "maps: missing required field";
  QTest::newRow("maps not an object")
      << manifest({{"maps", "height.png"}}) << none << "maps: expected an object of map files";
  QTest::newRow("missing map entry")
      << manifest({{"maps", QJsonObject{{"height", "height.png"},
                                        {"colour", "colour.png"},
                                        {"specular", "specular.png"}}}})
      << none << "maps.reflectivity: missing required field";
  QTest::newRow("map path") << manifest({{"maps", QJsonObject{{"height", "../height.png"},
                                                              {"colour", "colour.png"},
                                                              {"specular", "specular.png"},
                                                              {"reflectivity", "r.png"}}}})
                            << none << "maps.height: \"../height.png\" must be a file name";
  QTest::newRow("missing map file")
      << QString(kGoodManifest) << static_cast<int>(Breakage::RemoveSpecular)
      << "maps.specular: specular.png not found in";
  QTest::newRow("different size") << QString(kGoodManifest)
                                  << static_cast<int>(Breakage::SmallerSpecular)
                                  << "maps.specular: 8x8 differs from maps.height's 16x16";
  QTest::newRow("not an image") << QString(kGoodManifest)
                                << static_cast<int>(Breakage::TextAsColour) << "maps.colour: ";
  QTest::newRow("not square") << QString(kGoodManifest) << static_cast<int>(Breakage::NonSquare)
                              << "maps.height: 32x16 is not square";
  QTest::newRow("not a power of two")
      << QString(kGoodManifest) << static_cast<int>(Breakage::NotPow2)
      << "maps.height: 24x24 is not a power of two from 16 to 2048";
}

void MaterialCatalogTest::badMaterialIsRefused() {
  QFETCH(QString, manifest);
  QFETCH(int, breakage);
  QFETCH(QString, expected);
  static int row = 0;
  const fs::path folder = root() / ("bad-" + std::to_string(row++));
  writeMaterial(folder, manifest.toStdString());
  switch (static_cast<Breakage>(breakage)) {
  case Breakage::None:
    break;
  case Breakage::RemoveSpecular:
    fs::remove(folder / "specular.png");
    break;
  case Breakage::SmallerSpecular:
    core::writePng(flatImage(8, 1, 0.3f), folder / "specular.png");
    break;
  case Breakage::TextAsColour:
    writeFile(folder / "colour.png", "this is not a PNG\n");
    break;
  case Breakage::NonSquare: {
    core::RasterImage wide = flatImage(16, 1, 0.5f);
    wide.width = 32;
    wide.pixels.resize(32 * 16);
    core::writePng(wide, folder / "height.png");
    break;
  }
  case Breakage::NotPow2:
    for (const char* map : {"height.png", "specular.png", "reflectivity.png"})
      core::writePng(flatImage(24, 1, 0.5f), folder / map);
    core::writePng(flatImage(24, 3, 0.5f), folder / "colour.png");
    break;
  }
  const std::string message = errorOf(folder);
  const std::string prefix = (folder / "material.json").string() + ": ";
  QVERIFY2(message.starts_with(prefix + expected.toStdString()), message.c_str());
  if (static_cast<Breakage>(breakage) == Breakage::TextAsColour)
    QVERIFY2(message.find((folder / "colour.png").string() + ": not an image") != std::string::npos,
             message.c_str());
}

void MaterialCatalogTest::scanSkipsBrokenFoldersAndLoadsTheRest() {
  const fs::path top = root() / "scan";
  writeMaterial(top / "a-good", withId("good-one"));
  writeMaterial(top / "z-good", withId("good-two"));
  writeMaterial(top / "bad-json", "{ \"id\": ");
  writeMaterial(top / "missing-map", withId("missing-map"));
  fs::remove(top / "missing-map" / "height.png");
  writeMaterial(top / "other-size", withId("other-size"));
  core::writePng(flatImage(32, 1, 0.1f), top / "other-size" / "reflectivity.png");
  writeMaterial(top / "text-map", withId("text-map"));
  writeFile(top / "text-map" / "specular.png", "plain text");
  writeMaterial(top / "unknown-field", patched({{"id", "unknown-field"}, {"shine", 1}}));
  writeMaterial(top / "tile-zero", patched({{"id", "tile-zero"}, {"tileSize", 0}}));
  fs::create_directories(top / "no-manifest"); // not a material folder: ignored silently
  writeFile(top / "stray-file.txt", "ignored");

  MaterialCatalog catalog;
  catalog.scan({top, root() / "does-not-exist"});
  QCOMPARE(catalog.materials().size(), std::size_t(2));
  QCOMPARE(catalog.materials()[0].id, std::string("good-one"));
  QCOMPARE(catalog.materials()[1].id, std::string("good-two"));
  QVERIFY(catalog.find("good-two"));
  QVERIFY(!catalog.find("missing-map"));

  const auto errorFor = [&](const char* folder) -> std::string {
    const std::string prefix = (top / folder / "material.json").string() + ": ";
    for (const std::string& error : catalog.errors())
      if (error.starts_with(prefix)) return error.substr(prefix.size());
    return "no error for " + std::string(folder);
  };
  QCOMPARE(catalog.errors().size(), std::size_t(6));
  QVERIFY2(errorFor("bad-json").starts_with("invalid JSON"), errorFor("bad-json").c_str());
  QVERIFY2(errorFor("missing-map").starts_with("maps.height: height.png not found"),
           errorFor("missing-map").c_str());
  QVERIFY2(errorFor("other-size").starts_with("maps.reflectivity: 32x32 differs"),
           errorFor("other-size").c_str());
  QVERIFY2(errorFor("text-map").starts_with("maps.specular: "), errorFor("text-map").c_str());
  QVERIFY2(errorFor("unknown-field").starts_with("shine: unknown field"),
           errorFor("unknown-field").c_str());
  QVERIFY2(errorFor("tile-zero").starts_with("tileSize: 0 is outside"),
           errorFor("tile-zero").c_str());

  // A rescan forgets what the previous one found.
  catalog.scan({root() / "does-not-exist"});
  QVERIFY(catalog.materials().empty());
  QVERIFY(catalog.errors().empty());
}

void MaterialCatalogTest::laterFolderReplacesId() {
  const fs::path first = root() / "override" / "first", second = root() / "override" / "second";
  writeMaterial(first / "brick", withId("brick", "First brick"));
  writeMaterial(first / "other", withId("other", "Other"));
  writeMaterial(second / "my-brick", withId("brick", "Second brick"), 32);

  MaterialCatalog catalog;
  catalog.scan({first, second});
  QVERIFY(catalog.errors().empty());
  QCOMPARE(catalog.materials().size(), std::size_t(2));
  const Material* brick = catalog.find("brick");
  QVERIFY(brick);
  QCOMPARE(brick->name, std::string("Second brick"));
  QCOMPARE(brick->folder, second / "my-brick");
  QCOMPARE(brick->height.width, 32);

  catalog.scan({second, first});
  QCOMPARE(catalog.find("brick")->name, std::string("First brick"));
}

void MaterialCatalogTest::defaultSearchPathOrder() {
  const QByteArray savedPath = qgetenv("OCTACLAY_MATERIAL_PATH");
  const QByteArray savedXdg = qgetenv("XDG_DATA_HOME");
  const QByteArray savedHome = qgetenv("HOME");

  qputenv("OCTACLAY_MATERIAL_PATH", "/a/one::/b/two:");
  qputenv("XDG_DATA_HOME", "/data");
  QCOMPARE(MaterialCatalog::defaultSearchPath("/built-in"),
           (std::vector<fs::path>{"/built-in", "/a/one", "/b/two", "/data/octaclay/materials"}));

  // A relative XDG_DATA_HOME is invalid (XDG Base Directory spec): the default under HOME.
  qputenv("OCTACLAY_MATERIAL_PATH", "");
  qputenv("XDG_DATA_HOME", "relative");
  qputenv("HOME", "/home/me");
  QCOMPARE(MaterialCatalog::defaultSearchPath("/built-in"),
           (std::vector<fs::path>{"/built-in", "/home/me/.local/share/octaclay/materials"}));

  qputenv("OCTACLAY_MATERIAL_PATH", savedPath);
  qputenv("XDG_DATA_HOME", savedXdg);
  qputenv("HOME", savedHome);
}

void MaterialCatalogTest::materialPathIsScanned() {
  const QByteArray savedPath = qgetenv("OCTACLAY_MATERIAL_PATH");
  const QByteArray savedXdg = qgetenv("XDG_DATA_HOME");
  const fs::path mine = root() / "path" / "mine", xdg = root() / "path" / "xdg";
  // Overrides the shipped mirror, adds a material of its own.
  writeMaterial(mine / "mirror", withId("mirror", "My mirror"));
  writeMaterial(mine / "felt", withId("felt", "Felt"));
  writeMaterial(xdg / "octaclay" / "materials" / "felt", withId("felt", "XDG felt"));
  qputenv("OCTACLAY_MATERIAL_PATH", QByteArray::fromStdString(mine.string()));
  qputenv("XDG_DATA_HOME", QByteArray::fromStdString(xdg.string()));

  MaterialCatalog catalog;
  catalog.scan(MaterialCatalog::defaultSearchPath(kResources / "materials"));
  qputenv("OCTACLAY_MATERIAL_PATH", savedPath);
  qputenv("XDG_DATA_HOME", savedXdg);

  QVERIFY(catalog.errors().empty());
  QCOMPARE(catalog.materials().size(), std::size_t(6));
  QCOMPARE(catalog.find("mirror")->name, std::string("My mirror"));
  QCOMPARE(catalog.find("felt")->name, std::string("XDG felt")); // the user folder comes last
  QCOMPARE(catalog.find("brick")->folder, kResources / "materials" / "brick");
}

void MaterialCatalogTest::generatorIsDeterministic() {
  const fs::path a = root() / "generated-a", b = root() / "generated-b";
  tools::writeResources(a);
  tools::writeResources(b);
  const auto files = filesUnder(a);
  QCOMPARE(files, filesUnder(b));
  QCOMPARE(files.size(), std::size_t(5 * 5 + 1));
  for (const fs::path& file : files)
    QVERIFY2(readFile(a / file) == readFile(b / file), file.c_str());

  // What it writes is a catalog that loads.
  MaterialCatalog catalog;
  catalog.scan({a / "materials"});
  QVERIFY(catalog.errors().empty());
  QCOMPARE(catalog.materials().size(), std::size_t(5));

  for (const auto& [id, size] : {std::pair{"granite", 256}, std::pair{"brick", 100}}) {
    bool threw = false;
    try {
      tools::generateMaterial(id, size);
    } catch (const std::invalid_argument&) {
      threw = true;
    }
    QVERIFY2(threw, id);
  }
  // Other sizes keep the pattern periodic.
  const tools::MaterialMaps small = tools::generateMaterial("stone", 64);
  verifyTiles(small.height, "stone at 64² height");
}

void MaterialCatalogTest::committedResourcesMatchGenerator() {
  // The manifests are text and compare exactly. The maps compare decoded, within one 8-bit step:
  // a different libm may round sin, pow or sqrt differently in the last bit, which can move a
  // value across a rounding boundary but never further.
  const fs::path fresh = root() / "generated-fresh";
  tools::writeResources(fresh);
  const auto files = filesUnder(fresh);
  for (const fs::path& file : files) {
    const fs::path committed = kResources / file;
    QVERIFY2(
        fs::exists(committed),
        (committed.string() + " is missing: run make_resources (resources/README.md)").c_str());
    if (file.extension() == ".json") {
      QVERIFY2(readFile(committed) == readFile(fresh / file), committed.c_str());
      continue;
    }
    const core::RasterImage want = core::readImage(fresh / file, 4);
    const core::RasterImage have = core::readImage(committed, 4);
    QCOMPARE(have.width, want.width);
    QCOMPARE(have.height, want.height);
    float worst = 0.0f;
    for (std::size_t k = 0; k < want.pixels.size(); ++k)
      worst = std::max(worst, std::abs(want.pixels[k] - have.pixels[k]));
    QVERIFY2(worst <= kQuantum * 1.01f,
             (committed.string() + " differs from the generator by " +
              std::to_string(worst * 255.0f) + " steps: run make_resources (resources/README.md)")
                 .c_str());
  }
}

QTEST_APPLESS_MAIN(MaterialCatalogTest)
#include "material_catalog_test.moc"
