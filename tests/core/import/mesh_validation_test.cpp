// Import validation: every shared genus-0 mesh loads clean, closed, manifold, one component,
// Euler 2 and outward; every shared invalid mesh and every generated bad input (truncated files
// of all four formats at every length, damaged bytes, NaN, bad indices, no faces, components,
// non-manifold edges, pinches, handles) is refused with an Error naming the problem; small holes
// are filled on request.

#include "octaclay/core/error.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/import/mesh_validation.h"

#include <QtTest>

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

using Tri = std::array<std::uint32_t, 3>;

const fs::path kMeshes = fs::path(OCTACLAY_SHARED_DATA) / "meshes";

// Empty when f throws an Error of this kind whose message contains every one of `needles`;
// otherwise what went wrong.
QString expectError(const std::function<void()>& f, ErrorKind kind,
                    const std::vector<std::string>& needles = {}) {
  try {
    f();
  } catch (const Error& e) {
    const std::string message = e.what();
    if (e.kind() != kind)
      return QString("wrong ErrorKind %1 (expected %2): %3")
          .arg(int(e.kind()))
          .arg(int(kind))
          .arg(e.what());
    if (message.empty()) return "empty message";
    for (const std::string& needle : needles)
      if (message.find(needle) == std::string::npos)
        return QString("message lacks '%1': %2")
            .arg(QString::fromStdString(needle), QString::fromStdString(message));
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  }
  return "did not throw";
}

#define EXPECT_ERROR(call, kind, ...)                                                              \
  do {                                                                                             \
    const QString why_ = expectError([&] { call; }, kind, {__VA_ARGS__});                          \
    QVERIFY2(why_.isEmpty(), qPrintable(why_));                                                    \
  } while (false)

#define NO_THROW(call)                                                                             \
  do {                                                                                             \
    try {                                                                                          \
      call;                                                                                        \
    } catch (const std::exception& e_) {                                                           \
      QFAIL(qPrintable(QString(#call " threw: ") + e_.what()));                                    \
    }                                                                                              \
  } while (false)

// Counts edge-connected components independently of the code under test.
std::size_t componentCount(const TriangleMesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.positions.size());
  std::iota(parent.begin(), parent.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  };
  for (const Tri& t : mesh.triangles) {
    parent[find(t[1])] = find(t[0]);
    parent[find(t[2])] = find(t[0]);
  }
  std::size_t roots = 0;
  for (std::uint32_t v = 0; v < parent.size(); ++v)
    roots += find(v) == v ? 1 : 0;
  return roots;
}

// Empty when the mesh is what validation promises; otherwise what is wrong.
QString checkGenus0(const TriangleMesh& mesh) {
  const MeshTopology topo = analyzeTopology(mesh);
  if (!topo.closed()) return QString("%1 boundary edges").arg(topo.boundaryEdges);
  if (!topo.manifold()) return QString("%1 non-manifold edges").arg(topo.nonManifoldEdges);
  if (topo.unusedVertices) return QString("%1 unused vertices").arg(topo.unusedVertices);
  if (topo.euler != 2) return QString("Euler characteristic %1").arg(topo.euler);
  if (componentCount(mesh) != 1) return QString("%1 components").arg(componentCount(mesh));
  for (const Tri& t : mesh.triangles)
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "a face repeats a corner";
  if (!(signedVolume(mesh) > 0)) return QString("signed volume %1").arg(signedVolume(mesh));
  return {};
}

TriangleMesh tetrahedron(Vec3f offset = {}) {
  TriangleMesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (Vec3f& p : m.positions)
    p += offset;
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}}; // outward
  return m;
}

