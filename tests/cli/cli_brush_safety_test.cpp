// octaclay-cli stroke never saves what it cannot read again, and plugins cannot hang it
// (issue 20): NaN or infinity in --strength or --param is a usage error (exit 2), a brush whose
// result is not finite or beyond ±1e15 is refused (exit 3), a pass that overruns the watchdog
// is exit 5 with the shader's name; in every case a stroke written in place leaves the document
// byte for byte as it was. A manifest that is a named pipe, a link to /dev/zero or a link loop
// is listed as broken while the other brushes work, without blocking.

#include "cli_support.h"

#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QTemporaryDir>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

class CliBrushSafetyTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void nonFiniteArgumentsAreUsageErrors();
  void nonFiniteResultsAreRefused();
  void overrunningPassIsExit5();
  void unreadableManifestsNeitherBlockNorStopTheOthers();

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  // A plugin folder (under plugins/) with this brush; returns the plugins folder.
  QString writePlugin(const QString& id, const QString& shader);
  // Runs a stroke written in place on a copy of the sphere: expects code, a message holding
  // `message`, and the document unchanged.
  void expectRefused(int code, const QString& message, const QStringList& strokeArgs,
                     const QStringList& env = {});

  QTemporaryDir dir_;
  QString sphere_;
  QByteArray sphereBytes_;
};

void CliBrushSafetyTest::initTestCase() {
  QVERIFY(dir_.isValid());
  sphere_ = file("sphere.exr");
  RUN_JSON(created, "new", "--size", "64", "-o", sphere_, "--json");
  QFile in(sphere_);
  QVERIFY(in.open(QIODevice::ReadOnly));
  sphereBytes_ = in.readAll();
}

QString CliBrushSafetyTest::writePlugin(const QString& id, const QString& shader) {
  const QString folder = file("plugins/" + id);
  QDir().mkpath(folder);
  QFile m(folder + "/manifest.json"), s(folder + "/brush.glsl");
  if (!m.open(QIODevice::WriteOnly) || !s.open(QIODevice::WriteOnly)) return {};
  m.write(QString(R"({"id": "%1", "name": "T", "api": 1, "shader": "brush.glsl",
                      "writes": ["positions"], "area": "volume", "falloff": "constant",
                      "parameters": [{"id": "amount", "type": "float", "min": 0, "max": 1}]})")
              .arg(id)
              .toUtf8());
  s.write(shader.toUtf8());
  return file("plugins");
}

void CliBrushSafetyTest::expectRefused(int code, const QString& message,
                                       const QStringList& strokeArgs, const QStringList& env) {
  const QString doc = file("doc.exr");
  QFile::remove(doc);
  QVERIFY(QFile::copy(sphere_, doc));
  const QStringList args =
      QStringList{"stroke", doc, "--path", "0.5,0.5;0.6,0.5", "-o", doc} + strokeArgs;
  const Result r = runCli(args, env);
  QVERIFY2(!r.crashed && r.exitCode == code, qPrintable(describe(args, r)));
  QVERIFY2(QString::fromUtf8(r.err).contains(message), qPrintable(describe(args, r)));
  QFile in(doc);
  QVERIFY(in.open(QIODevice::ReadOnly));
  QVERIFY2(in.readAll() == sphereBytes_, qPrintable("the document changed: " + describe(args, r)));
  const Result info = runCli({"info", doc});
  QVERIFY2(info.exitCode == kOk, qPrintable(describe({"info", doc}, info)));
}

void CliBrushSafetyTest::nonFiniteArgumentsAreUsageErrors() {
  expectRefused(kUsage, "not a finite number", {"--brush", "push", "--strength", "nan"});
  expectRefused(kUsage, "not a finite number", {"--brush", "push", "--strength", "inf"});
  expectRefused(kUsage, "--radius", {"--brush", "push", "--radius", "nan"});
  const QString plugins =
      writePlugin("tunable", "vec4 brush(vec4 value, BrushInput b) { return value; }\n");
  expectRefused(kUsage, "amount", {"--brush", "tunable", "--param", "amount=nan"},
                {"OCTACLAY_PLUGIN_PATH=" + plugins});
}

