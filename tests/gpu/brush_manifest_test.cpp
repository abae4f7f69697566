// Brush manifests and the brush catalog, without GL: every bad manifest is refused with a message
// that starts with the file path and names the field; the template brush parses; the catalog
// keeps going past a bad brush, lets a later folder override an id, notices edited files and
// keeps the old manifest when a reload fails, and notices brush folders appearing and vanishing.

#include "octaclay/gpu/brush_catalog.h"
#include "octaclay/gpu/brush_manifest.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

#include <chrono>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>

using namespace octaclay;
using namespace octaclay::gpu;
namespace fs = std::filesystem;

namespace {

const char* const kGoodManifest = R"({
  "id": "raise",
  "name": "Raise",
  "api": 1,
  "shader": "brush.glsl",
  "writes": ["positions"],
  "area": "volume+normal",
  "parameters": [{"id": "height", "type": "float", "default": 0.5}]
})";

void writeFile(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out << text;
  QVERIFY2(out.good(), file.c_str());
}

// Writes <folder>/manifest.json and, when withShader, <folder>/brush.glsl.
fs::path writeBrush(const fs::path& folder, const std::string& manifest, bool withShader = true) {
  const fs::path file = folder / "manifest.json";
  writeFile(file, manifest);
  if (withShader)
    writeFile(folder / "brush.glsl", "vec4 brush(vec4 v, BrushInput b) { return v; }\n");
  return file;
}

std::string manifestWithName(const std::string& id, const std::string& name) {
  return R"({"id": ")" + id + R"(", "name": ")" + name +
         R"(", "api": 1, "shader": "brush.glsl", "writes": ["diffuse"], "area": "uv"})";
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

// kGoodManifest with its parameters replaced.
std::string withParameters(const char* parametersJson) {
  return patched({{"parameters", QJsonDocument::fromJson(parametersJson).array()}});
}

// The message parseBrushManifest throws, or "parsed" when it does not.
std::string errorOf(const fs::path& manifestFile) {
  try {
    parseBrushManifest(manifestFile);
    return "parsed";
  } catch (const BrushLoadError& e) {
    return e.what();
  }
}

} // namespace

class BrushManifestTest : public QObject {
  Q_OBJECT

private slots:
  void goodManifestParses();
  void templateBrushParses();
  void strokeKindsAndStrokeStartParse();
  void builtInBrushesParse();
  void builtInBrushesDeclareWhatTheyRead();
  void readmeMatchesThePreludeAndTheSchema();
  void badManifestIsRefused_data();
  void badManifestIsRefused();
  void missingFileIsRefused();
  void syntaxErrorGivesBytePosition();
  void duplicateKeyIsRefused();
  void missingShaderNamesFolder();
  void iconMustBeAnSvgOrPngInsideTheFolder();
  void newerApiWinsOverUnknownFields();

  void defaultSearchPathOrder();
  void scanLoadsGoodAndReportsBad();
  void passContractIsCheckedWhenTheCatalogLoads();
  void pluginPathOverridesBuiltIn();
  void shaderSourceReadsFile();
  void changedBrushesReportsEditedShader();
  void reloadKeepsOldManifestOnError();
  void reloadRefusesChangedId();
  void brushFoldersChangedSeesFoldersComeAndGo();

private:
  QTemporaryDir dir_;
  fs::path root() const { return fs::path(dir_.path().toStdString()); }
};

void BrushManifestTest::goodManifestParses() {
  const fs::path file = writeBrush(root() / "good", R"({
    "x-comment": "notes are allowed",
    "id": "paint-blob-2",
    "name": "Paint blob",
    "version": "2.1",
    "description": "Paints.",
    "api": 1,
    "category": "paint",
    "shader": "brush.glsl",
    "reads": ["positions", "mask"],
    "writes": ["diffuse", "feature"],
    "mix": ["feature"],
    "needs": ["normal"],
    "area": "uv",
    "falloff": "curve",
    "falloffCurve": [1, 0.5, 0],
    "spacing": 0.3,
    "parameters": [
      {"id": "count", "type": "int", "min": 1, "max": 9, "default": 3, "label": "Size"},
      {"id": "soft", "type": "bool", "default": true, "tooltip": "Soft edge"},
      {"id": "tint", "type": "color", "default": [1, 0.5, 0.25, 1]},
      {"id": "blend-mode", "type": "enum", "options": ["mix", "add", "multiply"], "default": "add"},
      {"id": "amount", "type": "float", "min": -2, "max": 2, "step": 0.5}
    ]
  })");
  BrushManifest m;
  try {
    m = parseBrushManifest(file);
  } catch (const BrushLoadError& e) {
    QFAIL(e.what());
  }
  QCOMPARE(m.id, std::string("paint-blob-2"));
  QCOMPARE(m.name, std::string("Paint blob"));
  QCOMPARE(m.version, std::string("2.1"));
  QCOMPARE(m.api, 1);
  QCOMPARE(m.category, Category::Paint);
  QCOMPARE(m.shaderFile, std::string("brush.glsl"));
  QCOMPARE(m.folder, root() / "good");
  QCOMPARE(m.shaderPath(), root() / "good" / "brush.glsl");
  QVERIFY((m.reads == std::vector{core::EditLayer::Positions, core::EditLayer::Mask}));
  QVERIFY((m.writes == std::vector{core::EditLayer::Diffuse, core::EditLayer::Feature}));
  QVERIFY((m.mix == std::vector{core::EditLayer::Feature}));
  QVERIFY((m.needs == std::vector{BrushNeed::Normal}));
  QVERIFY(m.needsNormal());
  QVERIFY(m.readsLayer(core::EditLayer::Mask));
  QVERIFY(!m.readsLayer(core::EditLayer::Diffuse));
  QCOMPARE(m.area, AreaMode::Uv);
  QCOMPARE(m.falloff, Falloff::Curve);
  QVERIFY((m.falloffCurve == std::vector{1.0f, 0.5f, 0.0f}));
  QCOMPARE(m.spacing, 0.3f);
  QCOMPARE(m.parameters.size(), std::size_t(5));

  const BrushParameter* count = m.parameter("count");
  QVERIFY(count);
  QCOMPARE(count->type, ParameterType::Int);
  QCOMPARE(count->label, std::string("Size"));
  QCOMPARE(count->defaultValue[0], 3.0f);
  QCOMPARE(count->min, 1.0f);
  QCOMPARE(count->max, 9.0f);
  QCOMPARE(count->step, 1.0f);

  const BrushParameter* soft = m.parameter("soft");
  QCOMPARE(soft->defaultValue[0], 1.0f);
  QCOMPARE(soft->label, std::string("soft"));
  QCOMPARE(soft->tooltip, std::string("Soft edge"));

  QVERIFY((m.parameter("tint")->defaultValue == std::array{1.0f, 0.5f, 0.25f, 1.0f}));

  const BrushParameter* blend = m.parameter("blend-mode");
  QCOMPARE(blend->type, ParameterType::Enum);
  QCOMPARE(blend->defaultValue[0], 1.0f);
  QCOMPARE(blend->max, 2.0f);
  QVERIFY((blend->options == std::vector<std::string>{"mix", "add", "multiply"}));

  const BrushParameter* amount = m.parameter("amount");
  QCOMPARE(amount->defaultValue[0], 0.0f); // 0 lies in [-2, 2]
  QCOMPARE(amount->step, 0.5f);

  QVERIFY(!m.parameter("missing"));
}