TriangleMesh octahedron() {
  TriangleMesh m;
  m.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

// A unit cube of six quads, counter-clockwise from outside.
const std::vector<Vec3f> kCubeVertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                          {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
const std::vector<std::array<int, 4>> kCubeQuads = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                                    {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};

// A torus of n × n quads, each split into two triangles.
TriangleMesh torus(int n) {
  TriangleMesh m;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / n;
      m.positions.push_back({float((2 + std::cos(v)) * std::cos(u)),
                             float((2 + std::cos(v)) * std::sin(u)), float(std::sin(v))});
    }
  auto id = [n](int i, int j) { return std::uint32_t(((i + n) % n) * n + (j + n) % n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      m.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      m.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return m;
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

template <class T> void put(std::string& out, T value, bool bigEndian = false) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (bigEndian != (std::endian::native == std::endian::big))
    std::reverse(bytes, bytes + sizeof(T));
  out.append(bytes, sizeof(T));
}

std::string cubeObj() {
  std::string s = "# cube\no cube\n";
  for (const Vec3f& p : kCubeVertices)
    s += "v " + std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  s += "vt 0 0\nvn 0 0 1\ns off\n";
  for (const auto& q : kCubeQuads)
    s += "f " + std::to_string(q[0] + 1) + "/1/1 " + std::to_string(q[1] + 1) + "/1/1 " +
         std::to_string(q[2] + 1) + "/1/1 " + std::to_string(q[3] + 1) + "/1/1\n";
  return s;
}

std::string cubeOff() {
  std::string s = "OFF\n# a comment\n8 6 12\n";
  for (const Vec3f& p : kCubeVertices)
    s += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + "\n";
  for (const auto& q : kCubeQuads)
    s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) +
         " " + std::to_string(q[3]) + "\n";
  return s;
}

std::string plyHeader(const char* format) {
  return std::string("ply\nformat ") + format +
         " 1.0\ncomment made by a test\nelement vertex 8\nproperty float x\nproperty float y\n"
         "property float z\nproperty uchar red\nelement face 6\n"
         "property list uchar int vertex_indices\nend_header\n";
}

std::string cubePlyAscii() {
  std::string s = plyHeader("ascii");
  for (const Vec3f& p : kCubeVertices)
    s += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + " 255\n";
  for (const auto& q : kCubeQuads)
    s += "4 " + std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) +
         " " + std::to_string(q[3]) + "\n";
  return s;
}

std::string cubePlyBinary(bool bigEndian) {
  std::string s = plyHeader(bigEndian ? "binary_big_endian" : "binary_little_endian");
  for (const Vec3f& p : kCubeVertices) {
    put(s, p.x, bigEndian);
    put(s, p.y, bigEndian);
    put(s, p.z, bigEndian);
    put(s, std::uint8_t(255), bigEndian);
  }
  for (const auto& q : kCubeQuads) {
    put(s, std::uint8_t(4), bigEndian);
    for (int v : q)
      put(s, std::int32_t(v), bigEndian);
  }
  return s;
}

std::vector<std::array<Vec3f, 3>> cubeFacets() {
  std::vector<std::array<Vec3f, 3>> facets;
  for (const auto& q : kCubeQuads) {
    facets.push_back({kCubeVertices[q[0]], kCubeVertices[q[1]], kCubeVertices[q[2]]});
    facets.push_back({kCubeVertices[q[0]], kCubeVertices[q[2]], kCubeVertices[q[3]]});
  }
  return facets;
}

std::string cubeStlAscii() {
  std::string s = "solid cube\n";
  for (const auto& f : cubeFacets()) {
    s += "  facet normal 0 0 0\n    outer loop\n";
    for (const Vec3f& p : f)
      s += "      vertex " + std::to_string(p.x) + " " + std::to_string(p.y) + " " +
           std::to_string(p.z) + "\n";
    s += "    endloop\n  endfacet\n";
  }
  return s + "endsolid cube\n";
}

std::string cubeStlBinary() {
  std::string s(80, ' ');
  s.replace(0, 11, "binary cube");
  const auto facets = cubeFacets();
  put(s, std::uint32_t(facets.size()));
  for (const auto& f : facets) {
    for (int k = 0; k < 3; ++k)
      put(s, 0.0f);
    for (const Vec3f& p : f) {
      put(s, p.x);
      put(s, p.y);
      put(s, p.z);
    }
    put(s, std::uint16_t(0));
  }
  return s;
}

struct SampleFile {
  const char* name;
  std::string bytes;
};

std::vector<SampleFile> cubeFiles() {
  return {{"cube.obj", cubeObj()},
          {"cube.off", cubeOff()},
          {"cube_ascii.ply", cubePlyAscii()},
          {"cube_le.ply", cubePlyBinary(false)},
          {"cube_be.ply", cubePlyBinary(true)},
          {"cube_ascii.stl", cubeStlAscii()},
          {"cube_binary.stl", cubeStlBinary()}};
}

bool sameMesh(const TriangleMesh& a, const TriangleMesh& b) {
  return a.positions == b.positions && a.triangles == b.triangles;
}

// Attributes as affine functions of position, so that they can be checked after the cleanup
// renumbers vertices and turns faces: bytes for colours, floats for texture coordinates.
std::array<int, 3> colourBytes(Vec3f p) {
  auto byte = [](float c) { return std::clamp(int(std::lround(127.5f + 100.0f * c)), 0, 255); };
  return {byte(p.x), byte(p.y), byte(p.z)};
}
std::array<float, 2> uvOf(Vec3f p) {
  return {0.5f + 0.25f * p.x + 0.125f * p.z, 0.5f + 0.25f * p.y};
}

std::string shortest(float v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

// An OBJ of `m` with `v x y z r g b` colours (bytes) and one `vt` per face corner, written in
// the reverse order of the corners so that vt and v indices differ; faces alternate the
// v/vt and v/vt/vn forms. `head` goes first (mtllib lines).
std::string attributedObj(const TriangleMesh& m, bool colours, bool uvs,
                          const std::string& head = {}) {
  std::string s = head;
  for (const Vec3f& p : m.positions) {
    s += "v " + shortest(p.x) + " " + shortest(p.y) + " " + shortest(p.z);
    if (colours) {
      const auto c = colourBytes(p);
      s += " " + std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]);
    }
    s += "\n";
  }
  const std::size_t corners = 3 * m.triangles.size();
  for (std::size_t c = corners; c-- > 0;) {
    const auto uv = uvOf(m.positions[m.triangles[c / 3][c % 3]]);
    s += "vt " + shortest(uv[0]) + " " + shortest(uv[1]) + "\n";
  }
  s += "vn 0 0 1\n";
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    s += "f";
    for (std::size_t k = 0; k < 3; ++k) {
      s += " " + std::to_string(m.triangles[t][k] + 1);
      if (uvs) s += "/" + std::to_string(corners - (3 * t + k));
      if (t % 2) s += uvs ? "/1" : "//1";
    }
    s += "\n";
  }
  return s;
}

// Empty when every vertex colour and corner coordinate is the function of its position that
// attributedObj wrote; otherwise the first mismatch.
QString checkAttributes(const ValidatedMesh& r) {
  if (r.vertexColours.size() != r.mesh.positions.size())
    return QString("%1 colours for %2 vertices")
        .arg(r.vertexColours.size())
        .arg(r.mesh.positions.size());
  for (std::size_t v = 0; v < r.mesh.positions.size(); ++v) {
    const auto c = colourBytes(r.mesh.positions[v]);
    const Vec4f got = r.vertexColours[v];
    if (std::abs(got.x * 255 - float(c[0])) > 0.51f ||
        std::abs(got.y * 255 - float(c[1])) > 0.51f ||
        std::abs(got.z * 255 - float(c[2])) > 0.51f || got.w != 1.0f)
      return QString("vertex %1: colour %2 %3 %4 %5")
          .arg(v)
          .arg(got.x)
          .arg(got.y)
          .arg(got.z)
          .arg(got.w);
  }
  if (r.cornerUv.size() != r.mesh.triangles.size())
    return QString("%1 corner triples for %2 triangles")
        .arg(r.cornerUv.size())
        .arg(r.mesh.triangles.size());
  return {};
}

} // namespace

