// Textured export (core/textured_export.h): the OBJ's welded vertices, texture coordinates that
// land on the painted texels of the PNG maps, seams split only in `vt`, the MTL; the .glb read back
// with tinygltf's loader (octaclay_core links the Debian tinygltf library privately, which puts it
// on this test's link line too); and the errors.

#include "octaclay/core/document/document.h"
#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/export/textured_export.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/mesh_extraction.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/vertex_index.h"

#include <QtTest>
#include <tiny_gltf.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

constexpr float kTolerance = 1.0f / 255 + 1e-4f; // 8-bit maps

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

// The painted colour of texel (x, y): every channel varies so a swapped axis, flipped v or
// off-by-one texel shows.
std::array<float, 4> paintedColour(int n, int x, int y) {
  return {float(x) / float(n), float(y) / float(n), float((x * 7 + y * 3) % 16) / 15.0f,
          0.5f + 0.5f * float((x + y) % 2)};
}
// Feature: R height, G specular, B reflectivity.
std::array<float, 3> paintedFeature(int n, int x, int y) {
  return {float((x + 2 * y) % 8) / 7.0f, float(n - x) / float(n), float(y * x % 11) / 10.0f};
}

Document paintedDocument(int n) {
  Document doc = makeDocument(makeBaseShape(BaseShape::Blob, n));
  const int side = n + 1;
  doc.diffuse.texels.resize(std::size_t(side) * side * 4);
  doc.feature.texels.resize(std::size_t(side) * side * 3);
  for (int y = 0; y < side; ++y)
    for (int x = 0; x < side; ++x) {
      const std::size_t t = std::size_t(y) * side + x;
      const auto c = paintedColour(n, x, y);
      const auto f = paintedFeature(n, x, y);
      for (int k = 0; k < 4; ++k)
        doc.diffuse.texels[t * 4 + k] = c[k];
      for (int k = 0; k < 3; ++k)
        doc.feature.texels[t * 3 + k] = f[k];
    }
  return doc;
}

struct Obj {
  std::vector<Vec3f> positions, normals;
  std::vector<std::array<float, 2>> texcoords;
  std::vector<std::array<std::array<long, 3>, 3>> faces; // v/vt/vn, 1-based
  std::string mtllib, usemtl;
};

Obj readObj(const fs::path& path) {
  Obj obj;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "v") {
      std::array<std::string, 3> text;
      s >> text[0] >> text[1] >> text[2];
      obj.positions.push_back({std::stof(text[0]), std::stof(text[1]), std::stof(text[2])});
    } else if (key == "vt") {
      std::array<float, 2> t{};
      s >> t[0] >> t[1];
      obj.texcoords.push_back(t);
    } else if (key == "vn") {
      Vec3f v;
      s >> v.x >> v.y >> v.z;
      obj.normals.push_back(v);
    } else if (key == "f") {
      std::array<std::array<long, 3>, 3> f{};
      for (auto& corner : f) {
        std::string c;
        s >> c;
        char slash = 0;
        std::istringstream cs(c);
        cs >> corner[0] >> slash >> corner[1] >> slash >> corner[2];
      }
      obj.faces.push_back(f);
    } else if (key == "mtllib") {
      s >> obj.mtllib;
    } else if (key == "usemtl") {
      s >> obj.usemtl;
    }
  }
  return obj;
}

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The image pixel a texture coordinate (u right, v down) falls in.
std::array<int, 2> pixelOf(float u, float v, int width) {
  return {int(std::floor(u * float(width))), int(std::floor(v * float(width)))};
}

// Accessor data as floats (tightly packed float components), through its buffer view.
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

float imageAt(const tinygltf::Image& image, int x, int y, int c) {
  return float(image.image[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) *
                               std::size_t(image.component) +
                           std::size_t(c)]) /
         255.0f;
}

} // namespace

class TexturedExportTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void objSamplesTexcoordsAndMaps_data();
  void objSamplesTexcoordsAndMaps();
  void unpaintedLayersGiveUniformMaps();
  void glbReadsBackWithTinygltf_data();
  void glbReadsBackWithTinygltf();
  void errors();

