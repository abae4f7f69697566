#include "codec/zstd_blocks.h"

#include "octaclay/core/error.h"

#include <zstd.h>

#include <vector>

namespace octaclay::core::detail {

void writeZstdBlock(ByteWriter& out, std::span<const std::uint8_t> data, int level) {
  std::vector<std::uint8_t> frame(ZSTD_compressBound(data.size()));
  const std::size_t size =
      ZSTD_compress(frame.data(), frame.size(), data.data(), data.size(), level);
  if (ZSTD_isError(size))
    throw Error(ErrorKind::InvalidArgument, std::string("zstd: ") + ZSTD_getErrorName(size));
  out.u32(static_cast<std::uint32_t>(size));
  out.append({frame.data(), size});
}

std::vector<std::uint8_t> readZstdBlock(ByteReader& in, std::size_t expected) {
  const std::uint32_t length = in.u32();
  const auto frame = in.take(length);
  // A zstd block is at least 3 bytes and holds at most 128 KiB: a frame claiming more than
  // that ratio allows is refused before its output is allocated.
  if (expected / (std::size_t{128} << 10) > frame.size() / 3 + 1)
    in.fail("an entropy-coded block of " + std::to_string(frame.size()) +
            " bytes cannot hold the " + std::to_string(expected) + " bytes it should");
  const unsigned long long declared = ZSTD_getFrameContentSize(frame.data(), frame.size());
  if (declared != expected)
    in.fail("entropy-coded block declares " +
            (declared >= ZSTD_CONTENTSIZE_ERROR ? std::string("no valid size")
                                                : std::to_string(declared) + " bytes") +
            ", expected " + std::to_string(expected));
  std::vector<std::uint8_t> out(expected);
  const std::size_t size = ZSTD_decompress(out.data(), out.size(), frame.data(), frame.size());
  if (ZSTD_isError(size))
    in.fail(std::string("corrupt entropy-coded block: ") + ZSTD_getErrorName(size));
  if (size != out.size())
    in.fail("entropy-coded block holds " + std::to_string(size) + " bytes, expected " +
            std::to_string(out.size()));
  return out;
}

std::size_t zstdBlockBound(std::size_t size) {
  return 4 + ZSTD_compressBound(size);
}

} // namespace octaclay::core::detail
