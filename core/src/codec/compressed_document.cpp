// The .ocz container (compressed_document.h). Layout, little-endian:
//   "OCZ1", u16 format version, u32 N, u8 layer count (4: positions, diffuse, feature, mask),
//   per layer: u8 storage (0 absent, 1 uniform, 2 coded), u8 channels, then
//     uniform: channels × f32 fill;
//     coded:   u8 codec code, f64 quality, u8 mode length, mode, u64 stream length;
//   the coded layers' streams in layer order; u32 CRC-32 (zlib's) of everything before it.
// Positions store xyz only: saliency (alpha) is derived data, as in the native .exr, and reads
// back as zero until the saliency pass recomputes it.

#include "octaclay/core/codec/compressed_document.h"

#include "codec/byte_io.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/document/document_checks.h"
#include "octaclay/core/error.h"

#include <array>
#include <cmath>
#include <new>

namespace octaclay::core {
namespace {

using detail::ByteReader;
using detail::ByteWriter;
using detail::crc32Of;

constexpr std::array<std::uint8_t, 4> kMagic{'O', 'C', 'Z', '1'};
constexpr std::uint16_t kFormatVersion = 1;
constexpr std::uint8_t kLayerCount = 4;
enum Storage : std::uint8_t { Absent = 0, Uniform = 1, Coded = 2 };

const Codec& requireCodec(std::string_view id) {
  const Codec* codec = findCodec(id);
  if (!codec) {
    std::string known;
    for (const Codec& c : codecs())
      known += (known.empty() ? "" : ", ") + std::string(c.info.id);
    throw Error(ErrorKind::InvalidArgument,
                "unknown codec '" + std::string(id) + "'; choose one of " + known);
  }
  return *codec;
}

struct CodedLayer {
  const Codec* codec = nullptr;
  CodecParams params;
  std::vector<std::uint8_t> stream;
};

void writeCodedEntry(ByteWriter& out, int channels, const CodedLayer& coded) {
  out.u8(Coded);
  out.u8(static_cast<std::uint8_t>(channels));
  out.u8(coded.codec->info.code);
  out.f64(coded.params.quality);
  out.u8(static_cast<std::uint8_t>(coded.params.mode.size()));
  for (char c : coded.params.mode)
    out.u8(static_cast<std::uint8_t>(c));
  out.u64(coded.stream.size());
}

CodedLayer codeLayer(const Codec& codec, const CodecParams& params, FloatImage image) {
  if (params.mode.size() > 255)
    throw Error(ErrorKind::InvalidArgument, "codec mode '" + params.mode + "' is too long");
  CodedLayer coded{&codec, params, {}}; // quality ≤ 0: the codec picks its default
  coded.stream = codec.encode(image, coded.params);
  return coded;
}

} // namespace

std::vector<std::uint8_t> compressDocument(const Document& doc, const CompressOptions& options) {
  const int n = doc.size();
  requireValidSize(n);
  const Codec& positionCodec = requireCodec(options.codec);
  const Codec& layerCodec = requireCodec(options.layerCodec);

  FloatImage positions{n, 3, {}};
  positions.texels.reserve(doc.positions.texelCount() * 3);
  for (const Vec4f& t : doc.positions.texels())
    positions.texels.insert(positions.texels.end(), {t.x, t.y, t.z});

  ByteWriter out;
  for (std::uint8_t m : kMagic)
    out.u8(m);
  out.u16(kFormatVersion);
  out.u32(static_cast<std::uint32_t>(n));
  out.u8(kLayerCount);
  std::vector<CodedLayer> coded;
  coded.push_back(codeLayer(positionCodec, options.params, std::move(positions)));
  writeCodedEntry(out, 3, coded.back());
  for (const Layer* layer : {&doc.diffuse, &doc.feature, &doc.mask}) {
    if (layer == &doc.mask && !doc.hasMask) {
      out.u8(Absent);
      out.u8(static_cast<std::uint8_t>(layer->channels));
    } else if (layer->uniform()) {
      out.u8(Uniform);
      out.u8(static_cast<std::uint8_t>(layer->channels));
      for (int c = 0; c < layer->channels; ++c)
        out.f32(layer->fill[c]);
    } else {
      coded.push_back(codeLayer(layerCodec, {}, {n, layer->channels, layer->texels}));
      writeCodedEntry(out, layer->channels, coded.back());
    }
  }
  for (const CodedLayer& c : coded)
    out.append(c.stream);
  out.u32(crc32Of(out.bytes()));
  return out.take();
}

Document decompressDocument(std::span<const std::uint8_t> bytes) {
  ByteReader in(bytes, "compressed document");
  std::array<std::uint8_t, 4> magic{};
  for (auto& m : magic)
    m = in.u8();
  if (magic != kMagic)
    in.fail("not an Octaclay compressed document (wrong magic number; .ocz files start with "
            "OCZ1 and are written by `octaclay-cli compress`)");
  const std::uint16_t version = in.u16();
  if (version != kFormatVersion)
    in.fail("format version " + std::to_string(version) +
            " is not supported (this Octaclay reads version " + std::to_string(kFormatVersion) +
            "); update Octaclay");
  if (bytes.size() < 4 + 2 + 4 + 4)
    in.fail("truncated: " + std::to_string(bytes.size()) + " bytes");
  const auto body = bytes.first(bytes.size() - 4);
  ByteReader tail(bytes.last(4), "compressed document");
  if (tail.u32() != crc32Of(body)) in.fail("checksum mismatch: the file is damaged or truncated");
  in = ByteReader(body, "compressed document");
  in.take(6);

  const std::uint32_t n = in.u32();
  if (n > static_cast<std::uint32_t>(kMaxSize) || !isValidSize(static_cast<int>(n)))
    in.fail("N = " + std::to_string(n) + " is not a power of two between 2 and 8192");
  const std::uint8_t layerCount = in.u8();
  if (layerCount != kLayerCount)
    in.fail(std::to_string(layerCount) + " layers, expected " + std::to_string(kLayerCount));

  // Nothing of N's size is allocated until the entries and every stream's length hold
  // together and the positions decode: a header that lies about N costs no memory.
  Document doc;
  const std::array<Layer*, 4> layers{nullptr, &doc.diffuse, &doc.feature, &doc.mask};
  const std::array<const char*, 4> names{"positions", "diffuse", "feature", "mask"};
  struct Entry {
    const Codec* codec = nullptr;
    std::uint64_t length = 0;
    int channels = 0;
  };
  std::array<Entry, 4> entries{};
  for (int k = 0; k < kLayerCount; ++k) {
    const std::string name = names[k];
    const std::uint8_t storage = in.u8();
    const int channels = in.u8();
    const int expected = k == 0 ? 3 : layers[k]->channels;
    if (channels != expected)
      in.fail(name + " has " + std::to_string(channels) + " channels, expected " +
              std::to_string(expected));
    if (storage == Uniform && k > 0) {
      for (int c = 0; c < channels; ++c)
        layers[k]->fill[c] = in.f32();
      if (k == 3) doc.hasMask = true; // a mask stored uniform is a mask all the same
    } else if (storage == Absent && k == 3) {
      doc.hasMask = false;
    } else if (storage == Coded) {
      const std::uint8_t code = in.u8();
      entries[k].codec = findCodec(code);
      if (!entries[k].codec)
        in.fail(name + " uses codec code " + std::to_string(code) +
                ", which this Octaclay does not know; update Octaclay");
      in.f64(); // the quality it was coded with: informative, the stream is self-describing
      in.take(in.u8());
      entries[k].length = in.u64();
      entries[k].channels = channels;
      if (k == 3) doc.hasMask = true;
    } else {
      in.fail(name + " has storage kind " + std::to_string(storage) + ", which is not valid");
    }
  }
  if (!entries[0].codec) in.fail("positions are not stored");
  std::uint64_t streamBytes = 0;
  for (const Entry& e : entries) {
    if (e.length > in.remaining()) in.fail("a layer's stream is longer than the file");
    streamBytes += e.length;
  }
  if (streamBytes != in.remaining())
    in.fail("the layers' streams hold " + std::to_string(streamBytes) + " bytes, the file " +
            std::to_string(in.remaining()));

  try {
    for (int k = 0; k < kLayerCount; ++k) {
      if (!entries[k].codec) continue;
      const auto stream = in.take(entries[k].length);
      FloatImage image = entries[k].codec->decode(stream, static_cast<int>(n), entries[k].channels);
      if (k == 0) {
        doc.positions = GeometryImage(static_cast<int>(n));
        for (std::size_t t = 0; t < doc.positions.texelCount(); ++t) {
          const float* p = &image.texels[t * 3];
          doc.positions.texels()[t] = {p[0], p[1], p[2], 0.0f};
        }
        if (const auto problem = positionsProblem(doc.positions)) in.fail(*problem);
      } else {
        layers[k]->texels = std::move(image.texels);
        if (const auto problem = layerValuesProblem(*layers[k], static_cast<int>(n)))
          in.fail(*problem);
      }
    }
  } catch (const std::bad_alloc&) {
    in.fail("not enough memory to decode N = " + std::to_string(n) +
            ": the document is larger than this machine can hold");
  }
  in.expectEnd();
  return doc;
}

void writeCompressedDocument(const Document& doc, const CompressOptions& options,
                             const std::filesystem::path& path) {
  const auto bytes = compressDocument(doc, options);
  writeBytesAtomically(path, bytes);
}

Document readCompressedDocument(const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = detail::readCompressedFileBytes(path);
  try {
    return decompressDocument(bytes);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::InvalidInput) throw;
    throw Error(ErrorKind::InvalidInput, path.string() + ": " + e.what());
  }
}

} // namespace octaclay::core
