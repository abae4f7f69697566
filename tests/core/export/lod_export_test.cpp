// Normal maps baked for an LOD and the LOD written with its map: object-space texels are the
// full-resolution normals (core/normals.h) at the texels' image positions; tangent-space texels
// decode through the LOD's interpolated frame to the same normals; PNG and EXR hold them; the
// OBJ (read back through core's mesh reader) and GLB (through tinygltf) carry a closed mesh whose
// texture coordinates tile the image square once; failures leave no file behind.

#include "lod/lod_test_support.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/lod_export.h"
#include "octaclay/core/export/mesh_io.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/triangle_mesh.h"
#include "octaclay/core/lod/lod.h"
#include "octaclay/core/lod/lod_vertices.h"
#include "octaclay/core/lod/normal_map.h"
#include "octaclay/core/lod/saliency.h"

#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <QTemporaryDir>
#include <QtTest>
#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace octaclay::core;
using octaclay::core::testing::bumpySphere;
using octaclay::core::testing::gridLod;
namespace fs = std::filesystem;

Q_DECLARE_METATYPE(octaclay::core::NormalMapSpace)

namespace {

QString expectError(const std::function<void()>& f, ErrorKind kind) {
  try {
    f();
  } catch (const Error& e) {
    if (e.kind() != kind)
      return QString("wrong ErrorKind %1 (expected %2): %3")
          .arg(int(e.kind()))
          .arg(int(kind))
          .arg(e.what());
    if (QByteArray(e.what()).isEmpty()) return "empty message";
    return {};
  } catch (const std::exception& e) {
    return QString("threw a non-core exception: ") + e.what();
  }
  return "did not throw";
}

#define EXPECT_ERROR(call, kind)                                                                   \
  do {                                                                                             \
    const QString why_ = expectError([&] { call; }, kind);                                         \
    QVERIFY2(why_.isEmpty(), qPrintable(why_));                                                    \
  } while (false)

float angleDegrees(Vec3f a, Vec3f b) {
  return std::acos(std::clamp(dot(normalize(a), normalize(b)), -1.0f, 1.0f)) * 57.29578f;
}

Vec3f texel(const NormalMap& map, int x, int y) {
  return map.texels[std::size_t(y) * std::size_t(map.resolution) + std::size_t(x)];
}

// Brute force: the LOD triangle (split vertices) whose image footprint holds p, and p's
// barycentrics in it; the one with the largest smallest barycentric wins at shared edges.
bool locate(const LodVertices& v, Vec2f p, std::size_t& triangle, std::array<float, 3>& bary) {
  float best = -1e9f;
  for (std::size_t t = 0; t < v.triangles.size(); ++t) {
    const Vec2f a = v.uvs[v.triangles[t][0]], b = v.uvs[v.triangles[t][1]],
                c = v.uvs[v.triangles[t][2]];
    const float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (det == 0) continue;
    const float l1 = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
    const float l2 = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
    const float smallest = std::min({1 - l1 - l2, l1, l2});
    if (smallest > best) {
      best = smallest;
      triangle = t;
      bary = {1 - l1 - l2, l1, l2};
    }
  }
  return best > -1e-4f;
}

// What a glTF viewer does with texel m inside triangle t at barycentrics b: interpolate the
// vertices' t, b = cross(n, t)·w and n, normalise each, and map the texel through them.
Vec3f decode(const LodVertices& v, std::size_t t, const std::array<float, 3>& b, Vec3f m) {
  Vec3f tt{}, bb{}, nn{};
  for (int c = 0; c < 3; ++c) {
    const std::uint32_t k = v.triangles[t][std::size_t(c)];
    const Vec3f tan{v.tangents[k][0], v.tangents[k][1], v.tangents[k][2]};
    tt += tan * b[std::size_t(c)];
    bb += cross(v.normals[k], tan) * (v.tangents[k][3] * b[std::size_t(c)]);
    nn += v.normals[k] * b[std::size_t(c)];
  }
  return normalize(normalize(tt) * m.x + normalize(bb) * m.y + normalize(nn) * m.z);
}

// Signed image-space area of each triangle's corners (positive = counter-clockwise in (x, y)).
double uvArea(Vec2f a, Vec2f b, Vec2f c) {
  return 0.5 *
         ((double(b.x) - a.x) * (double(c.y) - a.y) - (double(c.x) - a.x) * (double(b.y) - a.y));
}

std::vector<float> readFloats(const tinygltf::Model& model, int accessorIndex) {
  const tinygltf::Accessor& a = model.accessors[std::size_t(accessorIndex)];
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
  const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
  std::vector<float> values(a.count * std::size_t(components));
  std::memcpy(values.data(),
              model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + a.byteOffset,
              values.size() * sizeof(float));
  return values;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

} // namespace

class LodExportTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase();
  void objectMapIsTheFullResolutionNormal();
  void tangentMapDecodesToTheFullResolutionNormal_data() { addLodRows(); }
  void tangentMapDecodesToTheFullResolutionNormal();
  void foldedTrianglesYieldTheirTexels();
  void tangentFrameFollowsGltf_data() { addLodRows(); }
  void tangentFrameFollowsGltf();
  void badResolutionIsRefused();
  void pngAndExrHoldTheMap();
  void objReadsBackClosedWithSeamSplitTexcoords_data() { addLodRows(); }
  void objReadsBackClosedWithSeamSplitTexcoords();
  void glbReadsBackWithTinygltf_data();
  void glbReadsBackWithTinygltf();
  void failedWritesLeaveNothing();

private:
  fs::path file(const QString& name) const { return fs::path(dir_.filePath(name).toStdString()); }
  QTemporaryDir dir_;
  void addLodRows();
  const LodMesh& lodRow();
  GeometryImage full_;
  LodMesh lod_;                     // the plain subsampled grid: coordinates known exactly
  std::map<QString, LodMesh> lods_; // generateLod's, with and without vertex collapse
};

