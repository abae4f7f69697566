// Arguments and inputs refused before anything is written (issue 20): NaN and infinity in every
// float argument, an empty -o, documents whose bounding box overflows float, meshes with huge
// coordinates or faces that share no vertices, an .ocz that claims a larger N than it holds
// (under a memory limit), and JSON output for names that are not UTF-8.

#include "../file_test_support.h"
#include "cli_support.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/document/document_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"

#include <QDir>
#include <QFile>
#include <QJsonDocument>
#include <QTemporaryDir>
#include <QtTest>
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace octaclay;

using octaclay::testing::resealCrc;

namespace {

struct RawResult {
  int exitCode = -1;
  std::string out, err;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs octaclay-cli with byte-exact arguments (QProcess would re-encode non-UTF-8 names), and
// with an address-space limit when asLimit > 0. stdout and stderr go through files in `dir`.
RawResult runRaw(const std::vector<std::string>& args, const std::string& dir, rlim_t asLimit = 0,
                 const std::vector<std::string>& env = {}) {
  const std::string outPath = dir + "/raw.out", errPath = dir + "/raw.err";
  const pid_t child = fork();
  if (child == 0) {
    const int out = open(outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, 1);
    dup2(err, 2);
    for (const std::string& e : env)
      putenv(const_cast<char*>(e.c_str()));
    if (asLimit > 0) {
      const rlimit limit{asLimit, asLimit};
      setrlimit(RLIMIT_AS, &limit);
    }
    std::vector<char*> argv{const_cast<char*>(OCTACLAY_CLI)};
    for (const std::string& a : args)
      argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(OCTACLAY_CLI, argv.data());
    _exit(127);
  }
  RawResult r;
  int status = 0;
  waitpid(child, &status, 0);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  r.out = slurp(outPath);
  r.err = slurp(errPath);
  return r;
}

QString describeRaw(const RawResult& r) {
  return QString("exit %1\nstdout: %2\nstderr: %3")
      .arg(r.exitCode)
      .arg(QString::fromUtf8(r.out.substr(0, 2000).c_str()),
           QString::fromUtf8(r.err.substr(0, 2000).c_str()));
}

void writeFile(const QString& path, const QByteArray& bytes) {
  QFile f(path);
  QVERIFY(f.open(QIODevice::WriteOnly | QIODevice::Truncate));
  f.write(bytes);
}

// Runs the CLI expecting `code` and a stderr message containing every needle.
#define EXPECT_MESSAGE(code, output, needles, ...)                                                 \
  do {                                                                                             \
    const QStringList args_{__VA_ARGS__};                                                          \
    const Result r_ = runCli(args_);                                                               \
    QVERIFY2(!r_.crashed && r_.exitCode == (code), qPrintable(describe(args_, r_)));               \
    for (const QString& needle_ : QStringList(needles))                                            \
      QVERIFY2(QString::fromUtf8(r_.err).contains(needle_),                                        \
               qPrintable("no '" + needle_ + "' in: " + describe(args_, r_)));                     \
    if (!QString(output).isEmpty())                                                                \
      QVERIFY2(!QFileInfo::exists(output),                                                         \
               qPrintable("output left behind: " + describe(args_, r_)));                          \
  } while (false)

} // namespace

class CliValidationTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void nonFiniteArguments_data();
  void nonFiniteArguments();
  void emptyOutputIsABadArgument();
  void overflowingDocumentRefused();
  void partialLayerRefusedByEveryCommand();
  void overflowingOczRefused();
  void oczClaimingLargerNUnderMemoryLimit();
  void hugeMeshCoordinatesRefused();
  void facesSharingNoVerticesHintWelding();
  void pipesAreNotRead();
  void jsonWithNonUtf8FileName();
  void brushesJsonWithNonUtf8Manifest();
  // QTemporaryDir cannot remove names that are not UTF-8.
  void cleanupTestCase() { std::filesystem::remove_all(dir_.path().toStdString()); }

private:
  QString file(const QString& name) const { return dir_.filePath(name); }
  QTemporaryDir dir_;
  QString doc_;
};

void CliValidationTest::initTestCase() {
  QVERIFY(dir_.isValid());
  QVERIFY2(QFileInfo(OCTACLAY_CLI).isExecutable(), OCTACLAY_CLI);
  doc_ = file("sphere.exr");
  const QStringList args{"new", "--shape", "sphere", "--size", "16", "-o", doc_};
  const Result r = runCli(args);
  QVERIFY2(r.exitCode == kOk, qPrintable(describe(args, r)));
}