private:
  fs::path file(const QString& name) const { return fs::path(dir_.filePath(name).toStdString()); }
  QTemporaryDir dir_;
};

void TexturedExportTest::objSamplesTexcoordsAndMaps_data() {
  QTest::addColumn<int>("n");
  QTest::addColumn<int>("step");
  QTest::newRow("N=16 full") << 16 << 1;
  QTest::newRow("N=16 step 2") << 16 << 2;
  QTest::newRow("N=32 step 8") << 32 << 8;
}

void TexturedExportTest::objSamplesTexcoordsAndMaps() {
  QFETCH(int, n);
  QFETCH(int, step);
  const Document doc = paintedDocument(n);
  const int m = n / step, side = n + 1;
  const fs::path path = file(QString("painted-%1-%2.obj").arg(n).arg(step));
  writeTexturedObj(doc, step, path);

  const std::vector<fs::path> files = texturedObjFiles(path);
  QCOMPARE(int(files.size()), 6);
  for (const fs::path& f : files)
    QVERIFY2(fs::is_regular_file(f), f.string().c_str());
  const std::string stem = path.stem().string();
  QCOMPARE(files[1].filename().string(), stem + ".mtl");
  QCOMPARE(files[2].filename().string(), stem + "_diffuse.png");
  QCOMPARE(files[3].filename().string(), stem + "_specular.png");
  QCOMPARE(files[4].filename().string(), stem + "_reflectivity.png");
  QCOMPARE(files[5].filename().string(), stem + "_height.png");
  // Nothing else beside them (no temporaries left).
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(path.parent_path()))
    if (e.path().stem().string().rfind(stem, 0) == 0 || e.path().filename().string()[0] == '.')
      ++entries;
  QCOMPARE(entries, 6);

  const Obj obj = readObj(path);
  const std::size_t count = std::size_t(m + 1) * std::size_t(m + 1);
  const std::size_t vertices = std::size_t(m) * std::size_t(m) + 2;
  QCOMPARE(obj.positions.size(), vertices); // each position once
  QCOMPARE(obj.texcoords.size(), count);
  QCOMPARE(obj.normals.size(), vertices);
  QCOMPARE(obj.faces.size(), 2 * std::size_t(m) * std::size_t(m));
  QCOMPARE(obj.mtllib, files[1].filename().string());
  QVERIFY(!obj.usemtl.empty());

  // Grid vertex (i, j) is image sample (i·step, j·step), welded vertex welded.at(i, j); its
  // texcoord is that texel's centre.
  const VertexIndex welded(n, step);
  const RasterImage diffuse = readImage(files[2], 4);
  QCOMPARE(diffuse.width, side);
  QCOMPARE(diffuse.height, side);
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      const std::size_t k = std::size_t(j) * std::size_t(m + 1) + std::size_t(i);
      const auto [u, v] = obj.texcoords[k];
      QVERIFY2(u > 0 && u < 1 && v > 0 && v < 1, qPrintable(QString("vt %1 %2").arg(u).arg(v)));
      const auto [x, y] = pixelOf(u, 1 - v, side); // OBJ's v points up
      QCOMPARE(x, i * step);
      QCOMPARE(y, j * step);
      const auto colour = paintedColour(n, x, y);
      for (int c = 0; c < 4; ++c)
        QVERIFY2(std::abs(diffuse.at(x, y, c) - colour[std::size_t(c)]) <= kTolerance,
                 qPrintable(QString("texel %1,%2 channel %3: %4, painted %5")
                                .arg(x)
                                .arg(y)
                                .arg(c)
                                .arg(diffuse.at(x, y, c))
                                .arg(colour[std::size_t(c)])));
      const Vec3f p = doc.positions.at(i * step, j * step).xyz();
      QVERIFY(length(obj.positions[welded.at(i, j)] - p) < 1e-6f);
      QVERIFY(std::abs(length(obj.normals[welded.at(i, j)]) - 1) < 1e-4f);
    }

  // Seams: identified samples are one vertex with their own texcoords.
  int duplicates = 0;
  for (int j = 0; j <= m; ++j)
    for (int i = 0; i <= m; ++i) {
      std::array<Sample, 4> same{};
      const int k = identifiedSamples(m, {i, j}, same);
      for (int s = 0; s < k; ++s) {
        if (same[std::size_t(s)] == Sample{i, j}) continue;
        const std::size_t a = std::size_t(j) * std::size_t(m + 1) + std::size_t(i);
        const std::size_t b = std::size_t(same[std::size_t(s)].j) * std::size_t(m + 1) +
                              std::size_t(same[std::size_t(s)].i);
        QCOMPARE(welded.at(i, j), welded.at(same[std::size_t(s)].i, same[std::size_t(s)].j));
        QVERIFY(obj.texcoords[a] != obj.texcoords[b]);
        ++duplicates;
      }
    }
  QVERIFY(duplicates >= 4 * m);

  // Faces: v = vn are extractMesh's vertices and triangles, in order (same split, same
  // orientation), and vt is the grid sample of the corner.
  const TriangleMesh mesh = extractMesh(doc.positions, step);
  QCOMPARE(mesh.positions.size(), vertices);
  for (std::size_t k = 0; k < vertices; ++k)
    QCOMPARE(obj.positions[k], mesh.positions[k]);
  for (std::size_t f = 0; f < obj.faces.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      const auto& corner = obj.faces[f][std::size_t(c)];
      QCOMPARE(corner[2], corner[0]);
      QCOMPARE(std::uint32_t(corner[0] - 1), mesh.triangles[f][std::size_t(c)]);
      QVERIFY(corner[1] >= 1 && std::size_t(corner[1]) <= count);
      const long k = corner[1] - 1;
      QCOMPARE(welded.at(int(k % (m + 1)), int(k / (m + 1))), mesh.triangles[f][std::size_t(c)]);
    }

  // The MTL names the maps and the material the OBJ uses.
  const std::string mtl = readText(files[1]);
  QVERIFY2(mtl.find("newmtl " + obj.usemtl) != std::string::npos, mtl.c_str());
  QVERIFY2(mtl.find("Kd 1 1 1") != std::string::npos, mtl.c_str());
  QVERIFY2(mtl.find("\nNs ") != std::string::npos, mtl.c_str());
  QVERIFY2(mtl.find("map_Kd " + files[2].filename().string()) != std::string::npos, mtl.c_str());
  QVERIFY2(mtl.find("map_Ks " + files[3].filename().string()) != std::string::npos, mtl.c_str());
  QVERIFY2(mtl.find("map_refl " + files[4].filename().string()) != std::string::npos, mtl.c_str());

  // Feature maps at full resolution: specular = G, reflectivity = B, height = R.
  for (int k = 3; k <= 5; ++k) {
    const RasterImage map = readImage(files[std::size_t(k)], 1);
    QCOMPARE(map.width, side);
    QCOMPARE(map.height, side);
    const int channel = k == 3 ? 1 : k == 4 ? 2 : 0;
    for (int y = 0; y < side; y += 3)
      for (int x = 0; x < side; x += 2)
        QVERIFY2(
            std::abs(map.at(x, y, 0) - paintedFeature(n, x, y)[std::size_t(channel)]) <= kTolerance,
            qPrintable(QString("%1 at %2,%3").arg(files[std::size_t(k)].c_str()).arg(x).arg(y)));
  }
}

