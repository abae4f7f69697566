// The exports' binary glTF writer, through tinygltf: a maintained glTF 2.0 reader and writer
// that Debian packages (libtinygltf-dev, built there as a shared library with its stb and JSON
// dependencies, so linking TinyGLTF::TinyGLTF is all it takes). It also lets the tests read
// the result back with a loader we did not write.

#include "export/glb_writer.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/triangle_mesh.h"

#include <tiny_gltf.h>

#include <sstream>

namespace octaclay::core::detail {
namespace fs = std::filesystem;

namespace {

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

// A float (or, with `target` the element array, uint32) attribute of `count` elements.
template <class T>
int appendAccessor(tinygltf::Model& model, std::span<const T> values, int target, int componentType,
                   int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = appendView(model, values.data(), values.size_bytes(), target);
  accessor.componentType = componentType;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(accessor);
  return static_cast<int>(model.accessors.size() - 1);
}

void appendTexture(tinygltf::Model& model, const GlbTexture& texture) {
  tinygltf::Image image;
  image.name = texture.name;
  image.mimeType = "image/png";
  image.bufferView = appendView(model, texture.png.data(), texture.png.size(), 0);
  model.images.push_back(image);
  tinygltf::Texture gltfTexture;
  gltfTexture.sampler = 0;
  gltfTexture.source = static_cast<int>(model.images.size() - 1);
  model.textures.push_back(gltfTexture);
}

tinygltf::Material gltfMaterial(const GlbMaterial& in) {
  tinygltf::Material material;
  material.name = in.name;
  material.pbrMetallicRoughness.baseColorTexture.index = in.baseColorTexture;
  material.pbrMetallicRoughness.metallicRoughnessTexture.index = in.metallicRoughnessTexture;
  material.pbrMetallicRoughness.metallicFactor = in.metallicFactor;
  material.pbrMetallicRoughness.roughnessFactor = in.roughnessFactor;
  material.normalTexture.index = in.normalTexture;
  if (in.objectSpaceNormalTexture >= 0)
    material.extras = tinygltf::Value(tinygltf::Value::Object{
        {"octaclay_object_space_normal_texture", tinygltf::Value(in.objectSpaceNormalTexture)}});
  return material;
}

tinygltf::Primitive appendPrimitive(tinygltf::Model& model, const GlbMesh& mesh, int material) {
  const std::size_t count = mesh.positions.size();
  constexpr int kArray = TINYGLTF_TARGET_ARRAY_BUFFER;
  constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;
  static_assert(sizeof(Vec3f) == 12 && sizeof(Vec2f) == 8);

  tinygltf::Primitive primitive;
  primitive.attributes["POSITION"] =
      appendAccessor(model, mesh.positions, kArray, kFloat, TINYGLTF_TYPE_VEC3, count);
  BoundingBox box;
  for (const Vec3f& p : mesh.positions)
    box.extend(p);
  model.accessors.back().minValues = {box.min.x, box.min.y, box.min.z};
  model.accessors.back().maxValues = {box.max.x, box.max.y, box.max.z};
  primitive.attributes["NORMAL"] =
      appendAccessor(model, mesh.normals, kArray, kFloat, TINYGLTF_TYPE_VEC3, count);
  if (!mesh.tangents.empty())
    primitive.attributes["TANGENT"] =
        appendAccessor(model, mesh.tangents, kArray, kFloat, TINYGLTF_TYPE_VEC4, count);
  primitive.attributes["TEXCOORD_0"] =
      appendAccessor(model, mesh.texcoords, kArray, kFloat, TINYGLTF_TYPE_VEC2, count);
  primitive.indices = appendAccessor(model, mesh.triangles, TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER,
                                     TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                     mesh.triangles.size() * 3);
  primitive.material = material;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  return primitive;
}

tinygltf::Model glbModel(std::span<const GlbNode> nodes, std::span<const GlbTexture> textures) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = "Octaclay";
  model.buffers.emplace_back();
  std::vector<tinygltf::Primitive> primitives;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    primitives.push_back(appendPrimitive(model, nodes[k].mesh, static_cast<int>(k)));

  // Clamping keeps the image's border (the octahedral seam) from blending with the opposite
  // side.
  tinygltf::Sampler sampler;
  sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
  model.samplers.push_back(sampler);
  for (const GlbTexture& texture : textures)
    appendTexture(model, texture);
  for (const GlbNode& node : nodes)
    model.materials.push_back(gltfMaterial(node.material));

  tinygltf::Scene scene;
  for (std::size_t k = 0; k < nodes.size(); ++k) {
    tinygltf::Mesh gltfMesh;
    gltfMesh.name = nodes[k].material.meshName;
    gltfMesh.primitives.push_back(primitives[k]);
    model.meshes.push_back(gltfMesh);
    tinygltf::Node node;
    node.name = nodes[k].material.nodeName;
    node.mesh = static_cast<int>(k);
    node.translation = nodes[k].translation;
    node.rotation = nodes[k].rotation;
    node.scale = nodes[k].scale;
    model.nodes.push_back(node);
    scene.nodes.push_back(static_cast<int>(k));
  }
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  return model;
}

} // namespace

void writeGlbFile(const GlbMesh& mesh, std::span<const GlbTexture> textures,
                  const GlbMaterial& material, const fs::path& path, OutputSet& set) {
  const GlbNode node{mesh, material, {}, {}, {}};
  writeGlbNodes(std::span(&node, 1), textures, path, set);
}

void writeGlbNodes(std::span<const GlbNode> nodes, std::span<const GlbTexture> textures,
                   const fs::path& path, OutputSet& set) {
  const tinygltf::Model model = glbModel(nodes, textures);
  // tinygltf writes to a stream: a memory one, handed whole to the one checked writer.
  std::ostringstream out(std::ios::binary);
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, out, false, true))
    throw Error(ErrorKind::Io, "cannot write " + path.string() + ": the glTF writer failed");
  set.stageText(path, out.view());
}

} // namespace octaclay::core::detail
