// Textured OBJ and binary glTF export: the unwelded sample grid with texture coordinates at the
// layer texels' centres, and the layers as PNG maps (DESIGN.md, "The geometry image").
//
// The .glb goes through tinygltf: a maintained glTF 2.0 reader and writer that Debian packages
// (libtinygltf-dev, built there as a shared library with its stb and JSON dependencies, so
// linking TinyGLTF::TinyGLTF is all it takes), and the one the CLI guide asks for. It also
// lets the tests read the result back with a loader we did not write.

#include "octaclay/core/export/textured_export.h"

#include "detail/atomic_file.h"
#include "geometry/subsampling.h"

#include "octaclay/core/document/image_io.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/normals.h"
#include "octaclay/core/geometry/octahedral.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <string>
#include <system_error>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

// The exported vertices: sample (i, j) of the (M+1)² grid is image sample (i·step, j·step),
// numbered j·(M+1) + i. Positions and normals come from the canonical sample so identified
// vertices are bit-equal in the file even before seaming.
struct SampleGrid {
  int n = 0, m = 0, step = 1;
  std::vector<Vec3f> positions, normals;

  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>((m + 1) * (m + 1)); }
  // Texture coordinates of vertex (i, j): the centre of texel (i·step, j·step), u to the right
  // and v down the image (glTF's convention; OBJ's is 1 − v).
  float u(int i) const { return (static_cast<float>(i * step) + 0.5f) / static_cast<float>(n + 1); }
  float v(int j) const { return (static_cast<float>(j * step) + 0.5f) / static_cast<float>(n + 1); }
};

void requireLayer(const Layer& layer, int n) {
  const std::size_t side = static_cast<std::size_t>(n) + 1;
  if (!layer.uniform() &&
      layer.texels.size() != side * side * static_cast<std::size_t>(layer.channels))
    throw Error(ErrorKind::InvalidArgument,
                "cannot export: the " + layer.name + " layer holds " +
                    std::to_string(layer.texels.size()) + " values, not (N+1)² × " +
                    std::to_string(layer.channels) + " for N = " + std::to_string(n));
}

SampleGrid makeGrid(const Document& doc, int step) {
  SampleGrid grid;
  grid.n = doc.size();
  grid.m = detail::subsampledSize(grid.n, step);
  grid.step = step;
  requireLayer(doc.diffuse, grid.n);
  requireLayer(doc.feature, grid.n);

  const GeometryImage& image = doc.positions;
  std::vector<Vec3f> fullNormals;
  if (step == 1) fullNormals = computeNormals(image); // parallel; every sample is exported
  const std::size_t count = grid.vertexCount();
  grid.positions.resize(count);
  grid.normals.resize(count);
  for (int j = 0; j <= grid.m; ++j)
    for (int i = 0; i <= grid.m; ++i) {
      const Sample c = canonical(grid.n, {i * step, j * step});
      const std::size_t k = static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.m + 1) +
                            static_cast<std::size_t>(i);
      grid.positions[k] = image.at(c).xyz();
      Vec3f normal =
          step == 1
              ? fullNormals[static_cast<std::size_t>(c.j) * static_cast<std::size_t>(grid.n + 1) +
                            static_cast<std::size_t>(c.i)]
              : vertexNormal(image, c);
      // A degenerate neighbourhood has no normal; glTF requires unit normals, so point it
      // outward from the origin (the base shapes are centred there).
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = normalize(image.at(c).xyz());
      if (!(std::abs(length(normal) - 1.0f) < 1e-3f)) normal = {0, 0, 1};
      grid.normals[k] = normal;
    }
  return grid;
}

// Calls triangle(a, b, c) for the 2M² triangles, counter-clockwise seen from outside, split as
// extractMesh splits them (the anti-diagonal where (i < M/2) == (j < M/2)).
template <class Triangle> void forEachTriangle(int m, Triangle&& triangle) {
  const int half = m / 2;
  const auto index = [m](int i, int j) { return static_cast<std::uint32_t>(j * (m + 1) + i); };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i) {
      const std::uint32_t a = index(i, j), b = index(i + 1, j);
      const std::uint32_t c = index(i + 1, j + 1), d = index(i, j + 1);
      if ((i < half) == (j < half)) {
        triangle(a, b, d);
        triangle(b, c, d);
      } else {
        triangle(a, b, c);
        triangle(a, c, d);
      }
    }
}

float layerValue(const Layer& layer, std::size_t texel, int channel) {
  return layer.uniform() ? layer.fill[static_cast<std::size_t>(channel)]
                         : layer.texels[texel * static_cast<std::size_t>(layer.channels) +
                                        static_cast<std::size_t>(channel)];
}