void LodExportTest::initTestCase() {
  QVERIFY(dir_.isValid());
  full_ = bumpySphere(64);
  lod_ = gridLod(full_, 16);
  lods_["grid"] = lod_;
  GeometryImage salient = full_;
  computeSaliency(salient);
  lods_["salient-point"] =
      generateLod(salient, {.size = 16, .method = ResampleMethod::SalientPoint});
  lods_["average"] = generateLod(salient, {.size = 16, .method = ResampleMethod::Average});
  lods_["collapsed"] = generateLod(salient, {.size = 32, .targetTriangles = 600});
  QVERIFY(lods_["collapsed"].mesh.triangles.size() <= 620);
}

void LodExportTest::addLodRows() {
  QTest::addColumn<QString>("lod");
  for (const auto& [name, lod] : lods_)
    QTest::newRow(qPrintable(name)) << name;
}

const LodMesh& LodExportTest::lodRow() {
  return lods_.at(QTest::currentDataTag() ? QString(QTest::currentDataTag()).section(' ', 0, 0)
                                          : "grid");
}

void LodExportTest::objectMapIsTheFullResolutionNormal() {
  const int n = full_.size();
  // At resolution N/2 texel x's centre is image position (2x + 1)/N: exactly sample 2x + 1.
  const NormalMap halfMap = bakeNormalMap(full_, lod_, NormalMapSpace::Object, n / 2);
  QCOMPARE(halfMap.resolution, n / 2);
  QCOMPARE(halfMap.texels.size(), std::size_t(n / 2) * std::size_t(n / 2));
  float worst = 0;
  for (int y = 0; y < n / 2; ++y)
    for (int x = 0; x < n / 2; ++x)
      worst = std::max(worst,
                       length(texel(halfMap, x, y) - vertexNormal(full_, {2 * x + 1, 2 * y + 1})));
  QVERIFY2(worst < 1e-5f, qPrintable(QString("largest difference %1").arg(worst)));

  // At resolution N a texel sits mid-cell: a unit blend of the cell's corner normals, so no
  // further from the nearest corner than the corners are from each other.
  const NormalMap map = bakeNormalMap(full_, lod_, NormalMapSpace::Object, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) {
      const Vec3f t = texel(map, x, y);
      QVERIFY(std::abs(length(t) - 1) < 1e-5f);
      const Vec3f corners[] = {vertexNormal(full_, {x, y}), vertexNormal(full_, {x + 1, y}),
                               vertexNormal(full_, {x, y + 1}),
                               vertexNormal(full_, {x + 1, y + 1})};
      float spread = 0, nearest = 180;
      for (const Vec3f& a : corners) {
        nearest = std::min(nearest, angleDegrees(a, t));
        for (const Vec3f& b : corners)
          spread = std::max(spread, angleDegrees(a, b));
      }
      QVERIFY2(nearest <= spread + 0.01f, qPrintable(QString("texel %1,%2: %3° from its nearest "
                                                             "corner, corners %4° apart")
                                                         .arg(x)
                                                         .arg(y)
                                                         .arg(nearest)
                                                         .arg(spread)));
    }
}

