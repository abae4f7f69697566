// The LOD written with its baked normal map: OBJ + MTL + PNG map (welded positions and
// normals, one texture coordinate per split vertex), or a binary glTF with the map embedded.

#include "octaclay/core/lod/lod_export.h"

#include "detail/atomic_file.h"
#include "lod/normal_map_encoding.h"

#include "octaclay/core/error.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <string>
#include <system_error>

namespace octaclay::core {
namespace fs = std::filesystem;

namespace {

std::string lowerExtension(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

class Text {
public:
  Text& operator<<(std::string_view s) {
    out_.append(s);
    return *this;
  }
  Text& operator<<(float value) {
    std::array<char, 32> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    out_.append(digits.data(), result.ptr);
    return *this;
  }
  Text& operator<<(std::uint64_t value) {
    std::array<char, 24> digits{};
    const auto result = std::to_chars(digits.data(), digits.data() + digits.size(), value);
    out_.append(digits.data(), result.ptr);
    return *this;
  }
  const std::string& str() const { return out_; }

private:
  std::string out_;
};

void writeText(const std::string& text, const fs::path& path) {
  detail::writeAtomically(path, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    out.close();
    if (!out) throw Error(ErrorKind::Io, "cannot write " + path.string() + " (disk full?)");
  });
}

void writeBytes(const std::vector<unsigned char>& bytes, const fs::path& path) {
  detail::writeAtomically(path, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw Error(ErrorKind::Io, "cannot write " + path.string() + " (disk full?)");
  });
}

// Welded normals: every copy of a vertex has the same one, so the first copy's serves.
std::vector<Vec3f> weldedNormals(const LodMesh& lod, const LodVertices& vertices) {
  std::vector<Vec3f> normals(lod.mesh.positions.size(), Vec3f{0, 0, 1});
  for (std::size_t k = 0; k < vertices.welded.size(); ++k)
    normals[vertices.welded[k]] = vertices.normals[k];
  return normals;
}

std::string objText(const LodMesh& lod, const LodVertices& vertices, const std::string& mtlName,
                    NormalMapSpace space) {
  Text w;
  w << "# Octaclay LOD: " << std::uint64_t{lod.mesh.positions.size()} << " vertices, "
    << std::uint64_t{lod.mesh.triangles.size()}
    << " triangles, resampled to M = " << std::uint64_t(static_cast<unsigned>(lod.resampledSize))
    << "; " << normalMapSpaceName(space)
    << "-space normal map; vt = image coordinates (x/N, 1 - y/N)\n";
  w << "mtllib " << mtlName << "\n";
  for (const Vec3f& p : lod.mesh.positions)
    w << "v " << p.x << " " << p.y << " " << p.z << "\n";
  for (const Vec2f& uv : vertices.uvs)
    w << "vt " << uv.x << " " << 1.0f - uv.y << "\n";
  for (const Vec3f& n : weldedNormals(lod, vertices))
    w << "vn " << n.x << " " << n.y << " " << n.z << "\n";
  w << "usemtl octaclay_lod\n";
  for (std::size_t t = 0; t < vertices.triangles.size(); ++t) {
    w << "f";
    for (int c = 0; c < 3; ++c) {
      const std::uint64_t v = std::uint64_t{lod.mesh.triangles[t][static_cast<std::size_t>(c)]} + 1;
      const std::uint64_t vt =
          std::uint64_t{vertices.triangles[t][static_cast<std::size_t>(c)]} + 1;
      w << " " << v << "/" << vt << "/" << v;
    }
    w << "\n";
  }
  return w.str();
}

std::string mtlText(const std::string& mapName, NormalMapSpace space) {
  return "# Octaclay LOD material: the normal map is " + std::string(normalMapSpaceName(space)) +
         "-space" +
         (space == NormalMapSpace::Tangent
              ? " (glTF convention: +X along u, +Y towards the image's top)\n"
              : " (object-space normals n*0.5+0.5; a tangent-space reader will misread it)\n") +
         "newmtl octaclay_lod\n"
         "Ka 0 0 0\n"
         "Kd 0.8 0.8 0.8\n"
         "Ks 0.04 0.04 0.04\n"
         "Ns 32\n"
         "d 1\n"
         "illum 2\n"
         "norm " +
         mapName + "\nmap_Bump " + mapName + "\n";
}

std::vector<fs::path> writeObj(const LodMesh& lod, const NormalMap& map, const fs::path& path) {
  const std::string stem = path.stem().string();
  const fs::path mtlPath = fs::path(path).replace_filename(stem + ".mtl");
  const fs::path mapPath = fs::path(path).replace_filename(stem + "_normal.png");
  const LodVertices vertices = lodVertices(lod);
  const std::string obj = objText(lod, vertices, mtlPath.filename().string(), map.space);
  const std::vector<unsigned char> png = detail::encodeNormalMapPng(map);

  // Map and material first, the OBJ last, so a complete OBJ never names missing files; on
  // failure the files already written are taken back.
  std::vector<fs::path> written;
  try {
    writeBytes(png, mapPath);
    written.push_back(mapPath);
    writeText(mtlText(mapPath.filename().string(), map.space), mtlPath);
    written.push_back(mtlPath);
    writeText(obj, path);
  } catch (...) {
    std::error_code ec;
    for (const fs::path& file : written)
      fs::remove(file, ec);
    throw;
  }
  return {path, mtlPath, mapPath};
}

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

int appendAccessor(tinygltf::Model& model, const void* data, std::size_t bytes, int target,
                   int componentType, int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = appendView(model, data, bytes, target);
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

tinygltf::Model glbModel(const LodMesh& lod, const LodVertices& v, const NormalMap& map) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Octaclay";
  model.buffers.emplace_back();
  const std::size_t count = v.positions.size();
  constexpr int kArray = TINYGLTF_TARGET_ARRAY_BUFFER;
  constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
  static_assert(sizeof(Vec3f) == 12 && sizeof(Vec2f) == 8);

  const int positions = appendAccessor(model, v.positions.data(), count * sizeof(Vec3f), kArray,
                                       kFloat, TINYGLTF_TYPE_VEC3, count);
  BoundingBox box;
  for (const Vec3f& p : v.positions)
    box.extend(p);
  model.accessors.back().minValues = {box.min.x, box.min.y, box.min.z};
  model.accessors.back().maxValues = {box.max.x, box.max.y, box.max.z};
  const int normals = appendAccessor(model, v.normals.data(), count * sizeof(Vec3f), kArray, kFloat,
                                     TINYGLTF_TYPE_VEC3, count);
  const int tangents = appendAccessor(model, v.tangents.data(), count * 4 * sizeof(float), kArray,
                                      kFloat, TINYGLTF_TYPE_VEC4, count);
  const int uvs = appendAccessor(model, v.uvs.data(), count * sizeof(Vec2f), kArray, kFloat,
                                 TINYGLTF_TYPE_VEC2, count);
  const int indices =
      appendAccessor(model, v.triangles.data(), v.triangles.size() * 3 * sizeof(std::uint32_t),
                     TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                     TINYGLTF_TYPE_SCALAR, v.triangles.size() * 3);

  // The map's texel centres are the image positions it was baked at; the square's border is
  // the octahedral seam, so clamping keeps it from blending with the opposite side.
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  model.samplers.push_back(sampler);
  const std::vector<unsigned char> png = detail::encodeNormalMapPng(map);
  tinygltf::Image image;
  image.name = std::string(normalMapSpaceName(map.space)) + "_normal";
  image.mimeType = "image/png";
  image.bufferView = appendView(model, png.data(), png.size(), 0);
  model.images.push_back(image);
  tinygltf::Texture texture;
  texture.sampler = 0;
  texture.source = 0;
  model.textures.push_back(texture);

  tinygltf::Material material;
  material.name = "octaclay_lod";
  material.pbrMetallicRoughness.metallicFactor = 0.0;
  material.pbrMetallicRoughness.roughnessFactor = 0.6;
  if (map.space == NormalMapSpace::Tangent) {
    material.normalTexture.index = 0;
  } else {
    // glTF has no object-space normal texture: keep it in the file, named in extras, for
    // renderers that know; standard viewers shade with NORMAL.
    material.extras = tinygltf::Value(
        tinygltf::Value::Object{{"octaclay_object_space_normal_texture", tinygltf::Value(0)}});
  }
  model.materials.push_back(material);

  tinygltf::Primitive primitive;
  primitive.attributes = {
      {"POSITION", positions}, {"NORMAL", normals}, {"TANGENT", tangents}, {"TEXCOORD_0", uvs}};
  primitive.indices = indices;
  primitive.material = 0;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  tinygltf::Mesh mesh;
  mesh.name = "octaclay_lod_" + std::to_string(lod.mesh.triangles.size());
  mesh.primitives.push_back(primitive);
  model.meshes.push_back(mesh);
  tinygltf::Node node;
  node.name = "octaclay_lod";
  node.mesh = 0;
  model.nodes.push_back(node);
  tinygltf::Scene scene;
  scene.nodes = {0};
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

void writeGlbFile(const LodMesh& lod, const NormalMap& map, const fs::path& path) {
  const LodVertices vertices = lodVertices(lod);
  const tinygltf::Model model = glbModel(lod, vertices, map);
  detail::writeAtomically(path, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw Error(ErrorKind::Io, "cannot open " + path.string() + " for writing");
    tinygltf::TinyGLTF writer;
    const bool ok = writer.WriteGltfSceneToStream(&model, out, false, true);
    out.close();
    if (!ok || !out) throw Error(ErrorKind::Io, "cannot write " + path.string());
  });
}

} // namespace

std::vector<fs::path> writeLodMesh(const LodMesh& lod, const NormalMap& map, const fs::path& path) {
  detail::requireNormalMap(map);
  if (lod.mesh.triangles.empty())
    throw Error(ErrorKind::InvalidArgument, "cannot write " + path.string() + ": the LOD is empty");
  const std::string ext = lowerExtension(path);
  if (ext == ".glb") {
    writeGlbFile(lod, map, path);
    return {path};
  }
  if (ext == ".obj") return writeObj(lod, map, path);
  throw Error(ErrorKind::InvalidArgument, "cannot write the LOD to " + path.string() +
                                              ": use .obj (with .mtl and map) or .glb");
}

} // namespace octaclay::core
