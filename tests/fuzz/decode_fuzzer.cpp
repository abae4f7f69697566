// libFuzzer target for every decoder (issue 8): the .ocz container (a document or a scene) and each
// codec's stream decoder must refuse any input with core::Error — never crash, read out of bounds,
// overflow or allocate without bound. Anything else escaping (or a sanitizer report) is a finding.

#include "fuzz_input.h"

#include "octaclay/core/codec/compressed_scene.h"
#include "octaclay/core/codec/wavelet_codec.h"
#include "octaclay/core/error.h"

#include <cstdlib>

namespace {

// Runs one decoder; core::Error is the refusal every bad stream must get.
template <class Decode> void refuseOrDecode(Decode&& decode) {
  try {
    decode();
  } catch (const octaclay::core::Error&) {
  }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz_input::Target target;
  if (!fuzz_input::parse({data, size}, target)) return 0;
  if (target.codec == nullptr) {
    // Both versions: one document (1) and a scene (2, each object a version-1 container).
    refuseOrDecode([&] {
      const octaclay::core::Scene scene = octaclay::core::decompressScene(target.stream);
      if (scene.objects.empty()) std::abort(); // a scene that decodes has an object
      for (const octaclay::core::SceneObject& object : scene.objects)
        if (object.document.size() <= 0) std::abort(); // and each object a size
    });
    return 0;
  }
  refuseOrDecode([&] {
    const octaclay::core::FloatImage image =
        target.codec->decode(target.stream, target.n, target.channels);
    const std::size_t side = static_cast<std::size_t>(target.n) + 1;
    // A stream that decodes gives exactly the image the container asked for.
    if (image.n != target.n || image.channels != target.channels ||
        image.texels.size() != side * side * static_cast<std::size_t>(target.channels))
      std::abort();
  });
  // The wavelet's progressive prefixes are a decoder of their own; byte 2's upper bits pick
  // the prefix length in 64ths of the stream.
  if (target.codec->info.id == "wavelet")
    refuseOrDecode([&] {
      const std::size_t prefix = target.stream.size() * (data[2] >> 2) / 64;
      octaclay::core::decodeWaveletPrefix(target.stream, target.n, target.channels, prefix);
    });
  return 0;
}
