// Normal maps on disk: 8-bit PNG through libpng (what every viewer reads) or float32 EXR through
// OpenEXR (no quantisation, for offline renderers and tests).

#include "detail/exr_memory_stream.h"
#include "detail/png_codec.h"
#include "lod/normal_map_encoding.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"
#include "octaclay/core/file_extension.h"
#include "octaclay/core/lod/normal_map.h"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace octaclay::core {
namespace detail {

void requireNormalMap(const NormalMap& map) {
  if (map.resolution < 1 || map.texels.size() != static_cast<std::size_t>(map.resolution) *
                                                     static_cast<std::size_t>(map.resolution))
    throw Error(ErrorKind::InvalidArgument, "the normal map's resolution and texels disagree");
}

std::vector<unsigned char> encodeNormalMapPng(const NormalMap& map) {
  requireNormalMap(map);
  const int r = map.resolution;
  const auto byte = [](float c) {
    return static_cast<std::uint8_t>(std::clamp(c * 0.5f + 0.5f, 0.0f, 1.0f) * 255.0f + 0.5f);
  };
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(r) * r * 3);
  for (std::size_t i = 0; i < static_cast<std::size_t>(r) * r; ++i) {
    rgb[3 * i] = byte(map.texels[i].x);
    rgb[3 * i + 1] = byte(map.texels[i].y);
    rgb[3 * i + 2] = byte(map.texels[i].z);
  }
  return encodePng(rgb, r, r, 3);
}

} // namespace detail

namespace {

std::vector<std::uint8_t> encodeExr(const NormalMap& map) {
  const int r = map.resolution;
  Imf::Header header(r, r);
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* channel : {"R", "G", "B"})
    header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
  Imf::FrameBuffer frame;
  char* base = reinterpret_cast<char*>(const_cast<Vec3f*>(map.texels.data()));
  const std::size_t xStride = sizeof(Vec3f), yStride = xStride * static_cast<std::size_t>(r);
  frame.insert("R", Imf::Slice(Imf::FLOAT, base, xStride, yStride));
  frame.insert("G", Imf::Slice(Imf::FLOAT, base + sizeof(float), xStride, yStride));
  frame.insert("B", Imf::Slice(Imf::FLOAT, base + 2 * sizeof(float), xStride, yStride));
  detail::ExrMemoryStream stream;
  {
    Imf::OutputFile file(stream, header);
    file.setFrameBuffer(frame);
    file.writePixels(r);
  }
  return std::move(stream.bytes());
}

} // namespace

void stageNormalMap(const NormalMap& map, const std::filesystem::path& path, OutputSet& set) {
  detail::requireNormalMap(map);
  const std::string ext = lowerExtension(path);
  if (ext == ".png") {
    set.stageBytes(path, detail::encodeNormalMapPng(map));
  } else if (ext == ".exr") {
    set.stageBytes(path, encodeExr(map));
  } else {
    throw Error(ErrorKind::InvalidArgument, "cannot write a normal map to " + path.string() +
                                                ": use .png (8-bit) or .exr (float)");
  }
}

void writeNormalMap(const NormalMap& map, const std::filesystem::path& path) {
  OutputSet set;
  stageNormalMap(map, path, set);
  set.commit();
}

} // namespace octaclay::core