void LodExportTest::tangentMapDecodesToTheFullResolutionNormal() {
  const LodMesh& lod = lodRow();
  const int r = 48; // not a multiple of M: texel centres fall anywhere in the LOD's triangles
  const NormalMap object = bakeNormalMap(full_, lod, NormalMapSpace::Object, r);
  const NormalMap tangent = bakeNormalMap(full_, lod, NormalMapSpace::Tangent, r);
  QCOMPARE(tangent.space, NormalMapSpace::Tangent);
  const LodVertices v = lodVertices(lod);
  float worst = 0, meanZ = 0, smallestZ = 1;
  for (int y = 0; y < r; ++y)
    for (int x = 0; x < r; ++x) {
      std::size_t t = 0;
      std::array<float, 3> b{};
      QVERIFY(locate(v, {(float(x) + 0.5f) / float(r), (float(y) + 0.5f) / float(r)}, t, b));
      const Vec3f m = texel(tangent, x, y);
      QVERIFY(std::abs(length(m) - 1) < 1e-5f);
      const Vec3f decoded = decode(v, t, b, m);
      worst = std::max(worst, angleDegrees(decoded, texel(object, x, y)));
      meanZ += m.z / float(r * r);
      smallestZ = std::min(smallestZ, m.z);
    }
  QVERIFY2(worst < 0.05f, qPrintable(QString("decoded normals up to %1° off").arg(worst)));
  // The bumps tilt the full normals away from the coarse LOD's, but never past its horizon.
  QVERIFY2(meanZ > 0.9f && meanZ < 0.999f, qPrintable(QString("mean z %1").arg(meanZ)));
  QVERIFY2(smallestZ > 0.3f, qPrintable(QString("smallest z %1").arg(smallestZ)));
}