void TexturedExportTest::unpaintedLayersGiveUniformMaps() {
  const Document doc = makeDocument(makeBaseShape(BaseShape::Sphere, 8));
  const fs::path path = file("plain.obj");
  writeTexturedObj(doc, 1, path);
  const std::vector<fs::path> files = texturedObjFiles(path);
  const RasterImage diffuse = readImage(files[2], 4);
  const RasterImage specular = readImage(files[3], 1);
  QCOMPARE(diffuse.width, 9);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 9; ++x) {
      for (int c = 0; c < 4; ++c)
        QVERIFY(std::abs(diffuse.at(x, y, c) - doc.diffuse.fill[std::size_t(c)]) <= kTolerance);
      QVERIFY(std::abs(specular.at(x, y, 0) - doc.feature.fill[1]) <= kTolerance);
    }
}

void TexturedExportTest::glbReadsBackWithTinygltf_data() {
  QTest::addColumn<int>("step");
  QTest::newRow("full") << 1;
  QTest::newRow("step 4") << 4;
}

void TexturedExportTest::glbReadsBackWithTinygltf() {
  QFETCH(int, step);
  const int n = 16, m = n / step, side = n + 1;
  const Document doc = paintedDocument(n);
  const fs::path path = file(QString("painted-%1.glb").arg(step));
  writeGlb(doc, step, path);

  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  QVERIFY2(loader.LoadBinaryFromFile(&model, &err, &warn, path.string()), err.c_str());
  QVERIFY2(err.empty(), err.c_str());
  QCOMPARE(model.meshes.size(), std::size_t(1));
  QCOMPARE(model.meshes[0].primitives.size(), std::size_t(1));
  const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
  QCOMPARE(primitive.mode, TINYGLTF_MODE_TRIANGLES);
  for (const char* attribute : {"POSITION", "NORMAL", "TEXCOORD_0"})
    QVERIFY2(primitive.attributes.count(attribute) == 1, attribute);

  const std::size_t count = std::size_t(m + 1) * std::size_t(m + 1);
  const std::vector<float> positions = readFloats(model, primitive.attributes.at("POSITION"));
  const std::vector<float> normals = readFloats(model, primitive.attributes.at("NORMAL"));
  const std::vector<float> uvs = readFloats(model, primitive.attributes.at("TEXCOORD_0"));
  QCOMPARE(positions.size(), 3 * count);
  QCOMPARE(normals.size(), 3 * count);
  QCOMPARE(uvs.size(), 2 * count);
  const tinygltf::Accessor& positionAccessor =
      model.accessors[std::size_t(primitive.attributes.at("POSITION"))];
  QCOMPARE(positionAccessor.minValues.size(), std::size_t(3));
  QCOMPARE(positionAccessor.maxValues.size(), std::size_t(3));

  const tinygltf::Accessor& indices = model.accessors[std::size_t(primitive.indices)];
  QCOMPARE(indices.count, 6 * std::size_t(m) * std::size_t(m));
  QCOMPARE(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  {
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(indices.bufferView)];
    std::vector<std::uint32_t> index(indices.count);
    std::memcpy(index.data(),
                model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset +
                    indices.byteOffset,
                index.size() * sizeof(std::uint32_t));
    for (const std::uint32_t k : index)
      QVERIFY(k < count);
    // Same triangles as extractMesh once welded.
    const VertexIndex welded(n, step);
    const TriangleMesh mesh = extractMesh(doc.positions, step);
    for (std::size_t t = 0; t < index.size(); ++t)
      QCOMPARE(
          welded.at(int(index[t] % std::uint32_t(m + 1)), int(index[t] / std::uint32_t(m + 1))),
          mesh.triangles[t / 3][t % 3]);
  }

  // Material: base colour = diffuse, metallic-roughness G = 1 − specular, B = reflectivity.
  QCOMPARE(primitive.material, 0);
  const tinygltf::Material& material = model.materials[0];
  const int base = material.pbrMetallicRoughness.baseColorTexture.index;
  const int mr = material.pbrMetallicRoughness.metallicRoughnessTexture.index;
  QVERIFY(base >= 0 && mr >= 0);
  QCOMPARE(material.pbrMetallicRoughness.metallicFactor, 1.0);
  QCOMPARE(material.pbrMetallicRoughness.roughnessFactor, 1.0);
  const tinygltf::Image& baseImage =
      model.images[std::size_t(model.textures[std::size_t(base)].source)];
  const tinygltf::Image& mrImage =
      model.images[std::size_t(model.textures[std::size_t(mr)].source)];
  QCOMPARE(baseImage.width, side);
  QCOMPARE(baseImage.height, side);
  QCOMPARE(mrImage.width, side);
  QVERIFY(baseImage.component >= 4 && mrImage.component >= 3);
  QVERIFY(baseImage.bufferView >= 0 && mrImage.bufferView >= 0); // embedded, not files

  for (std::size_t k = 0; k < count; ++k) {
    const int i = int(k % std::size_t(m + 1)), j = int(k / std::size_t(m + 1));
    QVERIFY(std::abs(positions[3 * k] - doc.positions.at(i * step, j * step).x) < 1e-6f);
    const float nl =
        std::sqrt(normals[3 * k] * normals[3 * k] + normals[3 * k + 1] * normals[3 * k + 1] +
                  normals[3 * k + 2] * normals[3 * k + 2]);
    QVERIFY(std::abs(nl - 1) < 1e-4f);
    const auto [x, y] = pixelOf(uvs[2 * k], uvs[2 * k + 1], side); // glTF's v points down
    QCOMPARE(x, i * step);
    QCOMPARE(y, j * step);
    const auto colour = paintedColour(n, x, y);
    for (int c = 0; c < 4; ++c)
      QVERIFY2(std::abs(imageAt(baseImage, x, y, c) - colour[std::size_t(c)]) <= kTolerance,
               qPrintable(QString("base colour at %1,%2 channel %3").arg(x).arg(y).arg(c)));
    const auto feature = paintedFeature(n, x, y);
    QVERIFY2(std::abs(imageAt(mrImage, x, y, 1) - (1 - feature[1])) <= 2.0f / 255,
             qPrintable(QString("roughness at %1,%2").arg(x).arg(y)));
    QVERIFY2(std::abs(imageAt(mrImage, x, y, 2) - feature[2]) <= 2.0f / 255,
             qPrintable(QString("metallic at %1,%2").arg(x).arg(y)));
  }
}

