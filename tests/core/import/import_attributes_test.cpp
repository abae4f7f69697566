// Import attributes: a PLY's vertex colours and an OBJ's diffuse texture (vt + mtllib + map_Kd)
// reach the diffuse layer of the imported document, checked against values computed here
// independently; the shared meshes whose materials are absent import plain, with a note.

#include "test_meshes.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/import/import.h"
#include "octaclay/core/import/mesh_validation.h"
#include "octaclay/core/import/octahedral_resampling.h"
#include "octaclay/core/import/spherical_parameterization.h"

#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

using namespace octaclay::core;
namespace fs = std::filesystem;

namespace {

using Tri = std::array<std::uint32_t, 3>;

const fs::path kMeshes = fs::path(OCTACLAY_SHARED_DATA) / "meshes";

TriangleMesh sphere(int levels) {
  return testing::unitSphere(levels);
}

// Attributes affine in position: interpolating them with a sample's weights gives their value
// at the sample's (interpolated) position, which the test can compute on its own.
Vec4f colourOf(Vec3f p) {
  return {0.5f + 0.45f * p.x, 0.5f + 0.45f * p.y, 0.5f + 0.45f * p.z, 0.75f + 0.2f * p.x};
}
std::array<float, 2> uvOf(Vec3f p) {
  return {0.5f + 0.4f * p.x, 0.5f + 0.3f * p.y + 0.1f * p.z};
}

std::string shortest(float v) {
  char buffer[32];
  const auto r = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, r.ptr);
}

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

const float* diffuseAt(const Document& d, int i, int j) {
  return &d.diffuse.texels[(static_cast<std::size_t>(j) * static_cast<std::size_t>(d.size() + 1) +
                            static_cast<std::size_t>(i)) *
                           4];
}

// Independent bilinear read, v up, texel centres at half-integers; (u, v) stays inside.
Vec4f bilinear(const RasterImage& image, float u, float v) {
  const float x = u * float(image.width) - 0.5f, y = (1 - v) * float(image.height) - 0.5f;
  const int x0 = std::clamp(int(std::floor(x)), 0, image.width - 2);
  const int y0 = std::clamp(int(std::floor(y)), 0, image.height - 2);
  const float fx = x - float(x0), fy = y - float(y0);
  float out[4];
  for (int c = 0; c < 4; ++c)
    out[c] = (1 - fy) * ((1 - fx) * image.at(x0, y0, c) + fx * image.at(x0 + 1, y0, c)) +
             fy * ((1 - fx) * image.at(x0, y0 + 1, c) + fx * image.at(x0 + 1, y0 + 1, c));
  return {out[0], out[1], out[2], out[3]};
}

const Vec4f kRed{1.0f, 0.2f, 0.1f, 1.0f};
const Vec4f kBlue{0.1f, 0.3f, 0.9f, 1.0f};

// Checker cells of `cell` texels, red where (column + row) of cells is even counting rows from
// the top: a vertical flip swaps the colours, so reading v the wrong way round shows.
RasterImage checker(int size, int cell) {
  RasterImage image{size, size, 4, std::vector<float>(std::size_t(size) * size * 4)};
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const Vec4f c = ((x / cell + y / cell) % 2 == 0) ? kRed : kBlue;
      float* p = &image.pixels[(std::size_t(y) * size + x) * 4];
      p[0] = c.x;
      p[1] = c.y;
      p[2] = c.z;
      p[3] = c.w;
    }
  return image;
}

// Empty when identified samples of the diffuse layer are equal; otherwise where they differ.
QString checkDiffuseSeam(const Document& d) {
  const int n = d.size();
  std::array<Sample, 4> same;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const int count = identifiedSamples(n, {i, j}, same);
      for (int k = 0; k < count; ++k)
        for (int c = 0; c < 4; ++c)
          if (diffuseAt(d, i, j)[c] != diffuseAt(d, same[k].i, same[k].j)[c])
            return QString("(%1, %2) and (%3, %4) differ")
                .arg(i)
                .arg(j)
                .arg(same[k].i)
                .arg(same[k].j);
    }
  return {};
}

} // namespace