class MeshValidationTest : public QObject {
  Q_OBJECT

private slots:
  void genus0Files_data();
  void genus0Files();
  void invalidFiles_data();
  void invalidFiles();
  void allFormatsRead();
  void openMeshWrittenFilesRead();
  void truncatedFiles();
  void damagedBytes();
  void badFiles();
  void generatedBadMeshes();
  void cleanupOfFixableMeshes();
  void fillHolesSmall();
  void fillHolesOpenBunny();
  void attributesFollowTheCleanup();
  void attributeNotes();

private:
  QTemporaryDir dir_;
  fs::path root() const { return fs::path(dir_.path().toStdString()); }
};

void MeshValidationTest::genus0Files_data() {
  QTest::addColumn<QString>("file");
  QTest::addColumn<int>("vertices"); // after unused vertices are removed (MANIFEST.md)
  QTest::addColumn<int>("faces");
  const std::vector<std::tuple<const char*, int, int>> files = {
      {"spot.obj", 2930, 5856},        {"blub.obj", 7106, 14208},
      {"bunny_npm.obj", 1839, 3674},   {"bunny_cgal.obj", 37706, 75408},
      {"wingnut.obj", 3047, 6090},     {"sword.obj", 22293, 44582},
      {"koala.obj", 49999, 99994},     {"scorpion.obj", 49997, 99990},
      {"armadillo.obj", 43243, 86482}, {"max_planck_decimated.obj", 5272, 10540},
      {"fandisk.obj", 6475, 12946},    {"airplane.obj", 7017 - 1617, 10796},
      {"horse.ply", 48485, 96966},     {"nefertiti.obj", 49971, 99938},
      {"igea.ply", 134345, 268686}};
  // Every file the folder holds must be listed, so a new file cannot slip past the test.
  std::size_t onDisk = 0;
  for (const auto& entry : fs::directory_iterator(kMeshes / "genus0"))
    onDisk += entry.is_regular_file() ? 1 : 0;
  QCOMPARE(onDisk, files.size());
  for (const auto& [file, v, f] : files)
    QTest::newRow(file) << QString(file) << v << f;
}

void MeshValidationTest::genus0Files() {
  QFETCH(QString, file);
  QFETCH(int, vertices);
  QFETCH(int, faces);
  const fs::path path = kMeshes / "genus0" / file.toStdString();
  QVERIFY2(fs::exists(path), qPrintable(QString::fromStdString(path.string())));
  ValidatedMesh result;
  const auto start = std::chrono::steady_clock::now();
  NO_THROW(result = loadGenus0Mesh(path));
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  qInfo("%s: %d faces validated in %.0f ms", qPrintable(file), faces, ms);

  const QString why = checkGenus0(result.mesh);
  QVERIFY2(why.isEmpty(), qPrintable(why));
  QCOMPARE(result.mesh.positions.size(), std::size_t(vertices));
  QCOMPARE(result.mesh.triangles.size(), std::size_t(faces));
  const MeshCleanup& c = result.cleanup;
  QCOMPARE(c.windingReversed, file == "horse.ply"); // the only one wound inward
  QCOMPARE(c.unusedVerticesRemoved, std::size_t(file == "airplane.obj" ? 1617 : 0));
  QCOMPARE(c.duplicateVerticesWelded, std::size_t(0));
  QCOMPARE(c.degenerateFacesRemoved, std::size_t(0));
  QCOMPARE(c.facesFlipped, std::size_t(0));
  QCOMPARE(c.holesFilled, std::size_t(0));

  // Validation is idempotent: its own output needs no further cleaning.
  ValidatedMesh again;
  NO_THROW(again = validateGenus0Mesh(result.mesh));
  QVERIFY(sameMesh(again.mesh, result.mesh));
  QVERIFY(!again.cleanup.windingReversed && again.cleanup.unusedVerticesRemoved == 0);
}

void MeshValidationTest::invalidFiles_data() {
  QTest::addColumn<QString>("file");
  QTest::addColumn<QStringList>("needles");
  QTest::newRow("bob") << "bob_genus1.obj" << QStringList{"genus 1", "one handle"};
  QTest::newRow("rocker_arm") << "rocker_arm_genus1.obj" << QStringList{"genus 1"};
  QTest::newRow("fertility") << "fertility_genus4.obj" << QStringList{"genus 4", "4 handles"};
  QTest::newRow("open bunny") << "stanford_bunny_open.obj"
                              << QStringList{"open", "5 holes", "223 boundary edges",
                                             "--fill-holes"};
  QTest::newRow("cow") << "cow_pinch_vertex.obj"
                       << QStringList{"pinch", "vertex 254", "2 separate fans"};
  std::size_t onDisk = 0;
  for (const auto& entry : fs::directory_iterator(kMeshes / "invalid"))
    onDisk += entry.is_regular_file() ? 1 : 0;
  QCOMPARE(onDisk, std::size_t(5));
}

void MeshValidationTest::invalidFiles() {
  QFETCH(QString, file);
  QFETCH(QStringList, needles);
  const fs::path path = kMeshes / "invalid" / file.toStdString();
  QVERIFY(fs::exists(path));
  std::vector<std::string> n{path.string()}; // messages start with the path
  for (const QString& s : needles)
    n.push_back(s.toStdString());
  const QString why = expectError([&] { loadGenus0Mesh(path); }, ErrorKind::InvalidInput, n);
  QVERIFY2(why.isEmpty(), qPrintable(why));
}