// Where an LOD's image coordinates fold (a vertex's source sample crossed its neighbour's), the
// folded triangles overlap unfolded ones: those keep the texels, so the majority shades right.
void LodExportTest::foldedTrianglesYieldTheirTexels() {
  LodMesh lod = gridLod(full_, 16);
  const Vec2f from{5.0f / 16, 5.0f / 16}, to{6.5f / 16, 5.5f / 16};
  for (auto& corners : lod.cornerUv)
    for (Vec2f& uv : corners)
      if (uv == from) uv = to;
  const LodVertices v = lodVertices(lod);
  std::vector<bool> folded(v.triangles.size());
  for (std::size_t t = 0; t < v.triangles.size(); ++t)
    folded[t] =
        uvArea(v.uvs[v.triangles[t][0]], v.uvs[v.triangles[t][1]], v.uvs[v.triangles[t][2]]) <= 0;
  QVERIFY(std::count(folded.begin(), folded.end(), true) > 0);

  const int r = 64;
  const NormalMap object = bakeNormalMap(full_, lod, NormalMapSpace::Object, r);
  const NormalMap tangent = bakeNormalMap(full_, lod, NormalMapSpace::Tangent, r);
  int contested = 0;
  float worst = 0;
  for (int y = 0; y < r; ++y)
    for (int x = 0; x < r; ++x) {
      const Vec2f p{(float(x) + 0.5f) / float(r), (float(y) + 0.5f) / float(r)};
      // Under a folded triangle two unfolded ones overlap (the winding number stays 1): the
      // texel must decode right through one of them.
      bool underFold = false;
      float best = 180;
      for (std::size_t t = 0; t < v.triangles.size(); ++t) {
        const Vec2f a = v.uvs[v.triangles[t][0]], b = v.uvs[v.triangles[t][1]],
                    c = v.uvs[v.triangles[t][2]];
        const float det = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const float l1 = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / det;
        const float l2 = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / det;
        const float inside = std::min({1 - l1 - l2, l1, l2});
        if (folded[t]) {
          underFold = underFold || inside > 1e-4f;
        } else if (inside > -1e-4f) {
          const Vec3f decoded = decode(v, t, {1 - l1 - l2, l1, l2}, texel(tangent, x, y));
          best = std::min(best, angleDegrees(decoded, texel(object, x, y)));
        }
      }
      if (!underFold) continue;
      ++contested;
      worst = std::max(worst, best);
    }
  QVERIFY2(contested > 0, "the fold covers no texel");
  QVERIFY2(
      worst < 0.05f,
      qPrintable(
          QString("%1 texels under the fold, decoded up to %2° off").arg(contested).arg(worst)));
}

void LodExportTest::tangentFrameFollowsGltf() {
  const LodMesh& lod = lodRow();
  const LodVertices v = lodVertices(lod);
  QCOMPARE(v.triangles.size(), lod.mesh.triangles.size());
  // Seam vertices are split: more vertices than the welded mesh, each with one uv.
  QVERIFY(v.positions.size() > lod.mesh.positions.size());
  if (&lod == &lods_.at("grid"))
    QCOMPARE(v.positions.size(), std::size_t(17 * 17)); // the (M+1)² grid, M = 16
  for (std::size_t k = 0; k < v.positions.size(); ++k) {
    const Vec3f t{v.tangents[k][0], v.tangents[k][1], v.tangents[k][2]};
    QVERIFY(std::abs(length(t) - 1) < 1e-5f);
    QVERIFY(std::abs(dot(t, v.normals[k])) < 1e-5f);
    QVERIFY(v.tangents[k][3] == 1.0f || v.tangents[k][3] == -1.0f);
    QCOMPARE(v.positions[k], lod.mesh.positions[v.welded[k]]);
  }
  // Along each triangle the (corner-averaged) tangent follows increasing u and the bitangent
  // decreasing v.
  int agreeing = 0;
  for (const auto& tri : v.triangles) {
    const Vec3f p0 = v.positions[tri[0]], e1 = v.positions[tri[1]] - p0,
                e2 = v.positions[tri[2]] - p0;
    const Vec2f w0 = v.uvs[tri[0]], w1 = v.uvs[tri[1]], w2 = v.uvs[tri[2]];
    const float du1 = w1.x - w0.x, dv1 = w1.y - w0.y, du2 = w2.x - w0.x, dv2 = w2.y - w0.y;
    const float det = du1 * dv2 - du2 * dv1;
    const Vec3f dpdu = (e1 * dv2 - e2 * dv1) * (1 / det), dpdv = (e2 * du1 - e1 * du2) * (1 / det);
    Vec3f t{}, b{};
    for (const std::uint32_t k : tri) {
      const Vec3f tk{v.tangents[k][0], v.tangents[k][1], v.tangents[k][2]};
      t += tk;
      b += cross(v.normals[k], tk) * v.tangents[k][3];
      QCOMPARE(v.tangents[k][3], -1.0f); // the octahedral map keeps orientation
    }
    agreeing += dot(t, dpdu) > 0 && dot(b, dpdv) < 0;
  }
  QCOMPARE(agreeing, int(v.triangles.size()));
}

