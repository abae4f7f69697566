#pragma once

// Entropy coding of codec byte streams through zstd (Debian's libzstd): its Huffman and FSE
// stages code the residual and offset streams close to their order-0 entropy, decode at
// > 1 GB/s, and a frame whose size we know is decoded into a buffer we allocate ourselves.

#include "codec/byte_io.h"

#include <cstdint>
#include <span>
#include <vector>

namespace octaclay::core::detail {

/// Writes u32 frame length, then a zstd frame of data.
void writeZstdBlock(ByteWriter& out, std::span<const std::uint8_t> data, int level);
/// Reads a block written by writeZstdBlock whose content must be exactly `size` bytes; the
/// frame's declared size is checked before anything is allocated.
std::vector<std::uint8_t> readZstdBlock(ByteReader& in, std::size_t size);
/// The most bytes writeZstdBlock can write for `size` bytes of data.
std::size_t zstdBlockBound(std::size_t size);

} // namespace octaclay::core::detail
