// libFuzzer target for the brush manifest parser (issue 20): any bytes, as a manifest.json's
// text, must end in a BrushManifest or a BrushLoadError, never a crash, a hang or another
// exception. The manifest sits in a temporary folder holding the shader the built-in manifests
// name (brush.glsl), so the fuzzer gets past the shader check into the parameters.

#include "octaclay/gpu/brush_manifest.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string_view>

namespace {

// The temporary folder, removed when the fuzzer exits.
struct ShaderFolder {
  std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                 ("octaclay-manifest-fuzz-" + std::to_string(::getpid()));
  ShaderFolder() {
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "brush.glsl")
        << "vec4 brush(vec4 value, BrushInput b) { return value; }\n";
  }
  ~ShaderFolder() {
    std::error_code ec;
    std::filesystem::remove_all(folder, ec);
  }
};

std::filesystem::path manifestFile() {
  static const ShaderFolder shaders;
  return shaders.folder / "manifest.json";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const octaclay::gpu::BrushManifest manifest =
        octaclay::gpu::parseBrushManifestText(text, manifestFile());
    // What a parsed manifest promises (brush_manifest.h): writes never empty, ranges ordered.
    if (manifest.writes.empty()) __builtin_trap();
    for (const octaclay::gpu::BrushParameter& p : manifest.parameters)
      if (!(p.min <= p.max) || !(p.step > 0)) __builtin_trap();
  } catch (const octaclay::gpu::BrushLoadError&) {
  }
  return 0;
}
