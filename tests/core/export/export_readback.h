#pragma once

// Reading the exports back as a viewer would: tinygltf for the GLB, the `v` and `f` records of
// an OBJ, identical positions welded, a map sampled with a viewer's linear filter.

#include "octaclay/core/geometry/triangle_mesh.h"

#include <QtGlobal>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace export_readback {

using octaclay::core::TriangleMesh;
using octaclay::core::Vec3f;
namespace fs = std::filesystem;

// What a viewer's linear filter with clamping reads from channel c at texture coordinate (u, v).
inline float sampleLinear(const tinygltf::Image& image, float u, float v, int c) {
  const auto at = [&](int x, int y) {
    x = std::clamp(x, 0, image.width - 1);
    y = std::clamp(y, 0, image.height - 1);
    return float(image.image[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) *
                                 std::size_t(image.component) +
                             std::size_t(c)]) /
           255.0f;
  };
  const float x = u * float(image.width) - 0.5f, y = v * float(image.height) - 0.5f;
  const int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  const float fx = x - float(x0), fy = y - float(y0);
  return (at(x0, y0) * (1 - fx) + at(x0 + 1, y0) * fx) * (1 - fy) +
         (at(x0, y0 + 1) * (1 - fx) + at(x0 + 1, y0 + 1) * fx) * fy;
}

// The `v` records and each face's position indices (`f a/.. b/.. c/..`, counted from 1).
inline TriangleMesh readObjPositions(const fs::path& path) {
  TriangleMesh mesh;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream s(line);
    std::string key;
    s >> key;
    if (key == "v") {
      Vec3f p;
      s >> p.x >> p.y >> p.z;
      mesh.positions.push_back(p);
    } else if (key == "f") {
      std::array<std::uint32_t, 3> t{};
      for (auto& index : t) {
        std::string corner;
        s >> corner;
        index = std::uint32_t(std::stoul(corner.substr(0, corner.find('/'))) - 1);
      }
      mesh.triangles.push_back(t);
    }
  }
  return mesh;
}

template <class T>
std::vector<T> accessorData(const tinygltf::Model& model, int index, std::size_t components) {
  const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
  const tinygltf::BufferView& view = model.bufferViews[std::size_t(a.bufferView)];
  std::vector<T> values(a.count * components);
  std::memcpy(values.data(),
              model.buffers[std::size_t(view.buffer)].data.data() + view.byteOffset + a.byteOffset,
              values.size() * sizeof(T));
  return values;
}

inline tinygltf::Model readGlb(const fs::path& path) {
  tinygltf::Model model;
  tinygltf::TinyGLTF loader;
  std::string err, warn;
  if (!loader.LoadBinaryFromFile(&model, &err, &warn, path.string()))
    qWarning("tinygltf: %s", err.c_str());
  return model;
}

inline TriangleMesh glbPositions(const tinygltf::Model& model) {
  TriangleMesh mesh;
  for (const tinygltf::Mesh& m : model.meshes)
    for (const tinygltf::Primitive& p : m.primitives) {
      const auto base = std::uint32_t(mesh.positions.size());
      const auto xyz = accessorData<float>(model, p.attributes.at("POSITION"), 3);
      for (std::size_t k = 0; k + 2 < xyz.size(); k += 3)
        mesh.positions.push_back({xyz[k], xyz[k + 1], xyz[k + 2]});
      const auto index = accessorData<std::uint32_t>(model, p.indices, 1);
      for (std::size_t k = 0; k + 2 < index.size(); k += 3)
        mesh.triangles.push_back({base + index[k], base + index[k + 1], base + index[k + 2]});
    }
  return mesh;
}

// Identical positions become one vertex, as importers that weld by position do.
inline TriangleMesh weldByPosition(const TriangleMesh& in) {
  std::map<std::array<float, 3>, std::uint32_t> first;
  std::vector<std::uint32_t> to(in.positions.size());
  TriangleMesh out;
  for (std::size_t k = 0; k < in.positions.size(); ++k) {
    const Vec3f p = in.positions[k];
    const auto [it, added] =
        first.try_emplace({p.x, p.y, p.z}, std::uint32_t(out.positions.size()));
    if (added) out.positions.push_back(p);
    to[k] = it->second;
  }
  for (const auto& t : in.triangles)
    out.triangles.push_back({to[t[0]], to[t[1]], to[t[2]]});
  return out;
}

inline int materialTexture(const tinygltf::Model& model, bool normal) {
  if (model.materials.empty()) return -1;
  const tinygltf::Material& m = model.materials[0];
  return normal ? m.normalTexture.index : m.pbrMetallicRoughness.baseColorTexture.index;
}

// The texture's image, decoded by tinygltf.
inline const tinygltf::Image* textureImage(const tinygltf::Model& model, int texture) {
  if (texture < 0 || std::size_t(texture) >= model.textures.size()) return nullptr;
  const int source = model.textures[std::size_t(texture)].source;
  return source < 0 ? nullptr : &model.images[std::size_t(source)];
}

// How many distinct colours the image's first three channels take (8-bit).
inline std::size_t colourCount(const tinygltf::Image& image) {
  std::map<std::array<unsigned char, 3>, int> seen;
  const std::size_t c = std::size_t(image.component);
  for (std::size_t k = 0; k + c <= image.image.size(); k += c)
    seen[{image.image[k], image.image[k + 1], image.image[k + 2]}] = 1;
  return seen.size();
}

} // namespace export_readback