void MeshValidationTest::allFormatsRead() {
  for (const SampleFile& f : cubeFiles()) {
    const fs::path path = root() / f.name;
    writeFile(path, f.bytes);
    ValidatedMesh result;
    NO_THROW(result = loadGenus0Mesh(path));
    QVERIFY2(checkGenus0(result.mesh).isEmpty(), f.name);
    QCOMPARE(result.mesh.positions.size(), std::size_t(8));
    QCOMPARE(result.mesh.triangles.size(), std::size_t(12));
    QVERIFY2(std::abs(signedVolume(result.mesh) - 1.0) < 1e-6, f.name);
    const bool stl = std::string(f.name).ends_with(".stl");
    // 36 STL corners become 8 vertices.
    QCOMPARE(result.cleanup.duplicateVerticesWelded, std::size_t(stl ? 28 : 0));
    QVERIFY(!result.cleanup.windingReversed);

    // Windows line endings read the same.
    if (f.name == std::string("cube_le.ply") || f.name == std::string("cube_be.ply") ||
        f.name == std::string("cube_binary.stl"))
      continue;
    std::string crlf;
    for (char ch : f.bytes)
      crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
    const fs::path crlfPath = root() / (std::string("crlf_") + f.name);
    writeFile(crlfPath, crlf);
    ValidatedMesh fromCrlf;
    NO_THROW(fromCrlf = loadGenus0Mesh(crlfPath));
    QVERIFY2(sameMesh(fromCrlf.mesh, result.mesh), f.name);
  }
  // OFF may put the counts on the header line.
  std::string off = cubeOff();
  off.replace(0, off.find("8 6 12") + 6, "OFF 8 6 12");
  writeFile(root() / "oneline.off", off);
  NO_THROW(loadGenus0Mesh(root() / "oneline.off"));
}

void MeshValidationTest::openMeshWrittenFilesRead() {
  // Files written by another implementation (OpenMesh's writers: binary PLY and STL) read back
  // as the same closed surface.
  const TriangleMesh blob = extractMesh(makeBaseShape(BaseShape::Blob, 16));
  for (const char* ext : {"obj", "ply", "stl", "off"}) {
    const fs::path path = root() / (std::string("blob.") + ext);
    NO_THROW(writeMesh(blob, path));
    ValidatedMesh result;
    NO_THROW(result = loadGenus0Mesh(path));
    QVERIFY2(checkGenus0(result.mesh).isEmpty(), ext);
    QCOMPARE(result.mesh.positions.size(), blob.positions.size());
    QCOMPARE(result.mesh.triangles.size(), blob.triangles.size());
    QVERIFY(std::abs(signedVolume(result.mesh) - signedVolume(blob)) <= 1e-5 * signedVolume(blob));
  }
}

void MeshValidationTest::truncatedFiles() {
  // Every prefix of every sample file: an Error, or (when only trailing whitespace or the
  // final newline was cut) exactly the full file's mesh. Never a crash or a different mesh.
  std::size_t refused = 0, accepted = 0;
  for (const SampleFile& f : cubeFiles()) {
    const fs::path full = root() / f.name;
    writeFile(full, f.bytes);
    const TriangleMesh expected = loadGenus0Mesh(full).mesh;
    const fs::path cut = root() / (std::string("cut_") + f.name);
    for (std::size_t length = 0; length < f.bytes.size(); ++length) {
      writeFile(cut, f.bytes.substr(0, length));
      try {
        const ValidatedMesh result = loadGenus0Mesh(cut);
        if (!sameMesh(result.mesh, expected))
          QFAIL(qPrintable(
              QString("%1 cut to %2 bytes loads a different mesh").arg(f.name).arg(length)));
        ++accepted;
      } catch (const Error& e) {
        if (e.kind() != ErrorKind::InvalidInput || std::string(e.what()).empty())
          QFAIL(qPrintable(QString("%1 cut to %2: kind %3: %4")
                               .arg(f.name)
                               .arg(length)
                               .arg(int(e.kind()))
                               .arg(e.what())));
        ++refused;
      }
    }
  }
  qInfo("%zu truncated files refused, %zu accepted as the full mesh", refused, accepted);
  QVERIFY(refused > 1000);
}

void MeshValidationTest::damagedBytes() {
  // Random byte damage (a fixed seed): an Error or a valid genus-0 mesh, never a crash.
  std::mt19937 random(6);
  std::size_t refused = 0;
  for (const SampleFile& f : cubeFiles()) {
    const fs::path path = root() / (std::string("damaged_") + f.name);
    for (int trial = 0; trial < 200; ++trial) {
      std::string bytes = f.bytes;
      const int hits = 1 + int(random() % 4);
      for (int h = 0; h < hits; ++h)
        bytes[random() % bytes.size()] = char(random() % 256);
      writeFile(path, bytes);
      try {
        const ValidatedMesh result = loadGenus0Mesh(path);
        QVERIFY2(checkGenus0(result.mesh).isEmpty(), f.name);
      } catch (const Error& e) {
        QVERIFY(!std::string(e.what()).empty());
        ++refused;
      }
    }
  }
  qInfo("%zu of 1400 damaged files refused", refused);
}