class ImportAttributesTest : public QObject {
  Q_OBJECT

private slots:
  void initTestCase() { QVERIFY(dir_.isValid()); }
  void locationsAreTheResamplingWalk();
  void plyVertexColoursReachTheDiffuseLayer();
  void objTextureReachesTheDiffuseLayer();
  void sharedMeshesWithoutMaterialsImportPlain();
  void badTextureArguments();

private:
  fs::path root() const { return fs::path(dir_.path().toStdString()); }
  QTemporaryDir dir_;
};

void ImportAttributesTest::locationsAreTheResamplingWalk() {
  const TriangleMesh mesh = sphere(3);
  const SphericalMap map = parameterizeOnSphere(mesh);
  QCOMPARE(map.flipped, 0);
  const int n = 32;
  const std::vector<SampleLocation> at = locateOctahedralSamples(mesh, map, n);
  const GeometryImage image = resampleOctahedral(mesh, map, n);
  QCOMPARE(at.size(), std::size_t(33 * 33));
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const SampleLocation& l = at[std::size_t(j) * 33 + std::size_t(i)];
      QVERIFY(l.triangle < mesh.triangles.size());
      QVERIFY(l.weights[0] >= 0 && l.weights[1] >= 0 && l.weights[2] >= 0);
      QVERIFY(std::abs(l.weights[0] + l.weights[1] + l.weights[2] - 1) < 1e-5f);
      const auto& f = mesh.triangles[l.triangle];
      const Vec3f p = mesh.positions[f[0]] * l.weights[0] + mesh.positions[f[1]] * l.weights[1] +
                      mesh.positions[f[2]] * l.weights[2];
      // The same arithmetic as the resampling; the border is averaged by seaming.
      const bool border = i == 0 || j == 0 || i == n || j == n;
      if (border)
        QVERIFY(length(p - image.at(i, j).xyz()) < 1e-5f);
      else
        QCOMPARE(p, image.at(i, j).xyz());
    }
}

void ImportAttributesTest::plyVertexColoursReachTheDiffuseLayer() {
  // A binary PLY with uchar colours, an unused vertex first (renumbering) and inward winding
  // (turned by validation).
  const TriangleMesh mesh = sphere(3);
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex " +
                    std::to_string(mesh.positions.size() + 1) +
                    "\nproperty float x\nproperty float y\nproperty float z\n"
                    "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                    "property uchar alpha\nelement face " +
                    std::to_string(mesh.triangles.size()) +
                    "\nproperty list uchar int vertex_indices\nend_header\n";
  const auto vertex = [&](Vec3f p, Vec4f c) {
    for (const float v : {p.x, p.y, p.z})
      ply.append(reinterpret_cast<const char*>(&v), 4);
    for (const float v : {c.x, c.y, c.z, c.w})
      ply.push_back(static_cast<char>(static_cast<unsigned char>(std::lround(v * 255))));
  };
  vertex({5, 5, 5}, {1, 0, 0, 1});
  for (const Vec3f& p : mesh.positions)
    vertex(p, colourOf(p));
  for (const Tri& t : mesh.triangles) {
    ply.push_back(3);
    for (const std::int32_t v :
         {std::int32_t(t[0] + 1), std::int32_t(t[2] + 1), std::int32_t(t[1] + 1)})
      ply.append(reinterpret_cast<const char*>(&v), 4);
  }
  const fs::path path = root() / "coloured.ply";
  writeFile(path, ply);

  const ValidatedMesh validated = loadGenus0Mesh(path);
  QVERIFY(validated.cleanup.windingReversed);
  QCOMPARE(validated.cleanup.unusedVerticesRemoved, std::size_t(1));
  QCOMPARE(validated.vertexColours.size(), mesh.positions.size());
  QVERIFY(validated.notes.empty());
  // Bytes: each channel within half a step of the colour of the vertex's position.
  const float step = 1.0f / 255;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const Vec4f want = colourOf(validated.mesh.positions[v]), got = validated.vertexColours[v];
    QVERIFY(std::abs(got.x - want.x) <= 0.51f * step && std::abs(got.w - want.w) <= 0.51f * step);
  }

  const SphericalMap map = parameterizeOnSphere(validated.mesh);
  QCOMPARE(map.flipped, 0);
  ImportedDiffuse diffuse;
  const Document document = importValidatedMesh(validated, map, 64, &diffuse);
  QCOMPARE(diffuse.source, DiffuseSource::VertexColours);
  QVERIFY(!document.diffuse.uniform());
  // Every sample, near vertices or not, has the colour of its position.
  float worst = 0;
  for (int j = 0; j <= 64; ++j)
    for (int i = 0; i <= 64; ++i) {
      const Vec4f want = colourOf(document.positions.at(i, j).xyz());
      const float* got = diffuseAt(document, i, j);
      worst = std::max({worst, std::abs(got[0] - want.x), std::abs(got[1] - want.y),
                        std::abs(got[2] - want.z), std::abs(got[3] - want.w)});
    }
  QVERIFY2(worst <= 0.51f * step + 1e-5f, qPrintable(QString::number(double(worst))));
  const QString seam = checkDiffuseSeam(document);
  QVERIFY2(seam.isEmpty(), qPrintable(seam));
}

