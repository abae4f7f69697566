#pragma once

// Reads plugin files (manifests, shaders) that a user dropped into a folder: only regular files
// under a size limit, opened so that a named pipe, a device or a symlink loop can neither block
// nor feed endless bytes.

#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace octaclay::gpu::detail {

/// The most bytes a manifest (brush or material) may have.
inline constexpr std::uintmax_t kMaxManifestBytes = 1u << 20;
/// The most bytes a brush shader may have.
inline constexpr std::uintmax_t kMaxShaderBytes = 1u << 20;

/// Why a plugin file was not read: the message starts with the file's path.
class BoundedFileError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// The text of file, which must be a regular file (a symlink to one is fine) of at most limit
/// bytes. Never blocks: a FIFO, socket or device is refused before it is opened for reading
/// (and opened non-blocking in case it was swapped in). kind names the file in "is a folder,
/// not a <kind>". Throws BoundedFileError "<file>: <reason>".
std::string readBoundedFile(const std::filesystem::path& file, std::uintmax_t limit,
                            const std::string& kind);

} // namespace octaclay::gpu::detail