void MeshValidationTest::badFiles() {
  const fs::path r = root();
  EXPECT_ERROR(loadGenus0Mesh(r / "missing.obj"), ErrorKind::Io, "missing.obj");
  fs::create_directory(r / "folder.obj");
  EXPECT_ERROR(loadGenus0Mesh(r / "folder.obj"), ErrorKind::Io);
  writeFile(r / "cube.txt", cubeObj());
  EXPECT_ERROR(loadGenus0Mesh(r / "cube.txt"), ErrorKind::InvalidArgument, ".obj");

  for (const char* ext : {"obj", "ply", "stl", "off"}) {
    const fs::path empty = r / (std::string("empty.") + ext);
    writeFile(empty, "");
    EXPECT_ERROR(loadGenus0Mesh(empty), ErrorKind::InvalidInput, "empty");
    writeFile(empty, " \n\n \t\n");
    EXPECT_ERROR(loadGenus0Mesh(empty), ErrorKind::InvalidInput, "empty");
    // Not a mesh: an image's bytes and a text file.
    const fs::path png = r / (std::string("picture.") + ext);
    std::string bytes = "\x89PNG\r\n\x1a\n";
    for (int k = 0; k < 300; ++k)
      bytes += char((k * 37) % 256);
    writeFile(png, bytes);
    EXPECT_ERROR(loadGenus0Mesh(png), ErrorKind::InvalidInput);
    const fs::path text = r / (std::string("letter.") + ext);
    writeFile(text, "Dear reader,\nthis is not a mesh.\n");
    EXPECT_ERROR(loadGenus0Mesh(text), ErrorKind::InvalidInput);
  }

  auto expectFile = [&](const char* name, const std::string& contents,
                        const std::vector<std::string>& needles) {
    writeFile(r / name, contents);
    return expectError([&] { loadGenus0Mesh(r / name); }, ErrorKind::InvalidInput, needles);
  };
  const std::string tetraV = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";
  const std::string tetraF = "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n";
  QCOMPARE(expectFile("ok.obj", tetraV + tetraF, {}), QString("did not throw"));
  QVERIFY(expectFile("points.obj", tetraV, {"no faces"}).isEmpty());
  QVERIFY(expectFile("nan.obj", "v 0 0 0\nv 1 nan 0\nv 0 1 0\nv 0 0 1\n" + tetraF,
                     {"vertex 2", "not a finite number"})
              .isEmpty());
  QVERIFY(expectFile("inf.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1e60\n" + tetraF,
                     {"vertex 4", "not a finite number"})
              .isEmpty());
  QVERIFY(expectFile("range.obj", tetraV + "f 1 3 2\nf 1 2 9\nf 1 4 3\nf 2 3 4\n",
                     {"line 6", "vertex 9", "only 4 vertices"})
              .isEmpty());
  QVERIFY(expectFile("zero.obj", tetraV + "f 0 3 2\n", {"line 5", "index 0"}).isEmpty());
  QVERIFY(expectFile("relative.obj", tetraV + "f -1 -2 -9\n", {"line 5", "-9"}).isEmpty());
  QVERIFY(expectFile("lowest.obj", tetraV + "f -9223372036854775808 1 2\n", {"line 5"}).isEmpty());
  QVERIFY(
      expectFile("overflow.obj", tetraV + "f 99999999999999999999 1 2\n", {"line 5"}).isEmpty());
  QVERIFY(expectFile("word.obj", tetraV + "f 1 2 x\n", {"line 5", "'x'"}).isEmpty());
  QVERIFY(expectFile("short.obj", "v 0 0\n", {"line 1", "three coordinates"}).isEmpty());
  // Relative indices and faces that refer to vertices defined later are fine.
  QCOMPARE(expectFile("relative_ok.obj",
                      tetraV + "f -4 -2 -3\nf -4 -3 -1\nf -4 -1 -2\nf -3 -2 -1\n", {}),
           QString("did not throw"));
  QCOMPARE(expectFile("forward.obj", tetraF + tetraV, {}), QString("did not throw"));

  QVERIFY(expectFile("range.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 4\n",
                     {"vertex index 4", "4 vertices"})
              .isEmpty());
  QVERIFY(expectFile("nan.off",
                     "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\nnan 0 1\n3 0 2 1\n3 0 1 3\n"
                     "3 0 3 2\n3 1 2 3\n",
                     {"vertex 4", "not a finite number"})
              .isEmpty());
  QVERIFY(expectFile("huge.off", "OFF\n4000000000 4 6\n0 0 0\n", {"truncated"}).isEmpty());
  QVERIFY(
      expectFile("points.off", "OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n", {"no faces"}).isEmpty());
  QVERIFY(expectFile("4d.off", "4OFF\n", {"3-D"}).isEmpty());

  std::string ply = plyHeader("ascii");
  for (const Vec3f& p : kCubeVertices)
    ply += std::to_string(p.x) + " " + std::to_string(p.y) + " " + std::to_string(p.z) + " 0\n";
  QVERIFY(expectFile("range.ply", ply + "3 0 1 8\n", {"face 1", "vertex index 8"}).isEmpty());
  QVERIFY(expectFile("negative.ply", ply + "3 0 -1 2\n", {"vertex index -1"}).isEmpty());
  std::string hugePly = plyHeader("binary_little_endian");
  hugePly.replace(hugePly.find("vertex 8"), 8, "vertex 4000000000");
  QVERIFY(expectFile("huge.ply", hugePly, {"truncated"}).isEmpty());
  QVERIFY(expectFile("noheader.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", {"end_header"})
              .isEmpty());
  // Found by ply_reader_fuzzer: a vertex element without properties read no positions while its
  // count still bounded the face indices.
  QVERIFY(expectFile("bare.ply",
                     "ply\nformat ascii 1.0\nelement vertex 4\nelement face 1\n"
                     "property list uchar int vertex_indices\nend_header\n3 0 1 2\n",
                     {"no x, y and z"})
              .isEmpty());
  QVERIFY(expectFile("points.ply",
                     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                     "property float z\nend_header\n0 0 0\n",
                     {"no faces"})
              .isEmpty());

  std::string stl = cubeStlBinary();
  stl.resize(stl.size() - 10);
  QVERIFY(expectFile("truncated.stl", stl, {"truncated"}).isEmpty());
}

