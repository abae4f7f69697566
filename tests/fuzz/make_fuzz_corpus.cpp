// Writes decode_fuzzer's seed corpus into the folder given: for every codec and setting a
// valid stream of a small sphere-like image (N = 8, 16; 1, 3 and 4 channels), and valid .ocz
// documents and scenes, each prefixed as fuzz_input.h reads them. A second folder, when given,
// gets document_lines_fuzzer's: the lines of its documents, each variant's byte first.

#include "document_lines_input.h"
#include "fuzz_input.h"

#include "octaclay/core/codec/compressed_document.h"
#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/document/document.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/base_shapes.h"
#include "octaclay/core/geometry/sheet.h"
#include "octaclay/core/geometry/torus.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using namespace octaclay;

void writeSeed(const std::filesystem::path& dir, const std::string& name,
               std::span<const std::uint8_t> prefix, const std::vector<std::uint8_t>& stream) {
  std::ofstream file(dir / name, std::ios::binary);
  file.write(reinterpret_cast<const char*>(prefix.data()),
             static_cast<std::streamsize>(prefix.size()));
  file.write(reinterpret_cast<const char*>(stream.data()),
             static_cast<std::streamsize>(stream.size()));
}

core::FloatImage imageOf(const core::GeometryImage& g, int channels) {
  core::FloatImage out{g.size(), channels, {}};
  for (const core::Vec4f& t : g.texels()) {
    const float values[4] = {t.x, t.y, t.z, 0.25f * t.x * t.y};
    out.texels.insert(out.texels.end(), values, values + channels);
  }
  return out;
}

} // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: make_fuzz_corpus <folder> [<lines folder>]\n");
    return 2;
  }
  if (argc == 3) {
    const std::filesystem::path lines = argv[2];
    std::filesystem::create_directories(lines);
    for (std::uint8_t variant = 0; variant < 4; ++variant) {
      const document_lines_input::Template t =
          document_lines_input::makeTemplate((variant & 1) != 0, lines / "template.exr");
      const std::uint8_t prefix[1] = {variant};
      writeSeed(lines, "lines_" + std::to_string(variant), prefix, t.body);
    }
    std::filesystem::remove(lines / "template.exr");
  }
  const std::filesystem::path dir = argv[1];
  std::filesystem::create_directories(dir);
  int written = 0;
  const auto& all = core::codecs();
  for (int n : {8, 16}) {
    const core::GeometryImage shape = core::makeBaseShape(core::BaseShape::Sphere, n);
    for (std::size_t k = 0; k < all.size(); ++k)
      for (int channels : {1, 3, 4}) {
        std::vector<core::CodecParams> settings{{.quality = all[k].info.defaultQuality}};
        if (all[k].info.id == "bytepack") settings = {{2, {}}, {4, {}}};
        if (all[k].info.id == "exr") settings = {{0, "zip"}, {0, "piz"}, {0, "pxr24"}, {0, "half"}};
        for (const core::CodecParams& params : settings) {
          try {
            const auto stream = all[k].encode(imageOf(shape, channels), params);
            writeSeed(dir,
                      std::to_string(written) + "_" + std::string(all[k].info.id) + params.mode +
                          "_" + std::to_string(n) + "_" + std::to_string(channels),
                      fuzz_input::header(k, n, channels), stream);
            ++written;
          } catch (const core::Error& e) {
            std::fprintf(stderr, "%s: %s\n", std::string(all[k].info.id).c_str(), e.what());
          }
        }
      }
    core::Document doc = core::makeDocument(shape);
    doc.diffuse.texels.assign(shape.texelCount() * 4, 0.5f);
    for (const core::Codec& codec : all) {
      const std::uint8_t container[1] = {0};
      writeSeed(dir, "ocz_" + std::string(codec.info.id) + "_" + std::to_string(n), container,
                core::compressDocument(doc, {.codec = std::string(codec.info.id),
                                             .params = {.quality = -1, .mode = {}},
                                             .layerCodec = "lossless"}));
      ++written;
    }
    // A scene (.ocz version 2): the ball, a torus of W ≠ H and a plane, placed, one hidden.
    core::Scene scene = core::sceneOf(doc, "Ball");
    scene.objects.push_back({"Ring",
                             core::makeDocument(core::makeTorus({}, n, n / 4 < 4 ? 4 : n / 4)),
                             {{1, 0, 0}, {90, 0, 0}, {0.5f, 0.5f, 0.5f}},
                             false,
                             false});
    scene.objects.push_back(
        {"Sheet", core::makeDocument(core::makeSheet(core::Sheet::Square, n)), {}, true, true});
    const std::uint8_t container[1] = {0};
    writeSeed(
        dir, "ocz_scene_" + std::to_string(n), container,
        core::compressScene(scene, {.codec = "lossless", .params = {}, .layerCodec = "lossless"}));
    ++written;
  }
  std::printf("%d seeds in %s\n", written, dir.string().c_str());
  return 0;
}