// API 3: "stroke" and "needs": ["stroke_start"]; an anchored stroke captures the stroke start
// without asking, and older manifests make spaced strokes.
void BrushManifestTest::strokeKindsAndStrokeStartParse() {
  const auto parse = [&](const char* name, const std::string& extra) {
    return parseBrushManifest(writeBrush(root() / name, R"({"id": "x", "name": "X", "api": 3,
      "shader": "brush.glsl", "writes": ["positions"], "area": "volume")" +
                                                            extra + "}"));
  };
  try {
    const BrushManifest anchored = parse("anchored", R"(, "stroke": "anchored")");
    QCOMPARE(anchored.stroke, StrokeKind::Anchored);
    QVERIFY(anchored.needsStrokeStart());
    const BrushManifest layer =
        parse("layer", R"(, "stroke": "target", "needs": ["stroke_start", "normal"])");
    QCOMPARE(layer.stroke, StrokeKind::Target);
    QVERIFY((layer.needs == std::vector{BrushNeed::StrokeStart, BrushNeed::Normal}));
    QVERIFY(layer.needsStrokeStart());
    const BrushManifest drag = parse("drag", R"(, "stroke": "drag")");
    QCOMPARE(drag.stroke, StrokeKind::Drag);
    QVERIFY(!drag.needsStrokeStart());
    const BrushManifest plain = parse("plain", "");
    QCOMPARE(plain.stroke, StrokeKind::Spaced);
    QVERIFY(!plain.needsStrokeStart());
  } catch (const BrushLoadError& e) {
    QFAIL(e.what());
  }
}

void BrushManifestTest::templateBrushParses() {
  const fs::path file =
      fs::path(OCTACLAY_SOURCE_DIR) / "plugins" / "examples" / "template-brush" / "manifest.json";
  BrushManifest m;
  try {
    m = parseBrushManifest(file);
  } catch (const BrushLoadError& e) {
    QFAIL(e.what());
  }
  QCOMPARE(m.id, std::string("template-brush"));
  QCOMPARE(m.api, 1); // the template needs nothing of API 2
  QVERIFY((m.writes == std::vector{core::EditLayer::Positions}));
  QCOMPARE(m.area, AreaMode::VolumeNormal);
  const BrushParameter* height = m.parameter("height");
  QVERIFY(height);
  QCOMPARE(height->type, ParameterType::Float);
  QCOMPARE(m.parameters.size(), std::size_t(1));
  QVERIFY(BrushCatalog::shaderSource(m).find("vec4 brush(vec4 value, BrushInput b)") !=
          std::string::npos);
}

void BrushManifestTest::builtInBrushesParse() {
  BrushCatalog catalog;
  catalog.scan({fs::path(OCTACLAY_SOURCE_DIR) / "plugins" / "brushes"});
  for (const BrushCatalogError& e : catalog.errors())
    qWarning("%s", e.message.c_str());
  QVERIFY(catalog.errors().empty());
  QVERIFY(!catalog.brushes().empty());
  QVERIFY(catalog.notes().empty()); // built-in ids are unique
}

// The engine binds and computes what a manifest declares: each built-in brush declares in
// "reads" exactly the layers its shader samples (through the prelude's helpers or a layer's
// sampler) and needs "normal" exactly where it reads b.normal.
void BrushManifestTest::builtInBrushesDeclareWhatTheyRead() {
  BrushCatalog catalog;
  catalog.scan({fs::path(OCTACLAY_SOURCE_DIR) / "plugins" / "brushes"});
  QVERIFY(!catalog.brushes().empty());
  const auto mentions = [](const std::string& code, const char* pattern) {
    return std::regex_search(code, std::regex(pattern));
  };
  for (const BrushManifest& m : catalog.brushes()) {
    // The body without its comments.
    const std::string code = std::regex_replace(BrushCatalog::shaderSource(m),
                                                std::regex(R"(//[^\n]*|/\*[\s\S]*?\*/)"), "");
    const auto readsThrough = [&](core::EditLayer layer) {
      switch (layer) {
      case core::EditLayer::Positions:
        return mentions(code, R"(\b(fetchPositions|normalAt|u_positions)\b)");
      case core::EditLayer::Diffuse:
        return mentions(code, R"(\bu_diffuseLayer\b)");
      case core::EditLayer::Feature:
        return mentions(code, R"(\bu_featureLayer\b)");
      case core::EditLayer::Mask:
        return mentions(code, R"(\b(maskAt|u_mask)\b)");
      }
      return false;
    };
    for (core::EditLayer layer : {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                  core::EditLayer::Feature, core::EditLayer::Mask})
      QVERIFY2(m.readsLayer(layer) == readsThrough(layer),
               (m.id + ": \"reads\" and " + std::string(toManifestName(layer))).c_str());
    // Another texel of the written layer (fetchLayer, u_layer): none of the built-ins.
    QVERIFY2(!mentions(code, R"(\b(fetchLayer|u_layer)\b)"), m.id.c_str());
    // The stroke-start positions exactly where the manifest asks for them.
    QVERIFY2(
        mentions(code, R"(\b(strokeStartAt|strokeStartNormalAt|u_strokeStart)\b)") ==
            (std::find(m.needs.begin(), m.needs.end(), BrushNeed::StrokeStart) != m.needs.end()),
        (m.id + ": \"needs\": [\"stroke_start\"]").c_str());
    const bool usesNormal = mentions(code, R"(\bb\.normal\b)");
    QVERIFY2(usesNormal ==
                 (std::find(m.needs.begin(), m.needs.end(), BrushNeed::Normal) != m.needs.end()),
             (m.id + ": \"needs\": [\"normal\"]").c_str());
  }
}