void ImportAttributesTest::objTextureReachesTheDiffuseLayer() {
  // model.obj with one vt per corner (indices unlike the v ones), some faces turned against
  // their neighbours, `mtllib model.mtl`, whose map_Kd (with options) names
  // textures/checker.png.
  const fs::path dir = root() / "textured";
  fs::create_directories(dir / "textures");
  writePng(checker(64, 8), dir / "textures" / "checker.png");
  writeFile(dir / "model.mtl", "# material\nnewmtl skin\nKa 0 0 0\nKd 1 1 1\n"
                               "map_Kd -s 1 1 1 -o 0 0 0 textures/checker.png\n");
  const TriangleMesh mesh = sphere(3);
  std::string obj = "mtllib model.mtl\n";
  for (const Vec3f& p : mesh.positions)
    obj += "v " + shortest(p.x) + " " + shortest(p.y) + " " + shortest(p.z) + "\n";
  const std::size_t corners = 3 * mesh.triangles.size();
  for (std::size_t c = corners; c-- > 0;) {
    const auto uv = uvOf(mesh.positions[mesh.triangles[c / 3][c % 3]]);
    obj += "vt " + shortest(uv[0]) + " " + shortest(uv[1]) + "\n";
  }
  obj += "vn 0 0 1\nusemtl skin\n";
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    std::array<std::size_t, 3> order{0, 1, 2};
    if (t % 7 == 3) std::swap(order[1], order[2]); // turned: validation turns it back
    obj += "f";
    for (const std::size_t k : order)
      obj += " " + std::to_string(mesh.triangles[t][k] + 1) + "/" +
             std::to_string(corners - (3 * t + k)) + (t % 2 ? "/1" : "");
    obj += "\n";
  }
  writeFile(dir / "model.obj", obj);

  const ValidatedMesh validated = loadGenus0Mesh(dir / "model.obj");
  QVERIFY(validated.cleanup.facesFlipped > 0);
  QVERIFY2(validated.notes.empty(), validated.notes.empty() ? "" : validated.notes[0].c_str());
  QCOMPARE(fs::canonical(validated.diffuseTexture),
           fs::canonical(dir / "textures" / "checker.png"));
  QCOMPARE(validated.cornerUv.size(), validated.mesh.triangles.size());

  const SphericalMap map = parameterizeOnSphere(validated.mesh);
  QCOMPARE(map.flipped, 0);
  ImportedDiffuse diffuse;
  const int n = 64;
  const Document document = importValidatedMesh(validated, map, n, &diffuse);
  QCOMPARE(diffuse.source, DiffuseSource::Texture);
  QCOMPARE(diffuse.texture, validated.diffuseTexture);

  // Each sample shows the texture at the (u, v) of its position, read back as the importer
  // reads it (8-bit PNG).
  const RasterImage texture = readImage(validated.diffuseTexture, 4);
  float worst = 0;
  int red = 0, blue = 0;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const auto uv = uvOf(document.positions.at(i, j).xyz());
      const Vec4f want = bilinear(texture, uv[0], uv[1]);
      const float* got = diffuseAt(document, i, j);
      worst = std::max({worst, std::abs(got[0] - want.x), std::abs(got[1] - want.y),
                        std::abs(got[2] - want.z), std::abs(got[3] - want.w)});
      red += std::abs(got[0] - kRed.x) < 0.02f && std::abs(got[2] - kRed.z) < 0.02f;
      blue += std::abs(got[0] - kBlue.x) < 0.02f && std::abs(got[2] - kBlue.z) < 0.02f;
    }
  QVERIFY2(worst < 2e-3f, qPrintable(QString::number(double(worst))));
  // Both checker colours cover a fair share (the rest straddles cell edges).
  const int samples = (n + 1) * (n + 1);
  QVERIFY2(red > samples / 4 && blue > samples / 4,
           qPrintable(QString("%1 red, %2 blue of %3").arg(red).arg(blue).arg(samples)));
  const QString seam = checkDiffuseSeam(document);
  QVERIFY2(seam.isEmpty(), qPrintable(seam));

  // A texture that does not decode is a note; the import goes on without it.
  writeFile(dir / "textures" / "checker.png", "not a PNG");
  const Document plain = importValidatedMesh(validated, map, 16, &diffuse);
  QCOMPARE(diffuse.source, DiffuseSource::None);
  QVERIFY(plain.diffuse.uniform());
  QCOMPARE(diffuse.notes.size(), std::size_t(1));
  QVERIFY(diffuse.notes[0].find("checker.png could not be read") != std::string::npos);
}