void MeshValidationTest::generatedBadMeshes() {
  {
    TriangleMesh m = tetrahedron();
    const TriangleMesh other = tetrahedron({3, 0, 0});
    for (const Tri& t : other.triangles)
      m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "2 components",
                 "keep the largest");
  }
  {
    // Three triangles on one edge: a fin.
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput,
                 "1 edge shared by more than two faces", "vertices 1 and 2");
    // A closed tetrahedron with a fin on one edge.
    m = tetrahedron();
    m.positions.push_back({1, 1, 1});
    m.triangles.push_back({0, 1, 4});
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "shared by more than two");
  }
  {
    // Two tetrahedra sharing vertex 1 (0-based 0).
    TriangleMesh m = tetrahedron();
    const TriangleMesh other = tetrahedron({-1, -1, -1});
    m.positions.insert(m.positions.end(), other.positions.begin() + 1, other.positions.end());
    auto id = [](std::uint32_t v) { return v == 0 ? 0u : v + 3; };
    for (const Tri& t : other.triangles)
      m.triangles.push_back({id(t[0]), id(t[1]), id(t[2])});
    m.positions[0] = {0, 0, 0};
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "vertex 1 is a pinch",
                 "2 separate fans");
  }
  EXPECT_ERROR(validateGenus0Mesh(torus(12)), ErrorKind::InvalidInput, "genus 1", "one handle");
  EXPECT_ERROR(validateGenus0Mesh(TriangleMesh{}), ErrorKind::InvalidInput, "no faces");
  {
    TriangleMesh m = tetrahedron();
    m.positions[2].y = std::numeric_limits<float>::quiet_NaN();
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "vertex 3", "not a finite");
    m = tetrahedron();
    m.positions[3].z = std::numeric_limits<float>::infinity();
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "vertex 4", "not a finite");
    m = tetrahedron();
    m.triangles[2][1] = 7;
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "triangle 3", "vertex 8",
                 "only 4 vertices");
    // Only degenerate faces.
    m.triangles = {{0, 0, 1}, {2, 2, 2}};
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "2 degenerate faces");
  }
  {
    // A Möbius strip of 5 quads: no consistent side.
    TriangleMesh m;
    const int n = 5;
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n;
      m.positions.push_back({float(std::cos(u)), float(std::sin(u)), -0.2f});
      m.positions.push_back({float(std::cos(u)), float(std::sin(u)), 0.2f});
    }
    for (std::uint32_t i = 0; i < n; ++i) {
      const std::uint32_t a = 2 * i, b = 2 * i + 1;
      // The last quad joins the strip's ends with a half twist.
      const std::uint32_t c = i + 1 < n ? 2 * i + 2 : 1, d = i + 1 < n ? 2 * i + 3 : 0;
      m.triangles.push_back({a, c, d});
      m.triangles.push_back({a, d, b});
    }
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "not orientable");
  }
  {
    // A flat closed pillow: a square on both sides with different diagonals; genus 0 but no
    // volume.
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 0, 3}, {1, 3, 2}};
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "no volume");
  }
  {
    // Open: a tetrahedron without one face, without --fill-holes.
    TriangleMesh m = tetrahedron();
    m.triangles.pop_back();
    EXPECT_ERROR(validateGenus0Mesh(m), ErrorKind::InvalidInput, "open: 1 hole", "3 boundary edges",
                 "--fill-holes");
  }
}

void MeshValidationTest::cleanupOfFixableMeshes() {
  {
    // Inward winding, unused vertices at both ends, a face with a repeated corner, a duplicate
    // face and a face turned against its neighbours.
    TriangleMesh m = octahedron();
    for (Tri& t : m.triangles)
      std::swap(t[1], t[2]);
    m.positions.insert(m.positions.begin(), Vec3f{9, 9, 9});
    for (Tri& t : m.triangles)
      for (std::uint32_t& v : t)
        ++v;
    m.positions.push_back({7, 7, 7});
    m.triangles.push_back({1, 1, 3});
    m.triangles.push_back(m.triangles[2]);
    std::swap(m.triangles[4][0], m.triangles[4][1]);
    ValidatedMesh result;
    NO_THROW(result = validateGenus0Mesh(m));
    QVERIFY(checkGenus0(result.mesh).isEmpty());
    QCOMPARE(result.mesh.positions.size(), std::size_t(6));
    QCOMPARE(result.mesh.triangles.size(), std::size_t(8));
    QCOMPARE(result.cleanup.unusedVerticesRemoved, std::size_t(2));
    QCOMPARE(result.cleanup.degenerateFacesRemoved, std::size_t(1));
    QCOMPARE(result.cleanup.duplicateFacesRemoved, std::size_t(1));
    QCOMPARE(result.cleanup.facesFlipped, std::size_t(1));
    QVERIFY(result.cleanup.windingReversed);
    QCOMPARE(result.mesh.positions, octahedron().positions); // file order kept
  }
  {
    // A collinear face is kept and counted: dropping it would open a hole. A tetrahedron whose
    // edge 0–1 is split by vertex 4 on one side only; the sliver (0, 1, 4) closes the seam.
    TriangleMesh m;
    m.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {0, 0, 2}, {1, 0, 0}};
    m.triangles = {{0, 2, 1}, {0, 4, 3}, {4, 1, 3}, {0, 3, 2}, {1, 2, 3}, {0, 1, 4}};
    ValidatedMesh result;
    NO_THROW(result = validateGenus0Mesh(m));
    QVERIFY(checkGenus0(result.mesh).isEmpty());
    QCOMPARE(result.cleanup.zeroAreaFacesKept, std::size_t(1));
  }
}

void MeshValidationTest::fillHolesSmall() {
  ValidationOptions fill;
  fill.fillHoles = true;
  {
    // A three-edge hole gets one triangle and no new vertex.
    TriangleMesh m = tetrahedron();
    m.triangles.erase(m.triangles.begin() + 1);
    ValidatedMesh result;
    NO_THROW(result = validateGenus0Mesh(m, fill));
    QVERIFY(checkGenus0(result.mesh).isEmpty());
    QCOMPARE(result.cleanup.holesFilled, std::size_t(1));
    QCOMPARE(result.mesh.positions.size(), std::size_t(4));
    QCOMPARE(result.mesh.triangles.size(), std::size_t(4));
    QVERIFY(std::abs(signedVolume(result.mesh) - 1.0 / 6) < 1e-6);
  }
  {
    // Two holes in an octahedron, one of 4 edges (two faces removed) and, with the winding of
    // the rest inward, filled consistently with a centroid fan.
    TriangleMesh m = octahedron();
    for (Tri& t : m.triangles)
      std::swap(t[1], t[2]);
    m.triangles.erase(m.triangles.begin(), m.triangles.begin() + 2); // (0 2 4), (2 1 4): 4 edges
    ValidatedMesh result;
    NO_THROW(result = validateGenus0Mesh(m, fill));
    QVERIFY(checkGenus0(result.mesh).isEmpty());
    QCOMPARE(result.cleanup.holesFilled, std::size_t(1));
    QCOMPARE(result.mesh.positions.size(), std::size_t(7));
    QCOMPARE(result.mesh.triangles.size(), std::size_t(10));
    QVERIFY(result.cleanup.windingReversed);
    // A limit below the hole's size refuses, saying what is left.
    fill.maxHoleEdges = 3;
    EXPECT_ERROR(validateGenus0Mesh(m, fill), ErrorKind::InvalidInput, "open: 1 hole",
                 "4 boundary edges", "filling 0 holes of at most 3 edges");
    fill.maxHoleEdges = 64;
  }
}