// plugins/examples/README.md cannot drift from the code: its uniform table lists exactly the
// uniforms the prelude declares (name and type), its parameter-type table exactly the types the
// manifest parser accepts.
void BrushManifestTest::readmeMatchesThePreludeAndTheSchema() {
  const fs::path source(OCTACLAY_SOURCE_DIR);
  const auto lines = [](const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> out;
    for (std::string line; std::getline(in, line);)
      out.push_back(line);
    return out;
  };
  const std::vector<std::string> readme = lines(source / "plugins" / "examples" / "README.md");
  QVERIFY(!readme.empty());

  std::set<std::string> declared, documented; // "type name[size]"
  // A dab's own values are uniforms declared through OCTACLAY_DAB_VALUE (a batch of dabs sets
  // them per rectangle instead).
  const std::regex declaration(
      R"(^\s*(?:uniform|OCTACLAY_DAB_VALUE)\s+(\w+)\s+(\w+(\[\d+\])?)\s*;)");
  for (const std::string& line : lines(source / "gpu" / "shaders" / "prelude.glsl")) {
    std::smatch m;
    if (std::regex_search(line, m, declaration)) declared.insert(m[1].str() + " " + m[2].str());
  }
  QVERIFY(declared.size() > 20);
  const std::regex uniformRow(R"(^\|\s*`(u_\w+(\[\d+\])?)`\s*\|\s*`(\w+)`\s*\|)");
  for (const std::string& line : readme) {
    std::smatch m;
    if (std::regex_search(line, m, uniformRow)) documented.insert(m[3].str() + " " + m[1].str());
  }
  for (const std::string& d : declared)
    QVERIFY2(documented.count(d), ("README lacks the prelude's uniform " + d).c_str());
  for (const std::string& d : documented)
    QVERIFY2(declared.count(d), ("README documents a uniform the prelude lacks: " + d).c_str());

  std::set<std::string> accepted, tabled;
  for (int k = 0; k <= static_cast<int>(ParameterType::Material); ++k)
    accepted.insert(std::string(toManifestName(static_cast<ParameterType>(k))));
  const auto header = std::find_if(readme.begin(), readme.end(), [](const std::string& line) {
    return line.rfind("| type | uniform |", 0) == 0;
  });
  QVERIFY2(header != readme.end(), "README has no | type | uniform | table");
  for (auto row = header + 2; row != readme.end() && row->rfind("|", 0) == 0; ++row) {
    std::istringstream cell(row->substr(1, row->find('|', 1) - 1));
    for (std::string type; std::getline(cell, type, ',');) {
      type.erase(0, type.find_first_not_of(' '));
      type.erase(type.find_last_not_of(' ') + 1);
      tabled.insert(type);
    }
  }
  QVERIFY2(tabled == accepted, "README's parameter types differ from the manifest schema's");
}

