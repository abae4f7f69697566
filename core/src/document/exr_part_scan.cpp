#include "exr_part_scan.h"

#include "octaclay/core/error.h"

#include <cstdint>
#include <fstream>

namespace octaclay::core::detail {

namespace fs = std::filesystem;

namespace {

// OpenEXR's version field: the low byte is the version, the rest flags.
constexpr std::uint32_t kSingleTileFlag = 0x200;
constexpr std::uint32_t kNonImageFlag = 0x800;
constexpr std::uint32_t kMultiPartFlag = 0x1000;
// An attribute's name and type are at most 255 bytes with long names (31 without).
constexpr std::size_t kLongestName = 255;
// No attribute an Octaclay part holds is larger (a channel list of 11 channels is ~200 bytes);
// a string longer than this is not ours either.
constexpr std::int64_t kLargestAttribute = 1 << 20;

class HeaderReader {
public:
  explicit HeaderReader(const fs::path& path) : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    fileSize_ = static_cast<std::int64_t>(fs::file_size(path, ec));
    if (!in_ || ec) throw Error(ErrorKind::Io, "cannot read " + path.string());
  }

  [[noreturn]] void refuse(const std::string& why) const {
    throw Error(ErrorKind::InvalidInput, path_.string() + ": " + why);
  }

  std::uint32_t u32() {
    unsigned char b[4];
    read(b, 4);
    return std::uint32_t(b[0]) | std::uint32_t(b[1]) << 8 | std::uint32_t(b[2]) << 16 |
           std::uint32_t(b[3]) << 24;
  }

  // A NUL-terminated name of at most kLongestName bytes ("" at a header's end).
  std::string name() {
    std::string text;
    for (;;) {
      const int c = in_.get();
      if (c == std::char_traits<char>::eof())
        refuse("truncated header: the file ends inside an attribute's name");
      if (c == 0) return text;
      if (text.size() == kLongestName)
        refuse("corrupt header: an attribute name longer than 255 bytes");
      text.push_back(static_cast<char>(c));
    }
  }

  void read(unsigned char* bytes, std::int64_t count) {
    in_.read(reinterpret_cast<char*>(bytes), count);
    if (in_.gcount() != count) refuse("truncated header: the file ends inside its headers");
  }

  void skip(std::int64_t count) {
    const std::int64_t at = static_cast<std::int64_t>(in_.tellg());
    if (at < 0 || count > fileSize_ - at)
      refuse("corrupt header: an attribute declares more bytes than the file holds");
    in_.seekg(count, std::ios::cur);
  }

private:
  const fs::path& path_;
  std::ifstream in_;
  std::int64_t fileSize_ = 0;
};

std::int32_t signedFrom(std::uint32_t v) {
  return static_cast<std::int32_t>(v);
}

// One header's attributes up to its terminating NUL; false when the header is empty (the end of
// a multi-part file's header list).
bool readHeader(HeaderReader& reader, ExrPartOutline& part, std::size_t index) {
  bool any = false, window = false;
  for (;;) {
    const std::string name = reader.name();
    if (name.empty()) break;
    any = true;
    const std::string type = reader.name();
    const std::int32_t size = signedFrom(reader.u32());
    if (size < 0 || size > kLargestAttribute)
      reader.refuse("corrupt header: attribute '" + name + "' declares " + std::to_string(size) +
                    " bytes");
    if (name == "tiles" || type == "tiledesc")
      reader.refuse("a tiled OpenEXR image, not an Octaclay document (its parts are scan lines)");
    if (name == "dataWindow" && type == "box2i" && size == 16) {
      const std::int64_t xMin = signedFrom(reader.u32()), yMin = signedFrom(reader.u32());
      const std::int64_t xMax = signedFrom(reader.u32()), yMax = signedFrom(reader.u32());
      const std::int64_t width = xMax - xMin + 1, height = yMax - yMin + 1;
      if (width < 1 || height < 1 || width > kLargestScannedSide || height > kLargestScannedSide ||
          width * height > kLargestScannedArea)
        reader.refuse("part " + std::to_string(index + 1) + " declares an image of " +
                      std::to_string(width) + "x" + std::to_string(height) +
                      " samples (a document's image is at most 8193x8193)");
      part.width = static_cast<int>(width);
      part.height = static_cast<int>(height);
      window = true;
    } else if (name == "name" && type == "string") {
      part.name.resize(static_cast<std::size_t>(size));
      reader.read(reinterpret_cast<unsigned char*>(part.name.data()), size);
    } else if (name == "type" && type == "string") {
      std::string value(static_cast<std::size_t>(size), '\0');
      reader.read(reinterpret_cast<unsigned char*>(value.data()), size);
      if (value != "scanlineimage")
        reader.refuse("part " + std::to_string(index + 1) + " is a '" + value +
                      "' part; an Octaclay document's parts are scan-line images");
    } else if (name == "chunkCount" && type == "int" && size == 4) {
      const std::int64_t chunks = signedFrom(reader.u32());
      if (chunks < 1 || chunks > kLargestScannedSide)
        reader.refuse("part " + std::to_string(index + 1) + " declares " + std::to_string(chunks) +
                      " chunks of pixels");
    } else {
      reader.skip(size);
    }
  }
  if (any && !window) reader.refuse("part " + std::to_string(index + 1) + " has no data window");
  return any;
}

} // namespace

ExrFileOutline scanExrHeaders(const fs::path& path, std::size_t maxParts) {
  HeaderReader reader(path);
  reader.u32(); // the magic number, checked by the caller
  const std::uint32_t version = reader.u32();
  if ((version & 0xff) != 2)
    reader.refuse("OpenEXR version " + std::to_string(version & 0xff) + " is not supported");
  if (version & (kSingleTileFlag | kNonImageFlag))
    reader.refuse("a tiled or deep OpenEXR image, not an Octaclay document");
  ExrFileOutline outline;
  outline.multiPart = (version & kMultiPartFlag) != 0;
  for (;;) {
    ExrPartOutline part;
    if (!readHeader(reader, part, outline.parts.size())) {
      if (outline.parts.empty()) reader.refuse("corrupt header: the file declares no part");
      break;
    }
    outline.parts.push_back(std::move(part));
    if (!outline.multiPart) break;
    if (outline.parts.size() > maxParts)
      reader.refuse("the file declares more than " + std::to_string(maxParts) +
                    " objects (parts); a document holds at most " + std::to_string(maxParts));
  }
  return outline;
}

} // namespace octaclay::core::detail