void MeshValidationTest::fillHolesOpenBunny() {
  // The open bunny's holes: 4 of them have at most 64 edges, the base has 80.
  const fs::path path = kMeshes / "invalid" / "stanford_bunny_open.obj";
  ValidationOptions fill;
  fill.fillHoles = true;
  EXPECT_ERROR(loadGenus0Mesh(path, fill), ErrorKind::InvalidInput, "open: 1 hole",
               "80 boundary edges", "after filling 4 holes of at most 64 edges");
  fill.maxHoleEdges = 80;
  ValidatedMesh result;
  NO_THROW(result = loadGenus0Mesh(path, fill));
  QVERIFY(checkGenus0(result.mesh).isEmpty());
  QCOMPARE(result.cleanup.holesFilled, std::size_t(5));
  QCOMPARE(result.cleanup.unusedVerticesRemoved, std::size_t(1113));
  // Holes of 3 edges get one triangle, larger ones a centroid vertex and one face per edge;
  // 223 edges in all, so at least 223 − 2 × 5 new faces.
  QVERIFY(result.mesh.triangles.size() >= std::size_t(69451 + 223 - 10));
  QVERIFY(result.mesh.triangles.size() <= std::size_t(69451 + 223));
}

void MeshValidationTest::attributesFollowTheCleanup() {
  // The faults of cleanupOfFixableMeshes in an OBJ with colours and texture coordinates: every
  // colour must move with its vertex and every coordinate stay with its corner.
  TriangleMesh m = octahedron();
  for (Tri& t : m.triangles)
    std::swap(t[1], t[2]);
  m.positions.insert(m.positions.begin(), Vec3f{0.5f, 0.25f, 0.125f});
  for (Tri& t : m.triangles)
    for (std::uint32_t& v : t)
      ++v;
  m.positions.push_back({0.75f, 0.75f, 0.75f});
  m.triangles.push_back({1, 1, 3});
  m.triangles.push_back(m.triangles[2]);
  std::swap(m.triangles[4][0], m.triangles[4][1]);
  const fs::path path = root() / "attributed.obj";
  writeFile(path, attributedObj(m, true, true));
  ValidatedMesh r;
  NO_THROW(r = loadGenus0Mesh(path));
  QVERIFY(checkGenus0(r.mesh).isEmpty());
  QCOMPARE(r.cleanup.unusedVerticesRemoved, std::size_t(2));
  QCOMPARE(r.cleanup.facesFlipped, std::size_t(1));
  QVERIFY(r.cleanup.windingReversed);
  const QString why = checkAttributes(r);
  QVERIFY2(why.isEmpty(), qPrintable(why));
  for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      QCOMPARE(r.cornerUv[t][k], uvOf(r.mesh.positions[r.mesh.triangles[t][k]]));
  // No mtllib: the coordinates are kept, with a note that there is no texture.
  QVERIFY(r.diffuseTexture.empty());
  QCOMPARE(r.notes.size(), std::size_t(1));
  QVERIFY(r.notes[0].find("mtllib") != std::string::npos);

  // Filled holes: a centre vertex gets the mean colour of its loop (colour is affine in
  // position, so that is the colour of its position), the loop corners their coordinates.
  TriangleMesh open = octahedron();
  open.triangles.erase(open.triangles.begin(), open.triangles.begin() + 2);
  writeFile(path, attributedObj(open, true, true));
  ValidationOptions fill;
  fill.fillHoles = true;
  NO_THROW(r = loadGenus0Mesh(path, fill));
  QCOMPARE(r.cleanup.holesFilled, std::size_t(1));
  QCOMPARE(r.mesh.positions.size(), std::size_t(7));
  const QString filled = checkAttributes(r);
  QVERIFY2(filled.isEmpty(), qPrintable(filled));
  for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k)
      if (r.mesh.triangles[t][k] < 6)
        QCOMPARE(r.cornerUv[t][k], uvOf(r.mesh.positions[r.mesh.triangles[t][k]]));

  // PLY colours, uchar and float, with alpha; vertices renumbered by the unused one.
  std::string ply = "ply\nformat ascii 1.0\nelement vertex 7\nproperty float x\nproperty float y\n"
                    "property float z\nproperty float nx\nproperty uchar red\n"
                    "property uchar green\nproperty uchar blue\nproperty float alpha\n"
                    "element face 8\nproperty list uchar int vertex_indices\nend_header\n"
                    "9 9 9 0 255 0 0 1\n";
  const TriangleMesh o = octahedron();
  for (const Vec3f& p : o.positions) {
    const auto c = colourBytes(p);
    ply += shortest(p.x) + " " + shortest(p.y) + " " + shortest(p.z) + " 0 " +
           std::to_string(c[0]) + " " + std::to_string(c[1]) + " " + std::to_string(c[2]) +
           " 0.5\n";
  }
  for (const Tri& t : o.triangles)
    ply += "3 " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
           std::to_string(t[2] + 1) + "\n";
  writeFile(root() / "coloured.ply", ply);
  NO_THROW(r = loadGenus0Mesh(root() / "coloured.ply"));
  QCOMPARE(r.vertexColours.size(), std::size_t(6));
  for (std::size_t v = 0; v < 6; ++v) {
    const auto c = colourBytes(r.mesh.positions[v]);
    QCOMPARE(r.vertexColours[v].x, float(c[0]) / 255.0f);
    QCOMPARE(r.vertexColours[v].z, float(c[2]) / 255.0f);
    QCOMPARE(r.vertexColours[v].w, 0.5f);
  }
  QVERIFY(r.cornerUv.empty());
  QVERIFY(r.notes.empty());
}

