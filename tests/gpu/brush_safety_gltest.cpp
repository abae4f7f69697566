// A stroke is all or nothing (issue 20): a brush that writes NaN or infinity into any layer, or
// moves a sample beyond ±1e15, is refused when the stroke ends and the layers are restored bit
// for bit; NaN and infinity in the stroke's settings are refused before any dab; a pass that
// overruns the watchdog's limit marks its brush broken, restores the layers and throws
// BrushTimeoutError.

#include "brush_test_support.h"
#include "path_stroke.h"

#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/gpu/gl_context.h"
#include "octaclay/gpu/stroke.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cstring>
#include <limits>
#include <optional>

using namespace octaclay;
using namespace octaclay::gpu;
using namespace octaclay::gpu::testing;
namespace fs = std::filesystem;

namespace {

constexpr core::EditLayer kLayers[] = {core::EditLayer::Positions, core::EditLayer::Diffuse,
                                       core::EditLayer::Feature, core::EditLayer::Mask};

// Every layer's texels in the mirror, then in the textures: what "unchanged" compares.
std::vector<std::vector<float>> snapshot(GpuDocument& document) {
  const int side = document.size() + 1;
  std::vector<std::vector<float>> layers;
  for (core::EditLayer layer : kLayers)
    layers.push_back(document.mirrorTexels(layer, {0, 0, side, side}));
  for (core::EditLayer layer : kLayers)
    layers.push_back(document.texture(layer).read({0, 0, side, side}));
  return layers;
}

PathStroke strokeOf(const std::string& brush, float strength) {
  PathStroke s;
  s.brush = brush;
  s.path = {{0.5f, 0.5f}, {0.6f, 0.5f}};
  s.radius = 0.3f;
  s.strength = strength;
  return s;
}

// Inside the dab, a float with these bits; outside it, the layer's value.
std::string bitsBody(const char* bits) {
  return std::string("vec4 brush(vec4 value, BrushInput b) {\n"
                     "  return b.weight > 0.0 ? vec4(uintBitsToFloat(") +
         bits + ")) : value;\n}\n";
}

} // namespace

class BrushSafetyTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void nonFiniteResultsAreUndone_data();
  void nonFiniteResultsAreUndone();
  void hugeResultsAreUndone();
  void nonFiniteSettingsAreRefused_data();
  void nonFiniteSettingsAreRefused();
  void overrunningPassMarksTheBrushBroken();
  void overrunningPaintPassIsCaughtByTheStrokesEnd();

private:
  // Writes a plugin brush (manifest and body) into the temporary folder, loads it and returns
  // its manifest.
  const BrushManifest& plugin(const std::string& id, const std::string& writes,
                              const std::string& body);
  // Runs the stroke and returns the core::Error kind and message it must throw; fails the test
  // when it does not throw, or when the document changed.
  std::pair<core::ErrorKind, std::string> refused(const BrushManifest& brush,
                                                  const PathStroke& stroke);

  std::optional<GlContext> context_;
  std::optional<BrushEngine> engine_;
  std::optional<QTemporaryDir> folder_;
  std::map<std::string, BrushManifest> manifests_;
};

void BrushSafetyTest::initTestCase() {
  try {
    context_.emplace(GlContext::createHeadless());
    engine_.emplace();
    folder_.emplace();
    loadBuiltIns(*engine_);
    manifests_.emplace("push", builtInManifest("push"));
  } catch (const std::exception& e) {
    QFAIL(e.what());
  }
}

const BrushManifest& BrushSafetyTest::plugin(const std::string& id, const std::string& writes,
                                             const std::string& body) {
  const fs::path folder = fs::path(folder_->path().toStdString()) / id;
  fs::create_directories(folder);
  std::ofstream(folder / "brush.glsl") << body;
  std::ofstream(folder / "manifest.json")
      << R"({"id": ")" << id << R"(", "name": "T", "api": 1, "shader": "brush.glsl", "writes": [")"
      << writes << R"("], "area": "volume", "falloff": "constant", "parameters": [
           {"id": "amount", "type": "float", "min": 0, "max": 1, "default": 0.5},
           {"id": "tint", "type": "color"}]})";
  BrushManifest manifest = parseBrushManifest(folder / "manifest.json");
  engine_->load(manifest, body);
  return manifests_.insert_or_assign(id, std::move(manifest)).first->second;
}