void LodExportTest::badResolutionIsRefused() {
  EXPECT_ERROR(bakeNormalMap(full_, lod_, NormalMapSpace::Object, 1), ErrorKind::InvalidArgument);
  EXPECT_ERROR(bakeNormalMap(full_, lod_, NormalMapSpace::Tangent, 8193),
               ErrorKind::InvalidArgument);
  LodMesh broken = lod_;
  broken.cornerUv.pop_back();
  EXPECT_ERROR(bakeNormalMap(full_, broken, NormalMapSpace::Tangent, 16),
               ErrorKind::InvalidArgument);
  QCOMPARE(parseNormalMapSpace("tangent"), std::optional(NormalMapSpace::Tangent));
  QCOMPARE(parseNormalMapSpace("object"), std::optional(NormalMapSpace::Object));
  QVERIFY(!parseNormalMapSpace("world"));
}

void LodExportTest::pngAndExrHoldTheMap() {
  const NormalMap map = bakeNormalMap(full_, lod_, NormalMapSpace::Tangent, 40);
  const fs::path png = file("map.png"), exr = file("map.exr");
  writeNormalMap(map, png);
  const RasterImage image = readImage(png, 3);
  QCOMPARE(image.width, 40);
  QCOMPARE(image.height, 40);
  float worst = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const Vec3f n = texel(map, x, y);
      const float expected[] = {n.x, n.y, n.z};
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(image.at(x, y, c) - (expected[c] * 0.5f + 0.5f)));
    }
  QVERIFY2(worst <= 0.5f / 255 + 1e-6f, qPrintable(QString("PNG off by %1").arg(worst)));

  writeNormalMap(map, exr);
  Imf::InputFile in(exr.c_str());
  const Imath::Box2i window = in.header().dataWindow();
  QCOMPARE(window.max.x - window.min.x + 1, 40);
  std::vector<float> rgb(40 * 40 * 3);
  Imf::FrameBuffer frame;
  const char* names[] = {"R", "G", "B"};
  for (int c = 0; c < 3; ++c)
    frame.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgb.data() + c),
                                      3 * sizeof(float), 40 * 3 * sizeof(float)));
  in.setFrameBuffer(frame);
  in.readPixels(window.min.y, window.max.y);
  QVERIFY(std::memcmp(rgb.data(), map.texels.data(), rgb.size() * sizeof(float)) == 0);

  EXPECT_ERROR(writeNormalMap(map, file("map.tga")), ErrorKind::InvalidArgument);
  QVERIFY(!fs::exists(file("map.tga")));
}

