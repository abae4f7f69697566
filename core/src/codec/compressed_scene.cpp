// The .ocz container of a scene (compressed_scene.h). Layout of version 2, little-endian:
//   "OCZ1", u16 format version 2, u32 object count,
//   per object: u8 name length, the name (UTF-8), u8 topology (0 octahedral, 1 torus, 2 plane),
//     u32 width, u32 height (cells), 9 × f32 transform (translation, rotation in degrees about
//     X then Y then Z, scale), u8 visible, u8 locked, u64 length of its document;
//   the objects' documents in order, each a version-1 container of side max(width, height);
//   u32 CRC-32 (zlib's) of everything before it.

#include "octaclay/core/codec/compressed_scene.h"

#include "codec/byte_io.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/sample_grid.h"

#include <algorithm>
#include <array>
#include <set>

namespace octaclay::core {
namespace {

using detail::ByteReader;
using detail::ByteWriter;

constexpr std::array<std::uint8_t, 4> kMagic{'O', 'C', 'Z', '1'};
constexpr std::uint16_t kDocumentVersion = 1;
// The fewest bytes an object's entry takes (an empty name is refused, so one more in truth).
constexpr std::size_t kEntryBytes = 1 + 1 + 4 + 4 + 9 * 4 + 1 + 1 + 8;
constexpr std::array<Topology, 3> kTopologies{Topology::Octahedral, Topology::Torus,
                                              Topology::Plane};

std::uint8_t topologyCode(Topology topology) {
  return static_cast<std::uint8_t>(std::find(kTopologies.begin(), kTopologies.end(), topology) -
                                   kTopologies.begin());
}

// Whether options decode every sample exactly, positions and painted layers both.
bool codesExactly(const CompressOptions& options) {
  const auto exact = [](const std::string& id, const std::string& mode) {
    const Codec* codec = findCodec(std::string_view(id));
    if (!codec) return true; // unknown: compressDocument names it
    if (codec->info.id == "exr") return mode.empty() || mode == "zip" || mode == "piz";
    return !codec->info.lossy;
  };
  return exact(options.codec, options.params.mode) && exact(options.layerCodec, "");
}

// A layer's texels of a (columns × rows) image on the square of side `side`, the last column and
// row repeated; or cut back from it.
std::vector<float> padded(const std::vector<float>& texels, int channels, int columns, int rows,
                          int side) {
  std::vector<float> out(static_cast<std::size_t>(side) * side * channels);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t from =
          (static_cast<std::size_t>(std::min(j, rows - 1)) * columns + std::min(i, columns - 1)) *
          channels;
      std::copy_n(texels.begin() + static_cast<std::ptrdiff_t>(from), channels,
                  out.begin() + (static_cast<std::ptrdiff_t>(j) * side + i) * channels);
    }
  return out;
}

std::vector<float> cut(const std::vector<float>& texels, int channels, int columns, int rows,
                       int side) {
  std::vector<float> out(static_cast<std::size_t>(columns) * rows * channels);
  for (int j = 0; j < rows; ++j)
    std::copy_n(texels.begin() + static_cast<std::ptrdiff_t>(j) * side * channels,
                columns * channels,
                out.begin() + static_cast<std::ptrdiff_t>(j) * columns * channels);
  return out;
}

// The document the codecs see: the object's own when octahedral, else its image on the square.
Document squareDocument(const Document& document) {
  const GeometryImage& image = document.positions;
  const int columns = image.side(), rows = image.rows(), side = std::max(columns, rows);
  Document square = document;
  square.topology = Topology::Octahedral;
  square.positions = GeometryImage(side - 1);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      square.positions.texels()[static_cast<std::size_t>(j) * side + i] =
          image.texels()[static_cast<std::size_t>(std::min(j, rows - 1)) * columns +
                         std::min(i, columns - 1)];
  for (Layer* layer : {&square.diffuse, &square.feature, &square.mask})
    if (!layer->uniform())
      layer->texels = padded(layer->texels, layer->channels, columns, rows, side);
  return square;
}

Document objectDocument(Document square, Topology topology, int width, int height) {
  if (topology == Topology::Octahedral) return square;
  const int side = square.positions.side();
  Document document = std::move(square);
  GeometryImage image(topology, width, height);
  for (int j = 0; j <= height; ++j)
    std::copy_n(document.positions.texels().begin() + static_cast<std::ptrdiff_t>(j) * side,
                width + 1, image.texels().begin() + static_cast<std::ptrdiff_t>(j) * (width + 1));
  document.positions = std::move(image);
  document.topology = topology;
  for (Layer* layer : {&document.diffuse, &document.feature, &document.mask})
    if (!layer->uniform())
      layer->texels = cut(layer->texels, layer->channels, width + 1, height + 1, side);
  return document;
}

Scene oneObject(Document document, std::string_view name) {
  Scene scene;
  scene.objects.push_back({std::string(name), std::move(document), {}, true, false});
  return scene;
}

} // namespace