void BrushManifestTest::badManifestIsRefused_data() {
  QTest::addColumn<QString>("manifest");
  QTest::addColumn<QString>("expected"); // the message after "<path>: "

  const auto row = [](const char* name, const std::string& manifest, const char* expected) {
    QTest::newRow(name) << QString::fromStdString(manifest) << QString(expected);
  };
  const auto missing = [&](const char* field) {
    row((std::string("missing ") + field).c_str(), patched({{field, QJsonValue::Null}}),
        (std::string(field) + ": missing required field").c_str());
  };
  for (const char* field : {"id", "name", "api", "shader", "writes", "area"})
    missing(field);

  row("not an object", "[1, 2]", "expected a JSON object { ... }, got an array");
  row("name not a string", patched({{"name", 3}}), "name: expected a string, got 3");
  row("api a string", patched({{"api", "1"}}), R"(api: expected an integer, got "1")");
  row("api fractional", patched({{"api", 1.5}}), "api: expected an integer, got 1.5");
  row("api zero", patched({{"api", 0}}), "api: must be 1 or more, got 0");
  row("api newer", patched({{"api", 5}}), "api: needs Octaclay brush API 5, this Octaclay has 4");
  row("writes a string", patched({{"writes", "positions"}}),
      R"(writes: expected an array of layers, got "positions" (use ["positions"]))");
  row("spacing a string", patched({{"spacing", "wide"}}),
      R"(spacing: expected a number, got "wide")");
  row("spacing zero", patched({{"spacing", 0}}),
      "spacing: 0 is outside (0, 10] (a fraction of the radius)");
  row("bad id", patched({{"id", "Big Raise"}}),
      R"(id: "Big Raise" is not a valid brush id (use lowercase letters, digits and -))");
  row("empty name", patched({{"name", ""}}), "name: must not be empty");
  row("unknown read layer", patched({{"reads", QJsonArray{"positions", "normals"}}}),
      R"(reads[1]: unknown layer "normals" (use positions, diffuse, feature or mask))");
  row("unknown write layer", patched({{"writes", QJsonArray{"colour"}}}),
      R"(writes[0]: unknown layer "colour" (use positions, diffuse, feature or mask))");
  row("layer twice", patched({{"writes", QJsonArray{"mask", "mask"}}}),
      R"(writes[1]: "mask" is listed twice)");
  row("mix positions",
      patched({{"writes", QJsonArray{"positions", "diffuse"}}, {"mix", QJsonArray{"positions"}}}),
      R"(mix[0]: "positions" cannot be mixed (only "diffuse" and "feature" can))");
  row("mix a layer not written",
      patched({{"writes", QJsonArray{"diffuse"}}, {"mix", QJsonArray{"diffuse", "feature"}}}),
      R"(mix[1]: "feature" is not in "writes")");
  row("mix a string", patched({{"mix", "diffuse"}}),
      R"(mix: expected an array of layers, got "diffuse" (use ["diffuse"]))");
  row("unknown need", patched({{"needs", QJsonArray{"normals"}}}),
      R"(needs[0]: unknown need "normals" (use normal or stroke_start))");
  row("stroke_start with api 2", patched({{"api", 2}, {"needs", QJsonArray{"stroke_start"}}}),
      R"(needs[0]: "stroke_start" needs "api": 3 (it came with brush API 3), the manifest says 2)");
  row("stroke with api 2", patched({{"api", 2}, {"stroke", "anchored"}}),
      R"(stroke: needs "api": 3 (stroke kinds came with brush API 3), the manifest says 2)");
  row("unknown stroke", patched({{"api", 3}, {"stroke", "hook"}}),
      R"(stroke: unknown stroke kind "hook" (use spaced, target, drag or anchored))");
  row("stroke a number", patched({{"api", 3}, {"stroke", 1}}), "stroke: expected a string, got 1");
  row("needs a string", patched({{"needs", "normal"}}),
      R"(needs: expected an array, got "normal" (use ["normal"]))");
  row("need twice", patched({{"needs", QJsonArray{"normal", "normal"}}}),
      R"(needs[1]: "normal" is listed twice)");
  const QJsonArray all{"positions", "diffuse", "feature", "mask"};
  row("pass with api 1", patched({{"pass", "reparameterize"}, {"writes", all}}),
      R"(pass: needs "api": 2 (pass kinds came with brush API 2), the manifest says 1)");
  row("unknown pass", patched({{"api", 2}, {"pass", "warp"}}),
      R"(pass: unknown pass "warp" (use layers, reparameterize or all-layers))");
  row("all-layers with api 3", patched({{"api", 3}, {"pass", "all-layers"}}),
      R"(pass: "all-layers" needs "api": 4 (it came with brush API 4), the manifest says 3)");
  row("all-layers writing the mask",
      patched({{"api", 4}, {"pass", "all-layers"}, {"writes", QJsonArray{"positions", "mask"}}}),
      R"(writes: an "all-layers" pass (brushLayers()) writes positions, diffuse and feature; )"
      R"(a brush that writes the mask uses "pass": "layers" (brush()))");
  row("mix without all-layers at api 4",
      patched({{"api", 4}, {"writes", QJsonArray{"diffuse"}}, {"mix", QJsonArray{"diffuse"}}}),
      R"(mix: needs "pass": "all-layers" (a brushLayers() body hands the colour back))");
  row("reparameterize writing positions only",
      patched({{"api", 2}, {"pass", "reparameterize"}, {"writes", QJsonArray{"positions"}}}),
      R"(writes: a "reparameterize" pass resamples every layer, so it writes all four: )"
      R"(["positions", "diffuse", "feature", "mask"] ("diffuse" is missing))");
  row("reparameterize mixing",
      patched({{"api", 2},
               {"pass", "reparameterize"},
               {"writes", all},
               {"mix", QJsonArray{"diffuse"}}}),
      R"(mix: a "reparameterize" pass resamples its layers and mixes none)");
  row("iterations without reparameterize", patched({{"api", 2}, {"iterations", 4}}),
      R"(iterations: only used when "pass" is "reparameterize")");
  row("iterations zero",
      patched({{"api", 2}, {"pass", "reparameterize"}, {"writes", all}, {"iterations", 0}}),
      "iterations: 0 is outside [1, 64]");
  row("iterations fractional",
      patched({{"api", 2}, {"pass", "reparameterize"}, {"writes", all}, {"iterations", 2.5}}),
      "iterations: expected an integer, got 2.5");
  row("empty writes", patched({{"writes", QJsonArray{}}}),
      "writes: a brush must write at least one layer");
  row("unknown area", patched({{"area", "surface"}}),
      R"(area: unknown area "surface" (use uv, volume or volume+normal))");
  row("unknown falloff", patched({{"falloff", "gauss"}}),
      R"(falloff: unknown falloff "gauss" (use linear, smooth, constant or curve))");
  row("curve value above 1",
      patched({{"falloff", "curve"}, {"falloffCurve", QJsonArray{1, 1.5, 0}}}),
      "falloffCurve[1]: 1.5 is outside [0, 1]");
  row("curve value below 0",
      patched({{"falloff", "curve"}, {"falloffCurve", QJsonArray{1, -0.25}}}),
      "falloffCurve[1]: -0.25 is outside [0, 1]");
  row("curve too short", patched({{"falloff", "curve"}, {"falloffCurve", QJsonArray{1}}}),
      "falloffCurve: needs 2 to 64 values, got 1");
  row("curve missing", patched({{"falloff", "curve"}}),
      R"(falloffCurve: missing required field ("falloff" is "curve"))");
  row("curve without curve falloff", patched({{"falloffCurve", QJsonArray{1, 0}}}),
      R"(falloffCurve: only used when "falloff" is "curve")");
  row("unknown category", patched({{"category", "sculpting"}}),
      R"(category: unknown category "sculpting" (use sculpt, paint or splat))");
  row("typo in field", patched({{"shadr", "brush.glsl"}}),
      R"(shadr: unknown field (did you mean "shader"?))");
  row("unknown field", patched({{"author", "me"}}),
      "author: unknown field (prefix your own fields with x-)");
  row("shader path", patched({{"shader", "../other/brush.glsl"}}),
      R"(shader: "../other/brush.glsl" must be a file name beside the manifest)");
  row("icon leaving the folder", patched({{"icon", "../push/icon.svg"}}),
      R"(icon: "../push/icon.svg" must be a path inside the brush folder (no .. or leading /))");
  row("icon absolute", patched({{"icon", "/usr/share/icons/a.png"}}),
      R"(icon: "/usr/share/icons/a.png" must be a path inside the brush folder (no .. or leading /))");
  row("icon empty", patched({{"icon", ""}}),
      R"(icon: "" must be a path inside the brush folder (no .. or leading /))");
  row("icon not an image", patched({{"icon", "brush.glsl"}}),
      R"(icon: "brush.glsl" must be an .svg or .png file)");
  row("icon not a string", patched({{"icon", 3}}), "icon: expected a string, got 3");

  row("parameters not an array", patched({{"parameters", QJsonObject{}}}),
      "parameters: expected an array, got an object");
  row("parameter not an object", withParameters("[3]"), "parameters[0]: expected an object, got 3");
  row("parameter missing id", withParameters(R"([{"type": "float"}])"),
      "parameters[0].id: missing required field");
  row("parameter bad id", withParameters(R"([{"id": "Height", "type": "float"}])"),
      R"(parameters[0].id: "Height" is not a valid parameter id (use lowercase letters and digits, words joined by single -))");
  row("parameter id with --", withParameters(R"([{"id": "a--b", "type": "float"}])"),
      R"(parameters[0].id: "a--b" is not a valid parameter id (use lowercase letters and digits, words joined by single -))");
  row("parameter id reserved", withParameters(R"([{"id": "radius", "type": "float"}])"),
      R"(parameters[0].id: "radius" is taken by the host's uniform u_radius)");
  row("parameter id reserved by the prelude",
      withParameters(R"([{"id": "mask", "type": "float"}])"),
      R"(parameters[0].id: "mask" is taken by the host's uniform u_mask)");
  row("duplicate parameter id",
      withParameters(R"([{"id": "height", "type": "float"}, {"id": "height", "type": "int"}])"),
      R"(parameters[1].id: "height" is already used by parameters[0])");
  row("parameter missing type", withParameters(R"([{"id": "height"}])"),
      "parameters[0].type: missing required field");
  row("unknown parameter type",
      withParameters(R"([{"id": "a", "type": "float"}, {"id": "b", "type": "int"},
                         {"id": "c", "type": "vector"}])"),
      R"(parameters[2].type: unknown type "vector" (use float, int, bool, color, enum or material))");
  row("unknown parameter field",
      withParameters(R"([{"id": "height", "type": "float", "defualt": 1}])"),
      R"(parameters[0].defualt: unknown field (did you mean "default"?))");
  row("min greater than max",
      withParameters(R"([{"id": "height", "type": "float", "min": 2, "max": 1}])"),
      "parameters[0].min: min 2 is greater than max 1");
  row("default above max",
      withParameters(R"([{"id": "height", "type": "float", "max": 1, "default": 5}])"),
      "parameters[0].default: 5 is outside [0, 1]");
  row("default below min",
      withParameters(R"([{"id": "n", "type": "int", "min": 1, "max": 4, "default": 0}])"),
      "parameters[0].default: 0 is outside [1, 4]");
  row("int default fractional", withParameters(R"([{"id": "n", "type": "int", "default": 2.5}])"),
      "parameters[0].default: expected an integer, got 2.5");
  row("zero step", withParameters(R"([{"id": "height", "type": "float", "step": 0}])"),
      "parameters[0].step: must be greater than 0, got 0");
  row("step a float rounds to 0",
      withParameters(R"([{"id": "height", "type": "float", "step": 1e-300}])"),
      "parameters[0].step: 1e-300 is too small for a float (it would be 0)");
  row("max beyond a float", withParameters(R"([{"id": "height", "type": "float", "max": 1e39}])"),
      "parameters[0].max: 1e+39 is too large for a float");
  row("bool default a number", withParameters(R"([{"id": "on", "type": "bool", "default": 1}])"),
      "parameters[0].default: expected true or false, got 1");
  row("bool with min", withParameters(R"([{"id": "on", "type": "bool", "min": 0}])"),
      "parameters[0].min: not used by a bool parameter (only float and int)");
  row("float with options", withParameters(R"([{"id": "h", "type": "float", "options": []}])"),
      "parameters[0].options: not used by a float parameter (only enum)");
  row("enum default not an option",
      withParameters(R"([{"id": "mode", "type": "enum", "options": ["a", "b"], "default": "c"}])"),
      R"(parameters[0].default: "c" is not one of the options ("a", "b"))");
  row("enum without options", withParameters(R"([{"id": "mode", "type": "enum"}])"),
      "parameters[0].options: missing required field");
  row("enum empty options", withParameters(R"([{"id": "mode", "type": "enum", "options": []}])"),
      "parameters[0].options: expected a non-empty array of strings, got an array");
  row("enum option twice",
      withParameters(R"([{"id": "mode", "type": "enum", "options": ["a", "a"]}])"),
      R"(parameters[0].options[1]: "a" is listed twice)");
  row("color default three numbers",
      withParameters(R"([{"id": "tint", "type": "color", "default": [1, 0, 0]}])"),
      "parameters[0].default: expected 4 numbers in [0, 1] (red, green, blue, alpha), got "
      "[1,0,0]");
  row("color default out of range",
      withParameters(R"([{"id": "tint", "type": "color", "default": [1, 0, 0, 2]}])"),
      "parameters[0].default: expected 4 numbers in [0, 1] (red, green, blue, alpha), got "
      "[1,0,0,2]");
  row("color default a string",
      withParameters(R"([{"id": "tint", "type": "color", "default": "red"}])"),
      R"(parameters[0].default: expected 4 numbers in [0, 1] (red, green, blue, alpha), got "red")");
}