void LodExportTest::objReadsBackClosedWithSeamSplitTexcoords() {
  const LodMesh& lod = lodRow();
  const NormalMap map = bakeNormalMap(full_, lod, NormalMapSpace::Object, 32);
  const QString stem = QTest::currentDataTag();
  const fs::path obj = file(stem + ".obj");
  const std::vector<fs::path> files = writeLodMesh(lod, map, obj);
  QCOMPARE(files.size(), std::size_t(3));
  QCOMPARE(files[0], obj);
  QCOMPARE(files[1], file(stem + ".mtl"));
  QCOMPARE(files[2], file(stem + "_normal.png"));
  for (const fs::path& f : files)
    QVERIFY2(fs::exists(f), f.c_str());

  const TriangleMesh back = readMesh(obj);
  QCOMPARE(back.triangles.size(), lod.mesh.triangles.size());
  const MeshTopology topology = analyzeTopology(back);
  QVERIFY(topology.closed());
  QVERIFY(topology.manifold());
  QCOMPARE(topology.euler, 2LL);
  QCOMPARE(topology.vertices, lod.mesh.positions.size());
  QVERIFY(signedVolume(back) > 0);

  // Texture coordinates: inside [0, 1], and the triangles' image footprints tile the square
  // exactly once, all counter-clockwise: a triangle spanning a seam would overlap others.
  std::vector<Vec2f> vt;
  std::vector<std::array<int, 3>> faces;
  std::istringstream lines(readText(obj));
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::string key;
    in >> key;
    if (key == "vt") {
      Vec2f uv;
      in >> uv.x >> uv.y;
      vt.push_back({uv.x, 1 - uv.y});
    } else if (key == "f") {
      std::array<int, 3> f{};
      for (int& k : f) {
        std::string corner;
        in >> corner;
        k = std::stoi(corner.substr(corner.find('/') + 1)) - 1;
      }
      faces.push_back(f);
    }
  }
  QCOMPARE(faces.size(), lod.mesh.triangles.size());
  QVERIFY(vt.size() > lod.mesh.positions.size()); // seam vertices have several
  for (const Vec2f uv : vt)
    QVERIFY(uv.x >= 0 && uv.x <= 1 && uv.y >= 0 && uv.y <= 1);
  double total = 0, smallest = 1;
  for (const auto& f : faces) {
    const double a = uvArea(vt[std::size_t(f[0])], vt[std::size_t(f[1])], vt[std::size_t(f[2])]);
    total += a;
    smallest = std::min(smallest, a);
  }
  QVERIFY2(std::abs(total - 1) < 1e-5, qPrintable(QString("footprints cover %1").arg(total)));
  QVERIFY(smallest > 0);

  const std::string mtl = readText(files[1]);
  const std::string mapName = (stem + "_normal.png").toStdString();
  QVERIFY(mtl.find("norm " + mapName + "\n") != std::string::npos);
  QVERIFY(mtl.find("map_Bump " + mapName + "\n") != std::string::npos);
  QVERIFY(readText(obj).find("mtllib " + (stem + ".mtl").toStdString()) != std::string::npos);
  const RasterImage image = readImage(files[2], 3);
  QCOMPARE(image.width, 32);
}

void LodExportTest::glbReadsBackWithTinygltf_data() {
  QTest::addColumn<NormalMapSpace>("space");
  QTest::newRow("tangent") << NormalMapSpace::Tangent;
  QTest::newRow("object") << NormalMapSpace::Object;
}