std::optional<std::string> compressProblem(const SceneObject& object,
                                           const CompressOptions& options) {
  const Topology topology = object.document.positions.topology();
  if (topology == Topology::Octahedral || codesExactly(options)) return std::nullopt;
  const bool positionsLossy = !codesExactly({options.codec, options.params, "lossless"});
  const std::string codec = positionsLossy ? options.codec : options.layerCodec;
  return "codec '" + codec + "'" + (positionsLossy ? "" : " (for the painted layers)") +
         " cannot code object '" + object.name + "', a " + std::string(topologyName(topology)) +
         ": it is lossy and seams its output as the octahedral ball's; a torus or plane needs an "
         "exact codec (lossless, or exr with --mode zip or piz)";
}

bool isOneDocument(const Scene& scene) {
  if (scene.objects.size() != 1) return false;
  const SceneObject& object = scene.objects.front();
  return object.document.positions.topology() == Topology::Octahedral &&
         object.transform == ObjectTransform{} && object.visible && !object.locked;
}

std::vector<std::uint8_t> compressScene(const Scene& scene, const CompressOptions& options) {
  if (const auto problem = sceneProblem(scene))
    throw Error(ErrorKind::InvalidArgument, "cannot compress the scene: " + *problem);
  for (const SceneObject& object : scene.objects)
    if (const auto problem = compressProblem(object, options))
      throw Error(ErrorKind::InvalidArgument, *problem);
  std::vector<std::vector<std::uint8_t>> bodies;
  bodies.reserve(scene.objects.size());
  for (const SceneObject& object : scene.objects)
    bodies.push_back(object.document.positions.topology() == Topology::Octahedral
                         ? compressDocument(object.document, options)
                         : compressDocument(squareDocument(object.document), options));

  ByteWriter out;
  for (std::uint8_t m : kMagic)
    out.u8(m);
  out.u16(kCompressedSceneVersion);
  out.u32(static_cast<std::uint32_t>(scene.objects.size()));
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const SceneObject& object = scene.objects[k];
    out.u8(static_cast<std::uint8_t>(object.name.size()));
    for (char c : object.name)
      out.u8(static_cast<std::uint8_t>(c));
    out.u8(topologyCode(object.document.positions.topology()));
    out.u32(static_cast<std::uint32_t>(object.document.positions.width()));
    out.u32(static_cast<std::uint32_t>(object.document.positions.height()));
    for (const Vec3f& v :
         {object.transform.translation, object.transform.rotationDegrees, object.transform.scale})
      for (float f : {v.x, v.y, v.z})
        out.f32(f);
    out.u8(object.visible ? 1 : 0);
    out.u8(object.locked ? 1 : 0);
    out.u64(bodies[k].size());
  }
  for (const auto& body : bodies)
    out.append(body);
  out.u32(detail::crc32Of(out.bytes()));
  return out.take();
}