std::pair<core::ErrorKind, std::string> BrushSafetyTest::refused(const BrushManifest& brush,
                                                                 const PathStroke& stroke) {
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 32)));
  const auto before = snapshot(document);
  std::pair<core::ErrorKind, std::string> error{core::ErrorKind::Io, "it did not throw"};
  try {
    strokeAlongPath(*engine_, document, brush, stroke);
  } catch (const core::Error& e) {
    error = {e.kind(), e.what()};
  }
  if (!sameBits(snapshot(document), before)) error.second = "the document changed";
  return error;
}

void BrushSafetyTest::nonFiniteResultsAreUndone_data() {
  QTest::addColumn<QString>("writes");
  QTest::addColumn<QString>("bits");
  QTest::newRow("NaN positions") << "positions"
                                 << "0x7fc00000u";
  QTest::newRow("infinite positions") << "positions"
                                      << "0x7f800000u";
  QTest::newRow("-infinite positions") << "positions"
                                       << "0xff800000u";
  QTest::newRow("NaN diffuse") << "diffuse"
                               << "0x7fc00000u";
  QTest::newRow("infinite mask") << "mask"
                                 << "0x7f800000u";
}

void BrushSafetyTest::nonFiniteResultsAreUndone() {
  QFETCH(QString, writes);
  QFETCH(QString, bits);
  const std::string id = "bad-" + writes.toStdString() + "-" + bits.mid(2, 2).toStdString();
  const BrushManifest& brush =
      plugin(id, writes.toStdString(), bitsBody(bits.toStdString().c_str()));
  const auto [kind, message] = refused(brush, strokeOf(id, 0.5f));
  QVERIFY2(kind == core::ErrorKind::InvalidInput, message.c_str());
  QVERIFY2(message.find("the brush produced a non-finite value at sample (") != std::string::npos,
           message.c_str());
  QVERIFY2(message.find("of the " + writes.toStdString() + " layer") != std::string::npos,
           message.c_str());
}

void BrushSafetyTest::hugeResultsAreUndone() {
  // A finite strength whose result is still far beyond what a document may hold.
  const auto [kind, message] = refused(manifests_.at("push"), strokeOf("push", 1e30f));
  QVERIFY2(kind == core::ErrorKind::InvalidInput, message.c_str());
  QVERIFY2(message.find("beyond the ±1e15") != std::string::npos, message.c_str());
}

void BrushSafetyTest::nonFiniteSettingsAreRefused_data() {
  QTest::addColumn<QString>("setting");
  QTest::addColumn<float>("value");
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  for (const char* setting : {"strength", "radius", "pressure", "amount", "tint", "view"}) {
    QTest::newRow((std::string(setting) + " nan").c_str()) << QString(setting) << nan;
    QTest::newRow((std::string(setting) + " inf").c_str()) << QString(setting) << inf;
  }
  QTest::newRow("amount above max") << "amount" << 2.0f;
  QTest::newRow("tint above 1") << "tint" << 1.5f;
}

void BrushSafetyTest::nonFiniteSettingsAreRefused() {
  QFETCH(QString, setting);
  QFETCH(float, value);
  const BrushManifest& brush =
      plugin("tunable", "positions",
             "vec4 brush(vec4 value, BrushInput b) {\n"
             "  return value + vec4(u_tint.rgb * u_amount * b.weight, 0);\n"
             "}\n");
  PathStroke stroke = strokeOf("tunable", 0.1f);
  if (setting == "strength") stroke.strength = value;
  if (setting == "radius") stroke.radius = value;
  if (setting == "pressure") stroke.pressure = value;
  if (setting == "amount") stroke.parameters["amount"] = {value, 0, 0, 0};
  if (setting == "tint") stroke.parameters["tint"] = {0.5f, value, 0.5f, 1};
  if (setting == "view") stroke.viewEye = core::Vec3f{0, value, 3};
  const auto [kind, message] = refused(brush, stroke);
  QVERIFY2(kind == core::ErrorKind::InvalidArgument, message.c_str());
}