void CliValidationTest::nonFiniteArguments_data() {
  QTest::addColumn<QStringList>("args");
  // The document does not exist: a refusal before reading it is exit 2, not 4.
  const QString missing = "/nonexistent/d.exr", out = "/nonexistent/o.exr";
  const QStringList stroke{"stroke", missing, "--path", "0.5,0.5", "-o", out};
  QTest::newRow("strength nan") << (QStringList(stroke) << "--brush"
                                                        << "push"
                                                        << "--strength"
                                                        << "nan");
  QTest::newRow("strength inf") << (QStringList(stroke) << "--brush"
                                                        << "push"
                                                        << "--strength"
                                                        << "inf");
  QTest::newRow("strength -inf") << (QStringList(stroke) << "--brush"
                                                         << "push"
                                                         << "--strength=-inf");
  QTest::newRow("radius nan") << (QStringList(stroke) << "--brush"
                                                      << "push"
                                                      << "--radius"
                                                      << "nan");
  QTest::newRow("spacing inf") << (QStringList(stroke) << "--brush"
                                                       << "push"
                                                       << "--spacing"
                                                       << "inf");
  QTest::newRow("view nan") << (QStringList(stroke) << "--brush"
                                                    << "splat"
                                                    << "--view"
                                                    << "nan,nan,nan");
  QTest::newRow("path inf") << QStringList{"stroke",  missing, "--path", "inf,0.5",
                                           "--brush", "push",  "-o",     out};
  QTest::newRow("float param nan") << (QStringList(stroke) << "--brush"
                                                           << "splat"
                                                           << "--param"
                                                           << "relief=nan");
  QTest::newRow("colour nan") << (QStringList(stroke) << "--brush"
                                                      << "paint"
                                                      << "--param"
                                                      << "color=1,nan,0");
  QTest::newRow("quality inf") << QStringList{
      "compress", missing, "--codec", "wavelet", "--quality", "inf", "-o", "/nonexistent/o.ocz"};
  QTest::newRow("max-error nan") << QStringList{
      "lod", missing, "--size", "8", "--max-error", "nan", "-o", "/nonexistent/l.obj"};
}

void CliValidationTest::nonFiniteArguments() {
  QFETCH(QStringList, args);
  const Result r = runCli(args);
  QVERIFY2(!r.crashed && r.exitCode == kUsage, qPrintable(describe(args, r)));
  QVERIFY2(QString::fromUtf8(r.err).contains("finite"), qPrintable(describe(args, r)));
}

void CliValidationTest::emptyOutputIsABadArgument() {
  EXPECT_MESSAGE(kUsage, QString(), QStringList{"-o"}, "new", "--size", "8", "-o", "");
  EXPECT_MESSAGE(kUsage, QString(), QStringList{"-o"}, "export", doc_, "-o", "");
}

// A coordinate of 3e19 makes the bounding-box diagonal infinite: every command refuses it on
// read (exit 3), `info` and `lod` included.
void CliValidationTest::overflowingDocumentRefused() {
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 16));
  doc.positions.at(3, 4).x = 3e19f;
  const QString huge = file("huge.exr");
  try {
    core::writeDocument(doc, huge.toStdString());
  } catch (const core::Error&) {
    QVERIFY(!QFileInfo::exists(huge)); // the writer refusing it is fine too
    return;
  }
  const QStringList tooLarge{"too large"};
  EXPECT_MESSAGE(kInvalidInput, QString(), tooLarge, "info", huge);
  EXPECT_MESSAGE(kInvalidInput, QString(), tooLarge, "info", "--json", huge);
  EXPECT_MESSAGE(kInvalidInput, file("l.obj"), tooLarge, "lod", huge, "--size", "8", "-o",
                 file("l.obj"));
  EXPECT_MESSAGE(kInvalidInput, file("h.ocz"), tooLarge, "compress", huge, "--codec", "wavelet",
                 "-o", file("h.ocz"));
  EXPECT_MESSAGE(kInvalidInput, file("h.obj"), tooLarge, "export", huge, "-o", file("h.obj"));
  EXPECT_MESSAGE(kInvalidInput, file("s.exr"), tooLarge, "stroke", huge, "--brush", "push",
                 "--path", "0.5,0.5", "-o", file("s.exr"));
}