// A full-resolution map: pixel (x, y) = value(texel index of layer sample (x, y)).
template <class Value> RasterImage makeMap(int n, int channels, Value&& value) {
  RasterImage map;
  map.width = map.height = n + 1;
  map.channels = channels;
  const std::size_t texels = static_cast<std::size_t>(n + 1) * static_cast<std::size_t>(n + 1);
  map.pixels.resize(texels * static_cast<std::size_t>(channels));
  for (std::size_t t = 0; t < texels; ++t)
    for (int c = 0; c < channels; ++c)
      map.pixels[t * static_cast<std::size_t>(channels) + static_cast<std::size_t>(c)] =
          value(t, c);
  return map;
}

RasterImage diffuseMap(const Document& doc) {
  return makeMap(doc.size(), 4,
                 [&](std::size_t t, int c) { return layerValue(doc.diffuse, t, c); });
}

RasterImage featureMap(const Document& doc, int channel) {
  return makeMap(doc.size(), 1,
                 [&](std::size_t t, int) { return layerValue(doc.feature, t, channel); });
}

// glTF's metallic-roughness texture: G roughness = 1 − specular, B metallic = reflectivity;
// R is unused by the core material (occlusion would read it), so it is 1.
RasterImage metallicRoughnessMap(const Document& doc) {
  return makeMap(doc.size(), 3, [&](std::size_t t, int c) {
    if (c == 0) return 1.0f;
    if (c == 1) return 1.0f - layerValue(doc.feature, t, 1);
    return layerValue(doc.feature, t, 2);
  });
}

// The same 8-bit encoding as writePng, into memory for the .glb's binary chunk.
std::vector<unsigned char> encodePng(const RasterImage& image) {
  cv::Mat raw(image.height, image.width, CV_8UC(image.channels));
  const std::size_t rowValues =
      static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.channels);
  for (int y = 0; y < image.height; ++y) {
    std::uint8_t* row = raw.ptr<std::uint8_t>(y);
    const float* in = image.pixels.data() + static_cast<std::size_t>(y) * rowValues;
    for (std::size_t x = 0; x < rowValues; ++x)
      row[x] = static_cast<std::uint8_t>(std::clamp(in[x], 0.0f, 1.0f) * 255.0f + 0.5f);
  }
  cv::Mat bgr;
  if (image.channels == 3)
    cv::cvtColor(raw, bgr, cv::COLOR_RGB2BGR);
  else if (image.channels == 4)
    cv::cvtColor(raw, bgr, cv::COLOR_RGBA2BGRA);
  else
    bgr = raw;
  std::vector<unsigned char> bytes;
  bool ok = false;
  try {
    ok = cv::imencode(".png", bgr, bytes);
  } catch (const cv::Exception&) {
    ok = false;
  }
  if (!ok) throw Error(ErrorKind::Io, "cannot encode a PNG texture for the glTF export");
  return bytes;
}

// Buffered text output for multi-gigabyte OBJs: numbers through to_chars (shortest round-trip
// form, so positions are exact), flushed in large blocks.
class TextWriter {
public:
  // Writes to `path`; errors name `shown` (the file the user asked for, not its temporary).
  TextWriter(const fs::path& path, const fs::path& shown)
      : out_(path, std::ios::binary), shown_(shown) {
    if (!out_) throw Error(ErrorKind::Io, "cannot open " + shown_.string() + " for writing");
    buffer_.reserve(kBlock + 256);
  }
  TextWriter& text(std::string_view s) {
    buffer_.append(s);
    return *this;
  }
  TextWriter& number(float value) {
    std::array<char, 32> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    buffer_.append(digits.data(), result.ptr);
    return *this;
  }
  TextWriter& number(std::uint64_t value) {
    std::array<char, 24> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    buffer_.append(digits.data(), result.ptr);
    return *this;
  }
  void endLine() {
    buffer_.push_back('\n');
    if (buffer_.size() >= kBlock) flush();
  }
  void finish() {
    flush();
    out_.close();
    if (!out_) throw Error(ErrorKind::Io, "cannot write " + shown_.string() + " (disk full?)");
  }

private:
  static constexpr std::size_t kBlock = std::size_t{1} << 22;
  void flush() {
    out_.write(buffer_.data(), static_cast<std::streamsize>(buffer_.size()));
    buffer_.clear();
    if (!out_) throw Error(ErrorKind::Io, "cannot write " + shown_.string() + " (disk full?)");
  }
  std::ofstream out_;
  fs::path shown_;
  std::string buffer_;
};