void TexturedExportTest::errors() {
  const Document doc = paintedDocument(16);
  EXPECT_ERROR(writeTexturedObj(doc, 3, file("bad-step.obj")), ErrorKind::InvalidArgument);
  EXPECT_ERROR(writeTexturedObj(doc, 16, file("bad-step.obj")), ErrorKind::InvalidArgument);
  EXPECT_ERROR(writeGlb(doc, 0, file("bad-step.glb")), ErrorKind::InvalidArgument);
  EXPECT_ERROR(writeGlb(doc, 32, file("bad-step.glb")), ErrorKind::InvalidArgument);
  QVERIFY(!fs::exists(file("bad-step.obj")));
  QVERIFY(!fs::exists(file("bad-step_diffuse.png")));
  QVERIFY(!fs::exists(file("bad-step.glb")));

  Document broken = doc;
  broken.diffuse.texels.resize(10);
  EXPECT_ERROR(writeTexturedObj(broken, 1, file("broken.obj")), ErrorKind::InvalidArgument);
  EXPECT_ERROR(writeGlb(broken, 1, file("broken.glb")), ErrorKind::InvalidArgument);

  const fs::path missing = file("no-such-dir");
  EXPECT_ERROR(writeTexturedObj(doc, 1, missing / "mesh.obj"), ErrorKind::Io);
  EXPECT_ERROR(writeGlb(doc, 1, missing / "mesh.glb"), ErrorKind::Io);
  QVERIFY(!fs::exists(missing));

  // The OBJ is written last: when it cannot be written, the maps already written are removed.
  fs::create_directory(file("folder.obj"));
  EXPECT_ERROR(writeTexturedObj(doc, 1, file("folder.obj")), ErrorKind::Io);
  QVERIFY(!fs::exists(file("folder_diffuse.png")));
  QVERIFY(!fs::exists(file("folder.mtl")));
}

QTEST_APPLESS_MAIN(TexturedExportTest)
#include "textured_export_test.moc"