// Renaming diffuse.R in the header leaves diffuse with 3 of its 4 channels: `info` and `lod`
// (which read positions only) refuse it as `stroke`, `export` and `compress` do.
void CliValidationTest::partialLayerRefusedByEveryCommand() {
  QFile source(doc_);
  QVERIFY(source.open(QIODevice::ReadOnly));
  QByteArray bytes = source.readAll();
  const qsizetype at = bytes.indexOf(QByteArray("diffuse.R", 10));
  QVERIFY(at > 0);
  bytes[at + 8] = 'S';
  const QString partial = file("partial.exr");
  writeFile(partial, bytes);
  const QStringList why{"diffuse has 3 of its 4 channels"};
  EXPECT_MESSAGE(kInvalidInput, QString(), why, "info", partial);
  EXPECT_MESSAGE(kInvalidInput, file("pl.obj"), why, "lod", partial, "--size", "8", "-o",
                 file("pl.obj"));
  EXPECT_MESSAGE(kInvalidInput, file("pe.obj"), why, "export", partial, "-o", file("pe.obj"));
  EXPECT_MESSAGE(kInvalidInput, file("pc.ocz"), why, "compress", partial, "--codec", "lossless",
                 "-o", file("pc.ocz"));
  EXPECT_MESSAGE(kInvalidInput, file("ps.exr"), why, "stroke", partial, "--brush", "push", "--path",
                 "0.5,0.5", "-o", file("ps.exr"));
}

void CliValidationTest::overflowingOczRefused() {
  core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Sphere, 16));
  doc.positions.at(5, 5).y = 1e30f;
  std::vector<std::uint8_t> bytes;
  try {
    bytes = core::compressDocument(doc, {"lossless", {}, "lossless"});
  } catch (const core::Error&) {
    return; // refusing to code it is fine too
  }
  const QString ocz = file("huge.ocz");
  writeFile(ocz, QByteArray(reinterpret_cast<const char*>(bytes.data()), qsizetype(bytes.size())));
  EXPECT_MESSAGE(kInvalidInput, file("huge-back.exr"), QStringList{"too large"}, "decompress", ocz,
                 "-o", file("huge-back.exr"));
}

// An 8 KB .ocz whose header claims N = 8192 (checksum redone): refused as input (exit 3), not
// "out of memory; try a smaller --size", with at most 512 MB of address space.
void CliValidationTest::oczClaimingLargerNUnderMemoryLimit() {
  const core::Document doc = core::makeDocument(core::makeBaseShape(core::BaseShape::Blob, 32));
  std::vector<std::uint8_t> bytes = core::compressDocument(doc, {"lossless", {}, "lossless"});
  const std::uint32_t n = 8192;
  for (int k = 0; k < 4; ++k)
    bytes[6 + k] = std::uint8_t(n >> (8 * k));
  resealCrc(bytes);
  const QString ocz = file("claims8192.ocz"), out = file("claims8192.exr");
  writeFile(ocz, QByteArray(reinterpret_cast<const char*>(bytes.data()), qsizetype(bytes.size())));
  const RawResult r = runRaw({"decompress", ocz.toStdString(), "-o", out.toStdString()},
                             dir_.path().toStdString(), rlim_t{512} << 20);
  QVERIFY2(r.exitCode == kInvalidInput, qPrintable(describeRaw(r)));
  QVERIFY2(r.err.find("claims8192.ocz") != std::string::npos, qPrintable(describeRaw(r)));
  QVERIFY2(r.err.find("--size") == std::string::npos, qPrintable(describeRaw(r)));
  QVERIFY(!QFileInfo::exists(out));
}

void CliValidationTest::hugeMeshCoordinatesRefused() {
  const QString obj = file("huge.obj"), out = file("huge-import.exr");
  writeFile(obj, "v 1e38 0 0\nv 0 1e38 0\nv 0 0 1e38\nv -1e38 -1e38 -1e38\n"
                 "f 1 2 3\nf 1 4 2\nf 2 4 3\nf 3 4 1\n");
  EXPECT_MESSAGE(kInvalidInput, out, QStringList{"too large"}, "import", obj, "--size", "16", "-o",
                 out);
  const Result r = runCli({"import", obj, "--size", "16", "-o", out});
  QVERIFY2(!QString::fromUtf8(r.err).contains("cannot compare"), r.err.constData());
}