void writeObjText(const SampleGrid& grid, const std::string& mtlName, const fs::path& path,
                  const fs::path& shown) {
  TextWriter w(path, shown);
  w.text("# Octaclay textured export: (M+1)^2 unwelded samples, M = ")
      .number(std::uint64_t(static_cast<unsigned>(grid.m)))
      .text(", maps at (N+1)^2, N = ")
      .number(std::uint64_t(static_cast<unsigned>(grid.n)))
      .endLine();
  w.text("mtllib ").text(mtlName).endLine();
  for (const Vec3f& p : grid.positions)
    w.text("v ").number(p.x).text(" ").number(p.y).text(" ").number(p.z).endLine();
  for (int j = 0; j <= grid.m; ++j)
    for (int i = 0; i <= grid.m; ++i)
      w.text("vt ").number(grid.u(i)).text(" ").number(1.0f - grid.v(j)).endLine();
  for (const Vec3f& nrm : grid.normals)
    w.text("vn ").number(nrm.x).text(" ").number(nrm.y).text(" ").number(nrm.z).endLine();
  w.text("usemtl octaclay").endLine();
  forEachTriangle(grid.m, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    w.text("f");
    for (const std::uint32_t k : {a, b, c}) {
      const std::uint64_t one = std::uint64_t{k} + 1; // OBJ counts from 1
      w.text(" ").number(one).text("/").number(one).text("/").number(one);
    }
    w.endLine();
  });
  w.finish();
}

std::string mtlText(const std::vector<fs::path>& files) {
  const auto name = [&](std::size_t k) { return files[k].filename().string(); };
  return "# Octaclay textured export: maps at the document's full resolution\n"
         "newmtl octaclay\n"
         "Ka 0 0 0\n"
         "Kd 1 1 1\n"
         "Ks 1 1 1\n"
         "Ns 64\n"
         "d 1\n"
         "illum 3\n" // colour, highlight and reflection
         "map_Kd " +
         name(2) + "\n" + "map_Ks " + name(3) + "\n" +
         // No MTL keyword is a scalar reflectivity map: map_refl is the common extension, and
         // map_Pm (the PBR extension's metallic) the closest reading in PBR importers.
         "map_refl " + name(4) + "\n" + "map_Pm " + name(4) + "\n" + "bump " + name(5) + "\n";
}