void CliBrushSafetyTest::nonFiniteResultsAreRefused() {
  expectRefused(kInvalidInput, "beyond the ±1e15", {"--brush", "push", "--strength", "1e30"});
  const QString plugins = writePlugin(
      "nan-brush", "vec4 brush(vec4 value, BrushInput b) {\n"
                   "  return b.weight > 0.0 ? vec4(uintBitsToFloat(0x7fc00000u)) : value;\n"
                   "}\n");
  writePlugin("inf-brush", "vec4 brush(vec4 value, BrushInput b) {\n"
                           "  return b.weight > 0.0 ? vec4(uintBitsToFloat(0x7f800000u)) : value;\n"
                           "}\n");
  const QStringList env{"OCTACLAY_PLUGIN_PATH=" + plugins};
  expectRefused(kInvalidInput, "the brush produced a non-finite value at sample (",
                {"--brush", "nan-brush"}, env);
  expectRefused(kInvalidInput, "non-finite value", {"--brush", "inf-brush"}, env);
}

void CliBrushSafetyTest::overrunningPassIsExit5() {
  // llvmpipe stops the loop after 65 535 iterations; a limit of 1 µs catches it anyway.
  const QString plugins =
      writePlugin("loop", "vec4 brush(vec4 value, BrushInput b) {\n"
                          "  float x = value.x;\n"
                          "  while (x == x) x += 1.0;\n"
                          "  return value + vec4(0, 0, b.weight + x * 1e-30, 0);\n"
                          "}\n");
  expectRefused(kGl, "brush.glsl: a pass took longer than 1 µs", {"--brush", "loop"},
                {"OCTACLAY_PLUGIN_PATH=" + plugins, "OCTACLAY_PASS_TIME_LIMIT_MS=0.001"});
}

void CliBrushSafetyTest::unreadableManifestsNeitherBlockNorStopTheOthers() {
  namespace fs = std::filesystem;
  const fs::path plugins = file("hostile").toStdString();
  for (const char* name : {"fifo", "zero", "loop"})
    fs::create_directories(plugins / name);
  QCOMPARE(::mkfifo((plugins / "fifo" / "manifest.json").c_str(), 0644), 0);
  fs::create_symlink("/dev/zero", plugins / "zero" / "manifest.json");
  fs::create_symlink("manifest.json", plugins / "loop" / "manifest.json");
  fs::create_directories(plugins / "badbyte"); // ill-formed UTF-8: the message must stay JSON
  std::ofstream(plugins / "badbyte" / "manifest.json") << "{\"id\": \"b\", \"name\": \"T\xff\"}";
  const QString out = file("pushed.exr");
  const QStringList args{"stroke", sphere_, "--brush", "push", "--path", "0.5,0.5", "-o", out};
  QElapsedTimer timer;
  timer.start();
  const Result r = runCli(args, {"OCTACLAY_PLUGIN_PATH=" + QString::fromStdString(plugins)});
  QVERIFY2(timer.elapsed() < 10000, qPrintable("took " + QString::number(timer.elapsed()) + " ms"));
  QVERIFY2(!r.crashed && r.exitCode == kOk, qPrintable(describe(args, r)));
  // brushes --json lists them as broken, each naming its file.
  const QStringList list{"brushes", "--json"};
  timer.restart();
  const Result brushes = runCli(list, {"OCTACLAY_PLUGIN_PATH=" + QString::fromStdString(plugins)});
  QVERIFY2(timer.elapsed() < 10000, qPrintable("took " + QString::number(timer.elapsed()) + " ms"));
  QVERIFY2(brushes.exitCode == kOk, qPrintable(describe(list, brushes)));
  const QString errors =
      QJsonDocument(QJsonDocument::fromJson(brushes.out).object()["errors"].toArray()).toJson();
  for (const char* reason :
       {"fifo/manifest.json: is a named pipe", "zero/manifest.json: is a device",
        "loop/manifest.json: is a symbolic link loop"})
    QVERIFY2(errors.contains(reason), qPrintable(reason + QString(" not in ") + errors));
}

QTEST_APPLESS_MAIN(CliBrushSafetyTest)
#include "cli_brush_safety_test.moc"