void ImportAttributesTest::sharedMeshesWithoutMaterialsImportPlain() {
  // spot has vt lines but no mtllib; blub names blub_triangulated.mtl, which is not shared.
  const ValidatedMesh spot = loadGenus0Mesh(kMeshes / "genus0" / "spot.obj");
  QCOMPARE(spot.cornerUv.size(), spot.mesh.triangles.size());
  QVERIFY(spot.diffuseTexture.empty());
  QVERIFY(spot.vertexColours.empty());
  QCOMPARE(spot.notes.size(), std::size_t(1));
  QVERIFY(spot.notes[0].find("no material library") != std::string::npos);
  const SphericalMap map = parameterizeOnSphere(spot.mesh);
  ImportedDiffuse diffuse;
  const Document document = importValidatedMesh(spot, map, 32, &diffuse);
  QCOMPARE(diffuse.source, DiffuseSource::None);
  QCOMPARE(diffuse.notes, spot.notes);
  QVERIFY(document.diffuse.uniform());
  QCOMPARE(document.diffuse.fill, Document().diffuse.fill);

  const ValidatedMesh blub = loadGenus0Mesh(kMeshes / "genus0" / "blub.obj");
  QCOMPARE(blub.mesh.triangles.size(), std::size_t(14208));
  QVERIFY(blub.diffuseTexture.empty());
  QCOMPARE(blub.notes.size(), std::size_t(1));
  QVERIFY(blub.notes[0].find("blub_triangulated.mtl not found") != std::string::npos);
}

void ImportAttributesTest::badTextureArguments() {
  const TriangleMesh mesh = sphere(1);
  const SphericalMap map = parameterizeOnSphere(mesh);
  std::vector<CornerUv> uv(mesh.triangles.size());
  const RasterImage texture = checker(8, 2);
  QVERIFY_THROWS_EXCEPTION(Error, importToDocument(mesh, map, 8, std::span(uv).first(3), texture));
  QVERIFY_THROWS_EXCEPTION(Error, importToDocument(mesh, map, 8, uv, RasterImage{}));
  RasterImage bad = texture;
  bad.pixels.pop_back();
  QVERIFY_THROWS_EXCEPTION(Error, importToDocument(mesh, map, 8, uv, bad));
  // Coordinates far outside [0, 1] repeat; the document is still made.
  for (CornerUv& c : uv)
    c = {{{-3.3f, 7.1f}, {1e6f, -2.0f}, {0.5f, 0.5f}}};
  const Document document = importToDocument(mesh, map, 8, uv, texture);
  for (const float c : document.diffuse.texels)
    QVERIFY(c >= 0 && c <= 1);
}

QTEST_GUILESS_MAIN(ImportAttributesTest)
#include "import_attributes_test.moc"