void BrushManifestTest::badManifestIsRefused() {
  QFETCH(QString, manifest);
  QFETCH(QString, expected);
  const fs::path folder = root() / "bad" / QTest::currentDataTag();
  const fs::path file = writeBrush(folder, manifest.toStdString());
  QCOMPARE(QString::fromStdString(errorOf(file)),
           QString::fromStdString(file.string()) + ": " + expected);
}

void BrushManifestTest::missingFileIsRefused() {
  const fs::path file = root() / "nowhere" / "manifest.json";
  QCOMPARE(errorOf(file), file.string() + ": file not found");
  const fs::path folder = root() / "folder-as-file" / "manifest.json";
  fs::create_directories(folder);
  QCOMPARE(errorOf(folder), folder.string() + ": is a folder, not a manifest file");
}

void BrushManifestTest::syntaxErrorGivesBytePosition() {
  const fs::path file = writeBrush(root() / "syntax", "{\n  \"id\": \"a\",\n}\n");
  QCOMPARE(errorOf(file), file.string() +
                              ": invalid JSON at byte 16, line 3, column 1: syntax error while "
                              "parsing object key - unexpected '}'; expected string literal");
  const fs::path empty = writeBrush(root() / "empty", "");
  QCOMPARE(errorOf(empty), empty.string() +
                               ": invalid JSON at byte 1, line 1, column 1: syntax error while "
                               "parsing value - unexpected end of input; expected '[', '{', or "
                               "a literal");
  // Found by manifest_fuzzer: a number beyond every JSON number type escaped as out_of_range.
  const fs::path huge =
      writeBrush(root() / "huge-number", "{\"max\": 4" + std::string(400, '4') + "}");
  QCOMPARE(errorOf(huge), huge.string() + ": invalid JSON: a number is too large to read");
}