// A cube whose six faces each have their own four vertices: filling holes cannot help.
void CliValidationTest::facesSharingNoVerticesHintWelding() {
  QByteArray text;
  const int faces[6][4][3] = {
      {{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}}, {{0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}}, {{0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}},
      {{0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}}, {{1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}}};
  for (const auto& face : faces)
    for (const auto& v : face)
      text += QString("v %1 %2 %3\n").arg(v[0]).arg(v[1]).arg(v[2]).toUtf8();
  for (int f = 0; f < 6; ++f)
    text += QString("f %1 %2 %3 %4\n")
                .arg(4 * f + 1)
                .arg(4 * f + 2)
                .arg(4 * f + 3)
                .arg(4 * f + 4)
                .toUtf8();
  const QString obj = file("loose.obj"), out = file("loose.exr");
  writeFile(obj, text);
  for (const QStringList& extra : {QStringList{}, QStringList{"--fill-holes"}}) {
    const QStringList args = QStringList{"import", obj, "--size", "16", "-o", out} + extra;
    const Result r = runCli(args);
    QVERIFY2(r.exitCode == kInvalidInput, qPrintable(describe(args, r)));
    const QString err = QString::fromUtf8(r.err);
    QVERIFY2(err.contains("weld"), qPrintable(describe(args, r)));
    QVERIFY2(!err.contains("try --fill-holes"), qPrintable(describe(args, r)));
    QVERIFY(!QFileInfo::exists(out));
  }
}

// A named pipe as input would block forever: refused as a file that cannot be read (exit 4).
void CliValidationTest::pipesAreNotRead() {
  for (const char* name : {"pipe.exr", "pipe.ocz"}) {
    const std::string fifo = dir_.path().toStdString() + "/" + name;
    QVERIFY(mkfifo(fifo.c_str(), 0644) == 0);
  }
  EXPECT_MESSAGE(kIo, QString(), QStringList{"not a regular file"}, "info", file("pipe.exr"));
  EXPECT_MESSAGE(kIo, file("p.obj"), QStringList{"pipe.exr"}, "export", file("pipe.exr"), "-o",
                 file("p.obj"));
  EXPECT_MESSAGE(kIo, file("p.exr"), QStringList{"pipe.ocz"}, "decompress", file("pipe.ocz"), "-o",
                 file("p.exr"));
}

void CliValidationTest::jsonWithNonUtf8FileName() {
  const std::string name = dir_.path().toStdString() + "/bad\xff\xfe name.exr";
  const RawResult r =
      runRaw({"new", "--size", "8", "-o", name, "--json"}, dir_.path().toStdString());
  QVERIFY2(r.exitCode == kOk, qPrintable(describeRaw(r)));
  QJsonParseError error{};
  const QJsonDocument json = QJsonDocument::fromJson(QByteArray::fromStdString(r.out), &error);
  QVERIFY2(error.error == QJsonParseError::NoError && json.isObject(), qPrintable(describeRaw(r)));
  const RawResult info = runRaw({"info", name, "--json"}, dir_.path().toStdString());
  QVERIFY2(info.exitCode == kOk, qPrintable(describeRaw(info)));
  QVERIFY(QJsonDocument::fromJson(QByteArray::fromStdString(info.out)).isObject());
}

void CliValidationTest::brushesJsonWithNonUtf8Manifest() {
  const std::string plugins = dir_.path().toStdString() + "/plugins";
  const std::string folder = plugins + "/odd\xff brush";
  QVERIFY(QDir().mkpath(QString::fromStdString(plugins)));
  QVERIFY(mkdir(folder.c_str(), 0755) == 0);
  std::ofstream(folder + "/manifest.json") << "{\"id\": \"odd\xff\", \"label\": \"\xc3\x28\"}";
  const RawResult r = runRaw({"brushes", "--json"}, dir_.path().toStdString(), 0,
                             {"OCTACLAY_PLUGIN_PATH=" + plugins});
  QVERIFY2(r.exitCode == kOk, qPrintable(describeRaw(r)));
  QVERIFY2(QJsonDocument::fromJson(QByteArray::fromStdString(r.out)).isObject(),
           qPrintable(describeRaw(r)));
}

QTEST_GUILESS_MAIN(CliValidationTest)
#include "cli_validation_test.moc"
