// The .ocz container of a scene (compressed_scene.h). Layout of version 2, little-endian:
//   "OCZ1", u16 format version 2, u32 object count,
//   per object: u8 name length, the name (UTF-8), u8 topology (0 octahedral, 1 torus, 2 plane;
//     + 0x80 for a torus or plane coded lossily),
//     u32 width, u32 height (cells), 9 × f32 transform (translation, rotation in degrees about
//     X then Y then Z, scale), u8 visible, u8 locked, u64 length of its document;
//   the objects' documents in order, each a version-1 container of N = max(width, height), or
//   for a torus or plane coded lossily N = 2·max(width, height) with the image one sample in;
//   u32 CRC-32 (zlib's) of everything before it.

#include "octaclay/core/codec/compressed_scene.h"

#include "codec/byte_io.h"

#include "octaclay/core/document/atomic_output.h"
#include "octaclay/core/error.h"
#include "octaclay/core/geometry/octahedral.h"
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
// Set in the topology byte of a torus or plane coded lossily (one sample in on a square twice its
// longer side).
constexpr std::uint8_t kInsetFlag = 0x80;
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

// The document the codecs see: the object's own when octahedral, else its image on a square,
// the last column and row repeated beyond it. An exact codec gets the square of its longer side,
// the image at its corner; a lossy one, which seams its output as the ball's along the square's
// border, gets the square twice that side with the image one sample in from the border
// (`inset`), so no sample of the image is on a seam.
Document squareDocument(const Document& document, bool inset) {
  const GeometryImage& image = document.positions;
  const int columns = image.side(), rows = image.rows();
  const int cells = std::max(image.width(), image.height()) * (inset ? 2 : 1);
  const int side = cells + 1, offset = inset ? 1 : 0;
  Document square = document;
  square.topology = Topology::Octahedral;
  square.positions = GeometryImage(cells);
  const auto from = [&](int i, int j) {
    return static_cast<std::size_t>(std::clamp(j - offset, 0, rows - 1)) * columns +
           static_cast<std::size_t>(std::clamp(i - offset, 0, columns - 1));
  };
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i)
      square.positions.texels()[static_cast<std::size_t>(j) * side + i] =
          image.texels()[from(i, j)];
  for (Layer* layer : {&square.diffuse, &square.feature, &square.mask})
    if (!layer->uniform()) {
      const auto ch = static_cast<std::size_t>(layer->channels);
      std::vector<float> out(static_cast<std::size_t>(side) * side * ch);
      for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
          std::copy_n(layer->texels.begin() + static_cast<std::ptrdiff_t>(from(i, j) * ch), ch,
                      out.begin() + static_cast<std::ptrdiff_t>(
                                        (static_cast<std::size_t>(j) * side + i) * ch));
      layer->texels = std::move(out);
    }
  return square;
}

// The object's W × H image cut from the square at (offset, offset); when inset (lossily coded),
// a torus's column W and row H made its column and row 0 again (the codec decodes them apart).
Document objectDocument(Document square, Topology topology, int width, int height, int offset) {
  if (topology == Topology::Octahedral) return square;
  const auto side = static_cast<std::size_t>(square.positions.side());
  const auto columns = static_cast<std::size_t>(width + 1);
  Document document = std::move(square);
  GeometryImage image(topology, width, height);
  const auto at = [&](int i, int j) {
    return static_cast<std::size_t>(j + offset) * side + static_cast<std::size_t>(i + offset);
  };
  // The sample of the square that (i, j) takes: a torus's last column and row its first.
  const auto source = [&](int i, int j) {
    if (topology == Topology::Torus && offset > 0) return at(i % width, j % height);
    return at(i, j);
  };
  for (int j = 0; j <= height; ++j)
    for (int i = 0; i <= width; ++i)
      image.texels()[static_cast<std::size_t>(j) * columns + i] =
          document.positions.texels()[source(i, j)];
  document.positions = std::move(image);
  document.topology = topology;
  for (Layer* layer : {&document.diffuse, &document.feature, &document.mask})
    if (!layer->uniform()) {
      const auto ch = static_cast<std::size_t>(layer->channels);
      std::vector<float> out(columns * static_cast<std::size_t>(height + 1) * ch);
      for (int j = 0; j <= height; ++j)
        for (int i = 0; i <= width; ++i)
          std::copy_n(layer->texels.begin() + static_cast<std::ptrdiff_t>(source(i, j) * ch), ch,
                      out.begin() + static_cast<std::ptrdiff_t>(
                                        (static_cast<std::size_t>(j) * columns + i) * ch));
      layer->texels = std::move(out);
    }
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
  const GeometryImage& image = object.document.positions;
  if (image.topology() == Topology::Octahedral || codesExactly(options)) return std::nullopt;
  if (2 * std::max(image.width(), image.height()) <= kMaxSize) return std::nullopt;
  return "object '" + object.name + "', a " + std::string(topologyName(image.topology())) + " of " +
         std::to_string(image.width()) + " x " + std::to_string(image.height()) +
         " cells, is coded lossily on a square twice its longer side, over the largest N (" +
         std::to_string(kMaxSize) +
         "): use an exact codec (lossless, or exr with --mode zip or "
         "piz) or a smaller image";
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
    bodies.push_back(
        object.document.positions.topology() == Topology::Octahedral
            ? compressDocument(object.document, options)
            : compressDocument(squareDocument(object.document, !codesExactly(options)), options));

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
    const bool grid = object.document.positions.topology() != Topology::Octahedral;
    out.u8(static_cast<std::uint8_t>(topologyCode(object.document.positions.topology()) |
                                     (grid && !codesExactly(options) ? kInsetFlag : 0)));
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
    bool inset = false; // coded one sample in on a square twice its longer side
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
    const std::uint8_t code = in.u8();
    const std::uint8_t topology = code & static_cast<std::uint8_t>(~kInsetFlag);
    e.inset = (code & kInsetFlag) != 0;
    if (topology >= kTopologies.size() || (e.inset && topology == 0))
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
    // A torus or plane coded lossily sits one sample in on a square of twice its longer side.
    const int side = std::max(e.width, e.height);
    ByteReader peek(document, "compressed document");
    if (document.size() < 10) in.fail(part + ": its document is truncated");
    peek.take(6);
    const std::uint32_t n = peek.u32();
    if (n != static_cast<std::uint32_t>(e.inset ? 2 * side : side))
      in.fail(part + ": its document is N = " + std::to_string(n) + " but its header says " +
              std::to_string(e.width) + " x " + std::to_string(e.height) + " cells");
    Document square;
    try {
      square = decompressDocument(document);
    } catch (const Error& error) {
      if (error.kind() != ErrorKind::InvalidInput) throw;
      in.fail(part + ": " + error.what());
    }
    scene.objects.push_back(
        {e.name, objectDocument(std::move(square), e.topology, e.width, e.height, e.inset ? 1 : 0),
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