void BrushManifestTest::duplicateKeyIsRefused() {
  const fs::path file = writeBrush(root() / "dup-top", R"({"id": "a", "name": "A", "name": "B"})");
  QCOMPARE(errorOf(file), file.string() + ": name: appears twice in the same object (remove one)");
  const fs::path nested =
      writeBrush(root() / "dup-nested",
                 R"({"parameters": [{"id": "a"}, {"id": "b", "min": 0, "min": 1}], "id": "x"})");
  QCOMPARE(errorOf(nested),
           nested.string() + ": parameters[1].min: appears twice in the same object (remove one)");
}

void BrushManifestTest::missingShaderNamesFolder() {
  const fs::path folder = root() / "no-shader";
  const fs::path file = writeBrush(folder, kGoodManifest, false);
  QCOMPARE(errorOf(file), file.string() + ": shader: brush.glsl not found in " + folder.string());
}

void BrushManifestTest::iconMustBeAnSvgOrPngInsideTheFolder() {
  const fs::path folder = root() / "with-icon";
  const fs::path file = writeBrush(folder, patched({{"icon", "art/raise.SVG"}}));
  QCOMPARE(errorOf(file), file.string() + ": icon: art/raise.SVG not found in " + folder.string());
  writeFile(folder / "art" / "raise.SVG", "<svg xmlns='http://www.w3.org/2000/svg'/>");
  QCOMPARE(errorOf(file), std::string("parsed"));
  const BrushManifest m = parseBrushManifest(file);
  QCOMPARE(m.iconFile, std::string("art/raise.SVG"));
  QCOMPARE(m.iconPath(), folder / "art" / "raise.SVG");
  QVERIFY(parseBrushManifest(writeBrush(root() / "no-icon", kGoodManifest)).iconPath().empty());

  // A folder named like an icon, and a link that leads out of the brush folder.
  fs::create_directories(folder / "dir.png");
  writeFile(file, patched({{"icon", "dir.png"}}));
  QCOMPARE(errorOf(file),
           file.string() + ": icon: dir.png in " + folder.string() + " is not a regular file");
  writeFile(root() / "outside.png", "png");
  fs::create_symlink(root() / "outside.png", folder / "linked.png");
  writeFile(file, patched({{"icon", "linked.png"}}));
  QCOMPARE(errorOf(file), file.string() + ": icon: linked.png leads out of " + folder.string() +
                              " (through a link)");
}

void BrushManifestTest::newerApiWinsOverUnknownFields() {
  // A manifest for a newer Octaclay may use fields this one does not know: say what matters.
  const fs::path file = writeBrush(root() / "future", patched({{"api", 5}, {"stencil", true}}));
  QCOMPARE(errorOf(file), file.string() + ": api: needs Octaclay brush API 5, this Octaclay has 4");
}

void BrushManifestTest::defaultSearchPathOrder() {
  qputenv("OCTACLAY_PLUGIN_PATH", "/a/one::/b/two:");
  qputenv("XDG_DATA_HOME", "/data");
  QVERIFY((BrushCatalog::defaultSearchPath("/built-in") ==
           std::vector<fs::path>{"/built-in", "/a/one", "/b/two", "/data/octaclay/brushes"}));
  // A relative XDG_DATA_HOME is ignored (XDG Base Directory spec).
  qputenv("OCTACLAY_PLUGIN_PATH", "");
  qputenv("XDG_DATA_HOME", "relative");
  qputenv("HOME", "/home/me");
  QVERIFY((BrushCatalog::defaultSearchPath("/built-in") ==
           std::vector<fs::path>{"/built-in", "/home/me/.local/share/octaclay/brushes"}));
}