Scene decompressScene(std::span<const std::uint8_t> bytes, std::string_view fallbackName) {
  ByteReader in(bytes, "compressed document");
  std::array<std::uint8_t, 4> magic{};
  for (auto& m : magic)
    m = in.u8();
  if (magic != kMagic)
    in.fail("not an Octaclay compressed document (wrong magic number; .ocz files start with "
            "OCZ1 and are written by `octaclay-cli compress`)");
  const std::uint16_t version = in.u16();
  if (version == kDocumentVersion) return oneObject(decompressDocument(bytes), fallbackName);
  if (version != kCompressedSceneVersion)
    in.fail("format version " + std::to_string(version) +
            " is not supported (this Octaclay reads versions 1 and 2); update Octaclay");
  if (bytes.size() < 4 + 2 + 4 + 4)
    in.fail("truncated: " + std::to_string(bytes.size()) + " bytes");
  const auto body = bytes.first(bytes.size() - 4);
  ByteReader tail(bytes.last(4), "compressed document");
  if (tail.u32() != detail::crc32Of(body))
    in.fail("checksum mismatch: the file is damaged or truncated");
  in = ByteReader(body, "compressed document");
  in.take(6);

  // Every object's entry is read and checked before any image is decoded.
  const std::uint32_t count = in.u32();
  if (count == 0 || count > kMaxSceneObjects)
    in.fail("it declares " + std::to_string(count) + " objects (1 to " +
            std::to_string(kMaxSceneObjects) + ")");
  if (std::uint64_t{count} * kEntryBytes > in.remaining())
    in.fail("it declares " + std::to_string(count) + " objects but holds " +
            std::to_string(in.remaining()) + " bytes: not even their headers fit");
  struct Entry {
    std::string name;
    Topology topology = Topology::Octahedral;
    int width = 0, height = 0;
    ObjectTransform transform;
    bool visible = true, locked = false;
    std::uint64_t length = 0;
  };
  std::vector<Entry> entries(count);
  std::set<std::string> names;
  for (std::uint32_t k = 0; k < count; ++k) {
    Entry& e = entries[k];
    const auto name = in.take(in.u8());
    e.name.assign(name.begin(), name.end());
    const std::string what = "object " + std::to_string(k + 1);
    if (const auto problem = objectNameProblem(e.name)) in.fail(what + ": " + *problem);
    if (!names.insert(e.name).second)
      in.fail(what + ": another object is named '" + e.name + "' too (names are unique)");
    const std::string part = what + " ('" + e.name + "')";
    const std::uint8_t topology = in.u8();
    if (topology >= kTopologies.size())
      in.fail(part + ": unknown topology code " + std::to_string(topology) +
              " (0 octahedral, 1 torus, 2 plane)");
    e.topology = kTopologies[topology];
    const std::uint32_t width = in.u32(), height = in.u32();
    if (width > kMaxSize || height > kMaxSize ||
        !isValidGrid({e.topology, static_cast<int>(width), static_cast<int>(height)}))
      in.fail(part + ": " + std::to_string(width) + " x " + std::to_string(height) +
              " cells is not a valid " + std::string(topologyName(e.topology)) + " image");
    e.width = static_cast<int>(width);
    e.height = static_cast<int>(height);
    for (Vec3f* v : {&e.transform.translation, &e.transform.rotationDegrees, &e.transform.scale})
      for (float* f : {&v->x, &v->y, &v->z})
        *f = in.f32();
    if (const auto problem = transformProblem(e.transform)) in.fail(part + ": " + *problem);
    const std::uint8_t visible = in.u8(), locked = in.u8();
    if (visible > 1 || locked > 1)
      in.fail(part + ": its visibility and lock are " + std::to_string(visible) + " and " +
              std::to_string(locked) + " (0 or 1 expected)");
    e.visible = visible == 1;
    e.locked = locked == 1;
    e.length = in.u64();
  }
  std::uint64_t total = 0;
  for (const Entry& e : entries) {
    if (e.length > in.remaining()) in.fail("object '" + e.name + "' is longer than the file");
    total += e.length;
  }
  if (total != in.remaining())
    in.fail("the objects hold " + std::to_string(total) + " bytes, the file " +
            std::to_string(in.remaining()));

  Scene scene;
  scene.objects.reserve(count);
  for (const Entry& e : entries) {
    const auto document = in.take(e.length);
    const std::string part = "object '" + e.name + "'";
    // Its side, read before it is decoded: a document larger than its header says is refused
    // before its memory is taken.
    const int side = std::max(e.width, e.height);
    ByteReader peek(document, "compressed document");
    if (document.size() < 10) in.fail(part + ": its document is truncated");
    peek.take(6);
    const std::uint32_t n = peek.u32();
    if (n != static_cast<std::uint32_t>(side))
      in.fail(part + ": its document is N = " + std::to_string(n) + " but its header says " +
              std::to_string(e.width) + " x " + std::to_string(e.height) + " cells");
    Document square;
    try {
      square = decompressDocument(document);
    } catch (const Error& error) {
      if (error.kind() != ErrorKind::InvalidInput) throw;
      in.fail(part + ": " + error.what());
    }
    scene.objects.push_back({e.name,
                             objectDocument(std::move(square), e.topology, e.width, e.height),
                             e.transform, e.visible, e.locked});
  }
  in.expectEnd();
  return scene;
}

void writeCompressedScene(const Scene& scene, const CompressOptions& options,
                          const std::filesystem::path& path) {
  writeBytesAtomically(path, compressScene(scene, options));
}

void writeCompressedModel(const Scene& scene, const CompressOptions& options,
                          const std::filesystem::path& path) {
  if (isOneDocument(scene))
    writeCompressedDocument(scene.objects.front().document, options, path);
  else
    writeCompressedScene(scene, options, path);
}

Scene readCompressedScene(const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = detail::readCompressedFileBytes(path);
  const std::string stem = path.stem().string();
  try {
    return decompressScene(bytes, objectNameProblem(stem) ? "Model" : stem);
  } catch (const Error& e) {
    if (e.kind() != ErrorKind::InvalidInput) throw;
    throw Error(ErrorKind::InvalidInput, path.string() + ": " + e.what());
  }
}

} // namespace octaclay::core