void MeshValidationTest::attributeNotes() {
  // Attributes that cannot be used are notes; the geometry always imports.
  const TriangleMesh o = octahedron();
  const fs::path dir = root() / "notes";
  fs::create_directories(dir / "maps");
  const fs::path obj = dir / "model.obj";
  auto load = [&](const std::string& text) {
    writeFile(obj, text);
    ValidatedMesh r;
    try {
      r = loadGenus0Mesh(obj);
    } catch (const std::exception& e) {
      qWarning("%s", e.what());
      r.mesh.triangles.clear();
    }
    return r;
  };
  auto noted = [](const ValidatedMesh& r, const std::string& needle) {
    for (const std::string& note : r.notes)
      if (note.find(needle) != std::string::npos) return true;
    QString all;
    for (const std::string& note : r.notes)
      all += QString::fromStdString(note) + " | ";
    qWarning("no note with '%s' among: %s", needle.c_str(), qPrintable(all));
    return false;
  };

  // Colours on some vertices only.
  std::string text = attributedObj(o, true, false);
  text.replace(text.find(" 228 128 128"), 12, "");
  ValidatedMesh r = load(text);
  QCOMPARE(r.mesh.triangles.size(), std::size_t(8));
  QVERIFY(r.vertexColours.empty());
  QVERIFY(noted(r, "only 5 of 6 vertices have colours"));
  // Colours already in [0, 1] are not scaled.
  r = load("v 1 0 0 1 0.5 0\nv -1 0 0 0 0 0\nv 0 1 0 0 0 0\nv 0 -1 0 0 0 0\nv 0 0 1 0 0 0\n"
           "v 0 0 -1 0 0 0.25\nf 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\n"
           "f 1 4 6\n");
  QCOMPARE(r.vertexColours.size(), std::size_t(6));
  QCOMPARE(r.vertexColours[0], (Vec4f{1, 0.5f, 0, 1}));
  QCOMPARE(r.vertexColours[5], (Vec4f{0, 0, 0.25f, 1}));

  // Texture coordinates on some faces only, or a bad vt index: dropped.
  text = attributedObj(o, false, true);
  const std::size_t face = text.find("f ");
  text.replace(face, text.find('\n', face) - face, "f 1 3 5");
  r = load(text);
  QCOMPARE(r.mesh.triangles.size(), std::size_t(8));
  QVERIFY(r.cornerUv.empty());
  QVERIFY(noted(r, "1 of 8 triangles have none"));
  text = attributedObj(o, false, true);
  text.replace(text.find("f 1/24 "), 7, "f 1/99 ");
  r = load(text);
  QCOMPARE(r.mesh.triangles.size(), std::size_t(8));
  QVERIFY(r.cornerUv.empty());
  QVERIFY(noted(r, "texture coordinate 99"));

  // A missing .mtl, a .mtl without map_Kd, a map_Kd naming a missing file.
  r = load(attributedObj(o, false, true, "mtllib absent.mtl\n"));
  QCOMPARE(r.cornerUv.size(), std::size_t(8));
  QVERIFY(noted(r, "material library absent.mtl not found"));
  writeFile(dir / "plain.mtl", "newmtl a\nKd 1 0 0\n");
  r = load(attributedObj(o, false, true, "mtllib plain.mtl\n"));
  QVERIFY(noted(r, "has no diffuse texture"));
  writeFile(dir / "lost.mtl", "newmtl a\nmap_Kd lost.png\n");
  r = load(attributedObj(o, false, true, "mtllib lost.mtl\n"));
  QVERIFY(r.diffuseTexture.empty());
  QVERIFY(noted(r, "texture lost.png (map_Kd of lost.mtl) not found"));

  // Found: options skipped, Windows separators, a name with a space, the second library, and a
  // .mtl in another folder naming its texture relative to itself.
  writeFile(dir / "maps" / "the skin.png", "not read here");
  writeFile(dir / "maps" / "skin.mtl",
            "newmtl a\nmap_Ka ambient.png\nmap_Kd -o 0 0 -s 1 1 1 -clamp on the skin.png\n");
  r = load(attributedObj(o, false, true, "mtllib absent.mtl maps\\skin.mtl\n"));
  QCOMPARE(fs::canonical(r.diffuseTexture), fs::canonical(dir / "maps" / "the skin.png"));
  QVERIFY(noted(r, "absent.mtl not found"));
  // The texture's own absolute path from another machine: found beside the .mtl by name.
  writeFile(dir / "maps" / "far.mtl", "map_Kd C:\\Users\\artist\\the skin.png\n");
  r = load(attributedObj(o, false, true, "mtllib maps/far.mtl\n"));
  QVERIFY(!r.diffuseTexture.empty());
  // A texture but no coordinates: a note, no texture.
  r = load(attributedObj(o, false, false, "mtllib maps/skin.mtl\n"));
  QVERIFY(r.diffuseTexture.empty());
  QVERIFY(noted(r, "no texture coordinates"));
  // PLY colour channels incomplete.
  writeFile(dir / "partial.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                                 "property float y\nproperty float z\nproperty uchar red\n"
                                 "element face 4\nproperty list uchar int vertex_indices\n"
                                 "end_header\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n3 0 2 1\n"
                                 "3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  NO_THROW(r = loadGenus0Mesh(dir / "partial.ply"));
  QVERIFY(r.vertexColours.empty());
  QVERIFY(noted(r, "only some of red, green and blue"));
}

QTEST_GUILESS_MAIN(MeshValidationTest)
#include "mesh_validation_test.moc"