void BrushManifestTest::scanLoadsGoodAndReportsBad() {
  const fs::path folder = root() / "scan";
  writeBrush(folder / "b-good", manifestWithName("second", "Second"));
  writeBrush(folder / "a-good", manifestWithName("first", "First"));
  const fs::path bad = writeBrush(folder / "broken", R"({"id": "broken", "api": 1)");
  fs::create_directories(folder / "not-a-brush");
  writeFile(folder / "README.md", "not a brush\n");

  BrushCatalog catalog;
  catalog.scan({folder, root() / "does-not-exist"});
  QCOMPARE(catalog.brushes().size(), std::size_t(2));
  QCOMPARE(catalog.brushes()[0].id, std::string("first"));
  QCOMPARE(catalog.brushes()[1].id, std::string("second"));
  QCOMPARE(catalog.find("second")->name, std::string("Second"));
  QVERIFY(!catalog.find("broken"));
  QVERIFY(!catalog.find("zzz"));
  QCOMPARE(catalog.errors().size(), std::size_t(1));
  QCOMPARE(catalog.errors()[0].path, bad);
  QVERIFY2(catalog.errors()[0].message.starts_with(bad.string() + ": invalid JSON at byte"),
           catalog.errors()[0].message.c_str());
  QVERIFY(catalog.notes().empty());
}

// The pass a manifest declares and the body its shader defines agree, or the brush is listed as
// broken when the catalog loads it (not later, as a GL error): an API 4 "all-layers" brush
// defines brushLayers(), an API 4 "layers" brush does not; an API 1-3 brush whose body defines
// it is an all-layers brush, as it always was.
void BrushManifestTest::passContractIsCheckedWhenTheCatalogLoads() {
  const fs::path folder = root() / "contract";
  const std::string layersBody =
      "void brushLayers(inout vec4 positions, inout vec4 diffuse, inout vec4 feature, "
      "BrushInput b) {}\n";
  const auto manifest = [](const std::string& id, int api, const std::string& pass) {
    return R"({"id": ")" + id + R"(", "name": "N", "api": )" + std::to_string(api) +
           R"(, "shader": "brush.glsl", "writes": ["diffuse"], "area": "uv")" +
           (pass.empty() ? "" : R"(, "pass": ")" + pass + "\"") + "}";
  };
  const fs::path declaredOnly =
      writeBrush(folder / "declared", manifest("declared", 4, "all-layers"));
  const fs::path undeclared = writeBrush(folder / "undeclared", manifest("undeclared", 4, ""));
  writeFile(folder / "undeclared" / "brush.glsl", layersBody);
  writeBrush(folder / "old", manifest("old", 3, ""));
  writeFile(folder / "old" / "brush.glsl", layersBody);
  writeBrush(folder / "new", manifest("new", 4, "all-layers"));
  writeFile(folder / "new" / "brush.glsl", layersBody);

  BrushCatalog catalog;
  catalog.scan({folder});
  QVERIFY(!catalog.find("declared"));
  QVERIFY(!catalog.find("undeclared"));
  QVERIFY(catalog.find("old") && catalog.find("new"));
  QCOMPARE(catalog.find("old")->pass, PassKind::AllLayers);
  QCOMPARE(catalog.find("new")->pass, PassKind::AllLayers);
  QCOMPARE(catalog.errors().size(), std::size_t(2));
  const auto errorFor = [&](const fs::path& file) {
    for (const auto& e : catalog.errors())
      if (e.path == file) return e.message;
    return std::string("no error");
  };
  const std::string declaredError = errorFor(declaredOnly);
  QVERIFY2(declaredError.starts_with((folder / "declared" / "brush.glsl").string() +
                                     ": the manifest's \"pass\" is \"all-layers\""),
           declaredError.c_str());
  const std::string undeclaredError = errorFor(undeclared);
  QVERIFY2(undeclaredError.find("declare \"pass\": \"all-layers\"") != std::string::npos,
           undeclaredError.c_str());
}

void BrushManifestTest::pluginPathOverridesBuiltIn() {
  const fs::path builtIn = root() / "override" / "built-in";
  const fs::path mine = root() / "override" / "mine";
  writeBrush(builtIn / "raise", manifestWithName("raise", "Built-in raise"));
  writeBrush(builtIn / "smooth", manifestWithName("smooth", "Smooth"));
  writeBrush(mine / "my-raise", manifestWithName("raise", "My raise"));
  qputenv("OCTACLAY_PLUGIN_PATH", QByteArray::fromStdString(mine.string()));
  qputenv("XDG_DATA_HOME", QByteArray::fromStdString((root() / "override" / "xdg").string()));

  BrushCatalog catalog;
  catalog.scan(BrushCatalog::defaultSearchPath(builtIn));
  QVERIFY(catalog.errors().empty());
  QCOMPARE(catalog.brushes().size(), std::size_t(2));
  QCOMPARE(catalog.find("raise")->name, std::string("My raise"));
  QCOMPARE(catalog.find("raise")->folder, mine / "my-raise");
  QCOMPARE(catalog.find("smooth")->name, std::string("Smooth"));
  QCOMPARE(catalog.notes().size(), std::size_t(1));
  QCOMPARE(catalog.notes()[0], (mine / "my-raise" / "manifest.json").string() +
                                   ": brush \"raise\" overrides " +
                                   (builtIn / "raise" / "manifest.json").string());
}

void BrushManifestTest::shaderSourceReadsFile() {
  const fs::path folder = root() / "source";
  writeBrush(folder, manifestWithName("source", "Source"));
  BrushCatalog catalog;
  catalog.scan({root()}); // "source" is a sub-folder of root()
  const BrushManifest* brush = catalog.find("source");
  QVERIFY(brush);
  QCOMPARE(BrushCatalog::shaderSource(*brush),
           std::string("vec4 brush(vec4 v, BrushInput b) { return v; }\n"));
  BrushManifest gone = *brush;
  gone.shaderFile = "gone.glsl";
  try {
    BrushCatalog::shaderSource(gone);
    QFAIL("no exception");
  } catch (const BrushLoadError& e) {
    QCOMPARE(std::string(e.what()),
             (folder / "gone.glsl").string() + ": cannot be read (No such file or directory)");
  }
}