void LodExportTest::glbReadsBackWithTinygltf() {
  QFETCH(NormalMapSpace, space);
  const NormalMap map = bakeNormalMap(full_, lod_, space, 32);
  const fs::path path = file(QString("lod-%1.glb").arg(int(space)));
  QCOMPARE(writeLodMesh(lod_, map, path), std::vector<fs::path>{path});

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  QVERIFY2(loader.LoadBinaryFromFile(&model, &err, &warn, path.string()), err.c_str());
  QCOMPARE(model.meshes.size(), std::size_t(1));
  const tinygltf::Primitive& primitive = model.meshes[0].primitives.at(0);
  for (const char* attribute : {"POSITION", "NORMAL", "TANGENT", "TEXCOORD_0"})
    QVERIFY2(primitive.attributes.count(attribute) == 1, attribute);
  const LodVertices v = lodVertices(lod_);
  const std::vector<float> positions = readFloats(model, primitive.attributes.at("POSITION"));
  const std::vector<float> tangents = readFloats(model, primitive.attributes.at("TANGENT"));
  const std::vector<float> uvs = readFloats(model, primitive.attributes.at("TEXCOORD_0"));
  const std::vector<float> normals = readFloats(model, primitive.attributes.at("NORMAL"));
  QCOMPARE(positions.size(), 3 * v.positions.size());
  QCOMPARE(tangents.size(), 4 * v.positions.size());
  for (std::size_t k = 0; k < v.positions.size(); ++k) {
    // The frame the tangent-space map was baked in, exactly.
    for (std::size_t c = 0; c < 4; ++c)
      QCOMPARE(tangents[4 * k + c], v.tangents[k][c]);
    QCOMPARE((Vec3f{normals[3 * k], normals[3 * k + 1], normals[3 * k + 2]}), v.normals[k]);
    QCOMPARE((Vec2f{uvs[2 * k], uvs[2 * k + 1]}), v.uvs[k]);
    QVERIFY(uvs[2 * k] >= 0 && uvs[2 * k] <= 1 && uvs[2 * k + 1] >= 0 && uvs[2 * k + 1] <= 1);
  }
  // Welding equal positions gives back the LOD's vertices.
  std::set<std::array<float, 3>> distinct;
  for (std::size_t k = 0; k < positions.size(); k += 3)
    distinct.insert({positions[k], positions[k + 1], positions[k + 2]});
  QCOMPARE(distinct.size(), lod_.mesh.positions.size());
  QCOMPARE(model.accessors[std::size_t(primitive.indices)].count, 3 * lod_.mesh.triangles.size());

  const tinygltf::Material& material = model.materials.at(std::size_t(primitive.material));
  QCOMPARE(model.images.size(), std::size_t(1));
  const tinygltf::Image& image = model.images[0];
  QCOMPARE(image.width, 32);
  QCOMPARE(image.height, 32);
  if (space == NormalMapSpace::Tangent) {
    QCOMPARE(material.normalTexture.index, 0);
  } else {
    QCOMPARE(material.normalTexture.index, -1); // viewers would misread object-space normals
    QVERIFY(material.extras.Has("octaclay_object_space_normal_texture"));
  }
  // The embedded PNG is the map: texel (5, 7) as n·0.5 + 0.5.
  const Vec3f n = texel(map, 5, 7);
  const std::size_t at = (7 * 32 + 5) * std::size_t(image.component);
  QVERIFY(std::abs(float(image.image[at]) / 255 - (n.x * 0.5f + 0.5f)) <= 0.5f / 255 + 1e-6f);
  QVERIFY(std::abs(float(image.image[at + 2]) / 255 - (n.z * 0.5f + 0.5f)) <= 0.5f / 255 + 1e-6f);
}

void LodExportTest::failedWritesLeaveNothing() {
  const NormalMap map = bakeNormalMap(full_, lod_, NormalMapSpace::Object, 16);
  const fs::path folder = file("failures");
  fs::create_directory(folder);
  const auto file = [&](const char* name) { return folder / name; };
  // No such folder: nothing at all is written.
  const fs::path missing = file("no-such-folder/lod.obj");
  EXPECT_ERROR(writeLodMesh(lod_, map, missing), ErrorKind::Io);
  QVERIFY(!fs::exists(missing.parent_path()));
  // The material cannot be written (a folder has its name) after the map was: the map is
  // taken back and no OBJ appears.
  const fs::path obj = file("blocked.obj");
  fs::create_directory(file("blocked.mtl"));
  EXPECT_ERROR(writeLodMesh(lod_, map, obj), ErrorKind::Io);
  QVERIFY(!fs::exists(obj));
  QVERIFY(!fs::exists(file("blocked_normal.png")));
  // Unknown extension and an empty LOD: refused before anything is written.
  EXPECT_ERROR(writeLodMesh(lod_, map, file("lod.fbx")), ErrorKind::InvalidArgument);
  QVERIFY(!fs::exists(file("lod.fbx")));
  EXPECT_ERROR(writeLodMesh(LodMesh{}, map, file("empty.glb")), ErrorKind::InvalidArgument);
  QVERIFY(!fs::exists(file("empty.glb")));
  const std::size_t files =
      std::size_t(std::distance(fs::directory_iterator(folder), fs::directory_iterator{}));
  QCOMPARE(files, std::size_t(1)); // only the blocking folder
}

QTEST_GUILESS_MAIN(LodExportTest)
#include "lod_export_test.moc"