// Appends bytes to the buffer at a 4-byte aligned offset and returns the view's index.
int appendView(tinygltf::Model& model, const void* data, std::size_t size, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  bytes.resize((bytes.size() + 3) / 4 * 4, 0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = size;
  view.target = target;
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes.insert(bytes.end(), begin, begin + size);
  model.bufferViews.push_back(view);
  return static_cast<int>(model.bufferViews.size() - 1);
}

int appendAccessor(tinygltf::Model& model, int view, int componentType, int type,
                   std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

int appendPng(tinygltf::Model& model, const RasterImage& map, const std::string& name) {
  const std::vector<unsigned char> png = encodePng(map);
  tinygltf::Image image;
  image.name = name;
  image.mimeType = "image/png";
  image.bufferView = appendView(model, png.data(), png.size(), 0);
  model.images.push_back(image);
  tinygltf::Texture texture;
  texture.sampler = 0;
  texture.source = static_cast<int>(model.images.size() - 1);
  model.textures.push_back(texture);
  return static_cast<int>(model.textures.size() - 1);
}

tinygltf::Model glbModel(const Document& doc, const SampleGrid& grid) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Octaclay";
  model.buffers.emplace_back();

  const std::size_t count = grid.vertexCount();
  std::vector<float> texcoords;
  texcoords.reserve(2 * count);
  for (int j = 0; j <= grid.m; ++j)
    for (int i = 0; i <= grid.m; ++i) {
      texcoords.push_back(grid.u(i));
      texcoords.push_back(grid.v(j));
    }
  std::vector<std::uint32_t> indices;
  indices.reserve(6 * static_cast<std::size_t>(grid.m) * static_cast<std::size_t>(grid.m));
  forEachTriangle(grid.m, [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    indices.insert(indices.end(), {a, b, c});
  });

  // Over glTF's limit the binary chunk's 32-bit length would wrap: refuse before building it.
  const double estimate =
      static_cast<double>(count) * (12 + 12 + 8) + static_cast<double>(indices.size()) * 4;
  if (estimate > static_cast<double>(std::numeric_limits<std::uint32_t>::max()) - (1 << 26))
    throw Error(ErrorKind::InvalidArgument,
                "the glTF export at level " + std::to_string(grid.m) +
                    " exceeds the 4 GiB a .glb can hold; export a coarser level");

  static_assert(sizeof(Vec3f) == 12);
  const int positions = appendAccessor(
      model,
      appendView(model, grid.positions.data(), count * sizeof(Vec3f), TINYGLTF_TARGET_ARRAY_BUFFER),
      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
  BoundingBox box;
  for (const Vec3f& p : grid.positions)
    box.extend(p);
  model.accessors[static_cast<std::size_t>(positions)].minValues = {box.min.x, box.min.y,
                                                                    box.min.z};
  model.accessors[static_cast<std::size_t>(positions)].maxValues = {box.max.x, box.max.y,
                                                                    box.max.z};
  const int normals = appendAccessor(
      model,
      appendView(model, grid.normals.data(), count * sizeof(Vec3f), TINYGLTF_TARGET_ARRAY_BUFFER),
      TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, count);
  const int uvs =
      appendAccessor(model,
                     appendView(model, texcoords.data(), texcoords.size() * sizeof(float),
                                TINYGLTF_TARGET_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, count);
  const int triangles =
      appendAccessor(model,
                     appendView(model, indices.data(), indices.size() * sizeof(std::uint32_t),
                                TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER),
                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, indices.size());
  texcoords = {};
  indices = {};

  // Linear filtering hits the texel centres exactly at the vertices; clamping keeps the image
  // border from blending with the opposite side.
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  model.samplers.push_back(sampler);

  tinygltf::Material material;
  material.name = "octaclay";
  material.pbrMetallicRoughness.baseColorTexture.index =
      appendPng(model, diffuseMap(doc), "diffuse");
  material.pbrMetallicRoughness.metallicRoughnessTexture.index =
      appendPng(model, metallicRoughnessMap(doc), "metallicRoughness");
  material.pbrMetallicRoughness.metallicFactor = 1.0;
  material.pbrMetallicRoughness.roughnessFactor = 1.0;
  model.materials.push_back(material);

  tinygltf::Primitive primitive;
  primitive.attributes = {{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}};
  primitive.indices = triangles;
  primitive.material = 0;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "octaclay";
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);

  tinygltf::Node node;
  node.name = "octaclay";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

} // namespace

std::vector<fs::path> texturedObjFiles(const fs::path& objPath) {
  const std::string stem = objPath.stem().string();
  std::vector<fs::path> files{objPath};
  for (const char* suffix :
       {".mtl", "_diffuse.png", "_specular.png", "_reflectivity.png", "_height.png"})
    files.push_back(fs::path(objPath).replace_filename(stem + suffix));
  return files;
}

void writeTexturedObj(const Document& doc, int step, const fs::path& objPath) {
  const SampleGrid grid = makeGrid(doc, step);
  const std::vector<fs::path> files = texturedObjFiles(objPath);
  if (objPath.filename() == files[1].filename())
    throw Error(ErrorKind::InvalidArgument,
                "cannot export to " + objPath.string() + ": its material file has that name");

  // Maps and material first, the OBJ last, so a complete OBJ never names missing files; on a
  // failure the files already written are taken back.
  std::vector<fs::path> written;
  try {
    writePng(diffuseMap(doc), files[2]);
    written.push_back(files[2]);
    writePng(featureMap(doc, 1), files[3]);
    written.push_back(files[3]);
    writePng(featureMap(doc, 2), files[4]);
    written.push_back(files[4]);
    writePng(featureMap(doc, 0), files[5]);
    written.push_back(files[5]);
    const std::string mtl = mtlText(files);
    detail::writeAtomically(files[1], [&](const fs::path& temporary) {
      std::ofstream out(temporary, std::ios::binary);
      out << mtl;
      out.close();
      if (!out) throw Error(ErrorKind::Io, "cannot write " + files[1].string());
    });
    written.push_back(files[1]);
    detail::writeAtomically(objPath, [&](const fs::path& temporary) {
      writeObjText(grid, files[1].filename().string(), temporary, objPath);
    });
  } catch (...) {
    std::error_code ec;
    for (const fs::path& path : written)
      fs::remove(path, ec);
    throw;
  }
}

void writeGlb(const Document& doc, int step, const fs::path& glbPath) {
  const SampleGrid grid = makeGrid(doc, step);
  const tinygltf::Model model = glbModel(doc, grid);
  detail::writeAtomically(glbPath, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw Error(ErrorKind::Io, "cannot open " + glbPath.string() + " for writing");
    tinygltf::TinyGLTF writer;
    const bool ok = writer.WriteGltfSceneToStream(&model, out, false, true);
    out.close();
    if (!ok || !out) throw Error(ErrorKind::Io, "cannot write " + glbPath.string());
  });
}

} // namespace octaclay::core