void BrushManifestTest::changedBrushesReportsEditedShader() {
  const fs::path folder = root() / "watch";
  writeBrush(folder / "one", manifestWithName("one", "One"));
  writeBrush(folder / "two", manifestWithName("two", "Two"));
  BrushCatalog catalog;
  catalog.scan({folder});
  QCOMPARE(catalog.brushes().size(), std::size_t(2));
  QVERIFY(catalog.changedBrushes().empty());

  // Move the time forward instead of sleeping past the file system's time resolution.
  const fs::path shader = folder / "two" / "brush.glsl";
  fs::last_write_time(shader, fs::last_write_time(shader) + std::chrono::seconds(5));
  QVERIFY((catalog.changedBrushes() == std::vector<std::string>{"two"}));
  QVERIFY(catalog.changedBrushes().empty()); // reported once

  // Same time, different size: still a change.
  const fs::path manifest = folder / "one" / "manifest.json";
  const auto time = fs::last_write_time(manifest);
  writeFile(manifest, manifestWithName("one", "One, renamed"));
  fs::last_write_time(manifest, time);
  QVERIFY((catalog.changedBrushes() == std::vector<std::string>{"one"}));

  fs::remove(shader);
  QVERIFY((catalog.changedBrushes() == std::vector<std::string>{"two"}));
}

void BrushManifestTest::reloadKeepsOldManifestOnError() {
  const fs::path folder = root() / "reload" / "brush";
  const fs::path manifest = writeBrush(folder, manifestWithName("reloaded", "Old name"));
  BrushCatalog catalog;
  catalog.scan({root() / "reload"});
  QCOMPARE(catalog.find("reloaded")->name, std::string("Old name"));

  writeFile(manifest, R"({"id": "reloaded", "name": )");
  fs::last_write_time(manifest, fs::last_write_time(manifest) + std::chrono::seconds(5));
  QVERIFY((catalog.changedBrushes() == std::vector<std::string>{"reloaded"}));
  QVERIFY(!catalog.reload("reloaded"));
  QCOMPARE(catalog.find("reloaded")->name, std::string("Old name"));
  QCOMPARE(catalog.errors().size(), std::size_t(1));
  QCOMPARE(catalog.errors()[0].path, manifest);
  QVERIFY2(catalog.errors()[0].message.starts_with(manifest.string() + ": invalid JSON"),
           catalog.errors()[0].message.c_str());
  QVERIFY(catalog.changedBrushes().empty()); // the broken edit is not reported again

  writeFile(manifest, manifestWithName("reloaded", "New name"));
  QVERIFY(catalog.reload("reloaded"));
  QCOMPARE(catalog.find("reloaded")->name, std::string("New name"));
  QVERIFY(catalog.errors().empty());
  QVERIFY(!catalog.reload("no-such-brush"));
}

void BrushManifestTest::reloadRefusesChangedId() {
  const fs::path folder = root() / "rename" / "brush";
  const fs::path manifest = writeBrush(folder, manifestWithName("before", "Before"));
  BrushCatalog catalog;
  catalog.scan({root() / "rename"});
  writeFile(manifest, manifestWithName("after", "After"));
  QVERIFY(!catalog.reload("before"));
  QCOMPARE(catalog.find("before")->name, std::string("Before"));
  QVERIFY(!catalog.find("after"));
  QCOMPARE(catalog.errors().size(), std::size_t(1));
  QCOMPARE(catalog.errors()[0].message,
           manifest.string() + ": id: changed from \"before\" to \"after\" while loaded (rescan "
                               "the brush folders to rename)");
}

void BrushManifestTest::brushFoldersChangedSeesFoldersComeAndGo() {
  const fs::path folder = root() / "appear";
  const fs::path later = root() / "appear-later"; // on the search path, created afterwards
  writeBrush(folder / "one", manifestWithName("one", "One"));
  BrushCatalog catalog;
  catalog.scan({folder, later});
  QVERIFY((catalog.searchPath() == std::vector<fs::path>{folder, later}));
  QVERIFY(!catalog.brushFoldersChanged());

  // A folder without a manifest is not a brush; editing a loaded brush is changedBrushes()'s.
  fs::create_directories(folder / "empty");
  const fs::path shader = folder / "one" / "brush.glsl";
  fs::last_write_time(shader, fs::last_write_time(shader) + std::chrono::seconds(5));
  QVERIFY(!catalog.brushFoldersChanged());

  writeBrush(folder / "two", manifestWithName("two", "Two"));
  QVERIFY(catalog.brushFoldersChanged());
  QVERIFY(catalog.brushFoldersChanged()); // until the next scan
  catalog.rescan();
  QVERIFY(!catalog.brushFoldersChanged());
  QVERIFY(catalog.find("two"));

  // Caught half-copied (manifest, no shader yet): an error now, loaded once the shader lands.
  const fs::path half = writeBrush(later / "three", manifestWithName("three", "Three"), false);
  QVERIFY(catalog.brushFoldersChanged());
  catalog.rescan();
  QVERIFY(!catalog.find("three"));
  QCOMPARE(catalog.errors().size(), std::size_t(1));
  QCOMPARE(catalog.errors()[0].path, half);
  QVERIFY(!catalog.brushFoldersChanged());
  writeFile(later / "three" / "brush.glsl", "vec4 brush(vec4 v, BrushInput b) { return v; }\n");
  fs::last_write_time(later / "three", fs::last_write_time(later / "three") +
                                           std::chrono::seconds(5)); // past coarse time stamps
  QVERIFY(catalog.brushFoldersChanged());
  catalog.rescan();
  QVERIFY(catalog.find("three"));
  QVERIFY(catalog.errors().empty());

  fs::remove_all(folder / "one");
  QVERIFY(catalog.brushFoldersChanged());
  catalog.rescan();
  QVERIFY(!catalog.find("one"));
  QCOMPARE(catalog.brushes().size(), std::size_t(2));

  fs::remove_all(later);
  QVERIFY(catalog.brushFoldersChanged());
  catalog.scan({folder}); // a scan of other folders starts over
  QVERIFY((catalog.searchPath() == std::vector<fs::path>{folder}));
  QVERIFY(!catalog.brushFoldersChanged());
}

QTEST_APPLESS_MAIN(BrushManifestTest)
#include "brush_manifest_test.moc"