void BrushSafetyTest::overrunningPassMarksTheBrushBroken() {
  // Mesa's llvmpipe stops each loop after 65 535 iterations: this body returns, slowly. With a
  // limit of 1 µs its pass overruns, as a hung one would overrun 2 s on a real GPU.
  const BrushManifest& brush = plugin("loop", "positions",
                                      "vec4 brush(vec4 value, BrushInput b) {\n"
                                      "  float x = value.x;\n"
                                      "  while (x == x) x += 1.0;\n"
                                      "  return value + vec4(0, 0, b.weight + x * 1e-30, 0);\n"
                                      "}\n");
  engine_->setPassTimeLimit(std::chrono::microseconds(1));
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 32)));
  const auto before = snapshot(document);
  const std::string expected =
      (brush.folder / "brush.glsl").string() + ": a pass took longer than 1 µs";
  try {
    strokeAlongPath(*engine_, document, brush, strokeOf("loop", 0.5f));
    QFAIL("the overrunning pass was not caught");
  } catch (const BrushTimeoutError& e) {
    QVERIFY2(std::string(e.what()).starts_with(expected), e.what());
  }
  engine_->setPassTimeLimit(std::chrono::seconds(2));
  QVERIFY(sameBits(snapshot(document), before));
  QVERIFY(engine_->brokenReason("loop") != nullptr);
  QVERIFY(engine_->brokenReason("push") == nullptr);
  // Broken until loaded again, even with a generous limit.
  QVERIFY_THROWS_EXCEPTION(BrushTimeoutError,
                           strokeAlongPath(*engine_, document, brush, strokeOf("loop", 0.5f)));
  QVERIFY(sameBits(snapshot(document), before));
  // The other brushes work on, and the reloaded brush runs within 2 s.
  strokeAlongPath(*engine_, document, manifests_.at("push"), strokeOf("push", 0.1f));
  engine_->load(brush, readFile(brush.shaderPath()));
  QVERIFY(engine_->brokenReason("loop") == nullptr);
  strokeAlongPath(*engine_, document, brush, strokeOf("loop", 0.5f));
}

void BrushSafetyTest::overrunningPaintPassIsCaughtByTheStrokesEnd() {
  // A paint layer is not read back after each dab, so the CPU does not wait for its passes as
  // they are issued: an overrun is caught at the next dab's wait for the pass before last, or
  // at the stroke's end before the paint layer's read-back, with the limit counted from the
  // pass's submission. The stroke is undone all the same.
  const BrushManifest& brush = plugin("paint-loop", "diffuse",
                                      "vec4 brush(vec4 value, BrushInput b) {\n"
                                      "  float x = value.x;\n"
                                      "  while (x == x) x += 1.0;\n"
                                      "  return vec4(b.weight + x * 1e-30, value.yzw);\n"
                                      "}\n");
  GpuDocument document(core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 32)));
  const auto before = snapshot(document);
  const std::string expected =
      (brush.folder / "brush.glsl").string() + ": a pass took longer than 1 µs";
  for (const std::vector<std::array<float, 2>>& path :
       {std::vector<std::array<float, 2>>{{0.5f, 0.5f}},                  // one dab: the end
        std::vector<std::array<float, 2>>{{0.5f, 0.5f}, {0.6f, 0.5f}}}) { // the next dab
    engine_->load(brush, readFile(brush.shaderPath()));
    engine_->setPassTimeLimit(std::chrono::microseconds(1));
    PathStroke stroke = strokeOf("paint-loop", 0.5f);
    stroke.path = path;
    try {
      strokeAlongPath(*engine_, document, brush, stroke);
      QFAIL("the overrunning paint pass was not caught");
    } catch (const BrushTimeoutError& e) {
      QVERIFY2(std::string(e.what()).starts_with(expected), e.what());
    }
    engine_->setPassTimeLimit(std::chrono::seconds(2));
    QVERIFY(sameBits(snapshot(document), before));
    QVERIFY(engine_->brokenReason("paint-loop") != nullptr);
  }
  // With the limit it needs, the same brush paints.
  engine_->load(brush, readFile(brush.shaderPath()));
  strokeAlongPath(*engine_, document, brush, strokeOf("paint-loop", 0.5f));
  QVERIFY(!sameBits(snapshot(document), before));
}

QTEST_APPLESS_MAIN(BrushSafetyTest)
#include "brush_safety_gltest.moc"
